#pragma once
// Numbers written in the working precision (DESIGN §6, issue 22): every number soma writes into
// JSON or text output, with the digits of its scalar, read back exactly by readJsonNumber.
//  * float and double: a JSON number, the shortest text that reads back as the same value (float:
//    0.1f is written 0.1, not 0.10000000149011612).
//  * long double, __float128 and mpfr: a decimal string, because a JSON number is a double (RFC
//    8259 §6) and would round: 21 significant digits for long double (64 bits), 36 for __float128
//    (113 bits), floor(p·log10 2) + 2 for mpfr at p bits (79 at 256 bits) — enough to read back
//    the same value (DESIGN §2).
//  * Infinity and NaN, which JSON has no number for: the strings "inf", "-inf", "nan" in every
//    scalar. -0 stays -0 ("-0.0" as a JSON number, "-0" as a string).
// numberText(x) is the same text for text output (a float/double without JSON's ".0").
#include "soma/algebra/scalar.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <type_traits>

namespace soma::io {

/// x as JSON: a number (float, double) or a decimal string (long double, __float128, mpfr),
/// "inf"/"-inf"/"nan" for the non-finite values.
template <class S> nlohmann::json jsonNumber(const S& x);
/// x as decimal text with the digits of S (the JSON string of jsonNumber, or the shortest text of a
/// float or double): for text output.
template <class S> std::string numberText(const S& x);
/// A fixed-size Eigen vector or matrix as JSON: a vector (one column) as an array of numbers, a
/// matrix as an array of rows, each entry jsonNumber.
template <class D> nlohmann::json jsonNumbers(const Eigen::MatrixBase<D>& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    if (m.cols() == 1) {
      rows.push_back(jsonNumber(m(i, 0)));
      continue;
    }
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(jsonNumber(m(i, j)));
    rows.push_back(std::move(row));
  }
  return rows;
}

/// The working scalar of an answer, for its JSON: "scalar" (its command-line name) and, for mpfr,
/// "bits" (the precision its numbers were written in, and must be read back in).
template <class S> void addScalar(nlohmann::json& j) {
  j["scalar"] = std::string(scalarName<S>());
  if constexpr (std::is_same_v<S, mpreal>) j["bits"] = mpfrBits();
}

/// A number written by jsonNumber, read back exactly in S (for mpfr at the precision it was
/// written in: setMpfrBits(bits) first): a JSON number, a decimal string (read
/// correctly rounded in S; a subnormal value is kept, it is what S computed), or "inf", "-inf",
/// "nan". InvalidInput naming `where` for anything else or a decimal S cannot hold (it overflows).
/// The readers of input files (number.hpp) refuse NaN, infinity and subnormals; this one reads
/// soma's output.
template <class S> S readJsonNumber(const nlohmann::json& value, const std::string& where);

#define SOMA_IO_JSON_NUMBER_EXTERN(S)                                   \
  extern template nlohmann::json jsonNumber<S>(const S&);               \
  extern template std::string numberText<S>(const S&);                  \
  extern template S readJsonNumber<S>(const nlohmann::json&, const std::string&);
SOMA_FOR_EACH_SCALAR(SOMA_IO_JSON_NUMBER_EXTERN)
#undef SOMA_IO_JSON_NUMBER_EXTERN

}  // namespace soma::io
