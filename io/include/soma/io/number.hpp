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
//    characters, a value S cannot hold (it overflows to ±∞ in S, or a non-zero value underflows to
//    0 in S; subnormal values are kept), and a JSON value that is not a number or a string.
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

namespace detail {
/// A digit 1–9 before the exponent: the decimal text is not zero (an underflow to 0 is an error).
bool decimalIsNonZero(std::string_view text);
}  // namespace detail

#define SOMA_IO_NUMBER_EXTERN(S)                                                          \
  extern template S parseDecimal<S>(std::string_view, const std::string&);                \
  extern template S readNumber<S>(const nlohmann::json&, const std::string&, NumberSource*);
SOMA_FOR_EACH_SCALAR(SOMA_IO_NUMBER_EXTERN)
#undef SOMA_IO_NUMBER_EXTERN

}  // namespace soma::io
