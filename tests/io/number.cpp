// The one number reader (io/number.hpp): every error class in all five scalars, decimal strings
// exact in S, integers exact, and both sides of each range threshold.
#include "soma/io/input_limits.hpp"
#include "soma/io/json_file.hpp"
#include "soma/io/number.hpp"

#include "support/scalars.hpp"

#include <limits>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::io;
using Catch::Contains;
using Catch::StartsWith;
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
  // Every range message says what S holds.
  CHECK_THROWS_WITH(text("1e999999999"), where + ": \"1e999999999\" is outside the range of " +
                                             std::string(scalarName<S>()) + " (it overflows to infinity; " +
                                             holdsText<S>() + ")");
  CHECK_THROWS_WITH(text("-1e999999999"), Contains("overflows to infinity"));
  CHECK_THROWS_WITH(text("1e-999999999"), where + ": \"1e-999999999\" is too small for " +
                                              std::string(scalarName<S>()) +
                                              " (a non-zero value that underflows to 0; " + holdsText<S>() + ")");
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
  CHECK_THROWS_WITH(readNumber<float>(json("3.5e38"), "w"),
                    "w: \"3.5e38\" is outside the range of float (it overflows to infinity; float holds 0 and "
                    "magnitudes from 1.17549435e-38 (its smallest normal number) to 3.40282347e+38)");
  CHECK_THROWS_WITH(readNumber<float>(json("-3.5e38"), "w"), Contains("overflows"));
  CHECK(readNumber<double>(json("3.5e38"), "w") == 3.5e38);
  // The same through a JSON double.
  CHECK_THROWS_WITH(readNumber<float>(json(3.5e38), "w"), StartsWith("w: 3.5e+38 is outside the range of float"));
  CHECK(readNumber<float>(json(3.4028234e38), "w") == std::numeric_limits<float>::max());
  // FLT_MIN = 1.17549435e-38, the smallest normal float: held; just below it a float is subnormal
  // (fewer than 24 bits): refused, as is 1e-50, which underflows to 0 (`--scalar float` of issue 24).
  CHECK(readNumber<float>(json("1.17549435e-38"), "w") == std::numeric_limits<float>::min());
  CHECK(readNumber<float>(json(1.17549435e-38), "w") == std::numeric_limits<float>::min());
  CHECK_THROWS_WITH(readNumber<float>(json("1.1e-38"), "w"),
                    StartsWith("w: \"1.1e-38\" is too small for float (a subnormal float keeps 23 of its 24 bits; "
                               "float holds 0 and magnitudes from 1.17549435e-38"));
  CHECK_THROWS_WITH(readNumber<float>(json("1e-45"), "w"), Contains("a subnormal float keeps 1 of its 24 bits"));
  CHECK_THROWS_WITH(readNumber<float>(json(1e-40), "w"), StartsWith("w: 1e-40 is too small for float (a subnormal"));
  CHECK_THROWS_WITH(readNumber<float>(json("1e-50"), "w"), Contains("\"1e-50\" is too small for float (a non-zero value that underflows to 0"));
  CHECK_THROWS_WITH(readNumber<float>(json(1e-50), "w"), Contains("1e-50 is too small for float (a non-zero value that underflows to 0"));
  CHECK(readNumber<double>(json("1e-50"), "w") == 1e-50);
}

TEST_CASE("readNumber: the range thresholds of double, long double, float128 and mpfr", "[io][number]") {
  // double: DBL_MAX = 1.797693e308, smallest normal 2.2250738585072014e-308; "1e-320" is a subnormal
  // double (11 of 53 bits): refused in double, held by the wider scalars (issue 24).
  CHECK(readNumber<double>(json("1.7976931348623157e308"), "w") == std::numeric_limits<double>::max());
  CHECK_THROWS_WITH(readNumber<double>(json("1.8e308"), "w"), Contains("outside the range of double"));
  CHECK(readNumber<double>(json("2.2250738585072014e-308"), "w") == std::numeric_limits<double>::min());
  CHECK_THROWS_WITH(readNumber<double>(json("2.2e-308"), "w"), Contains("a subnormal double keeps 52 of its 53 bits"));
  CHECK_THROWS_WITH(readNumber<double>(json("1e-320"), "w"),
                    "w: \"1e-320\" is too small for double (a subnormal double keeps 11 of its 53 bits; double holds 0 "
                    "and magnitudes from 2.2250738585072014e-308 (its smallest normal number) to 1.7976931348623157e+308)");
  CHECK_THROWS_WITH(readNumber<double>(json("2e-324"), "w"), Contains("underflows to 0"));
  CHECK(readNumber<long double>(json("1e-320"), "w") == fromString<long double>("1e-320"));
  CHECK(readNumber<__float128>(json("1e-320"), "w") == fromString<__float128>("1e-320"));
  CHECK(readNumber<mpreal>(json("1e-320"), "w") == mpreal("1e-320"));
  // long double (x87, 64-bit significand) and float128 both reach 1.18973e4932; their smallest
  // normal number is 3.3621e-4932.
  CHECK(readNumber<long double>(json("1e400"), "w") == fromString<long double>("1e400"));
  CHECK(readNumber<long double>(json("1.18973e4932"), "w") > 0);
  CHECK_THROWS_WITH(readNumber<long double>(json("1.2e4932"), "w"), Contains("outside the range of long-double"));
  CHECK(readNumber<__float128>(json("1.18973e4932"), "w") > 0);
  CHECK_THROWS_WITH(readNumber<__float128>(json("1.2e4932"), "w"), Contains("outside the range of float128"));
  CHECK(readNumber<long double>(json("3.3622e-4932"), "w") > 0);
  CHECK_THROWS_WITH(readNumber<long double>(json("3.36e-4932"), "w"), Contains("a subnormal long-double keeps 63 of its 64 bits"));
  CHECK(readNumber<__float128>(json("3.3622e-4932"), "w") > 0);
  CHECK_THROWS_WITH(readNumber<__float128>(json("3.36e-4932"), "w"), Contains("a subnormal float128 keeps 112 of its 113 bits"));
  CHECK_THROWS_WITH(readNumber<__float128>(json("3e-4966"), "w"), Contains("too small for float128 (a non-zero value that underflows to 0"));
  // mpfr has no subnormals: it holds 1e400 and 1e-400 (at every precision), and its exponent
  // range is 2^(emin−1) … 2^emax (the message says it); double does not.
  CHECK(readNumber<mpreal>(json("1e400"), "w") == mpreal("1e400"));
  CHECK(readNumber<mpreal>(json("1e-400"), "w") == mpreal("1e-400"));
  CHECK(holdsText<mpreal>() == "mpfr holds 0 and magnitudes from 2^" + std::to_string(mpfr_get_emin() - 1) + " to below 2^" +
                                   std::to_string(mpfr_get_emax()) + " (about 1e-323228497 to 1e323228496)");
  CHECK_THROWS_WITH(readNumber<double>(json("1e400"), "w"), StartsWith("w: \"1e400\" is outside the range of double (it overflows to infinity"));
  CHECK_THROWS_WITH(readNumber<double>(json("1e-400"), "w"), Contains("too small for double"));
}

TEST_CASE("parseInteger and readInteger: decided on the text, within the caller's bounds", "[io][number]") {
  CHECK(parseInteger("16", "--bits", 16, 8192) == 16);
  CHECK(parseInteger("+8192", "--bits", 16, 8192) == 8192);
  CHECK(parseInteger("1e3", "--samples", 1, 1000) == 1000);
  CHECK(parseInteger("2.0", "n", 0, 9) == 2);
  CHECK(parseInteger("0.50e1", "n", 0, 9) == 5);
  CHECK(parseInteger("010", "n", 0, 99) == 10);  // decimal, not octal
  CHECK(parseInteger("-0", "n", 0, 9) == 0);
  CHECK(parseInteger("-9223372036854775808", "n", std::numeric_limits<long long>::min(), 0) ==
        std::numeric_limits<long long>::min());
  CHECK(parseInteger("9223372036854775807", "n", 0, std::numeric_limits<long long>::max()) ==
        std::numeric_limits<long long>::max());
  // Both sides of each bound.
  CHECK_THROWS_WITH(parseInteger("15", "--bits", 16, 8192), "--bits: \"15\" is outside 16 … 8192");
  CHECK_THROWS_WITH(parseInteger("8193", "--bits", 16, 8192), "--bits: \"8193\" is outside 16 … 8192");
  CHECK_THROWS_WITH(parseInteger("9223372036854775808", "n", 0, std::numeric_limits<long long>::max()), Contains("is outside"));
  CHECK_THROWS_WITH(parseInteger("1e999999999999", "n", 0, 9), Contains("is outside"));
  // What is not an integer, or not a decimal number: never rounded, never read in another base.
  CHECK_THROWS_WITH(parseInteger("2.5", "n", 0, 9), "n: \"2.5\" is not an integer");
  CHECK_THROWS_WITH(parseInteger("1.0000000000000000000001", "n", 0, 9), Contains("is not an integer"));
  CHECK_THROWS_WITH(parseInteger("1e-999999999999", "n", 0, 9), Contains("is not an integer"));
  CHECK_THROWS_WITH(parseInteger("0x10", "--grid", 8, 4096), "--grid: \"0x10\" is not a decimal number (hexadecimal)");
  CHECK_THROWS_WITH(parseInteger("", "n", 0, 9), Contains("(empty)"));
  CHECK_THROWS_WITH(parseInteger("1,", "n", 0, 9), Contains("is not a decimal number"));
  // JSON: an integer, an integral double or a decimal string; 4294967297 is not 1 (issue 24: "mode").
  CHECK(readInteger(json(-1), "mode", -1, 1) == -1);
  CHECK(readInteger(json(1.0), "mode", -1, 1) == 1);
  CHECK(readInteger(json("1"), "mode", -1, 1) == 1);
  CHECK_THROWS_WITH(readInteger(json(4294967297LL), "mode", -1, 1), "mode: \"4294967297\" is outside -1 … 1");
  CHECK_THROWS_WITH(readInteger(json(std::numeric_limits<std::uint64_t>::max()), "mode", -1, 1), Contains("is outside"));
  CHECK_THROWS_WITH(readInteger(json(1.5), "mode", -1, 1), "mode: 1.5 is not an integer");
  CHECK_THROWS_WITH(readInteger(json(1e300), "mode", -1, 1), Contains("is outside"));
  CHECK_THROWS_WITH(readInteger(json(true), "mode", -1, 1), "mode: expected an integer, got boolean");
}

TEST_CASE("parseJson: a JSON number beyond a double is named with its key path", "[io][number]") {
  CHECK_THROWS_WITH(parseJson(R"({"joints": [{"a": 1}, {"a": 1, "alpha": 1e400}]})", "robot.json"),
                    Contains("robot.json: joints[1].alpha: 1e400 is outside the range of a JSON number") &&
                        Contains("decimal string \"1e400\""));
  CHECK_THROWS_WITH(parseJson(R"({"leg_lengths": [1, 2, -1e-400]})", "p.json"),
                    Contains("p.json: leg_lengths[2]: -1e-400 is too small for a JSON number (a double: it underflows to 0)"));
  CHECK_THROWS_WITH(parseJson(R"([[0, 1], [2, 1E999]])", "x.json"), Contains("x.json: [1][1]: 1E999 is outside the range"));
  // A subnormal JSON number keeps fewer than 53 bits: refused (the decimal string is exact where it fits).
  CHECK_THROWS_WITH(parseJson(R"({"a": [1e-320]})", "t.json"),
                    "t.json: a[0]: 1e-320 is too small for a JSON number (a double holds magnitudes from "
                    "2.2250738585072014e-308, its smallest normal number); write it as the decimal string \"1e-320\" "
                    "for a scalar that holds it");
  CHECK(parseJson(R"({"a": 2.2250738585072014e-308})", "t.json")["a"].get<double>() == std::numeric_limits<double>::min());
  // Zero is zero, and a syntax error stays a syntax error.
  CHECK(parseJson(R"({"a": 0e-999, "b": [0.0]})", "z.json")["a"].get<double>() == 0);
  CHECK_THROWS_WITH(parseJson("{\"a\": }", "s.json"), Contains("s.json: not valid JSON ([json.exception.parse_error"));
  CHECK_THROWS_WITH(parseJson("{\"a\": 0x10}", "s.json"), Contains("s.json: not valid JSON"));
}

TEST_CASE("parseJson: a key given twice is an error naming its key path", "[io]") {
  CHECK_THROWS_WITH(parseJson(R"({"joints": [{"a": 1, "alpha": 0, "a": 7}]})", "robot.json"),
                    "robot.json: joints[0].a: the key \"a\" is given twice in one object");
  CHECK_THROWS_WITH(parseJson(R"({"name": "x", "name": "y"})", "r.json"), "r.json: name: the key \"name\" is given twice in one object");
  // The same key in two objects is two keys.
  CHECK(parseJson(R"([{"a": 1}, {"a": 2}])", "r.json")[1]["a"] == 2);
}

TEST_CASE("parseJson: nesting is refused beyond limits::maxDepth, before a recursive reader sees it", "[io]") {
  const std::size_t n = limits::maxDepth;
  // n levels are read; n + 1 are refused, naming where the nesting starts.
  const json ok = parseJson(std::string(n, '[') + std::string(n, ']'), "d.json");
  CHECK(ok.is_array());
  CHECK_THROWS_WITH(parseJson(std::string(n + 1, '[') + std::string(n + 1, ']'), "d.json"),
                    "d.json: [0][0][0][0]…: arrays and objects nested deeper than 64 levels (the most soma reads)");
  // 10^5 levels (issue 24: a recursive dump() crashed on it): refused the same way.
  std::string deep = R"({"base": )";
  for (int k = 0; k < 100000; ++k) deep += R"({"a":)";
  CHECK_THROWS_WITH(parseJson(deep, "r.json"), StartsWith("r.json: base.a.a.a…: arrays and objects nested deeper than 64"));
}

TEST_CASE("readTextFile: bounded reads — a directory or an endless file is refused", "[io]") {
  CHECK_THROWS_WITH(readTextFile("/dev/zero", "robot"),
                    "/dev/zero: the robot file is larger than 16 MiB, the largest input soma reads");
  CHECK_THROWS_WITH(readTextFile("/", "robot"), "/: is a directory, not a robot file");
  CHECK(readTextFile("/dev/null", "robot").empty());
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
