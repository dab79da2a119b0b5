// analyseCuspidality (cuspidality.hpp): the 3R analysis, the 6R decompositions and the 6R witness
// search in one call.
#include "soma/geometry/cuspidal/cuspidality.hpp"

#include <chrono>

namespace soma {

namespace {

/// The 3R analysis of `arm` into r (cusps, singular curves, aspects, witness).
void analyse3R(const SerialRobot<double>& arm, const CuspidalOptions& options, CuspidalAnalysis& r) {
  r.cusps = findCuspsAdaptive(arm);
  r.verdictSeconds = r.cusps.seconds;
  r.cuspidal = !r.cusps.cusps.empty();
  r.dj = detJSeries(arm);
  r.branches = traceSingularCurves(arm, r.dj);
  r.reversals = imageReversals(r.branches);
  r.aspectMap = aspects(r.dj, options.aspectGrid);
  if (r.cuspidal && options.witness) r.witness = findWitness(arm, r.cusps, r.dj, r.aspectMap);
}

}  // namespace

CuspidalAnalysis analyseCuspidality(const SerialRobot<double>& robot, const CuspidalOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  auto seconds = [&]() { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  CuspidalAnalysis r;
  if (robot.dof() == 6) {
    r.sixR = true;
    if (!options.forceSearch) r.decomposition = decomposeForCuspidality(robot);
    const CuspidalDecomposition& d = r.decomposition;
    if (d.kind == CuspidalDecompositionKind::SphericalWrist) {
      r.method = "decomposition: " + d.reason + "; the arm's verdict by the triple root of its IK equation";
      analyse3R(*d.arm, options, r);
      if (r.cuspidal && r.witness.found) r.witness6r = liftArmWitness(robot, d, r.witness);
      r.seconds = seconds();
      return r;
    }
    if (d.kind == CuspidalDecompositionKind::ParallelChain) {
      r.method = "decomposition: " + d.reason;
      r.cuspidal = false;
      r.seconds = seconds();
      return r;
    }
    r.method = "6R witness search: random poses (seed 20261130), all IK postures, same-sign pairs joined by the "
               "straight joint path, then OMPL RRTConnect";
    Witness6ROptions wo;
    wo.poses = options.poses;
    wo.secondsPerPair = options.secondsPerPair;
    wo.budget = options.budget;
    wo.progress = options.progress;
    r.witness6r = findWitness6R(robot, wo);
    r.cuspidal = r.witness6r.found;
    r.decided = r.witness6r.found;
    r.seconds = seconds();
    return r;
  }
  r.method = "triple root of the IK equation (degree-12 cusp polynomial)";
  analyse3R(robot, options, r);
  r.seconds = seconds();
  return r;
}

}  // namespace soma
