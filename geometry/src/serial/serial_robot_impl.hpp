// SerialRobot: DH / MDH / POE models, forward kinematics, spatial and body Jacobians (GF §4.5).
#pragma once
#include "soma/geometry/serial/serial_robot.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/safe_norm.hpp"

#include <cmath>
#include <string>

namespace soma {

namespace {
std::string jointName(std::size_t i) { return "joint " + std::to_string(i + 1); }

template <class S> void requireFinite(const S& x, const std::string& what) {
  if (!isFinite(x)) throw InvalidInput(what + " is NaN or infinite");
}
}  // namespace

template <class S> SE3Tangent<S> SerialJoint<S>::twist() const {
  if (type == JointType::Prismatic) return SE3Tangent<S>(Vec3<S>::Zero(), axis);
  return SE3Tangent<S>(axis, Vec3<S>(point.cross(axis)));
}

// GF §5.2.1, GF-5.2.1-revolute-joint-exp: e^{θS} p = p + sin θ v×(p−r) + (1−cos θ) v×(v×(p−r)),
// i.e. R = Rodrigues(v, θ) and t = r − R r.
template <class S> SE3<S> SerialJoint<S>::motion(const S& theta) const {
  if (type == JointType::Prismatic) return SE3<S>(SO3<S>(), Vec3<S>(axis * theta));
  using std::cos;
  using std::sin;
  const S h = theta / S(2);
  const Quat<S> qr(cos(h), sin(h) * axis.x(), sin(h) * axis.y(), sin(h) * axis.z());
  const SO3<S> r = SO3<S>::fromQuaternion(qr);
  return SE3<S>(r, Vec3<S>(point - r.act(point)));
}

template <class S>
SerialRobot<S> SerialRobot<S>::fromDH(const std::vector<DHRow<S>>& rows, DHConvention convention,
                                      const SE3<S>& base, const SE3<S>& tool, std::string name) {
  if (rows.empty()) throw InvalidInput("DH table: no rows (a robot needs at least one joint)");
  if (convention == DHConvention::POE)
    throw InvalidInput("fromDH: convention must be standard or modified DH");
  SerialRobot r;
  r.name_ = std::move(name);
  r.convention_ = convention;
  r.dh_ = rows;
  r.base_ = base;
  r.tool_ = tool;
  SE3<S> f = base;  // F_{i-1} (standard) at the home configuration
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    requireFinite(row.a, "DH table: " + jointName(i) + " a");
    requireFinite(row.alpha, "DH table: " + jointName(i) + " alpha");
    requireFinite(row.d, "DH table: " + jointName(i) + " d");
    requireFinite(row.theta, "DH table: " + jointName(i) + " theta");
    SerialJoint<S> j;
    j.type = row.type;
    if (convention == DHConvention::Standard) {
      // Joint i turns about (slides along) z of F_{i-1}. GF §3.4 / §4.5 link transforms.
      j.axis = f.rotation().col(2);
      j.point = f.translation();
      f = f * dhTransform(row, S(0));
    } else {
      // Modified DH: joint i acts along z of F_i itself.
      f = f * mdhTransform(row, S(0));
      j.axis = f.rotation().col(2);
      j.point = f.translation();
    }
    r.joints_.push_back(j);
  }
  r.home_ = f * tool;
  r.computeScale();
  return r;
}

template <class S>
SerialRobot<S> SerialRobot<S>::fromPOE(std::vector<SerialJoint<S>> joints, const SE3<S>& home,
                                       std::string name) {
  using std::abs;
  if (joints.empty()) throw InvalidInput("POE robot: no joints (a robot needs at least one)");
  for (std::size_t i = 0; i < joints.size(); ++i) {
    auto& j = joints[i];
    if (!allFinite(j.axis))
      throw InvalidInput("POE robot: " + jointName(i) + " axis has a NaN or infinite component");
    if (!allFinite(j.point))
      throw InvalidInput("POE robot: " + jointName(i) + " point has a NaN or infinite component");
    requireFinite(j.offset, "POE robot: " + jointName(i) + " offset");
    const S n2 = j.axis.squaredNorm();
    if (abs(n2 - S(1)) > Tolerance<S>::input())
      throw InvalidInput("POE robot: " + jointName(i) + " axis is not a unit vector (|axis|² = " +
                         toString(n2, 8) + ")");
    if (isFinite(j.lower) == false && j.lower == j.lower && j.lower > S(0))
      throw InvalidInput("POE robot: " + jointName(i) + " lower limit is +infinity");
    if (j.lower != j.lower || j.upper != j.upper)
      throw InvalidInput("POE robot: " + jointName(i) + " limit is NaN");
    if (j.lower > j.upper)
      throw InvalidInput("POE robot: " + jointName(i) + " lower limit exceeds upper limit");
  }
  SerialRobot r;
  r.name_ = std::move(name);
  r.convention_ = DHConvention::POE;
  r.joints_ = std::move(joints);
  r.home_ = home;
  r.computeScale();
  return r;
}

template <class S> void SerialRobot<S>::computeScale() {
  using std::abs;
  // Norms, not squared norms (safeNorm): link lengths of 1e160 square to infinity in double.
  S m = safeNorm(home_.translation());
  for (const auto& j : joints_)
    if (j.type == JointType::Revolute) m = std::max<S>(m, safeNorm(j.point));
  for (const auto& d : dh_) m = std::max<S>(m, std::max<S>(abs(d.a), abs(d.d)));
  scale_ = m > S(0) ? m : S(1);
}

template <class S> bool SerialRobot<S>::allRevolute() const {
  for (const auto& j : joints_)
    if (j.type != JointType::Revolute) return false;
  return true;
}

template <class S>
SerialRobot<S> SerialRobot<S>::withLimits(const std::vector<S>& lower,
                                          const std::vector<S>& upper) const {
  if (lower.size() != joints_.size() || upper.size() != joints_.size())
    throw InvalidInput("joint limits: need " + std::to_string(joints_.size()) + " lower and upper values");
  SerialRobot r = *this;
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    if (lower[i] != lower[i] || upper[i] != upper[i])
      throw InvalidInput("joint limits: " + jointName(i) + " limit is NaN");
    if (lower[i] > upper[i])
      throw InvalidInput("joint limits: " + jointName(i) + " lower limit exceeds upper limit");
    r.joints_[i].lower = lower[i];
    r.joints_[i].upper = upper[i];
  }
  return r;
}

template <class S> SerialRobot<S> SerialRobot<S>::reversed() const {
  const SE3<S> minv = home_.inverse();
  std::vector<SerialJoint<S>> js;
  for (auto it = joints_.rbegin(); it != joints_.rend(); ++it) {
    SerialJoint<S> j = *it;
    j.axis = -minv.so3().act(it->axis);
    j.point = minv.act(it->point);
    js.push_back(j);
  }
  SerialRobot r;
  r.name_ = name_ + " (reversed)";
  r.convention_ = DHConvention::POE;
  r.joints_ = std::move(js);
  r.home_ = minv;
  r.scale_ = scale_;
  return r;
}

template <class S> void SerialRobot<S>::checkJoints(const JointVector<S>& q) const {
  if (q.size() != dof())
    throw InvalidInput("joint vector has " + std::to_string(q.size()) + " values, the robot has " +
                       std::to_string(dof()) + " joints");
  for (int i = 0; i < q.size(); ++i)
    if (!isFinite(q(i))) throw InvalidInput("joint value " + std::to_string(i + 1) + " is NaN or infinite");
}

template <class S> SE3<S> SerialRobot<S>::fk(const JointVector<S>& q) const {
  checkJoints(q);
  SE3<S> t;
  for (int i = 0; i < dof(); ++i) t = t * joints_[i].motion(q(i) + joints_[i].offset);
  return t * home_;
}

template <class S> std::vector<SE3<S>> SerialRobot<S>::frames(const JointVector<S>& q) const {
  checkJoints(q);
  std::vector<SE3<S>> out;
  if (convention_ != DHConvention::POE) {
    SE3<S> f = base_;
    if (convention_ == DHConvention::Standard) out.push_back(f);
    for (int i = 0; i < dof(); ++i) {
      f = f * (convention_ == DHConvention::Standard ? dhTransform(dh_[i], q(i))
                                                      : mdhTransform(dh_[i], q(i)));
      out.push_back(f);
    }
    if (convention_ == DHConvention::Modified) out.push_back(f * tool_);
    return out;
  }
  SE3<S> t;
  for (int i = 0; i < dof(); ++i) {
    const auto& j = joints_[i];
    // A frame with z along the axis, origin at the axis point.
    Vec3<S> z = j.axis, x = Vec3<S>::UnitX();
    if (z.cross(x).squaredNorm() < S(1) / S(4)) x = Vec3<S>::UnitY();
    x = (x - z * z.dot(x)).normalized();
    Mat3<S> r;
    r.col(0) = x;
    r.col(1) = z.cross(x);
    r.col(2) = z;
    out.push_back(t * SE3<S>(SO3<S>::fromMatrix(r), j.point));
    t = t * j.motion(q(i) + j.offset);
  }
  out.push_back(t * home_);
  return out;
}

template <class S> JacobianMatrix<S> SerialRobot<S>::spatialJacobian(const JointVector<S>& q) const {
  checkJoints(q);
  JacobianMatrix<S> J(6, dof());
  SE3<S> t;
  for (int i = 0; i < dof(); ++i) {
    const auto& j = joints_[i];
    // Ad(t) ξ for ξ = (ω, r × ω): ω' = R ω, r' = t(r).
    const Vec3<S> w = t.so3().act(j.axis);
    if (j.type == JointType::Prismatic) {
      J.col(i) << Vec3<S>::Zero(), w;
    } else {
      const Vec3<S> r = t.act(j.point);
      J.col(i) << w, r.cross(w);
    }
    t = t * j.motion(q(i) + j.offset);
  }
  return J;
}

template <class S> JacobianMatrix<S> SerialRobot<S>::bodyJacobian(const JointVector<S>& q) const {
  const JacobianMatrix<S> Js = spatialJacobian(q);
  const Mat6<S> adInv = fk(q).inverse().adjoint();
  return adInv * Js;
}

template <class S> JointVector<S> SerialRobot<S>::wrap(const JointVector<S>& q) const {
  using std::atan2;
  using std::cos;
  using std::sin;
  JointVector<S> out = q;
  for (int i = 0; i < dof() && i < q.size(); ++i)
    if (joints_[i].type == JointType::Revolute) out(i) = atan2(sin(q(i)), cos(q(i)));
  return out;
}

template <class S> bool SerialRobot<S>::withinLimits(const JointVector<S>& q) const {
  for (int i = 0; i < dof(); ++i)
    if (q(i) < joints_[i].lower || q(i) > joints_[i].upper) return false;
  return true;
}

template <class S> S poseResidual(const SE3<S>& a, const SE3<S>& b, const S& lengthScale) {
  using std::sqrt;
  const S r2 = (a.rotation() - b.rotation()).squaredNorm();
  const S t2 = (a.translation() - b.translation()).squaredNorm() / (lengthScale * lengthScale);
  return sqrt(std::max<S>(r2, t2));
}

#define SOMA_INSTANTIATE_SERIAL_ROBOT(S) \
  template struct SerialJoint<S>;  \
  template class SerialRobot<S>;   \
  template S poseResidual<S>(const SE3<S>&, const SE3<S>&, const S&);

}  // namespace soma
