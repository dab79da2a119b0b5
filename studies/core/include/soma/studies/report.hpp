#pragma once
// The three renderings of study results (DESIGN §4, §6): an aligned text table for the terminal
// (`soma study run`), report.json and a self-contained report folder (`soma report`).
#include "soma/studies/runner.hpp"
#include "soma/studies/study.hpp"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace soma::studies {

/// soma's version ("0.1.0"); from the SOMA_VERSION compile definition when given.
std::string_view somaVersion();

/// What the report says about the run itself.
struct ReportInfo {
  std::string version;   ///< soma version
  std::string scalar;    ///< requested scalar name ("double", "mpfr")
  int mpfrBits = 0;      ///< precision when scalar is mpfr, else 0
  std::string date;      ///< local time, ISO 8601 ("2025-03-01T14:05:09+0100")
  std::string machine;   ///< "hostname — Linux 6.1 x86_64 — CPU model (N threads)"
  std::string compiler;  ///< "GCC 12.2.0", build type
  std::string gitCommit; ///< `git describe --always --dirty` of the source tree, or "" if unknown
  std::string command;   ///< the command line that produced the report
  double seconds = 0;    ///< wall time of the whole run
  bool figures = true;   ///< figures were requested
};

/// Fill version, date, machine, compiler and git commit for the current process.
ReportInfo collectReportInfo(ScalarKind scalar, std::string command, double seconds,
                             bool figures);

/// Escape &, <, >, " and ' for HTML text and attribute values; invalid UTF-8 becomes U+FFFD.
std::string htmlEscape(std::string_view text);
/// The HTML id of a study's article in index.html: "study-" and its catalogue ID with anything
/// outside [A-Za-z0-9._-] replaced by "_" (the report's links and its sections' links).
std::string studyAnchor(std::string_view id);

/// One study result as a JSON object (the element of report.json's "studies"), indented text.
std::string studyJson(const StudyResult& r, int indent = 2);
/// report.json: {soma_version, scalar, mpfr_bits, date, machine, compiler, git_commit, command,
/// seconds, summary:{studies, studies_passed, studies_failed, checks, checks_passed,
/// checks_failed}, studies:[{id,title,source,chapter,passed,seconds,scalar,error,
/// runs_in,bits (mpfr and speed/accuracy studies), checks:[{name,expected,got,error,tolerance,
/// error_text,tolerance_text,seconds,passed}], figures:[{file,caption}],notes,trade:[{solver,sample,
/// error_label,figure,rungs:[{scalar,samples,median_seconds,p95_seconds,worst_error,
/// worst_error_text,escalated,escalated_to,comment}]}]}]}. error/tolerance are doubles (null when
/// not finite); error_text/tolerance_text, and expected/got of a numeric check, are the values in
/// the scalar's digits (io::numberText), read back exactly by io::readJsonNumber in that scalar.
std::string reportJson(const ReportInfo& info, const std::vector<StudyResult>& results);

/// A section of index.html that a caller adds (e.g. "Speed vs accuracy"): placed after the summary,
/// before the errata index, and listed at the top of the contents. `id` is its HTML anchor;
/// `html` is trusted markup (build it with htmlEscape and markdownHtml).
struct ReportSection {
  std::string id;
  std::string title;
  std::string html;
};

/// What the study ran in, for its header: "double", "mpfr (256 bits)", "double (runs in double:
/// <why>)", "every rung (…, mpfr 256 bits)".
std::string ranInText(const StudyResult& r);

/// The report's "speed vs accuracy" section (speed_accuracy_section.cpp): every study's trade
/// tables (Context::trade) with their figures; empty when no study recorded one.
std::string speedAccuracySectionHtml(const std::vector<StudyResult>& results);

/// index.html: one page (inline CSS and script; lunr.min.js beside it) with a sidebar (search,
/// filters by chapter, verdict, erratum and scalar; the contents by chapter), the summary, the
/// caller's sections, the errata index of papers/, and per chapter its summary and studies (links to
/// each study's source line and papers/ row; figures open full size). `reportDir` is used only to
/// mark figures whose file is missing and to link an SVG beside a PNG.
std::string reportHtml(const ReportInfo& info, const std::vector<StudyResult>& results,
                       const std::filesystem::path& reportDir = {},
                       const std::vector<ReportSection>& sections = {});

/// Write dir/index.html, dir/report.json, dir/lunr.min.js (Debian's libjs-lunr) and the 3-D viewer
/// dir/viewer.html with three.min.js and OrbitControls.js (libjs-three), each when installed
/// (creating dir); a figure X.png with X.scene.js beside it gets a "3-D view" link. Throws std::runtime_error naming the path on an I/O failure.
void writeReport(const std::filesystem::path& dir, const ReportInfo& info,
                 const std::vector<StudyResult>& results,
                 const std::vector<ReportSection>& sections = {});

/// A note's markdown as HTML: tables (a header row, a |---| row, body rows) become <table class="md">,
/// `code` and **bold** inline; other lines are escaped text with line breaks.
std::string markdownHtml(std::string_view text);

struct TextOptions {
  std::filesystem::path outDir;    ///< figure paths are printed relative to this directory
  std::size_t valueWidth = 26;     ///< wider expected/got values are shown in full below the row
  std::size_t nameWidth = 60;      ///< a longer check name gets its own line above the row
  bool color = false;              ///< ANSI colours for PASS/FAIL (a terminal, NO_COLOR unset)
};
/// The terminal rendering of one result: a header line, the aligned checks table, the error,
/// notes and figure paths.
std::string formatStudyText(const StudyResult& r, const TextOptions& options = {});
/// `soma study list`: an aligned table (ID, title, source, chapter, scalars) and its JSON form
/// [{id, title, source, chapter, scalar_generic, runs_in}] (runs_in: "--scalar", "every rung: …"
/// or "double: <why>").
std::string formatStudyList(const std::vector<const Study*>& studies);
std::string studyListJson(const std::vector<const Study*>& studies);

/// "N passed, M failed" over studies, plus the checks and time: the last line of a run.
std::string formatSummaryLine(const RunSummary& s);

/// Seconds in a readable unit: "850 ns", "12.3 µs", "4.56 ms", "1.23 s", "2 min 5 s".
std::string formatSeconds(double seconds);
/// A double in 3 significant digits ("1.2e-15", "0", "inf", "nan").
std::string formatShort(double x);

/// Display width of UTF-8 text in terminal columns (one per code point, zero for combining marks).
std::size_t displayWidth(std::string_view utf8);

}  // namespace soma::studies
