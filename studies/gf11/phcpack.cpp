// GF §11.5: the intersection counts checked by an independent solver. soma writes its own
// constraint quadrics (sphereConstraintQuadric, the Study quadric) for random platforms as
// polynomial systems, PHCpack's blackbox solver (Debian's phcpack, `phc -b -0`: fixed seed) tracks
// every path of a total-degree homotopy, and the study counts the regular finite solutions:
// 6-3 platform 16, general 6-6 platform 40 (the tripod wrist, 8 and 6: GF-11.5.3-tripod-wrist-eight).
// Double precision (PHCpack's).
#include "gf11/common.hpp"
#include "soma/geometry/study/constraint_quadrics.hpp"
#include "soma/geometry/study/intersection_ring.hpp"
#include "soma/studies/study.hpp"

#include "soma/studies/phc_runner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <complex>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace soma::studies::gf11::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using S = double;
constexpr const char* kWhyDouble = "PHCpack, the independent solver, works in double";

/// Leg lengths that a random real pose assembles (so the real pose must be among the solutions).
std::vector<double> legLengths(const SE3<S>& pose, const std::vector<Vec3<S>>& base, const std::vector<Vec3<S>>& top) {
  std::vector<double> L;
  for (std::size_t i = 0; i < base.size(); ++i) L.push_back((pose.act(top[i]) - base[i]).norm());
  return L;
}

/// The largest entry of the quadrics (the scale of xᵀQx for |x| = 1).
double quadricScale(const std::vector<Mat8<S>>& quadrics) {
  double m = 0;
  for (const auto& Q : quadrics) m = std::max(m, Q.cwiseAbs().maxCoeff());
  return m;
}

void countsByPhcpack(Context& c) {
  auto g = rng(1150);
  const std::vector<std::string> x8 = {"a0", "a1", "a2", "a3", "c0", "c1", "c2", "c3"};
  const Eigen::MatrixXd Qs = studyQuadricMatrix<S>();
  struct Case {
    std::string name, tag, claim;
    int expected;
    int distinctTop;
  };
  const std::vector<Case> cases = {
      {"6-3 Stewart platform (platform joints coincide in pairs)", "63", "GF-11.5.2-6-3-stewart-sixteen", 16, 3},
      {"general 6-6 Stewart platform", "66", "GF-11.5.4-stewart-forty", 40, 6}};
  for (const Case& k : cases) {
    const int legs = 6;
    std::vector<Vec3<S>> base, top;
    std::vector<Vec3<S>> distinct;
    for (int i = 0; i < k.distinctTop; ++i) distinct.push_back(rv3<S>(g));
    for (int i = 0; i < legs; ++i) {
      base.push_back(rv3<S>(g));
      top.push_back(distinct[std::size_t(i * k.distinctTop / legs)]);
    }
    const SO3<S> R = SO3<S>::Random(g);
    const SE3<S> pose(R, rv3<S>(g));
    const std::vector<double> L = legLengths(pose, base, top);
    std::vector<std::string> eqs;
    std::vector<Mat8<S>> quadrics;
    for (int i = 0; i < legs; ++i) quadrics.push_back(sphereConstraintQuadric<S>(base[i], top[i], L[i]));
    Eigen::VectorXd w(8);
    for (Eigen::Index i = 0; i < w.size(); ++i) w(i) = uni<S>(g);
    for (const auto& Q : quadrics) eqs.push_back(phcQuadric(Q, x8));
    eqs.push_back(phcQuadric(Qs, x8));
    eqs.push_back(phcLinear(w, x8, 1.0));
    const PhcResult run = solveWithPhc(eqs, x8, k.tag);
    // Regular solutions off the exceptional 3-plane a = 0 (the S–S varieties all contain the
    // conic a = 0, c·c = 0: paths ending there are singular), and soma's own residuals on them.
    int finite = 0;
    double worstResidual = 0, nearestPose = 1e300;
    const Vec8<S> truth = StudyParameters<S>::fromSE3(pose).coeffs();
    for (const PhcSolution& s : run.solutions) {
      if (!s.regular) continue;
      const Eigen::VectorXcd& x = s.x;
      if (!(x.head<4>().norm() > Tolerance<S>::sqrtEpsilon() * x.norm())) continue;
      ++finite;
      for (const auto& Q : quadrics) {
        const Eigen::MatrixXcd Qc = Q.cast<std::complex<double>>();
        worstResidual = std::max(worstResidual, std::abs((x.transpose() * Qc * x)(0, 0)) / x.squaredNorm());
      }
      // Distance to the generating pose in PR⁷: 1 − |⟨x, truth⟩|² / (|x|²|truth|²).
      const double cosine = std::norm(x.dot(truth.cast<std::complex<double>>())) / (x.squaredNorm() * truth.squaredNorm());
      nearestPose = std::min(nearestPose, std::max(0.0, 1 - cosine));  // rounding can make it −1e-16
    }
    c.note(fmt::format("{}: {} paths, PHCpack reports {} regular solutions, {:.1f} s (claim {}).", k.name, run.paths,
                       run.reportedRegular, run.seconds, k.claim));
    c.checkEqual(k.name + ": regular finite solutions found by PHCpack", k.expected, finite);
    c.checkEqual(k.name + ": PHCpack's own regular count agrees", k.expected, run.reportedRegular);
    // Bound: xᵀQx of 8 terms in double, |fl − exact| ≤ (n + 1)·n·ε·max|Q_ij|·|x|² (n = 8, 72 ε), plus
    // PHCpack's 16-digit solution (relative error ≈ ε: 2·n·ε·max|Q_ij|·|x|², 16 ε): 88 ε, k = 128.
    c.checkResidual(k.name + ": soma's constraint quadrics vanish on PHCpack's solutions (≤ 128 ε·max|Q_ij|·|x|²)",
                    worstResidual, 128 * Tolerance<S>::epsilon() * quadricScale(quadrics));
    // 1 − cos² of two unit directions agreeing to ≈ ε relative: the subtraction leaves a few ε.
    c.checkResidual(k.name + ": the generating real pose is among them (1 − cos² in PR⁷, ≤ 16 ε)", nearestPose,
                    Tolerance<S>::identity(16));
  }
}

// ---- GF-11.5.3-tripod-wrist-eight -------------------------------------------------------------
// Three S–S legs: (2σ₅)³ = 8σ_A + 8σ_B. With a ball joint at the origin (the A-plane c = 0 of
// rotations about it) 8 conformations; with the platform restricted to planar motions (the A-plane
// SE(2)_z: a₁ = a₂ = c₀ = c₃ = 0) only 6 are finite, two lie at infinity (a = 0).
void tripodWrist(Context& c) {
  const StudyClass legs = (StudyClass::sigma5() * 2).pow(3);
  c.checkEqual("ring: (2σ₅)³", "8σ_A + 8σ_B", legs.toString());
  c.checkEqual("ring: (2σ₅)³ ∩ σ_A (the rotations about the ball joint)", 8, (legs * StudyClass::sigmaA()).degree());
  auto g = rng(1153);
  for (const bool planar : {false, true}) {
    std::vector<Vec3<S>> base, top;
    for (int i = 0; i < 3; ++i) {
      base.push_back(rv3<S>(g));
      top.push_back(rv3<S>(g));
    }
    // A real pose in the subgroup, so that a real conformation exists.
    const double th = uni<S>(g) * 3;
    const SE3<S> pose = planar ? SE3<S>(SO3<S>::fromAxisAngle(Vec3<S>::UnitZ(), th), Vec3<S>(uni<S>(g), uni<S>(g), 0))
                               : SE3<S>(SO3<S>::Random(g), Vec3<S>::Zero());
    const std::vector<double> L = legLengths(pose, base, top);
    // The coordinates of the A-plane in PR⁷ and their names.
    const std::vector<int> idx = planar ? std::vector<int>{0, 3, 5, 6} : std::vector<int>{0, 1, 2, 3};
    const std::vector<std::string> names = planar ? std::vector<std::string>{"a0", "a3", "c1", "c2"}
                                                  : std::vector<std::string>{"a0", "a1", "a2", "a3"};
    std::vector<Eigen::MatrixXd> restricted;
    std::vector<std::string> eqs;
    for (int i = 0; i < 3; ++i) {
      const Mat8<S> Q = sphereConstraintQuadric<S>(base[i], top[i], L[i]);
      Eigen::MatrixXd R(4, 4);
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) R(a, b) = Q(idx[a], idx[b]);
      restricted.push_back(R);
      eqs.push_back(phcQuadric(R, names));
    }
    Eigen::VectorXd w(4);
    for (int i = 0; i < 4; ++i) w(i) = uni<S>(g);
    eqs.push_back(phcLinear(w, names, 1.0));
    const PhcResult run = solveWithPhc(eqs, names, planar ? "tripod-planar" : "tripod");
    int regular = 0, finite = 0;
    double worst = 0, nearest = 1e300;
    Eigen::VectorXd truth(4);
    const Vec8<S> t8 = StudyParameters<S>::fromSE3(pose).coeffs();
    for (int a = 0; a < 4; ++a) truth(a) = t8(idx[a]);
    for (const PhcSolution& sol : run.solutions) {
      if (!sol.regular) continue;
      ++regular;
      const Eigen::VectorXcd x = sol.x;
      // a-part: (a0, a3) for the planar plane, all four for the ball joint.
      const double aNorm = planar ? std::sqrt(std::norm(x(0)) + std::norm(x(1))) : x.norm();
      if (!(aNorm > Tolerance<S>::sqrtEpsilon() * x.norm())) continue;
      ++finite;
      for (const auto& R : restricted)
        worst = std::max(worst, std::abs((x.transpose() * R.cast<std::complex<double>>() * x)(0, 0)) / x.squaredNorm());
      nearest = std::min(nearest, std::max(0.0, 1 - std::norm(x.dot(truth.cast<std::complex<double>>())) / (x.squaredNorm() * truth.squaredNorm())));
    }
    const std::string what = planar ? "planar platform (SE(2)_z)" : "ball joint at the origin";
    c.note(fmt::format("{}: {} paths, {} regular, {} finite, {:.1f} s (PHCpack).", what, run.paths, regular, finite, run.seconds));
    c.checkEqual(what + ": regular solutions (PHCpack)", 8, regular);
    c.checkEqual(what + ": finite conformations (a ≠ 0)", planar ? 6 : 8, finite);
    // Bound as in countsByPhcpack with n = 4: (n + 1)·n + 2n = 28 ε·max|R_ij|·|x|², k = 64.
    double rScale = 0;
    for (const auto& R : restricted) rScale = std::max(rScale, R.cwiseAbs().maxCoeff());
    c.checkResidual(what + ": soma's leg quadrics vanish on them (≤ 64 ε·max|R_ij|·|x|²)", worst,
                    64 * Tolerance<S>::epsilon() * rScale);
    c.checkResidual(what + ": the generating real pose is among them (1 − cos², ≤ 16 ε)", nearest, Tolerance<S>::identity(16));
  }
}

SOMA_STUDY({.id = "SOMA-11.5-phcpack-counts",
            .title = "PHCpack confirms the §11.5 counts on soma's quadrics: 6-3 platform 16, 6-6 platform 40",
            .source = "GF §11.5.2–11.5.4",
            .chapter = kChapter,
            .scalarGeneric = false,
            .run = countsByPhcpack,
            .whyDouble = "PHCpack (an external program) reads and solves the systems in double"});
SOMA_STUDY({.id = "GF-11.5.3-tripod-wrist-eight",
            .title = "Tripod wrist: 8 conformations; 6 finite when the platform moves in a plane",
            .source = "GF §11.5.3",
            .chapter = kChapter,
            .scalarGeneric = false,
            .run = tripodWrist,
            .whyDouble = kWhyDouble});

}  // namespace
}  // namespace soma::studies::gf11::SOMA_UNITY_ID
