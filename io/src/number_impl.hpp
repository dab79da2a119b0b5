#pragma once
// Definitions of number.hpp's templates, instantiated for the five scalars by soma_instantiate (io/CMakeLists.txt).
#include "soma/io/number.hpp"

#include "soma/algebra/errors.hpp"

#include <nlohmann/json.hpp>

#include <cctype>
#include <charconv>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace soma::io {

namespace {

std::string quoted(std::string_view t) { return "\"" + std::string(t) + "\""; }

/// Shortest text that reads back as the double x.
std::string shortest(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

/// The correctly rounded value of the decimal `t` (already checked by isDecimal) in S. The C
/// library's strtof/strtod/strtold are used directly: std::stof & co. throw on a subnormal result.
template <class S> S convert(const std::string& t) {
  if constexpr (std::is_same_v<S, float>) return std::strtof(t.c_str(), nullptr);
  else if constexpr (std::is_same_v<S, double>) return std::strtod(t.c_str(), nullptr);
  else if constexpr (std::is_same_v<S, long double>) return std::strtold(t.c_str(), nullptr);
  else return fromString<S>(t);  // strtoflt128 and mpfr_set_str: exact in S, no range exception
}

/// Significant bits a subnormal x keeps (x ≠ 0, |x| below S's smallest normal number).
template <class S> int subnormalBits(const S& x) {
  using std::abs;
  S y = abs(x);
  int k = 0;
  while (y < std::numeric_limits<S>::min()) y *= S(2), ++k;
  return std::max(1, digits<S>() - k);
}

/// The range checks shared by decimal strings and JSON numbers: `shown` is the value as written.
/// S holds 0 and the normal magnitudes (number.hpp); mpfr has no subnormals (below 2^(emin−1) it
/// underflows to 0).
template <class S> void checkRange(const S& x, bool nonZero, const std::string& shown, const std::string& where) {
  using std::abs;
  const std::string name(scalarName<S>());
  if (!isFinite(x))
    throw InvalidInput(where + ": " + shown + " is outside the range of " + name + " (it overflows to infinity; " +
                       holdsText<S>() + ")");
  if (nonZero && x == S(0))
    throw InvalidInput(where + ": " + shown + " is too small for " + name + " (a non-zero value that underflows to 0; " +
                       holdsText<S>() + ")");
  if (x != S(0) && abs(x) < std::numeric_limits<S>::min())
    throw InvalidInput(where + ": " + shown + " is too small for " + name + " (a subnormal " + name + " keeps " +
                       std::to_string(subnormalBits(x)) + " of its " + std::to_string(digits<S>()) + " bits; " +
                       holdsText<S>() + ")");
}

}  // namespace

template <class S> std::string holdsText() {
  const std::string name(scalarName<S>());
  if constexpr (std::is_same_v<S, mpreal>) {
    // x = m·2^e with 1/2 ≤ m < 1 and emin ≤ e ≤ emax (mpfr_get_emin/emax), at every precision.
    const long emin = mpfr_get_emin(), emax = mpfr_get_emax();
    const double log2 = 0.30102999566398120;  // log10(2), for the decimal exponents shown
    return name + " holds 0 and magnitudes from 2^" + std::to_string(emin - 1) + " to below 2^" + std::to_string(emax) +
           " (about 1e" + std::to_string(static_cast<long long>(std::floor(double(emin - 1) * log2))) + " to 1e" +
           std::to_string(static_cast<long long>(std::floor(double(emax) * log2))) + ")";
  } else {
    return name + " holds 0 and magnitudes from " + toString(std::numeric_limits<S>::min()) +
           " (its smallest normal number) to " + toString(std::numeric_limits<S>::max());
  }
}

template <class S> S parseDecimal(std::string_view text, const std::string& where) {
  if (!detail::isDecimal(text))
    throw InvalidInput(where + ": " + quoted(text) + " is not a decimal number" + detail::decimalDefect(text));
  const std::string t(text);
  const S x = convert<S>(t);
  checkRange<S>(x, detail::decimalIsNonZero(text), quoted(text), where);
  return x;
}

template <class S> S readNumber(const nlohmann::json& j, const std::string& where, NumberSource* source) {
  if (j.is_string()) {
    if (source) *source = NumberSource::DecimalString;
    return parseDecimal<S>(j.get_ref<const std::string&>(), where);
  }
  if (j.is_number_integer()) {  // signed or unsigned 64-bit: exact, then correctly rounded in S
    if (source) *source = NumberSource::JsonInteger;
    const std::string t = j.is_number_unsigned() ? std::to_string(j.get<std::uint64_t>()) : std::to_string(j.get<std::int64_t>());
    return parseDecimal<S>(t, where);
  }
  if (j.is_number_float()) {  // the JSON parser has read it as a finite double
    if (source) *source = NumberSource::JsonDouble;
    const double d = j.get<double>();
    const S x = scalarCast<S>(d);
    checkRange<S>(x, d != 0, shortest(d), where);
    return x;
  }
  throw InvalidInput(where + ": expected a number, got " + std::string(j.type_name()));
}

#define SOMA_INSTANTIATE_NUMBER(S) namespace io {                                            \
  template S parseDecimal<S>(std::string_view, const std::string&);              \
  template S readNumber<S>(const nlohmann::json&, const std::string&, NumberSource*);      \
  template std::string holdsText<S>(); }

}  // namespace soma::io
