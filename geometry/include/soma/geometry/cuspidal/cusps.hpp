#pragma once
// Cusp points of a 3R positioning arm, found algebraically (GF §5.2.3 and Fig. 5.2 "circling a
// cusp"; Burdick, Smith; Wenger: a generic 3R arm is cuspidal ⇔ its workspace has a cusp point,
// i.e. a point where three inverse-kinematic postures coincide — Salunkhe, Spartalis, Capco,
// Chablat, Wenger 2022, arXiv:2202.08686).
//
// Reduction (GF §5.2.1, the two invariants of the rotation about axis 2): in the frame of axis 1
// (origin O1 the foot of the common normal of axes 1, 2; x along it; z = v1) axis 2 passes through
// (a1, 0, 0) with direction (0, −s1, c1). A target at cylindrical coordinates (ρ, ψ, z′) about
// axis 1 is reached by joint 3 angle φ3 iff
//     ρ² + z′² + a1² − 2 a1 ρ cos ψ = W(φ3) = |a(φ3) − r2|²,   c1 z′ − s1 ρ sin ψ = V(φ3) = v2·(a(φ3) − r2)
// (a(φ3) the tool point turned about axis 3). Eliminating ψ gives the IK equation in φ3 alone,
//     f(φ3) = s1² X² + 4 a1² Y² − 4 a1² s1² ρ² = 0,   X = ρ² + z′² + a1² − W,   Y = c1 z′ − V,
// a quartic in tan(φ3/2). A cusp is a triple root: f = f′ = f″ = 0. For fixed φ3, f′ = f″ = 0 are
// LINEAR in (X, Y) (W, V are first-degree trigonometric polynomials, W″ = −(W − W0), and
// E = W′V″ − V′W″ = W1 V2 − W2 V1 is constant), so X = −V′K/(aE), Y = W′K/(bE) with a = s1²,
// b = 4 a1², K = aW′² + bV′², and f = 0 gives ρ² = K³/(a²b²E²). Eliminating z′ between
// X = ρ² + z′² + a1² − W and Y = c1 z′ − V leaves one trigonometric equation of degree 6 in φ3,
//     G(φ3) = c1² [−a b² E V′ K + a² b² E² (W − a1²) − K³] − a² (W′ K + b E V)² = 0,
// a polynomial of degree 12 in tan(φ3/2): every real root is one cusp point (ρ ≥ 0, z).
// The derivation needs a1 ≠ 0, s1 ≠ 0 (axes 1, 2 neither meeting nor parallel) and E ≠ 0 (axes 2,
// 3 neither meeting nor parallel, tool point off axis 3): otherwise the IK splits into quadratics
// and the arm has no cusp (reported as `decoupled`, with the reason).
#include "soma/geometry/serial/serial_robot.hpp"

#include <string>
#include <vector>

namespace soma {

/// A 3R arm in the frame of its first axis: everything the cusp computation needs.
template <class S> struct Arm3RFrame {
  Vec3<S> o1;              ///< foot of the common normal of axes 1, 2 on axis 1 (home, world frame)
  Vec3<S> ex, ey, ez;      ///< ez = v1, ex along the common normal, ey = ez × ex
  Vec3<S> c;               ///< foot of the base origin on axis 1: z is measured from here
  S a1 = S(0);             ///< signed length of the common normal (along ex = v1 × v2 / |v1 × v2|)
  S s1 = S(0), c1 = S(1);  ///< sine (≥ 0) and cosine of the twist from axis 1 to axis 2
  S z0 = S(0);             ///< z of O1 (so z = z′ + z0)
  Vec3<S> W, V;            ///< (W0, W1, W2), (V0, V1, V2): W(φ) = W0 + W1 cos φ + W2 sin φ
  Vec3<S> r2, v2;          ///< foot of the common normal on axis 2, unit direction of axis 2 (world)
  Vec3<S> p0;              ///< tool point at home (world)
  S E = S(0);              ///< W1 V2 − W2 V1
  S scale = S(1);          ///< the robot's length scale L
  bool decoupled = false;  ///< a1 = 0, s1 = 0 or E = 0 within Tolerance<S>::rank(): no cusp
  std::string reason;      ///< why decoupled
};

/// Throws InvalidInput unless the robot has exactly three revolute joints (naming what it has).
// GF §5.2.1, GF-5.2.1-3r-ik-procedure (the invariants v2·(a − r2), |a − r2|² of the middle rotation)
template <class S> Arm3RFrame<S> arm3RFrame(const SerialRobot<S>& robot);

/// Cylindrical coordinates (ρ, z) of the tool point of posture q about axis 1.
template <class S> Vec2<S> workspaceSection(const Arm3RFrame<S>& frame, const SerialRobot<S>& robot,
                                            const JointVector<S>& q);

template <class S> struct CuspPoint {
  S rho = S(0), z = S(0);
  JointVector<S> posture;  ///< the triple-root posture with q1 = 0
  S residual = S(0);       ///< |p(posture) − p(ρ, z)| / L
};

template <class S> struct CuspAnalysis {
  Arm3RFrame<S> frame;
  std::vector<CuspPoint<S>> cusps;  ///< sorted by z, then ρ
  std::vector<S> polynomial;        ///< G in t = tan((φ3 − phase)/2), ascending, degree ≤ 12
  S phase = S(0);                   ///< rotation of φ3 that keeps the roots away from t = ∞
  int candidates = 0;               ///< real (or near-real) roots of G
  double seconds = 0;
  std::string scalar;               ///< the scalar the cusp points were computed in (findCuspsAdaptive)
  std::string conditioning;         ///< why it escalated, empty when S sufficed
};

/// Every cusp point of the workspace section of a 3R arm (counted once in the half-plane ρ ≥ 0).
// GF §5.2.3, GF-5.2.3-cuspidal-posture-change (triple root of the IK quartic of GF-5.2.1-3r-ik-procedure)
template <class S> CuspAnalysis<S> findCusps(const SerialRobot<S>& robot);

/// The IK function f(φ3) of the target (ρ, z) and its first two φ3-derivatives (a triple root
/// makes all three vanish). Exposed for tests.
template <class S> Vec3<S> ikFunction(const Arm3RFrame<S>& frame, const S& rho, const S& z, const S& phi3);

/// Conditioning of the cusp polynomial in S (GF §5.2.3, near-degenerate arms). As b = (2a1/L)² → 0
/// (axes 1, 2 about to meet) G → −a³W′⁶: its 12 roots gather in two clusters of six about the
/// zeros of W′, and near each G ≈ −a³w⁶ − 2a³bEVw³ + b²a²E²(c1²W − V²) (w = W′), so a cluster
/// splits only by w ~ b^{1/3}. Likewise a = s1² → 0 (axes 1, 2 about to be parallel) clusters the
/// roots about the zeros of V′ with spread ~ a^{1/3}. Round-off of the coefficients blurs a six-fold
/// cluster by ~eps^{1/6}, so S separates the cusps when b^{1/3} ≳ eps^{1/6}, i.e. min(a, b) ≳ √eps.
/// `cuspClusterParameter` is min(a, b); `cuspsIllConditioned` is min(a, b) ≤ Tolerance<S>::sqrtEpsilon().
/// Measured on the orthogonal arm (a1, 2, 1.5, 1, 0): double first loses cusps at min(a, b) ≈ 2.5e-11
/// (a1 = 1e-5), float128 at 2.5e-19 (a1 = 1e-9): the threshold keeps a factor ≥ 100 in b in both.
template <class S> S cuspClusterParameter(const Arm3RFrame<S>& frame);
template <class S> bool cuspsIllConditioned(const Arm3RFrame<S>& frame);

/// findCusps in double; when the double frame is ill-conditioned (cuspsIllConditioned), the same
/// robot (its double parameters, exactly) is re-solved in __float128, and in mpfr at enough bits
/// (√eps ≤ min(a, b)/2⁸) when __float128 is ill-conditioned too. `scalar` names the rung used,
/// `conditioning` says why. The answer is in double.
// GF §5.2.3, GF-5.2.3-cuspidal-posture-change (near-degenerate arms: finding in papers ch05)
CuspAnalysis<double> findCuspsAdaptive(const SerialRobot<double>& robot);

/// The limit of the cusp points of an arm as a1 → 0+ with everything else fixed (an orthogonal
/// first pair, c1 = 0): at the two zeros φ* of W′ (W, V of the a1 = 0 arm), ρ = |V(φ*)|,
/// z = z0 ± √(W(φ*) − V(φ*)²): the corners of the decoupled arm's section. From the local form of G
/// above (T = aw³ + bEV = 0 has one real w per cluster; u² = U → W − V²). Empty unless c1 = 0 within
/// Tolerance<double>::rank() and both W − V² > 0. Exposed for tests and studies.
std::vector<Vec2<double>> cuspLimitA1Zero(const SerialRobot<double>& robot);

#define SOMA_CUSPS_EXTERN(S)                                                                    \
  extern template Arm3RFrame<S> arm3RFrame<S>(const SerialRobot<S>&);                          \
  extern template Vec2<S> workspaceSection<S>(const Arm3RFrame<S>&, const SerialRobot<S>&,     \
                                              const JointVector<S>&);                          \
  extern template CuspAnalysis<S> findCusps<S>(const SerialRobot<S>&);                         \
  extern template Vec3<S> ikFunction<S>(const Arm3RFrame<S>&, const S&, const S&, const S&);      \
  extern template S cuspClusterParameter<S>(const Arm3RFrame<S>&);                             \
  extern template bool cuspsIllConditioned<S>(const Arm3RFrame<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_CUSPS_EXTERN)
#undef SOMA_CUSPS_EXTERN

}  // namespace soma
