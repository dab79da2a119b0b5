#pragma once
// The scalar ladder (DESIGN §2): float, double, long double, __float128 and mpfr::mpreal.
// Include this header before anything that includes Eigen.
#include "soma/algebra/float128.hpp"
#include <unsupported/Eigen/MPRealSupport>
#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>

namespace soma {

using mpreal = mpfr::mpreal;
using float128 = __float128;

/// The five scalar types soma is instantiated for.
enum class ScalarKind { Float, Double, LongDouble, Float128, Mpfr };

/// X-macro over the ladder, for explicit instantiations: SOMA_FOR_EACH_SCALAR(MY_MACRO).
#define SOMA_FOR_EACH_SCALAR(M) M(float) M(double) M(long double) M(__float128) M(mpfr::mpreal)

template <class S> constexpr ScalarKind scalarKind();
template <> constexpr ScalarKind scalarKind<float>() { return ScalarKind::Float; }
template <> constexpr ScalarKind scalarKind<double>() { return ScalarKind::Double; }
template <> constexpr ScalarKind scalarKind<long double>() { return ScalarKind::LongDouble; }
template <> constexpr ScalarKind scalarKind<__float128>() { return ScalarKind::Float128; }
template <> constexpr ScalarKind scalarKind<mpreal>() { return ScalarKind::Mpfr; }

/// Command-line name of a scalar kind: float double long-double float128 mpfr.
std::string_view scalarName(ScalarKind k);
template <class S> std::string_view scalarName() { return scalarName(scalarKind<S>()); }
/// Parse a command-line scalar name; std::nullopt for an unknown name.
std::optional<ScalarKind> parseScalarKind(std::string_view name);
/// "float double long-double float128 mpfr", for error messages.
std::string scalarNames();

/// Call f.template operator()<S>() with S the type named by k (C++20 template lambda).
template <class F> decltype(auto) withScalar(ScalarKind k, F&& f) {
  switch (k) {
    case ScalarKind::Float: return f.template operator()<float>();
    case ScalarKind::Double: return f.template operator()<double>();
    case ScalarKind::LongDouble: return f.template operator()<long double>();
    case ScalarKind::Float128: return f.template operator()<__float128>();
    case ScalarKind::Mpfr: break;
  }
  return f.template operator()<mpreal>();
}

/// Working precision of mpfr::mpreal, in bits (default 256). Affects new mpreal values.
void setMpfrBits(int bits);
int mpfrBits();

// ---- conversions between any two rungs of the ladder -------------------------------------
namespace detail {
template <class To, class From> struct ScalarCast {
  static To apply(const From& x) { return static_cast<To>(x); }
};
template <class From> struct ScalarCast<mpreal, From> {
  static mpreal apply(const From& x) { return mpreal(static_cast<long double>(x)); }
};
template <> struct ScalarCast<mpreal, mpreal> {
  static mpreal apply(const mpreal& x) { return x; }
};
template <> struct ScalarCast<mpreal, __float128> {
  static mpreal apply(const __float128& x) {  // two long doubles carry all 113 bits
    const long double hi = static_cast<long double>(x);
    const long double lo = static_cast<long double>(x - static_cast<__float128>(hi));
    return mpreal(hi) + mpreal(lo);
  }
};
template <class To> struct ScalarCast<To, mpreal> {
  static To apply(const mpreal& x) { return static_cast<To>(x.toLDouble()); }
};
template <> struct ScalarCast<__float128, mpreal> {
  static __float128 apply(const mpreal& x) {
    const long double hi = x.toLDouble();
    const long double lo = (x - mpreal(hi)).toLDouble();
    return static_cast<__float128>(hi) + static_cast<__float128>(lo);
  }
};
}  // namespace detail

/// Convert a scalar to another rung, keeping all the bits the target can hold.
template <class To, class From> To scalarCast(const From& x) {
  return detail::ScalarCast<To, From>::apply(x);
}
template <class From> double toDouble(const From& x) { return scalarCast<double>(x); }

/// Decimal text of x with `digits` significant digits (0: enough to round-trip the type).
std::string toString(float x, int digits = 0);
std::string toString(double x, int digits = 0);
std::string toString(long double x, int digits = 0);
std::string toString(const mpreal& x, int digits = 0);
// toString(__float128, digits) is in float128.hpp.

/// Parse decimal text exactly into S (e.g. "0.1" in mpfr is not the double 0.1).
template <class S> S fromString(const std::string& text);

/// π in S, to the full precision of S.
template <class S> S pi() {
  if constexpr (std::is_same_v<S, mpreal>) return mpfr::const_pi();
  else if constexpr (std::is_same_v<S, __float128>) return M_PIq;
  else return std::numbers::pi_v<S>;
}

/// Binary digits of the significand of S (for mpreal: the current default precision).
template <class S> int digits() {
  if constexpr (std::is_same_v<S, mpreal>) return int(mpreal::get_default_prec());
  else return std::numeric_limits<S>::digits;
}

template <class S> bool isFinite(const S& x) {
  using std::isfinite;
  if constexpr (std::is_same_v<S, mpreal>) return mpfr::isfinite(x);
  else return isfinite(x);
}

// ---- fixed-size Eigen aliases --------------------------------------------------------------
template <class S> using Vec2 = Eigen::Matrix<S, 2, 1>;
template <class S> using Vec3 = Eigen::Matrix<S, 3, 1>;
template <class S> using Vec4 = Eigen::Matrix<S, 4, 1>;
template <class S> using Vec6 = Eigen::Matrix<S, 6, 1>;
template <class S> using Vec8 = Eigen::Matrix<S, 8, 1>;
template <class S> using Mat2 = Eigen::Matrix<S, 2, 2>;
template <class S> using Mat3 = Eigen::Matrix<S, 3, 3>;
template <class S> using Mat4 = Eigen::Matrix<S, 4, 4>;
template <class S> using Mat6 = Eigen::Matrix<S, 6, 6>;
template <class S> using Quat = Eigen::Quaternion<S>;

/// Cast a fixed-size Eigen object to another scalar rung.
template <class To, class Derived> auto castMatrix(const Eigen::MatrixBase<Derived>& m) {
  using From = typename Derived::Scalar;
  return m.unaryExpr([](const From& x) { return scalarCast<To>(x); }).eval();
}

/// True when every entry is finite (no NaN, no infinity).
template <class Derived> bool allFinite(const Eigen::MatrixBase<Derived>& m) {
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (!isFinite(m(i, j))) return false;
  return true;
}

}  // namespace soma
