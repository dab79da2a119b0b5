#pragma once
// PHCpack as the independent solver of a Stewart platform's forward kinematics (GF §11.5.4): the six
// leg quadrics xᵀQᵢx = 0 (sphereConstraintQuadric), the Study quadric and an affine chart w·x = 1 in
// the Study parameters x = (a, c) ∈ PR⁷; its finite regular solutions (a ≠ 0) and the real ones among
// them. Shared by GF-11-fig-11.1, SOMA-11.5-stewart-classes and SOMA-11.5.4-dietmaier-forty-real.
#include "soma/algebra/study_parameters.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/geometry/study/constraint_quadrics.hpp"
#include "soma/studies/phc_runner.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace soma::studies::stewart_phc {

inline const std::vector<std::string>& studyNames() {
  static const std::vector<std::string> x8 = {"a0", "a1", "a2", "a3", "c0", "c1", "c2", "c3"};
  return x8;
}

/// A random affine chart w (entries uniform in [−1, 1], from `seed`).
inline Eigen::VectorXd randomChart(std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd w(8);
  for (Eigen::Index i = 0; i < 8; ++i) w(i) = u(g);
  return w;
}

/// The 8 equations in PHCpack's syntax: six legs, the Study quadric, the chart w·x = 1.
inline std::vector<std::string> equations(const StewartPlatform<double>& P, const Eigen::VectorXd& chart) {
  std::vector<std::string> eqs;
  for (std::size_t i = 0; i < 6; ++i)
    eqs.push_back(phcQuadric(sphereConstraintQuadric<double>(P.base[i], P.platform[i], P.legs[i]), studyNames()));
  eqs.push_back(phcQuadric(studyQuadricMatrix<double>(), studyNames()));
  eqs.push_back(phcLinear(chart, studyNames(), 1.0));
  return eqs;
}

struct Solutions {
  int finite = 0;                                   ///< regular, off the plane a = 0 at infinity
  std::vector<Eigen::Matrix<double, 8, 1>> real;    ///< real ones, scaled so the largest |xᵢ| is 1
};

/// Finite: regular with |a| > √ε |x|. Real: the representative whose largest coordinate is 1 has
/// every imaginary part ≤ Tolerance::input() (64 √ε), the threshold soma's own solver uses.
inline Solutions classify(const PhcResult& run) {
  Solutions out;
  for (const PhcSolution& sol : run.solutions) {
    if (!sol.regular || !(sol.x.head<4>().norm() > Tolerance<double>::sqrtEpsilon() * sol.x.norm())) continue;
    ++out.finite;
    Eigen::Index k = 0;
    sol.x.cwiseAbs().maxCoeff(&k);
    const Eigen::VectorXcd y = sol.x / sol.x(k);
    if (y.imag().cwiseAbs().maxCoeff() <= Tolerance<double>::input()) out.real.push_back(y.real());
  }
  return out;
}

/// The largest, over soma's real postures, of the distance 1 − cos² in PR⁷ to the nearest real
/// PHCpack solution: 0 when every posture is one of PHCpack's.
inline double worstMatch(const std::vector<SE3<double>>& postures, const std::vector<Eigen::Matrix<double, 8, 1>>& real) {
  double worst = 0;
  for (const auto& h : postures) {
    const Eigen::Matrix<double, 8, 1> x = StudyParameters<double>::fromSE3(h).coeffs();
    double best = 1;
    for (const auto& y : real) best = std::min(best, std::max(0.0, 1 - (x.dot(y) * x.dot(y)) / (x.squaredNorm() * y.squaredNorm())));
    worst = std::max(worst, best);
  }
  return worst;
}

}  // namespace soma::studies::stewart_phc
