#pragma once
// __float128 as a first-class scalar: std::numeric_limits, <cmath>-style overloads and
// Eigen::NumTraits, so templates written with `using std::sin; sin(x)` and Eigen both work.
// The overloads must be declared before Eigen is first included: __float128 is a builtin type,
// so argument-dependent lookup cannot find them later.
// (DESIGN §2: the scalar ladder.)  Requires GNU extensions (gnu++20) and libquadmath.
#include <bit>
#include <cmath>
#include <limits>
#include <string>
extern "C" {
#include <quadmath.h>
}
#ifdef EIGEN_CORE_H
#error "soma/algebra/float128.hpp must be included before Eigen (include soma/algebra/scalar.hpp first)"
#endif

namespace soma::detail {
// IEEE binary128 special values from their bit patterns (sign 0, exponent 0x7fff; the top mantissa
// bit is the quiet bit). GCC's __builtin_huge_valq/__builtin_nanq are not in clang, so neither is used.
inline __float128 float128FromHighBits(unsigned long long high) noexcept {
  return std::bit_cast<__float128>(static_cast<unsigned __int128>(high) << 64);
}
}  // namespace soma::detail

namespace std {
#if !defined(__GLIBCXX_FLOAT128_LIMITS)
template <> struct numeric_limits<__float128> {
  static constexpr bool is_specialized = true;
  static constexpr bool is_signed = true;
  static constexpr bool is_integer = false;
  static constexpr bool is_exact = false;
  static constexpr bool has_infinity = true;
  static constexpr bool has_quiet_NaN = true;
  static constexpr bool has_signaling_NaN = true;
  static constexpr bool is_iec559 = true;
  static constexpr bool is_bounded = true;
  static constexpr bool is_modulo = false;
  static constexpr int digits = 113;
  static constexpr int digits10 = 33;
  static constexpr int max_digits10 = 36;
  static constexpr int radix = 2;
  static constexpr int min_exponent = -16381;
  static constexpr int max_exponent = 16384;
  static constexpr int min_exponent10 = -4931;
  static constexpr int max_exponent10 = 4932;
  static constexpr float_round_style round_style = round_to_nearest;
  static __float128 min() noexcept { return FLT128_MIN; }
  static __float128 max() noexcept { return FLT128_MAX; }
  static __float128 lowest() noexcept { return -FLT128_MAX; }
  static __float128 epsilon() noexcept { return FLT128_EPSILON; }
  static __float128 round_error() noexcept { return 0.5Q; }
  static __float128 infinity() noexcept { return soma::detail::float128FromHighBits(0x7fff000000000000ULL); }
  static __float128 quiet_NaN() noexcept { return soma::detail::float128FromHighBits(0x7fff800000000000ULL); }
  static __float128 signaling_NaN() noexcept { return soma::detail::float128FromHighBits(0x7fff400000000000ULL); }
  static __float128 denorm_min() noexcept { return FLT128_DENORM_MIN; }
};
#endif

// std::abs(__float128) is provided by libstdc++ in GNU mode; the rest is ours.
inline __float128 fabs(__float128 x) { return fabsq(x); }
inline __float128 sqrt(__float128 x) { return sqrtq(x); }
inline __float128 cbrt(__float128 x) { return cbrtq(x); }
inline __float128 sin(__float128 x) { return sinq(x); }
inline __float128 cos(__float128 x) { return cosq(x); }
inline __float128 tan(__float128 x) { return tanq(x); }
inline __float128 asin(__float128 x) { return asinq(x); }
inline __float128 acos(__float128 x) { return acosq(x); }
inline __float128 atan(__float128 x) { return atanq(x); }
inline __float128 atan2(__float128 y, __float128 x) { return atan2q(y, x); }
inline __float128 sinh(__float128 x) { return sinhq(x); }
inline __float128 cosh(__float128 x) { return coshq(x); }
inline __float128 tanh(__float128 x) { return tanhq(x); }
inline __float128 exp(__float128 x) { return expq(x); }
inline __float128 expm1(__float128 x) { return expm1q(x); }
inline __float128 log(__float128 x) { return logq(x); }
inline __float128 log1p(__float128 x) { return log1pq(x); }
inline __float128 log10(__float128 x) { return log10q(x); }
inline __float128 log2(__float128 x) { return log2q(x); }
inline __float128 pow(__float128 x, __float128 y) { return powq(x, y); }
inline __float128 pow(__float128 x, int n) { return powq(x, __float128(n)); }
inline __float128 hypot(__float128 x, __float128 y) { return hypotq(x, y); }
inline __float128 fmod(__float128 x, __float128 y) { return fmodq(x, y); }
inline __float128 remainder(__float128 x, __float128 y) { return remainderq(x, y); }
inline __float128 floor(__float128 x) { return floorq(x); }
inline __float128 ceil(__float128 x) { return ceilq(x); }
inline __float128 round(__float128 x) { return roundq(x); }
inline __float128 trunc(__float128 x) { return truncq(x); }
inline __float128 fma(__float128 x, __float128 y, __float128 z) { return fmaq(x, y, z); }
inline __float128 fmin(__float128 x, __float128 y) { return fminq(x, y); }
inline __float128 fmax(__float128 x, __float128 y) { return fmaxq(x, y); }
inline __float128 copysign(__float128 x, __float128 y) { return copysignq(x, y); }
inline __float128 ldexp(__float128 x, int e) { return ldexpq(x, e); }
inline __float128 frexp(__float128 x, int* e) { return frexpq(x, e); }
inline bool isnan(__float128 x) { return isnanq(x); }
inline bool isinf(__float128 x) { return isinfq(x); }
inline bool isfinite(__float128 x) { return finiteq(x); }
inline bool signbit(__float128 x) { return signbitq(x); }
}  // namespace std

#include <Eigen/Core>

namespace Eigen {
template <> struct NumTraits<__float128> : GenericNumTraits<__float128> {
  typedef __float128 Real;
  typedef __float128 NonInteger;
  typedef __float128 Nested;
  enum {
    IsInteger = 0, IsSigned = 1, IsComplex = 0, RequireInitialization = 0,
    ReadCost = 2, AddCost = 8, MulCost = 8
  };
  static inline Real epsilon() { return FLT128_EPSILON; }
  static inline Real dummy_precision() { return Real(1e-28); }
  static inline Real highest() { return FLT128_MAX; }
  static inline Real lowest() { return -FLT128_MAX; }
  static inline Real infinity() { return std::numeric_limits<__float128>::infinity(); }
  static inline Real quiet_NaN() { return std::numeric_limits<__float128>::quiet_NaN(); }
  static inline int digits10() { return 33; }
  static inline int max_digits10() { return 36; }
};
}  // namespace Eigen

namespace soma {
/// Decimal text of a __float128 with `digits` significant digits (0: round-trip, 36).
inline std::string toString(__float128 x, int digits = 0) {
  if (digits <= 0) digits = 36;
  char buf[128];
  quadmath_snprintf(buf, sizeof buf, "%.*Qg", digits, x);
  return buf;
}
}  // namespace soma
