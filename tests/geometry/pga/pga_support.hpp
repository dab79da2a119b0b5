#pragma once
// Shared helpers for the Cl(0,3,1) geometry tests: random elements from coordinates, so every
// algebraic result can be compared with a coordinate formula computed independently.
#include "soma/geometry/pga/angle.hpp"
#include "soma/geometry/pga/common_perpendicular.hpp"
#include "soma/geometry/pga/distance.hpp"
#include "soma/geometry/pga/incidence.hpp"
#include "soma/geometry/pga/motor.hpp"
#include "soma/geometry/pga/projection.hpp"
#include "soma/geometry/pga/reflection.hpp"
#include "support/scalars.hpp"

namespace soma::test::pga {

using namespace soma::pga;

template <class S> Vec3<S> rvec(std::mt19937_64& g, double r = 1) { return uniformVec<S, 3>(g, -r, r); }
/// A unit-normal plane with |d| ≤ r.
template <class S> Plane<S> randomPlane(std::mt19937_64& g, double r = 1) {
  return Plane<S>(unitVec3<S>(g), uniform<S>(g, -r, r));
}
/// A unit line through a random point.
template <class S> Line<S> randomLine(std::mt19937_64& g, double r = 1) {
  return Line<S>::throughPoint(rvec<S>(g, r), unitVec3<S>(g));
}
template <class S> S maxDiff(const Vec3<S>& a, const Vec3<S>& b) { return (a - b).cwiseAbs().maxCoeff(); }
template <class S> S tol(int ulps = 256) { return Tolerance<S>::identity(ulps); }

}  // namespace soma::test::pga
