// Singularity measures of a serial robot from the singular values of its Jacobian (GF §4.5,
// GF-10.3-closing-remarks: a singular configuration is one where the joint screws are dependent).
// The singular values come from a one-sided (Hestenes) Jacobi iteration on the 6 × n matrix:
// accurate to high relative precision and a few lines long (Eigen's JacobiSVD instantiated for
// the five scalars took over ten minutes to compile).
#include "soma/geometry/serial/serial_robot.hpp"

#include <algorithm>

namespace soma {

namespace {
/// Singular values of a 6 × n matrix, descending (n ≤ 6 keeps the work tiny).
template <class S> std::vector<S> singularValues(JacobianMatrix<S> A) {
  using std::abs;
  using std::sqrt;
  const int n = int(A.cols());
  for (int sweep = 0; sweep < 60; ++sweep) {
    bool rotated = false;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const S a = A.col(i).squaredNorm(), b = A.col(j).squaredNorm(), c = A.col(i).dot(A.col(j));
        if (c == S(0) || abs(c) <= Tolerance<S>::epsilon() * sqrt(a * b)) continue;
        rotated = true;
        const S zeta = (b - a) / (S(2) * c);
        const S t = (zeta >= S(0) ? S(1) : S(-1)) / (abs(zeta) + sqrt(S(1) + zeta * zeta));
        const S cs = S(1) / sqrt(S(1) + t * t), sn = cs * t;
        for (int r = 0; r < 6; ++r) {
          const S x = A(r, i), y = A(r, j);
          A(r, i) = cs * x - sn * y;
          A(r, j) = sn * x + cs * y;
        }
      }
    if (!rotated) break;
  }
  std::vector<S> sv(n);
  for (int i = 0; i < n; ++i) sv[i] = sqrt(A.col(i).squaredNorm());
  std::sort(sv.begin(), sv.end(), [](const S& x, const S& y) { return x > y; });
  sv.resize(std::min(n, 6));
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

#define SOMA_SING_INSTANTIATE(S)                                                      \
  template SingularityMeasures<S> singularityMeasures<S>(const SerialRobot<S>&,       \
                                                         const JointVector<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_SING_INSTANTIATE)
#undef SOMA_SING_INSTANTIATE

}  // namespace soma
