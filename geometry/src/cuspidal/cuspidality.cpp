// analyseCuspidality (cuspidality.hpp): the 3R analysis and the 6R witness search in one call.
#include "soma/geometry/cuspidal/cuspidality.hpp"

#include <chrono>

namespace soma {

CuspidalAnalysis analyseCuspidality(const SerialRobot<double>& robot, const CuspidalOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  CuspidalAnalysis r;
  if (robot.dof() == 6) {
    r.sixR = true;
    r.method = "6R witness search: random poses (seed 20261130), all IK postures, OMPL RRTConnect between same-sign pairs";
    r.witness6r = findWitness6R(robot, options.poses, options.secondsPerPair);
    r.cuspidal = r.witness6r.found;
    r.seconds = r.witness6r.seconds;
    return r;
  }
  r.method = "triple root of the IK equation (degree-12 cusp polynomial)";
  r.cusps = findCuspsAdaptive(robot);
  r.verdictSeconds = r.cusps.seconds;
  r.cuspidal = !r.cusps.cusps.empty();
  r.dj = detJSeries(robot);
  r.branches = traceSingularCurves(robot, r.dj);
  r.reversals = imageReversals(r.branches);
  r.aspectMap = aspects(r.dj, options.aspectGrid);
  if (r.cuspidal && options.witness) r.witness = findWitness(robot, r.cusps, r.dj, r.aspectMap);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace soma
