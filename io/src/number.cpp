// The non-template part of number.hpp (the decimal grammar, integers); parseDecimal and readNumber:
// number_impl.hpp.
#include "soma/io/number.hpp"

#include "soma/algebra/errors.hpp"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>

namespace soma::io {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

std::string lower(std::string_view t) {
  std::string s(t);
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string quoted(std::string_view t) { return "\"" + std::string(t) + "\""; }

std::string range(long long lo, long long hi) { return std::to_string(lo) + " … " + std::to_string(hi); }

}  // namespace

bool detail::decimalIsNonZero(std::string_view t) {
  for (const char c : t) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

bool detail::isDecimal(std::string_view t) {
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

std::string detail::decimalDefect(std::string_view t) {
  if (t.empty()) return " (empty)";
  if (std::isspace(static_cast<unsigned char>(t.front())) || std::isspace(static_cast<unsigned char>(t.back())))
    return " (leading or trailing space)";
  std::string s = lower(t);
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.erase(0, 1);
  if (s.rfind("0x", 0) == 0) return " (hexadecimal)";
  if (s == "nan" || s.rfind("nan(", 0) == 0 || s == "inf" || s == "infinity") return " (NaN and infinity are not numbers soma reads)";
  return "";
}

long long parseInteger(std::string_view text, const std::string& where, long long lo, long long hi) {
  if (!detail::isDecimal(text))
    throw InvalidInput(where + ": " + quoted(text) + " is not a decimal number" + detail::decimalDefect(text));
  // The value, decided on the text: sign, significant digits D (no leading zeros) and the power of
  // ten p, value = ±D·10^p. It is an integer when the digits below 10^0 are zeros.
  std::size_t i = 0;
  bool negative = false;
  if (text[i] == '+' || text[i] == '-') negative = text[i++] == '-';
  std::string digits;
  long long point = 0;  // digits after the decimal point
  bool fraction = false;
  for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
    if (text[i] == '.') {
      fraction = true;
      continue;
    }
    if (fraction) ++point;
    digits += text[i];
  }
  long long exponent = 0;
  bool hugeExponent = false, minus = false;
  if (i < text.size()) {
    ++i;
    if (text[i] == '+' || text[i] == '-') minus = text[i++] == '-';
    for (; i < text.size(); ++i) {
      if (exponent > std::numeric_limits<int>::max()) hugeExponent = true;
      else exponent = exponent * 10 + (text[i] - '0');
    }
    if (minus) exponent = -exponent;
  }
  // Trailing zeros of D raise p; leading zeros do not count.
  long long p = exponent - point;
  while (!digits.empty() && digits.back() == '0') digits.pop_back(), ++p;
  const std::size_t first = digits.find_first_not_of('0');
  digits = first == std::string::npos ? std::string() : digits.substr(first);
  const std::string shown = quoted(text);
  if (digits.empty()) {  // zero, however it is written
    if (lo <= 0 && 0 <= hi) return 0;
    throw InvalidInput(where + ": " + shown + " is outside " + range(lo, hi));
  }
  if (hugeExponent ? minus : p < 0) throw InvalidInput(where + ": " + shown + " is not an integer");
  // |value| = D·10^p: beyond 19 digits it exceeds every long long bound.
  if (hugeExponent || std::size_t(p) + digits.size() > 19)
    throw InvalidInput(where + ": " + shown + " is outside " + range(lo, hi));
  unsigned long long magnitude = 0;
  for (const char c : digits) magnitude = magnitude * 10 + static_cast<unsigned long long>(c - '0');
  for (long long k = 0; k < p; ++k) magnitude *= 10;
  // At most 19 digits: below 10^19 < 2^64, so no wrap; now compare with the bounds.
  const unsigned long long limit = negative ? static_cast<unsigned long long>(-(lo + 1)) + 1
                                            : static_cast<unsigned long long>(hi < 0 ? 0 : hi);
  if ((negative && lo >= 0) || (!negative && hi < 0) || magnitude > limit)
    throw InvalidInput(where + ": " + shown + " is outside " + range(lo, hi));
  const long long value = negative ? -static_cast<long long>(magnitude - 1) - 1 : static_cast<long long>(magnitude);
  if (value < lo || value > hi) throw InvalidInput(where + ": " + shown + " is outside " + range(lo, hi));
  return value;
}

long long readInteger(const nlohmann::json& j, const std::string& where, long long lo, long long hi) {
  if (j.is_string()) return parseInteger(j.get_ref<const std::string&>(), where, lo, hi);
  if (j.is_number_unsigned()) return parseInteger(std::to_string(j.get<std::uint64_t>()), where, lo, hi);
  if (j.is_number_integer()) return parseInteger(std::to_string(j.get<std::int64_t>()), where, lo, hi);
  if (j.is_number_float()) {  // a finite double: its exact decimal value decides (2.0 is 2, 2.5 is not an integer)
    const double d = j.get<double>();
    if (d != std::floor(d)) throw InvalidInput(where + ": " + j.dump() + " is not an integer");
    if (!(d >= -0x1p63 && d < 0x1p63)) throw InvalidInput(where + ": " + j.dump() + " is outside " + range(lo, hi));
    const long long v = static_cast<long long>(d);
    if (v < lo || v > hi) throw InvalidInput(where + ": " + j.dump() + " is outside " + range(lo, hi));
    return v;
  }
  throw InvalidInput(where + ": expected an integer, got " + std::string(j.type_name()));
}

}  // namespace soma::io
