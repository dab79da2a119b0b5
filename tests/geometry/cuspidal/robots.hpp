#pragma once
// 3R test arms for the cuspidal tests (standard DH, A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i)).
#include "soma/geometry/serial/serial_robot.hpp"

#include <string>

namespace soma::test {

template <class S> SerialRobot<S> dh3r(double a1, double al1, double d1, double a2, double al2, double d2,
                                       double a3, double al3, double d3, const std::string& name = "") {
  auto row = [](double a, double al, double d) {
    DHRow<S> r;
    r.a = scalarCast<S>(a);
    r.alpha = scalarCast<S>(al);
    r.d = scalarCast<S>(d);
    return r;
  };
  return SerialRobot<S>::fromDH({row(a1, al1, d1), row(a2, al2, d2), row(a3, al3, d3)},
                                DHConvention::Standard, SE3<S>(), SE3<S>(), name);
}

/// α = ±90° written exactly in S.
template <class S> S halfPi() { return pi<S>() / S(2); }

}  // namespace soma::test
