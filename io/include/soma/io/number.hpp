#pragma once
// The one number reader of every file format (DESIGN §6): a JSON number or a decimal string read
// into any scalar of the ladder, with one set of errors shared by all readers.
//  * A decimal string ("0.1", "-2.5e-3") is read exactly in S: correctly rounded to S's own
//    precision ("0.1" in mpfr at 256 bits is mpfr's 0.1, not the double 0.1).
//  * A JSON number is read as JSON defines it: an integer exactly (correctly rounded in S), any
//    other number as the IEEE double nearest to its text (RFC 8259 §6), then taken exactly in S
//    (rounded once more in float). A finer scalar needs decimal strings for digits beyond double.
//  * Rejected, with a message naming the key path and the value: hexadecimal ("0x10"), NaN and
//    infinity ("nan", "inf", "infinity"), an empty string, leading or trailing spaces or other
//    characters, a value S cannot hold, and a JSON value that is not a number or a string.
//  * What S holds (holdsText<S>() says it in every range message): 0 and the magnitudes from S's
//    smallest normal number to its largest (float 1.18e-38 … 3.40e38, double 2.23e-308 … 1.80e308,
//    long double and float128 3.36e-4932 … 1.19e4932, mpfr 2^(emin−1) … 2^emax: about
//    1e-323228497 … 1e323228496). A value beyond the largest overflows; a non-zero value below the
//    smallest normal is refused too: it would underflow to 0 or be a subnormal that keeps fewer
//    than S's significant bits (1e-320 in double keeps 11 of 53), a silent loss of precision. A
//    JSON number is a double (parseJsonText refuses a subnormal one), so a value below 2.23e-308
//    reaches long double, float128 or mpfr only as a decimal string ("1e-320").
//  * Integers (flags such as --bits, fields such as "mode"): parseInteger/readInteger, the same
//    decimal grammar ("16", "1e3"), the value an integer within the caller's bounds.
#include "soma/algebra/scalar.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <string_view>

namespace soma::io {

/// How a number was written in its file.
enum class NumberSource {
  JsonInteger,    ///< a JSON integer: exact
  JsonDouble,     ///< a JSON number with a fraction or an exponent: carries a double's precision
  DecimalString,  ///< a decimal string: exact in S
};

/// Decimal text `text` in S: [+|-] digits [. digits] [(e|E) [+|-] digits] (".5" and "5." too).
/// `where` (a file and key path, e.g. "robot.json: joints[2].alpha") starts every message:
///   robot.json: joints[2].alpha: "0x10" is not a decimal number (hexadecimal)
/// Throws InvalidInput.
template <class S> S parseDecimal(std::string_view text, const std::string& where);

/// A JSON number or decimal string in S; `source`, when given, says how it was written (the pose
/// reader judges rotations typed as JSON doubles at double's tolerance). Throws InvalidInput.
template <class S>
S readNumber(const nlohmann::json& value, const std::string& where, NumberSource* source = nullptr);

/// An integer written in decimal (parseDecimal's grammar: "16", "+3", "1e3", "2.0"), exactly,
/// within [lo, hi]. InvalidInput naming `where` for any other text, a fraction ("2.5 is not an
/// integer") or a value out of bounds ("100001 is outside 16 … 8192"): decided on the text, never
/// on a rounded value (4294967297 is not 1).
long long parseInteger(std::string_view text, const std::string& where, long long lo, long long hi);
/// A JSON integer, a JSON number with an integral value, or a decimal string, as parseInteger.
long long readInteger(const nlohmann::json& value, const std::string& where, long long lo, long long hi);

/// What S holds, for messages: "float holds 0 and magnitudes from 1.17549435e-38 (its smallest
/// normal number) to 3.40282347e+38".
template <class S> std::string holdsText();

namespace detail {
/// A digit 1–9 before the exponent: the decimal text is not zero (an underflow to 0 is an error).
bool decimalIsNonZero(std::string_view text);
/// [+|-] digits [. digits] [(e|E) [+|-] digits], with at least one digit before the exponent.
bool isDecimal(std::string_view text);
/// Why `text` is not a decimal number, for a message (" (hexadecimal)", " (empty)", or "").
std::string decimalDefect(std::string_view text);
}  // namespace detail

#define SOMA_IO_NUMBER_EXTERN(S)                                                          \
  extern template S parseDecimal<S>(std::string_view, const std::string&);                \
  extern template S readNumber<S>(const nlohmann::json&, const std::string&, NumberSource*); \
  extern template std::string holdsText<S>();
SOMA_FOR_EACH_SCALAR(SOMA_IO_NUMBER_EXTERN)
#undef SOMA_IO_NUMBER_EXTERN

}  // namespace soma::io
