#pragma once
// Inverse kinematics of the general 6R robot: every real posture (GF §11.5, up to 16).
//
// The algebraic method is Raghavan–Roth's elimination with Manocha–Canny's eigenproblem:
// write A3·A4·A5 = A2⁻¹·A1⁻¹·T·A6⁻¹ for the axis line of joint 6 (a point p on it and its
// direction l), and form the 14 line quantities p, l, p·p, p·l, p×l, (p·p)l − 2(p·l)p. Each
// side is of degree ≤ 1 in the cosine and sine of every joint angle it contains (the set is
// closed under rigid motions, linearly in the rotation), so the left side is a trilinear
// trigonometric polynomial in θ3, θ4, θ5 and the right side a bilinear one in θ1, θ2. The 8
// monomials of θ1, θ2 are eliminated by the 6-dimensional left null space of their 14×8
// coefficient matrix; the half-angle substitution in θ4, θ5 and a multiplication by x4 give a
// 12×12 matrix polynomial M(x3) = A x3² + B x3 + C whose determinant (degree 24) carries the 16
// solutions and the extraneous factor (1 + x3²)⁴. Its 24×24 companion matrix gives x3; the null
// vector of M(x3) gives θ4, θ5; the 14×8 system gives θ1, θ2; the forward chain gives θ6; Newton
// steps on the pose polish each real posture in the working scalar.
//
// Conditioning: the coefficients are computed by exact interpolation on the grid {0, π/2, π}
// (no symbolic expansion); lengths are scaled to unit size (angles do not change); θ3 is
// rotated by an offset β (a Möbius change of the half-angle variable) when the leading matrix
// A is singular — θ3 = β + π is then the root at infinity; when A is singular for every β
// (structurally, e.g. a PUMA whose wrist axes nearly meet or a UR whose axis 4 is nearly parallel
// to 2 and 3) the closed loop Rz(θ1)K1···Rz(θ6)K6 = I is relabelled cyclically or reversed so
// that another joint is eliminated last, the best-conditioned of the 12 — and the whole solve is repeated in
// the next scalar of the ladder (float → double → long double → float128 → mpfr) when the
// eigenvalue count, a cluster of eigenvalues, an odd real count or a failed polish says the
// answer may be short. Every such step is written into `notes`.
#include "soma/algebra/errors.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/serial/dh.hpp"
#include "soma/geometry/serial/ik_solution.hpp"

#include <array>
#include <string>
#include <vector>

namespace soma {

template <class S> using Robot6R = std::array<DHRow<S>, 6>;

/// The answer of the general-6R solver: Solution<S> plus what the eigenproblem saw.
template <class S> struct General6RSolution : Solution<S> {
  /// Complex solutions the eigenproblem produced (24 eigenvalues minus the 8 extraneous ones at
  /// x3 = ±i); 16 for a generic robot.
  int complex_count = 0;
  /// The scalar the eigenproblem was finally solved in (after any escalation).
  std::string solved_in;
  /// Reciprocal condition estimate of the leading matrix A used (after any θ3 offset).
  double leading_rcond = 0;
  /// θ3 offset β of the half-angle variable x3 = tan((θ3 − β)/2).
  double theta3_offset = 0;
  /// The smallest distance between two real candidates of x3 (relative): a cluster warning.
  double min_gap = 0;
  /// The elimination used: "theta3 last" (the chain as given), or "thetaK last" with
  /// ", reversed loop" when the leading matrix was singular for every θ3 offset and a cyclic
  /// relabelling or the reversed loop of the closed chain was better conditioned.
  std::string elimination;
};

struct General6ROptions {
  /// Re-solve in the next scalar of the ladder when the answer may be short.
  bool escalate = true;
  /// Eliminate another joint last (a cyclic relabelling or the reversed loop) when the leading
  /// matrix of the θ3-last elimination is singular for every offset; false keeps θ3 last (and
  /// its generalized eigenproblem).
  bool choose_elimination = true;
  /// Newton iterations of the polish (stops earlier at convergence).
  int polish_iterations = 12;
};

/// Forward kinematics of a 6R DH chain: A1(q1)···A6(q6). GF §3.4 / §4.5
template <class S> SE3<S> general6rForward(const Robot6R<S>& robot, const std::array<S, 6>& q);

/// Residual of a posture as Solution<S> defines it, with scale = the length scale of the robot
/// and target (max over |a_i|, |d_i|, |t|; 1 when all vanish): max(|R(q) − R*|_F, |t(q) − t*|/scale).
template <class S>
S general6rResidual(const Robot6R<S>& robot, const SE3<S>& target, const std::array<S, 6>& q);

/// Every real posture of a general 6R robot reaching `target` (the pose of frame 6 in frame 0),
/// by the Raghavan–Roth / Manocha–Canny eigenproblem. Joint values are q_i with the DH row's
/// theta as offset, wrapped to (−π, π]. Throws InvalidInput for a prismatic joint or a
/// non-finite robot or target. GF §11.5 (16 complex postures).
template <class S>
General6RSolution<S> solveGeneral6R(const Robot6R<S>& robot, const SE3<S>& target,
                                    const General6ROptions& options = {});

/// Same, from a 4×4 matrix, validated first (a matrix that is not a rigid motion → InvalidInput).
template <class S>
General6RSolution<S> solveGeneral6R(const Robot6R<S>& robot, const Mat4<S>& target,
                                    const General6ROptions& options = {});

/// Newton polish of one posture on the pose equations in S (used by all methods).
template <class S>
std::array<S, 6> polishGeneral6R(const Robot6R<S>& robot, const SE3<S>& target,
                                 std::array<S, 6> q, int iterations);

// ---- numerical alternatives (double only) --------------------------------------------------
struct General6RNumericOptions {
  int starts = 64;                ///< random initial joint vectors
  unsigned long long seed = 1;    ///< fixed seed of the starts
  int max_iterations = 100;       ///< per start
};

/// Multi-start Levenberg–Marquardt with Ceres, distinct converged postures kept (clustering),
/// each polished by Newton. Method name "ceres".
General6RSolution<double> solveGeneral6RCeres(const Robot6R<double>& robot,
                                              const SE3<double>& target,
                                              const General6RNumericOptions& options = {});
/// Multi-start local minimisation with NLopt (LD_SLSQP on the squared residual... see .cpp),
/// distinct postures kept by clustering. Method name "nlopt".
General6RSolution<double> solveGeneral6RNlopt(const Robot6R<double>& robot,
                                              const SE3<double>& target,
                                              const General6RNumericOptions& options = {});

#define SOMA_GENERAL6R_EXTERN(S)                                                              \
  extern template SE3<S> general6rForward<S>(const Robot6R<S>&, const std::array<S, 6>&);     \
  extern template S general6rResidual<S>(const Robot6R<S>&, const SE3<S>&,                    \
                                         const std::array<S, 6>&);                            \
  extern template General6RSolution<S> solveGeneral6R<S>(const Robot6R<S>&, const SE3<S>&,    \
                                                         const General6ROptions&);            \
  extern template General6RSolution<S> solveGeneral6R<S>(const Robot6R<S>&, const Mat4<S>&,   \
                                                         const General6ROptions&);            \
  extern template std::array<S, 6> polishGeneral6R<S>(const Robot6R<S>&, const SE3<S>&,       \
                                                      std::array<S, 6>, int);
SOMA_FOR_EACH_SCALAR(SOMA_GENERAL6R_EXTERN)
#undef SOMA_GENERAL6R_EXTERN

}  // namespace soma
