#pragma once
// An immutable serial robot (Pinocchio-style Model): n revolute or prismatic joints described by
// standard DH, modified DH or product-of-exponentials data, all converted once to the POE form
// (GF §4.5, §5.2.1): each joint is a unit twist ξ_i at the home configuration, and
//   T(q) = exp(ξ_1 (q_1 + o_1)) ··· exp(ξ_n (q_n + o_n)) · M
// with joint offsets o_i and the tool's home pose M. Twists are (ω, v), v = r × ω for a revolute
// joint through r (soma's convention), (0, u) for a prismatic joint along u.
// Every method is defined in geometry/src/serial/serial_robot.cpp for the five scalars.
#include "soma/algebra/se3.hpp"
#include "soma/geometry/serial/dh.hpp"
#include "soma/geometry/serial/ik_solution.hpp"

#include <limits>
#include <string>
#include <vector>

namespace soma {

enum class DHConvention { Standard, Modified, POE };

/// One joint in POE form, at the home configuration, in base coordinates.
template <class S> struct SerialJoint {
  JointType type = JointType::Revolute;
  Vec3<S> axis = Vec3<S>::UnitZ();   ///< unit direction of the joint axis (or of the slide)
  Vec3<S> point = Vec3<S>::Zero();   ///< a point of the axis line (ignored for prismatic)
  S offset = S(0);                   ///< added to the joint variable
  S lower = -std::numeric_limits<S>::infinity();  ///< joint limits on q (not on q + offset)
  S upper = std::numeric_limits<S>::infinity();

  /// Unit twist ξ = (axis, point × axis) for a revolute joint, (0, axis) for a prismatic one.
  SE3Tangent<S> twist() const;
  /// exp(ξ θ) in closed form (Rodrigues about the axis line; a translation for prismatic).
  // GF §5.2.1, GF-5.2.1-revolute-joint-exp
  SE3<S> motion(const S& theta) const;
};

/// Joint frame for drawing: origin on the joint axis (or DH frame origin), z along the axis.
template <class S> using JacobianMatrix = Eigen::Matrix<S, 6, Eigen::Dynamic>;

template <class S> class SerialRobot {
 public:
  /// From standard DH rows A_i = Rz(θ_i+q)·Tz(d_i)·Tx(a_i)·Rx(α_i) (or modified DH rows
  /// Rx(α_{i-1})·Tx(a_{i-1})·Rz(θ_i+q)·Tz(d_i)), between a base and a tool transform.
  /// θ_i (revolute) or d_i (prismatic) is the joint's offset, built into the home pose.
  /// Throws InvalidInput for an empty table or a NaN/infinite entry (naming the joint).
  static SerialRobot fromDH(const std::vector<DHRow<S>>& rows,
                            DHConvention convention = DHConvention::Standard,
                            const SE3<S>& base = SE3<S>(), const SE3<S>& tool = SE3<S>(),
                            std::string name = "");
  /// From POE joints and the tool home pose M. Throws InvalidInput for no joints, a non-unit
  /// or NaN axis, a NaN point or offset, or limits with lower > upper (naming the joint).
  static SerialRobot fromPOE(std::vector<SerialJoint<S>> joints, const SE3<S>& home,
                             std::string name = "");

  int dof() const { return int(joints_.size()); }
  const std::string& name() const { return name_; }
  DHConvention convention() const { return convention_; }
  const std::vector<SerialJoint<S>>& joints() const { return joints_; }
  /// The DH rows the robot was built from (empty for a POE robot).
  const std::vector<DHRow<S>>& dhRows() const { return dh_; }
  const SE3<S>& home() const { return home_; }
  const SE3<S>& base() const { return base_; }
  const SE3<S>& tool() const { return tool_; }
  /// Length scale L of the robot (largest distance of an axis point or the tool from the base
  /// origin, at least the largest DH length; 1 for a robot with no length at all). Position
  /// residuals are divided by L.
  S lengthScale() const { return scale_; }
  bool allRevolute() const;

  /// A copy with joint limits set (q units: radians or lengths). Throws if lower > upper.
  SerialRobot withLimits(const std::vector<S>& lower, const std::vector<S>& upper) const;
  /// The same robot with the joints in reverse order: T'(q') = T(q)⁻¹ with q'_k = q_{n+1-k}
  /// (twists −Ad(M⁻¹)ξ, home M⁻¹). Used to solve robots whose first joints form the wrist.
  SerialRobot reversed() const;

  /// Forward kinematics T(q). Throws InvalidInput when q has the wrong length or a NaN.
  // GF §4.5 (product of exponentials), GF-5.2.1-revolute-joint-exp
  SE3<S> fk(const JointVector<S>& q) const;
  /// Frames along the chain for drawing: for a DH robot the DH frames F_0..F_n (F_0 = base),
  /// for a POE robot one frame per joint (origin at its axis point, z along the axis) then the
  /// tool; n + 1 frames in both cases, base coordinates.
  std::vector<SE3<S>> frames(const JointVector<S>& q) const;
  /// Spatial Jacobian: column i = Ad(exp(ξ_1 θ_1)···exp(ξ_{i-1} θ_{i-1})) ξ_i, so that
  /// (dT/dt) T⁻¹ = hat(J_s q̇) (GF §4.5, velocities in the base frame, twists (ω, v)).
  JacobianMatrix<S> spatialJacobian(const JointVector<S>& q) const;
  /// Body Jacobian J_b = Ad(T⁻¹) J_s: T⁻¹ dT/dt = hat(J_b q̇) (velocities in the tool frame).
  JacobianMatrix<S> bodyJacobian(const JointVector<S>& q) const;

  /// Wrap revolute joint values into (−π, π] (prismatic values untouched).
  JointVector<S> wrap(const JointVector<S>& q) const;
  /// True when every joint value lies within its limits.
  bool withinLimits(const JointVector<S>& q) const;

  template <class T> SerialRobot<T> cast() const;

 private:
  template <class T> friend class SerialRobot;
  void checkJoints(const JointVector<S>& q) const;
  void computeScale();
  std::string name_;
  DHConvention convention_ = DHConvention::POE;
  std::vector<SerialJoint<S>> joints_;
  std::vector<DHRow<S>> dh_;
  SE3<S> base_, tool_, home_;
  S scale_ = S(1);
};

/// Scalar measures of how close a configuration is to a singularity, from the singular values
/// σ_1 ≥ … ≥ σ_m of the (6 × n) Jacobian (m = min(6, n)). Angular and linear rows mix units:
/// the linear rows are divided by the robot's length scale first.
template <class S> struct SingularityMeasures {
  S manipulability = S(0);  ///< Yoshikawa's √det(J Jᵀ) (n ≤ 6: √det(JᵀJ)) = Π σ_i
  S smallestSingularValue = S(0);
  S largestSingularValue = S(0);
  S condition = S(0);  ///< σ_1 / σ_m (infinite at a singularity)
  int rank = 0;        ///< number of σ_i > Tolerance<S>::rank()·σ_1
};

/// Singularity measures of the spatial Jacobian at q (one-sided Jacobi SVD; its own TU).
template <class S> SingularityMeasures<S> singularityMeasures(const SerialRobot<S>& robot,
                                                             const JointVector<S>& q);

/// Pose residual used by every IK method: max(‖R − R*‖_F, ‖t − t*‖ / L).
template <class S> S poseResidual(const SE3<S>& a, const SE3<S>& b, const S& lengthScale);

template <class S> template <class T> SerialRobot<T> SerialRobot<S>::cast() const {
  SerialRobot<T> r;
  r.name_ = name_;
  r.convention_ = convention_;
  for (const auto& j : joints_) {
    SerialJoint<T> k;
    k.type = j.type;
    k.axis = castMatrix<T>(j.axis);
    k.point = castMatrix<T>(j.point);
    k.offset = scalarCast<T>(j.offset);
    k.lower = scalarCast<T>(j.lower);
    k.upper = scalarCast<T>(j.upper);
    r.joints_.push_back(k);
  }
  for (const auto& d : dh_) r.dh_.push_back(d.template cast<T>());
  r.base_ = base_.template cast<T>();
  r.tool_ = tool_.template cast<T>();
  r.home_ = home_.template cast<T>();
  r.scale_ = scalarCast<T>(scale_);
  return r;
}

#define SOMA_SERIAL_EXTERN(S)                                                                  \
  extern template struct SerialJoint<S>;                                                     \
  extern template class SerialRobot<S>;                                                      \
  extern template SingularityMeasures<S> singularityMeasures<S>(const SerialRobot<S>&,       \
                                                                const JointVector<S>&);      \
  extern template S poseResidual<S>(const SE3<S>&, const SE3<S>&, const S&);
SOMA_FOR_EACH_SCALAR(SOMA_SERIAL_EXTERN)
#undef SOMA_SERIAL_EXTERN

}  // namespace soma
