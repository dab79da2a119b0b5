// The one number reader (io/number.hpp): every error class in all five scalars, decimal strings
// exact in S, integers exact, and both sides of each range threshold.
#include "soma/io/json_file.hpp"
#include "soma/io/number.hpp"

#include "support/scalars.hpp"

#include <limits>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::io;
using Catch::Contains;
using json = nlohmann::json;

TEMPLATE_TEST_CASE("readNumber: one set of errors in every scalar", "[io][number]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const std::string where = "robot.json: joints[2].alpha";
  auto text = [&](const std::string& t) { return readNumber<S>(json(t), where); };
  // Hexadecimal: strtod reads "0x10" as 16, mpfr's decimal reader as 0; both are refused.
  CHECK_THROWS_WITH(text("0x10"), "robot.json: joints[2].alpha: \"0x10\" is not a decimal number (hexadecimal)");
  CHECK_THROWS_WITH(text("-0X1p3"), Contains("(hexadecimal)"));
  for (const char* t : {"nan", "NaN", "-nan", "inf", "-inf", "Infinity", "+infinity", "nan(1)"})
    CHECK_THROWS_WITH(text(t), Contains("\"" + std::string(t) + "\" is not a decimal number (NaN and infinity"));
  CHECK_THROWS_WITH(text(""), where + ": \"\" is not a decimal number (empty)");
  for (const char* t : {" 1", "1 ", "\t1", "1\n"})
    CHECK_THROWS_WITH(text(t), Contains("is not a decimal number (leading or trailing space)"));
  for (const char* t : {"1.5x", "x1", "1e", "1e+", "--1", "+-1", ".", "-", "e5", "1,5", "1.2.3", "1e5.5", "١"})
    CHECK_THROWS_WITH(text(t), where + ": \"" + std::string(t) + "\" is not a decimal number");
  // A JSON value that is not a number or a string.
  CHECK_THROWS_WITH(readNumber<S>(json(true), where), where + ": expected a number, got boolean");
  CHECK_THROWS_WITH(readNumber<S>(json(nullptr), where), where + ": expected a number, got null");
  CHECK_THROWS_WITH(readNumber<S>(json::array({1}), where), where + ": expected a number, got array");
  CHECK_THROWS_WITH(readNumber<S>(json::object(), where), where + ": expected a number, got object");
  // Values no scalar of the ladder holds: beyond mpfr's exponent range (2^(2^30) ≈ 10^323228496).
  CHECK_THROWS_WITH(text("1e999999999"), Contains("\"1e999999999\" is outside the range of " +
                                                  std::string(scalarName<S>()) + " (it overflows to infinity)"));
  CHECK_THROWS_WITH(text("-1e999999999"), Contains("overflows to infinity"));
  CHECK_THROWS_WITH(text("1e-999999999"), Contains("\"1e-999999999\" is too small for " +
                                                   std::string(scalarName<S>()) + " (a non-zero value that underflows to 0)"));
  // Zero written with a huge exponent is zero, not an underflow.
  CHECK(text("0e-999999999") == S(0));
  CHECK(text("-0.000e5") == S(0));
  // What is accepted: sign, fraction, exponent, ".5" and "5.".
  CHECK(text("+2.5e1") == S(25));
  CHECK(text("-.5") == S(-0.5));
  CHECK(text("5.") == S(5));
  CHECK(text("1E2") == S(100));
}

TEMPLATE_TEST_CASE("readNumber: decimal strings exact in S, integers exact, JSON doubles as doubles", "[io][number]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  NumberSource source{};
  // A decimal string is S's own rounding of the decimal (what S's own parser gives).
  CHECK(readNumber<S>(json("0.1"), "w", &source) == fromString<S>("0.1"));
  CHECK(source == NumberSource::DecimalString);
  // A JSON number with a fraction is the double nearest to it, taken exactly in S.
  CHECK(readNumber<S>(json(0.1), "w", &source) == scalarCast<S>(0.1));
  CHECK(source == NumberSource::JsonDouble);
  // Integers are exact (2^24 + 1 is not a float: it rounds to even, 2^24).
  CHECK(readNumber<S>(json(7), "w", &source) == S(7));
  CHECK(source == NumberSource::JsonInteger);
  CHECK(readNumber<S>(json(-3), "w") == S(-3));
  CHECK(readNumber<S>(json("16777217"), "w") == fromString<S>("16777217"));
  CHECK(readNumber<S>(json(16777217), "w") == fromString<S>("16777217"));
}

TEST_CASE("readNumber: 0.1 in mpfr and float128 is their own 0.1, not the double 0.1", "[io][number]") {
  setMpfrBits(256);
  const mpreal m = readNumber<mpreal>(json("0.1"), "w");
  CHECK(m == mpreal("0.1"));
  CHECK(m.get_prec() == 256);
  CHECK(m != mpreal(0.1));
  // |m − 1/10| ≤ half an ulp at 256 bits; the double 0.1 is off by 5.55e-18.
  CHECK(abs(m * 10 - 1) < mpreal("1e-76"));
  CHECK(abs(mpreal(0.1) * 10 - 1) > mpreal("1e-17"));
  const __float128 q = readNumber<__float128>(json("0.1"), "w");
  CHECK(q == strtoflt128("0.1", nullptr));
  CHECK(q != __float128(0.1));
  // Integers beyond a double's 53 bits: exact in float128 and mpfr.
  const std::uint64_t big = (std::uint64_t(1) << 62) + 1;
  CHECK(readNumber<mpreal>(json(big), "w") == mpreal("4611686018427387905"));
  CHECK(readNumber<__float128>(json(big), "w") == __float128(big));
  CHECK(readNumber<long double>(json(big), "w") == static_cast<long double>(big));
  CHECK(readNumber<double>(json(big), "w") == 4611686018427387904.0);  // rounded once, to even
  CHECK(readNumber<long double>(json(std::numeric_limits<std::int64_t>::min()), "w") ==
        static_cast<long double>(std::numeric_limits<std::int64_t>::min()));
}

TEST_CASE("readNumber: both sides of the float overflow and underflow thresholds", "[io][number]") {
  // FLT_MAX = 3.40282347e38; 3.4028234e38 rounds to it, 3.5e38 is beyond it.
  CHECK(readNumber<float>(json("3.4028234e38"), "w") == std::numeric_limits<float>::max());
  CHECK_THROWS_WITH(readNumber<float>(json("3.5e38"), "w"), "w: \"3.5e38\" is outside the range of float (it overflows to infinity)");
  CHECK_THROWS_WITH(readNumber<float>(json("-3.5e38"), "w"), Contains("overflows"));
  CHECK(readNumber<double>(json("3.5e38"), "w") == 3.5e38);
  // The same through a JSON double.
  CHECK_THROWS_WITH(readNumber<float>(json(3.5e38), "w"), "w: 3.5e+38 is outside the range of float (it overflows to infinity)");
  CHECK(readNumber<float>(json(3.4028234e38), "w") == std::numeric_limits<float>::max());
  // The smallest subnormal float is 1.4e-45: 1e-45 rounds to it (kept), 5e-46 rounds to 0 (refused).
  CHECK(readNumber<float>(json("1e-45"), "w") == std::numeric_limits<float>::denorm_min());
  CHECK_THROWS_WITH(readNumber<float>(json("5e-46"), "w"), "w: \"5e-46\" is too small for float (a non-zero value that underflows to 0)");
  CHECK(readNumber<float>(json(1e-45), "w") == std::numeric_limits<float>::denorm_min());
  CHECK_THROWS_WITH(readNumber<float>(json(5e-46), "w"), Contains("underflows to 0"));
  CHECK(readNumber<double>(json("5e-46"), "w") == 5e-46);
}

TEST_CASE("readNumber: the range thresholds of double, long double and float128", "[io][number]") {
  // double: DBL_MAX = 1.797693e308, smallest subnormal 4.94e-324 (half of it, 2.47e-324, rounds to 0).
  CHECK(readNumber<double>(json("1.7976931348623157e308"), "w") == std::numeric_limits<double>::max());
  CHECK_THROWS_WITH(readNumber<double>(json("1.8e308"), "w"), Contains("outside the range of double"));
  CHECK(readNumber<double>(json("3e-324"), "w") == std::numeric_limits<double>::denorm_min());
  CHECK_THROWS_WITH(readNumber<double>(json("2e-324"), "w"), Contains("too small for double"));
  // long double (x87, 64-bit significand) and float128 both reach 1.18973e4932.
  CHECK(readNumber<long double>(json("1e400"), "w") == fromString<long double>("1e400"));
  CHECK(readNumber<long double>(json("1.18973e4932"), "w") > 0);
  CHECK_THROWS_WITH(readNumber<long double>(json("1.2e4932"), "w"), Contains("outside the range of long-double"));
  CHECK(readNumber<__float128>(json("1.18973e4932"), "w") > 0);
  CHECK_THROWS_WITH(readNumber<__float128>(json("1.2e4932"), "w"), Contains("outside the range of float128"));
  // Smallest subnormals: long double 3.6e-4951, float128 6.5e-4966.
  CHECK(readNumber<long double>(json("4e-4951"), "w") == std::numeric_limits<long double>::denorm_min());
  CHECK_THROWS_WITH(readNumber<long double>(json("1e-4951"), "w"), Contains("too small for long-double"));
  CHECK(readNumber<__float128>(json("7e-4966"), "w") > 0);
  CHECK_THROWS_WITH(readNumber<__float128>(json("3e-4966"), "w"), Contains("too small for float128"));
  // mpfr holds 1e400 and 1e-400 (at every precision); double does not.
  CHECK(readNumber<mpreal>(json("1e400"), "w") == mpreal("1e400"));
  CHECK(readNumber<mpreal>(json("1e-400"), "w") == mpreal("1e-400"));
  CHECK_THROWS_WITH(readNumber<double>(json("1e400"), "w"), "w: \"1e400\" is outside the range of double (it overflows to infinity)");
  CHECK_THROWS_WITH(readNumber<double>(json("1e-400"), "w"), Contains("too small for double"));
}

TEST_CASE("parseJson: a JSON number beyond a double is named with its key path", "[io][number]") {
  CHECK_THROWS_WITH(parseJson(R"({"joints": [{"a": 1}, {"a": 1, "alpha": 1e400}]})", "robot.json"),
                    Contains("robot.json: joints[1].alpha: 1e400 is outside the range of a JSON number") &&
                        Contains("decimal string \"1e400\""));
  CHECK_THROWS_WITH(parseJson(R"({"leg_lengths": [1, 2, -1e-400]})", "p.json"),
                    Contains("p.json: leg_lengths[2]: -1e-400 is too small for a JSON number (a double: it underflows to 0)"));
  CHECK_THROWS_WITH(parseJson(R"([[0, 1], [2, 1E999]])", "x.json"), Contains("x.json: [1][1]: 1E999 is outside the range"));
  // Zero is zero, and a syntax error stays a syntax error.
  CHECK(parseJson(R"({"a": 0e-999, "b": [0.0]})", "z.json")["a"].get<double>() == 0);
  CHECK_THROWS_WITH(parseJson("{\"a\": }", "s.json"), Contains("s.json: not valid JSON ([json.exception.parse_error"));
  CHECK_THROWS_WITH(parseJson("{\"a\": 0x10}", "s.json"), Contains("s.json: not valid JSON"));
}

TEST_CASE("KeyPath and checkKeys", "[io]") {
  CHECK(KeyPath("robot.json").key("joints").index(2).key("alpha").str() == "robot.json: joints[2].alpha");
  CHECK(KeyPath().key("positions").index(0).key("x").str() == "positions[0].x");
  CHECK(KeyPath("f.json").str() == "f.json");
  CHECK(KeyPath("f.json").index(3).index(1).str() == "f.json: [3][1]");
  const json j = json::parse(R"({"a": 1, "b": 2})");
  CHECK_NOTHROW(checkKeys(j, {"a", "b", "c"}, "f.json"));
  CHECK_THROWS_WITH(checkKeys(j, {"a"}, "f.json"), "f.json: unknown field \"b\"");
  CHECK_THROWS_WITH(checkKeys(j, {"a"}, "f.json", "(a has only a)"), "f.json: unknown field \"b\" (a has only a)");
}

}  // namespace SOMA_UNITY_ID
