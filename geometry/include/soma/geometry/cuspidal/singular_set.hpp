#pragma once
// The singular set of a 3R arm in joint space (GF §5.2.3): det J = 0 for the 3×3 Jacobian of the
// tool point, a function of (θ2, θ3) only (turning joint 1 turns the whole arm). det J is a
// trigonometric polynomial of degree ≤ 2 in each of θ2 and θ3 (det J = ½ det ∂(|b|², z)/∂(θ2, θ3)
// up to sign, both entries bilinear in (cos, sin) of θ2 and θ3), so 5 × 5 Fourier coefficients,
// computed exactly from a 6 × 6 sample grid, give it everywhere. From it: roots along lines
// (every crossing of a grid line, exactly), the curves traced by continuation, their images in the
// workspace section (ρ, z), and the aspects — the connected components of det J ≠ 0 on the torus.
// Runs in double.
#include "soma/geometry/cuspidal/cusps.hpp"

#include <Eigen/Core>

#include <vector>

namespace soma {

/// det J(θ2, θ3) = Σ_jk C(j, k) e_j(θ2) e_k(θ3), e = (1, cos, sin, cos 2·, sin 2·).
struct DetJSeries {
  Eigen::Matrix<double, 5, 5> C = Eigen::Matrix<double, 5, 5>::Zero();
  double scale = 1;  ///< max |det J| over the sample grid (for relative thresholds)
  double value(double t2, double t3) const;
  /// (∂/∂θ2, ∂/∂θ3)
  Eigen::Vector2d gradient(double t2, double t3) const;
  /// Roots in [−π, π) of θ2 ↦ det J(θ2, θ3) (ascending), and of θ3 ↦ det J(θ2, θ3).
  std::vector<double> rootsInTheta2(double t3) const;
  std::vector<double> rootsInTheta3(double t2) const;
  /// True when det J vanishes identically along the line (a whole line of the singular set).
  bool vanishesAlongTheta2(double t3) const;
};

/// det of the 3×3 Jacobian of the tool point at q (θ1 irrelevant), from the spatial Jacobian.
double toolPointJacobianDet(const SerialRobot<double>& robot, const JointVector<double>& q);
// GF §5.2.3, GF-5.2.3-position-jacobian-singular-line (det J of the point velocities)
DetJSeries detJSeries(const SerialRobot<double>& robot);

/// One traced branch of det J = 0: joint points (θ2, θ3), unwrapped (continuous, may leave
/// [−π, π)), and whether it closed on itself (possibly after winding around the torus).
struct SingularBranch {
  std::vector<Eigen::Vector2d> joints;
  std::vector<Eigen::Vector2d> section;  ///< (ρ, z) of each point
  std::vector<double> gradient;          ///< |∇ det J| at each point (0 at a node of the curve)
  bool closed = false;
};

/// Trace every branch of det J = 0 by predictor–corrector continuation with step `step` (rad),
/// seeded from the exact roots along `seedLines` lines θ3 = const and θ2 = const.
std::vector<SingularBranch> traceSingularCurves(const SerialRobot<double>& robot, const DetJSeries& dj,
                                                double step = 0.004, int seedLines = 24);

/// Second method for the cusp count: the points along the traced branches where the image in
/// (ρ², z) turns back (consecutive chords with a negative dot product) — a cusp of the section.
/// (ρ² rather than ρ so that a branch crossing axis 1 does not count; a reversal where |∇ det J|
/// nearly vanishes is a node of det J = 0 — two singular curves crossing, as in decoupled arms —
/// not a cusp, and does not count either.) Returns (ρ, z) of each.
std::vector<Eigen::Vector2d> imageReversals(const std::vector<SingularBranch>& branches);

/// Aspects: connected components of det J ≠ 0 on the torus [−π, π)², by union–find over an
/// n × n grid whose edges are cut exactly where det J has a root on them.
struct AspectMap {
  int n = 0;
  std::vector<int> label;  ///< per grid node (i along θ2, j along θ3: label[j * n + i]); −1 on det J = 0
  std::vector<int> sign;   ///< per aspect: sign of det J
  int count() const { return int(sign.size()); }
  double theta(int i) const;  ///< grid coordinate of index i
  /// Aspect of a joint point: the label of a grid node joined to it by a segment free of roots
  /// (−1 if none of the four surrounding nodes is).
  int aspectOf(const DetJSeries& dj, double t2, double t3) const;
};
AspectMap aspects(const DetJSeries& dj, int n = 256);

}  // namespace soma
