#pragma once
// File data are judged at double's precision in every scalar (issue 24): a unit or orthogonality
// defect of a file's numbers (a quaternion, a rotation matrix, a POE joint axis) is measured on the
// numbers in double against Tolerance<double>::input(), then the data are made exact in S (the
// quaternion normalised, the matrix's rotation taken, the axis normalised). Judged at S's own
// tolerance (64 √eps: 0.02 in float, 1e-37 in mpfr) one file would be a different robot per scalar:
// float would take a 1 % off-unit axis that double refuses, and mpfr would refuse every 9-digit
// rotation that double takes. The differential fuzz harness (tests/fuzz/differential.cpp) holds it.
#include "soma/algebra/errors.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/so3.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/io/json_file.hpp"
#include "soma/io/number.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <type_traits>

namespace soma::io::detail {

/// A file's vector of N numbers, in S and in double (the numbers to judge defects on): read again in
/// double when S is float (float's own rounding, 6e-8, is no defect of the file), else S's values cast.
template <class S, int N> struct ReadVector {
  Eigen::Matrix<S, N, 1> value;
  Eigen::Matrix<double, N, 1> inDouble;
};

template <class S, int N>
ReadVector<S, N> readVector(const nlohmann::json& j, const KeyPath& where, NumberSource* sawDouble = nullptr) {
  if (!j.is_array() || j.size() != std::size_t(N))
    throw InvalidInput(where.str() + ": expected an array of " + std::to_string(N) + " numbers");
  ReadVector<S, N> v;
  for (int i = 0; i < N; ++i) {
    const KeyPath w = where.index(std::size_t(i));
    NumberSource source{};
    v.value(i) = readNumber<S>(j[std::size_t(i)], w, &source);
    if (sawDouble && source == NumberSource::JsonDouble) *sawDouble = NumberSource::JsonDouble;
    if constexpr (std::is_same_v<S, float>) v.inDouble(i) = readNumber<double>(j[std::size_t(i)], w);
    else v.inDouble(i) = scalarCast<double>(v.value(i));
  }
  return v;
}

/// The rotation of a quaternion read as `q` (in S) and `qd` (in double): |‖q‖ − 1| judged in double
/// (SO3<double>::fromQuaternion's message), then q normalised in S.
template <class S> SO3<S> unitQuaternion(const Vec4<S>& q, const Vec4<double>& qd) {
  (void)SO3<double>::fromQuaternion(Quat<double>(qd(0), qd(1), qd(2), qd(3)));
  return SO3<S>::fromQuaternionUnchecked(Quat<S>(q(0), q(1), q(2), q(3)));
}

/// The rotation of a matrix read as `m` (in S) and `md` (in double): finiteness, |RᵀR − I| and the
/// determinant judged in double (SO3<double>::fromMatrix's messages), then m's rotation in S
/// (Shepperd's chart, normalised).
template <class S> SO3<S> rotationMatrix(const Mat3<S>& m, const Mat3<double>& md) {
  (void)SO3<double>::fromMatrix(md);
  if constexpr (std::is_same_v<S, double>) return SO3<double>::fromMatrix(m);
  else return SO3<S>::fromQuaternionUnchecked(quaternionFromRotation(m));
}

/// A joint axis read as `a` (in S) and `ad` (in double): |‖a‖² − 1| ≤ Tolerance<double>::input()
/// judged in double, then a normalised in S (so that the library's own check in S holds).
template <class S> Vec3<S> unitAxis(const Vec3<S>& a, const Vec3<double>& ad, const std::string& where) {
  const double n2 = ad.squaredNorm();
  if (!std::isfinite(n2) || std::abs(n2 - 1) > Tolerance<double>::input())
    throw InvalidInput(where + " is not a unit vector (|axis|² = " + toString(n2, 8) + ")");
  return a / a.norm();
}

}  // namespace soma::io::detail
