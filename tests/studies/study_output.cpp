// Study output in the working precision (issue 22): the numbers of a check (expected, got, error,
// tolerance) and of a speed/accuracy table are written with the digits of the scalar the study ran
// in, and read back exactly by io::readJsonNumber; `runs_in` says what --scalar does.
#include "soma/studies/report.hpp"
#include "soma/studies/runner.hpp"

#include "soma/algebra/float128.hpp"
#include "soma/algebra/tolerance.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::studies;

namespace {

/// The values the check records, in S: 1/3, 1/3 + 5ε/3 (error not a short decimal), tolerance 1/7.
template <class S> struct Values {
  S expected = S(1) / S(3);
  S got = expected + S(5) * Tolerance<S>::epsilon() / S(3);
  S error = got - expected;  // > 0
  S tolerance = S(1) / S(7);
};

template <class S> void roundTrip(ScalarKind kind) {
  Study st;
  st.id = "T-1";
  st.title = "t";
  st.source = "GF §0";
  st.chapter = "GF 0";
  st.scalarGeneric = true;
  st.run = [](Context& c) {
    withScalar(c.scalar(), [&]<class T>() {
      const Values<T> v;
      c.checkNear<T>("near", v.expected, v.got, v.tolerance);
      c.checkResidual<T>("residual", v.error, v.tolerance);
    });
  };
  const StudyResult r = runStudy(st, kind, {}, false);
  REQUIRE(r.passed());
  REQUIRE(r.scalar == kind);
  const auto j = nlohmann::json::parse(studyJson(r));
  CHECK(j["scalar"] == std::string(scalarName<S>()));
  CHECK(j["runs_in"] == "--scalar");
  if constexpr (std::is_same_v<S, mpreal>) CHECK(j["bits"] == mpfrBits());
  const Values<S> v;
  const auto& near = j["checks"][0];
  // Exactly the values S computed, through text and back.
  CHECK(io::readJsonNumber<S>(near["expected"], "expected") == v.expected);
  CHECK(io::readJsonNumber<S>(near["got"], "got") == v.got);
  CHECK(io::readJsonNumber<S>(near["error_text"], "error_text") == v.error);
  CHECK(io::readJsonNumber<S>(near["tolerance_text"], "tolerance_text") == v.tolerance);
  CHECK(io::readJsonNumber<S>(j["checks"][1]["got"], "residual") == v.error);
  // The doubles are kept beside them (for plots): the value rounded to double.
  CHECK(near["error"].get<double>() == toDouble(v.error));
  // The terminal shows the same digits (the error line under the row).
  const std::string text = formatStudyText(r);
  CHECK(text.find(near["error_text"].get<std::string>()) != std::string::npos);
  CHECK(text.find(near["got"].get<std::string>()) != std::string::npos);
}

}  // namespace

TEST_CASE("study checks are written in the working scalar's digits and read back exactly", "[report][precision]") {
  roundTrip<float>(ScalarKind::Float);
  roundTrip<double>(ScalarKind::Double);
  roundTrip<long double>(ScalarKind::LongDouble);
  roundTrip<__float128>(ScalarKind::Float128);
  const int old = mpfrBits();
  setMpfrBits(256);
  roundTrip<mpreal>(ScalarKind::Mpfr);
  // 256 bits: ⌊256 log10 2⌋ + 2 = 79 significant digits of 1/3 (issue 22: "~77 digits").
  Study st;
  st.id = "T-2";
  st.scalarGeneric = true;
  st.run = [](Context& c) { c.checkNear<mpreal>("third", mpreal(1) / 3, mpreal(1) / 3, mpreal(0)); };
  const auto j = nlohmann::json::parse(studyJson(runStudy(st, ScalarKind::Mpfr, {}, false)));
  const std::string got = j["checks"][0]["got"];
  std::string mantissa = got.substr(0, got.find_first_of("eE"));
  mantissa.erase(std::remove(mantissa.begin(), mantissa.end(), '.'), mantissa.end());
  mantissa.erase(0, mantissa.find_first_not_of('0'));
  CHECK(mantissa.size() == 79);
  CHECK(mantissa.substr(0, 77) == std::string(77, '3'));  // 256 bits hold 77 decimal digits of 1/3
  setMpfrBits(old);
}

TEST_CASE("a study that is not scalar-generic says why — a ladder study says it runs every rung", "[report][precision]") {
  Study d;
  d.id = "T-3";
  d.whyDouble = "OMPL is double only";
  d.run = [](Context& c) { c.checkEqual("n", 1, 1); };
  CHECK(runsInText(d) == "double: OMPL is double only");
  Study e = d;
  e.whyDouble.clear();
  CHECK(runsInText(e) == std::string("double: ") + kWhyDouble);
  const StudyResult r = runStudy(d, ScalarKind::Float128, {}, false);
  CHECK(r.scalar == ScalarKind::Double);
  CHECK(ranInText(r) == "double (runs in double: OMPL is double only)");
  Study l = d;
  l.ladder = true;
  CHECK(l.runsIn() == RunsIn::Ladder);
  CHECK(runsInText(l).rfind("every rung", 0) == 0);
  const auto list = nlohmann::json::parse(studyListJson({&d, &l}));
  CHECK(list[0]["runs_in"] == "double: OMPL is double only");
  CHECK(list[0]["scalar_generic"] == false);
  CHECK(list[1]["runs_in"].get<std::string>().rfind("every rung", 0) == 0);
}

TEST_CASE("a speed/accuracy table is carried to report.json and the terminal, escalations said", "[report][precision]") {
  Study st;
  st.id = "T-4";
  st.ladder = true;
  st.run = [](Context& c) {
    TradeTable t;
    t.solver = "solver X";
    t.sample = "pose";
    t.errorLabel = "worst residual";
    const __float128 w = __float128(1) / 3 * Tolerance<__float128>::epsilon();
    t.rungs.push_back({"float", 200, 1e-5, 2e-5, 1e-6, "1e-06", 166, "double", ""});
    t.rungs.push_back({"float128", 40, 1e-3, 2e-3, toDouble(w), io::numberText(w), 0, "", ""});
    c.trade(t);
    c.checkEqual("n", 1, 1);
  };
  const StudyResult r = runStudy(st, ScalarKind::Double, {}, false);
  REQUIRE(r.trades.size() == 1);
  const auto j = nlohmann::json::parse(studyJson(r));
  const auto& rungs = j["trade"][0]["rungs"];
  CHECK(rungs[0]["escalated"] == 166);
  CHECK(rungs[0]["escalated_to"] == "double");
  CHECK(rungs[1]["escalated_to"].is_null());
  CHECK(io::readJsonNumber<__float128>(rungs[1]["worst_error_text"], "w") ==
        __float128(1) / 3 * Tolerance<__float128>::epsilon());
  const std::string text = formatStudyText(r);
  CHECK(text.find("166 of 200 (to double)") != std::string::npos);
  CHECK(text.find(rungs[1]["worst_error_text"].get<std::string>()) != std::string::npos);
  const std::string html = speedAccuracySectionHtml({r});
  CHECK(html.find("Speed vs accuracy") != std::string::npos);
  // Not a section.chapter: the page's filter script hides every chapter without a study in it.
  CHECK(html.find("<section class=\"extra\" id=\"speed-vs-accuracy\">") != std::string::npos);
  CHECK(html.find("166 of 200 (to double)") != std::string::npos);
  CHECK(speedAccuracySectionHtml({}).empty());
}

}  // namespace SOMA_UNITY_ID
