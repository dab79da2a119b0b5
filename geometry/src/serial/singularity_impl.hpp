// Singularity measures of a serial robot from the singular values of its Jacobian (GF §4.5,
// GF-10.3-closing-remarks: a singular configuration is one where the joint screws are dependent).
// The singular values come from the one-sided (Hestenes) Jacobi SVD of soma/algebra/small_linalg.hpp:
// accurate to high relative precision (Eigen's JacobiSVD instantiated for one scalar (soma_instantiate) took
// over ten minutes to compile).
#pragma once
#include "soma/geometry/serial/serial_robot.hpp"

#include "soma/algebra/small_linalg.hpp"

#include <algorithm>

namespace soma {

namespace {
/// Singular values of a 6 × n Jacobian, descending, at most min(6, n) of them.
template <class S> std::vector<S> singularValues(const JacobianMatrix<S>& A) {
  std::vector<S> sv = detail::smallSingularValues<S>(detail::SmallMat<S>(A));
  sv.resize(std::min<std::size_t>(sv.size(), 6));
  return sv;
}
}  // namespace

template <class S>
SingularityMeasures<S> singularityMeasures(const SerialRobot<S>& robot, const JointVector<S>& q) {
  JacobianMatrix<S> J = robot.spatialJacobian(q);
  J.bottomRows(3) /= robot.lengthScale();
  const std::vector<S> sv = singularValues<S>(J);
  SingularityMeasures<S> m;
  const int k = int(sv.size());
  m.largestSingularValue = sv[0];
  m.smallestSingularValue = sv[k - 1];
  m.manipulability = S(1);
  for (int i = 0; i < k; ++i) {
    m.manipulability *= sv[i];
    if (sv[i] > Tolerance<S>::rank() * sv[0]) ++m.rank;
  }
  m.condition = sv[k - 1] > S(0) ? S(sv[0] / sv[k - 1]) : std::numeric_limits<S>::infinity();
  return m;
}

#define SOMA_INSTANTIATE_SINGULARITY(S)                                                      \
  template SingularityMeasures<S> singularityMeasures<S>(const SerialRobot<S>&,       \
                                                         const JointVector<S>&);

}  // namespace soma
