#pragma once
// Closed-form inverse kinematics of the classes GF solves by hand, every real posture with its
// residual (DESIGN §3):
//   wrist3r — three revolute axes through one point (GF §5.1): ≤ 2 postures for a rotation;
//   arm3r   — a general 3R positioning arm (GF §5.2.1–5.2.2): ≤ 4 postures for a point, from a
//             pencil of conics reduced to a quartic;
//   pieper  — a 6R robot with three consecutive axes meeting in a point or mutually parallel
//             (GF §10.3, §5.2.1 "elbow-pieper"): ≤ 8 postures for a pose.
// All three reduce to one kernel, solveCirclePair: two objects (points or planes) each turning
// about a line, related by a rotation about a third line — two equations linear in the cosines
// and sines of the two angles (the invariants of the middle rotation).
// Each residual is a full forward kinematics of the posture against the target, evaluated with the
// cosine and sine each joint angle was computed from (the angle is their atan2: cos and sin of the
// returned angle to about 1 ulp); Newton's polish, when the residual exceeds 64 ulps, uses sin and cos.
#include "soma/geometry/serial/ik_solution.hpp"
#include "soma/geometry/serial/serial_robot.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace soma {

/// Roots of p cos φ + q sin φ = k. `free`: p = q = k = 0 (every φ). `doubleRoot`: the two
/// roots merged (discriminant within Tolerance<S>::rank() of 0, clamped); both copies returned.
template <class S> struct TrigRoots {
  std::vector<S> angles;
  bool free = false;
  bool doubleRoot = false;
};
// GF §5.1, GF-5.1-wrist-theta2 (the book's a = sin θ − b cos θ, solved by atan2 without dividing
// by v1·(v2×v3); discriminant 1 − a² + b² scaled by (v1·(v2×v3))²)
template <class S> TrigRoots<S> solveLinearTrig(const S& p, const S& q, const S& k);

/// All (θ1, θ2, θ3) with exp(θ1 v̂1) exp(θ2 v̂2) exp(θ3 v̂3) = R (unit axes through one point).
/// `gimbal`: y = e^{θ2 v2} v3 within √(64 eps) of ±v1 — θ1 and θ3 are then determined only in
/// combination; θ1 = 0 is returned as the representative of the continuum.
template <class S> struct WristAngles {
  std::vector<Vec3<S>> angles;
  bool gimbal = false;
  bool doubleRoot = false;
};
// GF §5.1, GF-5.1-wrist-theta2, GF-5.1-wrist-theta1-theta3 (corrected sign, erratum E5.1)
template <class S>
WristAngles<S> wrist3R(const Vec3<S>& v1, const Vec3<S>& v2, const Vec3<S>& v3, const Mat3<S>& R);

/// The IK methods of solveIk (ik.hpp): the closed forms here, the general-6R eigenproblem
/// (general_6r.hpp) and the numerical general-6R methods (Ceres, NLopt in double).
enum class IkMethod { Auto, Wrist3R, Arm3R, Pieper, General6R, Ceres, Nlopt };
std::optional<IkMethod> parseIkMethod(std::string_view name);
std::string_view ikMethodName(IkMethod m);
/// "auto wrist3r arm3r pieper general6r ceres nlopt", for messages.
std::string ikMethodNames();

/// Which consecutive triple of axes makes a 6R robot a Pieper robot (0-based first joint).
template <class S> struct PieperTriple {
  int first = -1;          ///< -1: none
  bool concurrent = true;  ///< axes meet in `point`; else parallel to `direction`
  Vec3<S> point = Vec3<S>::Zero();
  Vec3<S> direction = Vec3<S>::Zero();
  /// How far the triple is from exact: the largest distance of an axis from `point` over the
  /// robot's length scale (concurrent), or the largest |v₀ × vᵢ| (parallel). Rounding-level for a
  /// Pieper robot, up to Tolerance<S>::input() for a robot near one (a calibrated arm).
  S defect = S(0);
};
/// Axes meet when each is within Tolerance<S>::input()·L of their common point; parallel when
/// |v_i × v_j| ≤ Tolerance<S>::input(). Triples are tried in the order (4,5,6), (1,2,3), (2,3,4),
/// (3,4,5). GF §10.3, GF-10.3-pieper-theorem
template <class S> PieperTriple<S> findPieperTriple(const SerialRobot<S>& robot);
/// True when the three axes of a 3-joint revolute robot meet in one point (a wrist).
template <class S> bool isWrist(const SerialRobot<S>& robot);
/// The class `auto` picks: Wrist3R, Arm3R, Pieper or General6R. Throws InvalidInput when no
/// method applies (prismatic joints, or a joint count other than 3 or 6).
template <class S> IkMethod classifyRobot(const SerialRobot<S>& robot);

/// Wrist: the target's rotation (R_target = R(q) R_M); the tool position follows from it.
/// Residual ‖R(q) − R*‖_F. Expected count 2.
template <class S> Solution<S> solveWrist3R(const SerialRobot<S>& robot, const SE3<S>& target);
/// 3R arm: the tool origin reaches the target's translation (orientation not controlled).
/// Residual |p(q) − p*| / L. Expected count 4. GF §5.2.1, GF-5.2.1-3r-ik-procedure
template <class S> Solution<S> solveArm3R(const SerialRobot<S>& robot, const SE3<S>& target);
/// Pieper 6R robot: full pose. Residual poseResidual. Expected count 8.
// GF §10.3.1, GF-10.3.1-pieper-algorithm (with errata E10.2, E10.3 applied); GF-5.2.1-elbow-pieper
template <class S> Solution<S> solvePieper(const SerialRobot<S>& robot, const SE3<S>& target);

/// Dispatch by method among the closed forms (Auto: classifyRobot). The general-6R methods are
/// not closed forms: InvalidInput (solveIk in ik.hpp dispatches every method).
template <class S>
Solution<S> solveClosedForm(const SerialRobot<S>& robot, const SE3<S>& target, IkMethod method);

#define SOMA_CFIK_EXTERN(S)                                                                    \
  extern template TrigRoots<S> solveLinearTrig<S>(const S&, const S&, const S&);              \
  extern template WristAngles<S> wrist3R<S>(const Vec3<S>&, const Vec3<S>&, const Vec3<S>&,    \
                                            const Mat3<S>&);                                   \
  extern template PieperTriple<S> findPieperTriple<S>(const SerialRobot<S>&);                  \
  extern template bool isWrist<S>(const SerialRobot<S>&);                                      \
  extern template IkMethod classifyRobot<S>(const SerialRobot<S>&);                            \
  extern template Solution<S> solveWrist3R<S>(const SerialRobot<S>&, const SE3<S>&);           \
  extern template Solution<S> solveArm3R<S>(const SerialRobot<S>&, const SE3<S>&);             \
  extern template Solution<S> solvePieper<S>(const SerialRobot<S>&, const SE3<S>&);            \
  extern template Solution<S> solveClosedForm<S>(const SerialRobot<S>&, const SE3<S>&, IkMethod);
SOMA_FOR_EACH_SCALAR(SOMA_CFIK_EXTERN)
#undef SOMA_CFIK_EXTERN

}  // namespace soma
