// The study machinery: glob selection, natural order, checks, failure propagation, report text.
#include "soma/studies/report.hpp"
#include "soma/studies/runner.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::studies;

namespace {
Study makeStudy(std::string id, std::function<void(Context&)> run) {
  Study s;
  s.id = std::move(id);
  s.title = "t";
  s.source = "GF §0";
  s.chapter = "GF 0";
  s.run = std::move(run);
  return s;
}
std::vector<Study> sampleRegistry() {
  std::vector<Study> r;
  auto pass = [](Context& c) { c.checkEqual("count", 16, 16); };
  for (const char* id : {"GF-10.1-a", "GF-2.1-b", "GF-2.10-c", "GF-2.2-d", "SB-4-e"})
    r.push_back(makeStudy(id, pass));
  return r;
}
}  // namespace

TEST_CASE("globMatch: *, ?, classes, escapes", "[runner]") {
  CHECK(globMatch("GF-4.*", "GF-4.4.1-rodrigues"));
  CHECK_FALSE(globMatch("GF-4.*", "GF-14.1-x"));
  CHECK(globMatch("*rodrigues", "GF-4.4.1-rodrigues"));
  CHECK(globMatch("GF-?.1-*", "GF-2.1-U1"));
  CHECK_FALSE(globMatch("GF-?.1-*", "GF-12.1-U1"));
  CHECK(globMatch("GF-[24].*", "GF-4.1-x"));
  CHECK_FALSE(globMatch("GF-[!24].*", "GF-4.1-x"));
  CHECK(globMatch("GF-[0-9].*", "GF-7.1"));
  CHECK(globMatch("a\\*b", "a*b"));
  CHECK_FALSE(globMatch("a\\*b", "axb"));
  CHECK(globMatch("*", ""));
  CHECK_FALSE(globMatch("?", ""));
  CHECK(isGlob("GF-*"));
  CHECK_FALSE(isGlob("GF-4.4.1-rodrigues"));
}

TEST_CASE("naturalLess orders chapter numbers as numbers", "[runner]") {
  CHECK(naturalLess("GF-2.1-x", "GF-10.1-x"));
  CHECK(naturalLess("GF-2.2-x", "GF-2.10-x"));
  CHECK_FALSE(naturalLess("GF-10.1-x", "GF-2.1-x"));
  CHECK(naturalLess("GF 9 — a", "GF 10 — a"));
  CHECK_FALSE(naturalLess("a", "a"));
}

TEST_CASE("selectStudies: exact IDs, globs, natural order, clear errors", "[runner]") {
  const auto reg = sampleRegistry();
  const auto all = selectStudies({}, reg);
  REQUIRE(all.size() == 5);
  CHECK(all[0]->id == "GF-2.1-b");
  CHECK(all[1]->id == "GF-2.2-d");
  CHECK(all[2]->id == "GF-2.10-c");
  CHECK(all[3]->id == "GF-10.1-a");
  const auto two = selectStudies({"GF-2.*"}, reg);
  CHECK(two.size() == 3);
  // A study named twice is run once.
  CHECK(selectStudies({"GF-2.1-b", "GF-2.1-*"}, reg).size() == 1);
  CHECK_THROWS_WITH(selectStudies({"gf-2.1-b"}, reg), Catch::Contains("did you mean 'GF-2.1-b'"));
  CHECK_THROWS_WITH(selectStudies({"GF-2.1"}, reg), Catch::Contains("did you mean 'GF-2.1*'"));
  CHECK_THROWS_AS(selectStudies({"XX-*"}, reg), SelectionError);
}

TEST_CASE("a study fails when a check fails, throws, or checks nothing", "[runner]") {
  const Study good = makeStudy("ok", [](Context& c) {
    c.checkNear("near", 1.0, 1.0 + 1e-17, 1e-15);
    c.checkResidual("residual", 0.0, 1e-15);
  });
  const Study bad = makeStudy("bad", [](Context& c) {
    c.checkNear("near", 1.0, 1.1, 1e-3);
    c.checkEqual("count", 40, 40);
  });
  const Study nan = makeStudy("nan", [](Context& c) {
    c.checkResidual("residual", std::numeric_limits<double>::quiet_NaN(), 1.0);
  });
  // A residual is a norm: a negative one is a signed value passed by mistake, and fails.
  const Study negative = makeStudy("negative", [](Context& c) { c.checkResidual("residual", -1e-300, 1.0); });
  const Study throws = makeStudy("throws", [](Context&) { throw std::runtime_error("boom"); });
  const Study empty = makeStudy("empty", [](Context&) {});
  const auto dir = std::filesystem::temp_directory_path() / "soma-test-runner";
  const auto rGood = runStudy(good, ScalarKind::Double, dir, false);
  CHECK(rGood.passed());
  REQUIRE(rGood.checks.size() == 2);
  CHECK(rGood.checks[0].error == Approx(1e-17).margin(2e-16));
  const auto rBad = runStudy(bad, ScalarKind::Double, dir, false);
  CHECK_FALSE(rBad.passed());
  CHECK_FALSE(rBad.checks[0].passed);
  CHECK(rBad.checks[1].passed);
  CHECK_FALSE(runStudy(nan, ScalarKind::Double, dir, false).passed());  // NaN never passes
  CHECK_FALSE(runStudy(negative, ScalarKind::Double, dir, false).passed());
  const auto rThrows = runStudy(throws, ScalarKind::Double, dir, false);
  CHECK_FALSE(rThrows.passed());
  CHECK(rThrows.error == "boom");
  const auto rEmpty = runStudy(empty, ScalarKind::Double, dir, false);
  CHECK_FALSE(rEmpty.passed());
  CHECK_THAT(rEmpty.error, Catch::Contains("no check"));

  const auto sum = summarize({rGood, rBad, rThrows});
  CHECK(sum.studiesPassed == 1);
  CHECK(sum.studiesFailed == 2);
  CHECK(sum.checksFailed == 1);
  CHECK_FALSE(sum.allPassed());
}

TEST_CASE("a study that is not scalar-generic runs in double", "[runner]") {
  Study s = makeStudy("fixed", [](Context& c) { c.checkEqual("scalar", "double", std::string(scalarName(c.scalar()))); });
  const auto dir = std::filesystem::temp_directory_path() / "soma-test-runner";
  CHECK(runStudy(s, ScalarKind::Float128, dir, false).passed());
  s.scalarGeneric = true;
  CHECK_FALSE(runStudy(s, ScalarKind::Float128, dir, false).passed());
}

TEST_CASE("report.json carries every check and null for non-finite numbers", "[report]") {
  const Study s = makeStudy("GF-0-json", [](Context& c) {
    c.record("inf tolerance", "x", "y", 0.5, std::numeric_limits<double>::infinity(), true);
    c.checkNear("near", 2.0, 2.0, 0.0);
    c.note("a note <b>");
    c.figure("f.png", "caption & more");
  });
  const auto r = runStudy(s, ScalarKind::Double, std::filesystem::temp_directory_path(), false);
  ReportInfo info = collectReportInfo(ScalarKind::Double, "soma report", 1.5, false);
  const auto j = nlohmann::json::parse(reportJson(info, {r}));
  CHECK(j["summary"]["studies"] == 1);
  CHECK(j["summary"]["checks"] == 2);
  CHECK(j["summary"]["checks_failed"] == 0);
  const auto& st = j["studies"][0];
  CHECK(st["id"] == "GF-0-json");
  CHECK(st["checks"][0]["tolerance"].is_null());
  CHECK(st["checks"][1]["passed"] == true);
  CHECK(st["figures"][0]["file"] == "figures/f.png");
  CHECK(st["notes"][0] == "a note <b>");
  const std::string html = reportHtml(info, {r});
  CHECK_THAT(html, Catch::Contains("a note &lt;b&gt;"));
  CHECK_THAT(html, Catch::Contains("caption &amp; more"));
  CHECK_THAT(html, Catch::Contains("GF-0-json"));
}

TEST_CASE("text helpers", "[report]") {
  CHECK(htmlEscape("<a href=\"x\">&'") == "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
  CHECK(htmlEscape("\xff") == "\xEF\xBF\xBD");  // invalid UTF-8 becomes U+FFFD
  CHECK(formatSeconds(0.00123) == "1.23 ms");
  CHECK(formatSeconds(2.5e-7) == "250 ns");
  CHECK(formatSeconds(125) == "2 min 5 s");
  CHECK(formatShort(std::nan("")) == "nan");
  CHECK(displayWidth("θ − π") == 5);
}

}  // namespace SOMA_UNITY_ID
