#pragma once
// Definitions of number.hpp's templates, instantiated for the five scalars by soma_instantiate (io/CMakeLists.txt).
#include "soma/io/number.hpp"

#include "soma/algebra/errors.hpp"

#include <nlohmann/json.hpp>

#include <cctype>
#include <charconv>
#include <cstdlib>
#include <limits>

namespace soma::io {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

/// [+|-] digits [. digits] [(e|E) [+|-] digits], with at least one digit before the exponent.
bool isDecimal(std::string_view t) {
  std::size_t i = 0;
  const std::size_t n = t.size();
  if (i < n && (t[i] == '+' || t[i] == '-')) ++i;
  std::size_t digits = 0;
  for (; i < n && isDigit(t[i]); ++i) ++digits;
  if (i < n && t[i] == '.')
    for (++i; i < n && isDigit(t[i]); ++i) ++digits;
  if (digits == 0) return false;
  if (i < n && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < n && (t[i] == '+' || t[i] == '-')) ++i;
    std::size_t exponent = 0;
    for (; i < n && isDigit(t[i]); ++i) ++exponent;
    if (exponent == 0) return false;
  }
  return i == n;
}

std::string lower(std::string_view t) {
  std::string s(t);
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// Why `t` is not a decimal number, for the message ("" when there is nothing more to say).
std::string defect(std::string_view t) {
  if (t.empty()) return " (empty)";
  if (std::isspace(static_cast<unsigned char>(t.front())) || std::isspace(static_cast<unsigned char>(t.back())))
    return " (leading or trailing space)";
  std::string s = lower(t);
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.erase(0, 1);
  if (s.rfind("0x", 0) == 0) return " (hexadecimal)";
  if (s == "nan" || s.rfind("nan(", 0) == 0 || s == "inf" || s == "infinity") return " (NaN and infinity are not numbers of a file)";
  return "";
}

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

template <class S> bool isZero(const S& x) { return x == S(0); }

/// The range checks shared by decimal strings and JSON numbers: `shown` is the value as written.
template <class S> void checkRange(const S& x, bool nonZero, const std::string& shown, const std::string& where) {
  if (!isFinite(x))
    throw InvalidInput(where + ": " + shown + " is outside the range of " + std::string(scalarName<S>()) +
                       " (it overflows to infinity)");
  if (nonZero && isZero(x))
    throw InvalidInput(where + ": " + shown + " is too small for " + std::string(scalarName<S>()) +
                       " (a non-zero value that underflows to 0)");
}

}  // namespace

template <class S> S parseDecimal(std::string_view text, const std::string& where) {
  if (!isDecimal(text)) throw InvalidInput(where + ": " + quoted(text) + " is not a decimal number" + defect(text));
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
  template S readNumber<S>(const nlohmann::json&, const std::string&, NumberSource*); }

}  // namespace soma::io
