#pragma once
// Denavit–Hartenberg joint rows (DESIGN §6): standard DH A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i),
// modified DH (Craig) A_i = Rx(α_{i-1})·Tx(a_{i-1})·Rz(θ_i)·Tz(d_i). GF §3.4 / §4.5 use these links.
#include "soma/algebra/se3.hpp"
#include "soma/algebra/so3.hpp"

#include <cmath>

namespace soma {

enum class JointType { Revolute, Prismatic };

/// One row of a DH table. For a revolute joint the joint variable q is added to theta, for a
/// prismatic joint it is added to d (theta and d then act as offsets).
template <class S> struct DHRow {
  JointType type = JointType::Revolute;
  S a = S(0);
  S alpha = S(0);
  S d = S(0);
  S theta = S(0);

  template <class T> DHRow<T> cast() const {
    return {type, scalarCast<T>(a), scalarCast<T>(alpha), scalarCast<T>(d), scalarCast<T>(theta)};
  }
};

/// Standard DH link transform Rz(θ+q)·Tz(d)·Tx(a)·Rx(α) (q on d for a prismatic joint).
template <class S> SE3<S> dhTransform(const DHRow<S>& r, const S& q) {
  using std::cos;
  using std::sin;
  const S th = r.type == JointType::Revolute ? r.theta + q : r.theta;
  const S d = r.type == JointType::Prismatic ? r.d + q : r.d;
  const S ct = cos(th), st = sin(th), ca = cos(r.alpha), sa = sin(r.alpha);
  Mat3<S> R;
  R << ct, -st * ca, st * sa,  //
      st, ct * ca, -ct * sa,   //
      S(0), sa, ca;
  return SE3<S>(SO3<S>::fromMatrix(R), Vec3<S>(r.a * ct, r.a * st, d));
}

/// Modified (Craig) DH link transform Rx(α)·Tx(a)·Rz(θ+q)·Tz(d) (q on d for a prismatic joint).
template <class S> SE3<S> mdhTransform(const DHRow<S>& r, const S& q) {
  using std::cos;
  using std::sin;
  const S th = r.type == JointType::Revolute ? r.theta + q : r.theta;
  const S d = r.type == JointType::Prismatic ? r.d + q : r.d;
  const S ct = cos(th), st = sin(th), ca = cos(r.alpha), sa = sin(r.alpha);
  Mat3<S> R;
  R << ct, -st, S(0),     //
      st * ca, ct * ca, -sa,  //
      st * sa, ct * sa, ca;
  return SE3<S>(SO3<S>::fromMatrix(R), Vec3<S>(r.a, -sa * d, ca * d));
}

}  // namespace soma
