// The report page (issue 25): the errata index against papers/ itself, the links to each study's
// source line and papers/ row, markdown tables in notes, the search and figure hooks of the page.
#include "soma/studies/report.hpp"
#include "soma/studies/runner.hpp"
#include "soma/studies/source_index.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <set>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::studies;

namespace {

std::vector<std::string> registeredIds() {
  std::vector<std::string> ids;
  for (const auto& s : registry()) ids.push_back(s.id);
  return ids;
}

std::vector<std::string> fileLines(const std::filesystem::path& p) {
  std::ifstream f(p);
  std::vector<std::string> lines;
  for (std::string l; std::getline(f, l);) lines.push_back(l);
  return lines;
}

const Erratum* findErratum(const SourceIndex& index, const std::string& label) {
  for (const auto& e : index.errata)
    if (e.label == label) return &e;
  return nullptr;
}

bool names(const Erratum* e, const std::string& id) {
  return e && std::find(e->studies.begin(), e->studies.end(), id) != e->studies.end();
}

}  // namespace

TEST_CASE("the errata index lists every erratum label papers/ writes", "[report][errata]") {
  const auto root = sourceRoot();
  const SourceIndex index = indexSources(root, registeredIds());
  // An independent reading of papers/: every "E<a>.<b>" a regular expression finds.
  const std::regex label(R"((^|[^A-Za-z0-9-])(E[0-9]+\.[0-9]+)(?![0-9A-Za-z]|\.[0-9]))");
  std::set<std::string> labels;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root / "papers")) {
    if (entry.path().extension() != ".md") continue;
    for (const auto& l : fileLines(entry.path()))
      for (std::sregex_iterator it(l.begin(), l.end(), label), end; it != end; ++it) labels.insert((*it)[2]);
  }
  REQUIRE(labels.size() > 90);  // 99 on 2026-12-02
  for (const auto& l : labels) {
    INFO(l);
    CHECK(findErratum(index, l) != nullptr);
  }
  // The numbered lists (GF ch. 13, 14: "**8** (8206, 8210): …") and SB's erratum column.
  CHECK(names(findErratum(index, "E13.8"), "GF-13.4.3-small-oscillations"));
  CHECK(names(findErratum(index, "E14.2"), "GF-14.1.3-tree-recursive-dynamics"));
  CHECK(names(findErratum(index, "SB-E3"), "SB-3-rigid-motion-element-study-conditions"));
  // A table row of an errata section: its study and its "what the book prints" cell.
  const Erratum* e45 = findErratum(index, "E4.5");
  REQUIRE(e45);
  CHECK(names(e45, "GF-4.4.1-so3-log-polynomial"));
  CHECK(e45->place.file == "papers/selig-2005/ch04.md");
  CHECK_THAT(e45->text, Catch::Contains("what the book prints: Lagrange denominator"));
  // Every entry's place is a line of its file that names the label (or its number).
  for (const auto& e : index.errata) {
    INFO(e.label << " at " << e.place.file << ":" << e.place.line);
    const auto lines = fileLines(root / e.place.file);
    REQUIRE(e.place.line >= 1);
    REQUIRE(e.place.line <= static_cast<int>(lines.size()));
    const std::string number = e.label.substr(e.label.find_last_of(".E") + 1);
    CHECK(lines[e.place.line - 1].find(number) != std::string::npos);
  }
}

TEST_CASE("each study links to its source line and its papers/ row", "[report][errata]") {
  const auto root = sourceRoot();
  const SourceIndex index = indexSources(root, registeredIds());
  REQUIRE(index.code.size() == registry().size());
  for (const auto& [id, place] : index.code) {
    INFO(id << " at " << place.file << ":" << place.line);
    const auto lines = fileLines(root / place.file);
    REQUIRE(place.line <= static_cast<int>(lines.size()));
    CHECK(lines[place.line - 1].find("\"" + id + "\"") != std::string::npos);
  }
  const auto row = index.papers.find("GF-4.1-hat-map");
  REQUIRE(row != index.papers.end());
  CHECK(row->second.file == "papers/selig-2005/ch04.md");
  CHECK(fileLines(root / row->second.file)[row->second.line - 1].rfind("| GF-4.1-hat-map |", 0) == 0);
}

TEST_CASE("markdown tables in notes become HTML tables", "[report]") {
  const std::string html = markdownHtml("Timings:\n| method | seconds |\n|---|---:|\n| `a<b` | 1.2 |\n| **b** | 3\\|4 |\nend");
  CHECK_THAT(html, Catch::Contains("<table class=\"md\"><thead><tr><th>method</th><th>seconds</th></tr></thead>"));
  CHECK_THAT(html, Catch::Contains("<tr><td><code>a&lt;b</code></td><td>1.2</td></tr>"));
  CHECK_THAT(html, Catch::Contains("<tr><td><b>b</b></td><td>3|4</td></tr>"));
  CHECK_THAT(html, Catch::Contains("<span>Timings:</span>"));
  CHECK_THAT(html, Catch::Contains("<span>end</span>"));
  CHECK(markdownHtml("a | b") == "<span>a | b</span>");  // a pipe alone is text
}

TEST_CASE("the page carries the search, filter and figure hooks", "[report]") {
  Study s;
  s.id = "GF-4.4.3-adjoint-log";
  s.title = "the adjoint log";
  s.source = "GF §4.4.3";
  s.chapter = "GF 4 — Lie algebra";
  s.run = [](Context& c) {
    c.checkPrintedFails("prefactor 1/(8 sin³θ)", "E4.8", 0.5, 1e-9);
    c.figure("f.png", "a figure");
  };
  const auto r = runStudy(s, ScalarKind::Double, std::filesystem::temp_directory_path(), false);
  const ReportInfo info = collectReportInfo(ScalarKind::Double, "soma report", 1.0, true);
  const std::string html = reportHtml(info, {r}, {}, {{"speed-accuracy", "Speed vs accuracy", "<p>x</p>"}});
  CHECK_THAT(html, Catch::Contains("data-id=\"GF-4.4.3-adjoint-log\""));
  CHECK_THAT(html, Catch::Contains("data-errata=\"E4.8\""));
  CHECK_THAT(html, Catch::Contains("data-verdict=\"pass\""));
  CHECK_THAT(html, Catch::Contains("<input type=\"search\" id=\"f-q\""));
  CHECK_THAT(html, Catch::Contains("<script src=\"lunr.min.js\"></script>"));
  CHECK_THAT(html, Catch::Contains("<a class=\"fig\" href=\"figures/f.png\""));
  CHECK_THAT(html, Catch::Contains("<section class=\"extra\" id=\"speed-accuracy\">"));
  CHECK_THAT(html, Catch::Contains("<a href=\"#speed-accuracy\">Speed vs accuracy</a>"));
  // The errata index row of E4.8 shows this run's check and links the study.
  const auto row = html.find("<tr data-erratum=\"E4.8\">");
  REQUIRE(row != std::string::npos);
  const std::string rowHtml = html.substr(row, html.find("</tr>", row) - row);
  CHECK_THAT(rowHtml, Catch::Contains("prefactor 1/(8 sin³θ) [as printed]: residual 0.5"));
  CHECK_THAT(rowHtml, Catch::Contains("href=\"#study-GF-4.4.3-adjoint-log\""));
  CHECK_THAT(rowHtml, Catch::Contains("GF §4.4.3"));
}

}  // namespace SOMA_UNITY_ID
