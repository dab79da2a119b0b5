#pragma once
// Definitions of json_number.hpp's templates, instantiated for the five scalars by soma_instantiate (io/CMakeLists.txt).
#include "soma/io/json_number.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/number.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <type_traits>

namespace soma::io {

namespace detail {

/// Shortest decimal text that reads back as x (float or double), in %g's style: "0.1", "-0",
/// "1e+20", "1.4584876e+12" (not the 13 exact digits "1458487558144", no longer but less clear).
template <class F> std::string shortestText(F x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general);
  return std::string(buf, r.ptr);
}

/// The correctly rounded value of decimal text `t` in S, subnormals and "inf"/"nan" included (the
/// C library's strto*: std::stof & co. throw on a subnormal result).
template <class S> S decimalValue(const std::string& t) {
  if constexpr (std::is_same_v<S, float>) return std::strtof(t.c_str(), nullptr);
  else if constexpr (std::is_same_v<S, double>) return std::strtod(t.c_str(), nullptr);
  else if constexpr (std::is_same_v<S, long double>) return std::strtold(t.c_str(), nullptr);
  else return fromString<S>(t);  // strtoflt128 and mpfr_set_str: exact in S
}

template <class S> bool isNan(const S& x) { return !(x == x); }

}  // namespace detail

template <class S> std::string numberText(const S& x) {
  if (detail::isNan(x)) return "nan";
  if (!isFinite(x)) return x > S(0) ? "inf" : "-inf";
  if constexpr (std::is_same_v<S, float> || std::is_same_v<S, double>) return detail::shortestText(x);
  else return toString(x);  // 21, 36 or floor(p·log10 2) + 2 significant digits: reads back as x
}

template <class S> nlohmann::json jsonNumber(const S& x) {
  if (!isFinite(x)) return numberText(x);
  if constexpr (std::is_same_v<S, double>) {
    return x;  // nlohmann writes a double in its shortest round-trip form
  } else if constexpr (std::is_same_v<S, float>) {
    // The double nearest to the float's shortest text: JSON shows that text, and the double read
    // back rounds to x. Should that rounding ever miss (a text within half a double ulp of a
    // midpoint between two floats), the exact double value of x is written instead.
    const double d = std::strtod(detail::shortestText(x).c_str(), nullptr);
    return static_cast<float>(d) == x && std::signbit(d) == std::signbit(x) ? d : static_cast<double>(x);
  } else {
    return numberText(x);
  }
}

template <class S> S readJsonNumber(const nlohmann::json& j, const std::string& where) {
  if (j.is_string()) {
    const std::string& t = j.get_ref<const std::string&>();
    if (t == "inf" || t == "-inf" || t == "nan") return detail::decimalValue<S>(t);
    if (!detail::isDecimal(t))
      throw InvalidInput(where + ": \"" + t + "\" is not a decimal number, \"inf\", \"-inf\" or \"nan\"" +
                         detail::decimalDefect(t));
    const S x = detail::decimalValue<S>(t);
    if (!isFinite(x))
      throw InvalidInput(where + ": \"" + t + "\" is outside the range of " + std::string(scalarName<S>()) +
                         " (it overflows to infinity; " + holdsText<S>() + ")");
    return x;
  }
  if (j.is_number_integer())  // signed or unsigned 64-bit: exact, then correctly rounded in S
    return detail::decimalValue<S>(j.is_number_unsigned() ? std::to_string(j.get<std::uint64_t>())
                                                          : std::to_string(j.get<std::int64_t>()));
  if (j.is_number_float()) {
    const double d = j.get<double>();
    if constexpr (std::is_same_v<S, float>) return static_cast<float>(d);  // jsonNumber wrote a double that rounds to x
    else return scalarCast<S>(d);
  }
  throw InvalidInput(where + ": expected a number, or a decimal string, \"inf\", \"-inf\" or \"nan\", got " +
                     std::string(j.type_name()));
}

#define SOMA_INSTANTIATE_JSON_NUMBER(S) namespace io {                         \
  template nlohmann::json jsonNumber<S>(const S&);                            \
  template std::string numberText<S>(const S&);                               \
  template S readJsonNumber<S>(const nlohmann::json&, const std::string&); }

}  // namespace soma::io
