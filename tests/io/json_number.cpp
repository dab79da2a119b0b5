// Numbers in the working precision (io/json_number.hpp, issue 22): written into JSON and read back
// by io's own reader, exactly, in all five scalars — random values over the whole exponent range,
// the extremes of each scalar, -0, infinities and NaN.
#include "soma/io/json_number.hpp"

#include "soma/algebra/errors.hpp"

#include "support/scalars.hpp"

#include <cctype>
#include <limits>
#include <type_traits>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::io;
using Catch::Contains;
using json = nlohmann::json;

/// Significant digits of a decimal text: the digits before the exponent, leading and trailing
/// zeros dropped (to_chars writes 1.2345678e12 as "1234567800000").
int significantDigits(const std::string& t) {
  std::string d;
  for (const char c : t) {
    if (c == 'e' || c == 'E') break;
    if (std::isdigit(static_cast<unsigned char>(c))) d += c;
  }
  const auto first = d.find_first_not_of('0');
  if (first == std::string::npos) return 0;
  return int(d.find_last_not_of('0') - first + 1);
}

/// The text as written, dumped and parsed again as JSON, and read back in S.
template <class S> S roundTrip(const S& x) {
  const json parsed = json::parse(json{{"x", jsonNumber(x)}}.dump());
  return readJsonNumber<S>(parsed.at("x"), "out.json: x");
}

template <class S> bool negative(const S& x) { return x < S(0) || (x == S(0) && S(1) / x < S(0)); }

/// x reads back as x: the same value, the same sign of zero, NaN as NaN.
template <class S> void checkRoundTrip(const S& x) {
  const S y = roundTrip(x);
  INFO(scalarName<S>() << ": " << numberText(x) << " read back as " << numberText(y));
  if (!(x == x)) {
    CHECK(!(y == y));
    return;
  }
  CHECK(y == x);
  CHECK(negative(y) == negative(x));
}

/// Round-trip digits of S: 9, 17, 21, 36, floor(p·log10 2) + 2.
template <class S> int roundTripDigits() {
  if constexpr (std::is_same_v<S, float>) return 9;
  else if constexpr (std::is_same_v<S, double>) return 17;
  else if constexpr (std::is_same_v<S, long double>) return 21;
  else if constexpr (std::is_same_v<S, __float128>) return 36;
  else return int(std::floor(digits<S>() * 0.30102999566398120)) + 2;
}

TEMPLATE_TEST_CASE("jsonNumber: random values read back exactly", "[io][json_number]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = test::rng();
  // A value with all of S's bits (a quotient of two draws), scaled by 2^e over most of S's range
  // (float: ±120, double and wider: ±1000, each factor exact).
  const int range = std::is_same_v<S, float> ? 120 : 1000;
  std::uniform_int_distribution<int> exponent(-range, range);
  int longest = 0;
  std::string longestText;
  for (int k = 0; k < 2000; ++k) {
    const S q = test::uniform<S>(g, -1, 1) / test::uniform<S>(g, 0.5, 1);
    S scale = scalarCast<S>(std::ldexp(1.0, exponent(g)));
    if constexpr (!std::is_same_v<S, float> && !std::is_same_v<S, double>) scale *= scale;  // ±2000: beyond double
    const S x = q * scale;
    checkRoundTrip(x);
    if (significantDigits(numberText(x)) > longest) longest = significantDigits(longestText = numberText(x));
    // float and double are JSON numbers; the wider scalars decimal strings (a JSON double would round).
    CHECK(jsonNumber(x).is_number_float() == (std::is_same_v<S, float> || std::is_same_v<S, double>));
  }
  // The text carries S's digits: at most the round-trip count, and exactly it for some value.
  INFO("the longest: " << longestText);
  CHECK(longest == roundTripDigits<S>());
}

TEMPLATE_TEST_CASE("jsonNumber: the extremes of each scalar, -0, inf and nan", "[io][json_number]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using L = std::numeric_limits<S>;
  const S one(1), eps = L::epsilon();
  std::vector<S> xs = {S(0), -S(0), one, -one, one + eps, one - eps / S(2), eps, L::min(), -L::min(),
                       L::max(), -L::max(), S(0.1), S(1) / S(3), pi<S>()};
  if constexpr (!std::is_same_v<S, mpreal>) xs.push_back(L::denorm_min());  // a subnormal: what S computed is kept
  for (const S& x : xs) checkRoundTrip(x);
  const S inf = one / S(0);
  checkRoundTrip(inf);
  checkRoundTrip(-inf);
  checkRoundTrip(inf - inf);
  CHECK(jsonNumber(inf) == json("inf"));
  CHECK(jsonNumber(-inf) == json("-inf"));
  CHECK(jsonNumber(inf - inf) == json("nan"));
  // -0 keeps its sign in the text.
  CHECK(numberText(-S(0)) == "-0");
}

TEST_CASE("jsonNumber: the text of each scalar", "[io][json_number]") {
  // float in its own shortest form, not the double's digits.
  CHECK(json(jsonNumber(0.1f)).dump() == "0.1");
  CHECK(json(jsonNumber(0.1)).dump() == "0.1");
  CHECK(numberText(0.1f) == "0.1");
  CHECK(json(jsonNumber(-0.0)).dump() == "-0.0");
  // The wider scalars: their own digits of 1/3 (21, 36 and, at 256 bits, 79), the correctly rounded
  // decimals of the nearest binary value (computed apart with Python's fractions).
  CHECK(numberText(1.0L / 3.0L) == "0.333333333333333333342");
  CHECK(numberText(__float128(1) / 3) == "0.333333333333333333333333333333333317");
  const int bits = mpfrBits();
  setMpfrBits(256);
  // 1/3 at 256 bits is 0.333…3334772…: its 79 digits end in …348 (exact binary value, computed apart).
  CHECK(numberText(mpreal(1) / 3) == "0.3333333333333333333333333333333333333333333333333333333333333333333333333333348");
  setMpfrBits(bits);
}

TEMPLATE_TEST_CASE("readJsonNumber: what it refuses", "[io][json_number]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const std::string where = "out.json: x";
  CHECK_THROWS_WITH(readJsonNumber<S>(json("0x10"), where), where + ": \"0x10\" is not a decimal number, \"inf\", \"-inf\" or \"nan\" (hexadecimal)");
  CHECK_THROWS_WITH(readJsonNumber<S>(json("Infinity"), where), Contains("is not a decimal number"));
  CHECK_THROWS_WITH(readJsonNumber<S>(json(true), where), where + ": expected a number, or a decimal string, \"inf\", \"-inf\" or \"nan\", got boolean");
  CHECK_THROWS_WITH(readJsonNumber<S>(json("1e999999999"), where), Contains("overflows to infinity"));
}

}  // namespace SOMA_UNITY_ID
