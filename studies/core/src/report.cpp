#include "soma/studies/report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <sys/utsname.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>

#ifndef SOMA_VERSION
#define SOMA_VERSION "0.1.0"
#endif

namespace soma::studies {

std::string_view somaVersion() { return SOMA_VERSION; }

// ---- UTF-8 ---------------------------------------------------------------------------------
namespace {

/// Decode one code point at s[i]; returns its length in bytes, or 0 for an invalid sequence.
std::size_t decodeUtf8(std::string_view s, std::size_t i, char32_t& cp) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  std::size_t len;
  if (c < 0x80) {
    cp = c;
    return 1;
  } else if ((c & 0xE0) == 0xC0) {
    len = 2;
    cp = c & 0x1F;
  } else if ((c & 0xF0) == 0xE0) {
    len = 3;
    cp = c & 0x0F;
  } else if ((c & 0xF8) == 0xF0) {
    len = 4;
    cp = c & 0x07;
  } else {
    return 0;
  }
  if (i + len > s.size()) return 0;
  for (std::size_t k = 1; k < len; ++k) {
    if ((b(i + k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (b(i + k) & 0x3F);
  }
  // Reject overlong forms, surrogates and values past U+10FFFF.
  static constexpr char32_t minimum[5] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < minimum[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return len;
}

bool isCombining(char32_t cp) {
  return (cp >= 0x0300 && cp <= 0x036F) || (cp >= 0x1AB0 && cp <= 0x1AFF) ||
         (cp >= 0x1DC0 && cp <= 0x1DFF) || (cp >= 0x20D0 && cp <= 0x20FF) ||
         (cp >= 0xFE20 && cp <= 0xFE2F) || cp == 0x200B || cp == 0x200D;
}

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

/// The longest prefix of `s` that fits in `width` columns.
std::string_view prefixOfWidth(std::string_view s, std::size_t width) {
  std::size_t i = 0, w = 0;
  while (i < s.size()) {
    char32_t cp;
    std::size_t len = decodeUtf8(s, i, cp);
    if (len == 0) len = 1, cp = 0xFFFD;
    const std::size_t cw = isCombining(cp) ? 0 : 1;
    if (w + cw > width) break;
    w += cw;
    i += len;
  }
  return s.substr(0, i);
}

std::string padRight(std::string_view s, std::size_t width) {
  std::string out(s);
  const std::size_t w = displayWidth(s);
  if (w < width) out.append(width - w, ' ');
  return out;
}

std::string padLeft(std::string_view s, std::size_t width) {
  const std::size_t w = displayWidth(s);
  std::string out = w < width ? std::string(width - w, ' ') : std::string();
  out += s;
  return out;
}

}  // namespace

std::size_t displayWidth(std::string_view s) {
  std::size_t i = 0, w = 0;
  while (i < s.size()) {
    char32_t cp;
    std::size_t len = decodeUtf8(s, i, cp);
    if (len == 0) len = 1, cp = 0xFFFD;
    if (!isCombining(cp)) ++w;
    i += len;
  }
  return w;
}

std::string htmlEscape(std::string_view s) {
  std::string out;
  out.reserve(s.size() + s.size() / 8);
  std::size_t i = 0;
  while (i < s.size()) {
    char32_t cp;
    const std::size_t len = decodeUtf8(s, i, cp);
    if (len == 0) {
      out += kReplacement;
      ++i;
      continue;
    }
    switch (cp) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        if (cp < 0x20 && cp != '\n' && cp != '\t') out += kReplacement;  // control characters
        else out.append(s.substr(i, len));
    }
    i += len;
  }
  return out;
}

// ---- numbers -------------------------------------------------------------------------------
std::string formatShort(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  if (x == 0) return "0";
  return fmt::format("{:.3g}", x);
}

std::string formatSeconds(double s) {
  if (!std::isfinite(s) || s < 0) return formatShort(s) + " s";
  if (s == 0) return "0 s";
  if (s < 1e-6) return fmt::format("{:.0f} ns", s * 1e9);
  if (s < 1e-3) return fmt::format("{:.3g} µs", s * 1e6);
  if (s < 1) return fmt::format("{:.3g} ms", s * 1e3);
  if (s < 60) return fmt::format("{:.3g} s", s);
  const double m = std::floor(s / 60);
  return fmt::format("{:.0f} min {:.0f} s", m, std::floor(s - 60 * m));
}

// ---- run information -----------------------------------------------------------------------
namespace {

std::string runCommand(const std::string& cmd) {
  std::string out;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return out;
  char buf[256];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  if (::pclose(p) != 0) return {};
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r' || out.back() == ' '))
    out.pop_back();
  return out;
}

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string gitCommit() {
#ifdef SOMA_GIT_COMMIT
  return SOMA_GIT_COMMIT;
#else
  // The source tree the studies were compiled from.
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path root = sourceRoot();
  if (!fs::exists(root / ".git", ec)) return {};
  const std::string git = "GIT_OPTIONAL_LOCKS=0 git -C " + shellQuote(root.string());
  std::string head = runCommand(git + " rev-parse --short=12 HEAD 2>/dev/null");
  if (head.empty()) return {};
  const std::string dirty =
      runCommand(git + " status --porcelain --untracked-files=no 2>/dev/null | head -c 1");
  if (!dirty.empty()) head += "-dirty";
  return head;
#endif
}

std::string machineDescription() {
  std::string out;
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) == 0 && host[0]) out = host;
  struct utsname u {};
  if (::uname(&u) == 0) {
    if (!out.empty()) out += " — ";
    out += fmt::format("{} {} {}", u.sysname, u.release, u.machine);
  }
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) {
        std::string model = line.substr(colon + 1);
        model.erase(0, model.find_first_not_of(' '));
        out += " — " + model;
      }
      break;
    }
  }
  if (const unsigned n = std::thread::hardware_concurrency(); n > 0)
    out += fmt::format(" ({} threads)", n);
  return out;
}

std::string compilerDescription() {
  std::string c;
#if defined(__clang__)
  c = "Clang " __clang_version__;
#elif defined(__GNUC__)
  c = "GCC " __VERSION__;
#else
  c = "unknown compiler";
#endif
#ifdef NDEBUG
  c += ", optimised (NDEBUG)";
#else
  c += ", debug (assertions on)";
#endif
  return c;
}

std::string localTime(const char* format) {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  ::localtime_r(&t, &tm);
  char buf[64];
  std::strftime(buf, sizeof buf, format, &tm);
  return buf;
}

}  // namespace

ReportInfo collectReportInfo(ScalarKind scalar, std::string command, double seconds,
                             bool figures) {
  ReportInfo info;
  info.version = std::string(somaVersion());
  info.scalar = std::string(scalarName(scalar));
  info.mpfrBits = scalar == ScalarKind::Mpfr ? mpfrBits() : 0;
  info.date = localTime("%Y-%m-%dT%H:%M:%S%z");
  info.machine = machineDescription();
  info.compiler = compilerDescription();
  info.gitCommit = gitCommit();
  info.command = std::move(command);
  info.seconds = seconds;
  info.figures = figures;
  return info;
}

// ---- what a study ran in ----------------------------------------------------------------------
std::string ranInText(const StudyResult& r) {
  const int bits = r.mpfrBits > 0 ? r.mpfrBits : mpfrBits();
  if (r.study && r.study->runsIn() == RunsIn::Ladder)
    return fmt::format("every rung (float, double, long double, float128, mpfr {} bits)", bits);
  std::string s(scalarName(r.scalar));
  if (r.scalar == ScalarKind::Mpfr) s += fmt::format(" ({} bits)", bits);
  if (r.study && r.study->runsIn() == RunsIn::Double)
    s += " (runs in double: " + (r.study->whyDouble.empty() ? std::string(kWhyDouble) : r.study->whyDouble) + ")";
  return s;
}

// ---- JSON ----------------------------------------------------------------------------------
namespace {

using nlohmann::json;

json finiteOrNull(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

std::string scalarLabel(const StudyResult& r) { return ranInText(r); }

json tradeObject(const TradeTable& t) {
  json rungs = json::array();
  for (const auto& r : t.rungs)
    rungs.push_back({{"scalar", r.scalar},
                     {"samples", r.samples},
                     {"median_seconds", r.medianSeconds},
                     {"p95_seconds", r.p95Seconds},
                     {"worst_error", finiteOrNull(r.worstError)},
                     {"worst_error_text", r.worstErrorText},
                     {"escalated", r.escalated},
                     {"escalated_to", r.escalatedTo.empty() ? json(nullptr) : json(r.escalatedTo)},
                     {"comment", r.comment}});
  return {{"solver", t.solver},
          {"sample", t.sample},
          {"error_label", t.errorLabel},
          {"figure", t.figure.empty() ? json(nullptr) : json(t.figure)},
          {"rungs", std::move(rungs)}};
}

json studyObject(const StudyResult& r) {
  json checks = json::array();
  for (const auto& c : r.checks)
    checks.push_back({{"name", c.name},
                      {"expected", c.expected},
                      {"got", c.got},
                      {"error", finiteOrNull(c.error)},
                      {"tolerance", finiteOrNull(c.tolerance)},
                      {"error_text", c.errorText},
                      {"tolerance_text", c.toleranceText},
                      {"seconds", c.seconds},
                      {"passed", c.passed}});
  json figures = json::array();
  for (const auto& f : r.figures) figures.push_back({{"file", f.file}, {"caption", f.caption}});
  const Study* s = r.study;
  json trades = json::array();
  for (const auto& t : r.trades) trades.push_back(tradeObject(t));
  json j = {{"id", s ? s->id : ""},
          {"title", s ? s->title : ""},
          {"source", s ? s->source : ""},
          {"chapter", s ? s->chapter : ""},
          {"scalar_generic", s ? s->scalarGeneric : false},
          {"passed", r.passed()},
          {"seconds", r.seconds},
          {"runs_in", s ? runsInText(*s) : std::string()},
          {"scalar", std::string(scalarName(r.scalar))},
          {"error", r.error.empty() ? json(nullptr) : json(r.error)},
          {"checks", std::move(checks)},
          {"figures", std::move(figures)},
          {"notes", r.notes},
          {"trade", std::move(trades)}};
  // The precision the *_text numbers were written in (read them back at it: readJsonNumber).
  if (r.scalar == ScalarKind::Mpfr || (s && s->runsIn() == RunsIn::Ladder)) j["bits"] = r.mpfrBits;
  return j;
}

std::string dump(const json& j, int indent) {
  return j.dump(indent, ' ', false, json::error_handler_t::replace);
}

}  // namespace

std::string studyJson(const StudyResult& r, int indent) { return dump(studyObject(r), indent); }

std::string reportJson(const ReportInfo& info, const std::vector<StudyResult>& results) {
  const RunSummary s = summarize(results);
  json studies = json::array();
  for (const auto& r : results) studies.push_back(studyObject(r));
  const json j = {
      {"soma_version", info.version},
      {"scalar", info.scalar},
      {"mpfr_bits", info.mpfrBits > 0 ? json(info.mpfrBits) : json(nullptr)},
      {"date", info.date},
      {"machine", info.machine},
      {"compiler", info.compiler},
      {"git_commit", info.gitCommit.empty() ? json(nullptr) : json(info.gitCommit)},
      {"command", info.command},
      {"seconds", info.seconds},
      {"figures", info.figures},
      {"summary",
       {{"studies", s.studiesPassed + s.studiesFailed},
        {"studies_passed", s.studiesPassed},
        {"studies_failed", s.studiesFailed},
        {"checks", s.checksPassed + s.checksFailed},
        {"checks_passed", s.checksPassed},
        {"checks_failed", s.checksFailed}}},
      {"studies", std::move(studies)}};
  return dump(j, 2) + "\n";
}

// ---- HTML ----------------------------------------------------------------------------------
namespace {

constexpr std::string_view kCss = R"css(
:root { --ink:#1d232b; --muted:#5f6b78; --rule:#d9d4c7; --paper:#fbfaf6; --card:#ffffff;
  --pass:#1f7a45; --pass-bg:#e6f4ea; --fail:#b3261e; --fail-bg:#fdecea; --accent:#2c5c8a; }
* { box-sizing: border-box; }
html { background: var(--paper); }
body { margin: 0; color: var(--ink); font: 15px/1.5 "Charter", "Georgia", "DejaVu Serif", serif; }
main { max-width: 1180px; margin: 0 auto; padding: 28px 36px 60px; }
h1, h2, h3 { font-family: "Helvetica Neue", "Liberation Sans", "DejaVu Sans", Arial, sans-serif;
  font-weight: 600; letter-spacing: -0.01em; }
h1 { font-size: 26px; margin: 0 0 2px; }
h2 { font-size: 19px; margin: 34px 0 10px; padding-bottom: 4px; border-bottom: 2px solid var(--ink); }
h3 { font-size: 15px; margin: 0; font-family: "DejaVu Sans Mono", "Liberation Mono", monospace; }
a { color: var(--accent); text-decoration: none; }
a:hover { text-decoration: underline; }
code, .mono { font-family: "DejaVu Sans Mono", "Liberation Mono", Menlo, monospace; font-size: 12.5px; }
.subtitle { color: var(--muted); margin: 0 0 18px; font-style: italic; }
.verdict { display: inline-block; font: 600 14px/1 "DejaVu Sans", Arial, sans-serif;
  padding: 9px 14px; border-radius: 4px; letter-spacing: .04em; margin-bottom: 14px; }
.verdict.pass { background: var(--pass-bg); color: var(--pass); border: 1px solid #a8d5b5; }
.verdict.fail { background: var(--fail-bg); color: var(--fail); border: 1px solid #f0b4ae; }
table { border-collapse: collapse; }
table.meta { font-size: 13.5px; margin-bottom: 8px; }
table.meta th { text-align: left; color: var(--muted); font-weight: normal; padding: 2px 18px 2px 0;
  vertical-align: top; white-space: nowrap; }
table.meta td { padding: 2px 0; }
.counts b.pass { color: var(--pass); } .counts b.fail { color: var(--fail); }
.failed-list { background: var(--fail-bg); border: 1px solid #f0b4ae; border-left: 5px solid var(--fail);
  padding: 10px 18px 12px; margin: 18px 0; border-radius: 3px; }
.failed-list h2 { border: 0; margin: 0 0 6px; color: var(--fail); font-size: 16px; padding: 0; }
.failed-list ul { margin: 0; padding-left: 18px; }
.failed-list li { margin: 3px 0; }
.failed-list .why { color: var(--muted); font-size: 13.5px; }
nav.toc ol { padding-left: 20px; margin: 0; }
nav.toc > ol > li { margin: 6px 0; font-weight: 600; }
nav.toc ul { list-style: none; padding-left: 4px; margin: 3px 0 8px; font-weight: normal; }
nav.toc ul li { margin: 1px 0; font-size: 14px; }
nav.toc .tally { color: var(--muted); font-weight: normal; font-size: 13px; margin-left: 6px; }
nav.toc .id { font-family: "DejaVu Sans Mono", monospace; font-size: 12.5px; }
.badge { display: inline-block; min-width: 40px; text-align: center; font: 700 11px/1 "DejaVu Sans", Arial,
  sans-serif; letter-spacing: .06em; padding: 4px 6px; border-radius: 3px; vertical-align: 1px; }
.badge.pass { background: var(--pass); color: #fff; }
.badge.fail { background: var(--fail); color: #fff; }
nav.toc .badge { min-width: 34px; padding: 2px 4px; font-size: 9.5px; margin-right: 6px; }
.chapter-tally { float: right; font: normal 13px "DejaVu Sans", Arial, sans-serif; color: var(--muted);
  padding-top: 5px; }
article.study { background: var(--card); border: 1px solid var(--rule); border-left: 5px solid var(--pass);
  border-radius: 3px; padding: 12px 16px 10px; margin: 14px 0 18px; }
article.study.fail { border-color: #f0b4ae; border-left-color: var(--fail); background: #fffafa;
  box-shadow: 0 0 0 1px #f6d3cf; }
.study-head { display: flex; align-items: baseline; gap: 10px; flex-wrap: wrap; }
.study-title { margin: 2px 0 0; font-size: 15.5px; }
.study-meta { margin: 2px 0 8px; color: var(--muted); font-size: 13px; }
.error { background: var(--fail-bg); border: 1px solid #f0b4ae; color: var(--fail); padding: 6px 10px;
  margin: 8px 0; border-radius: 3px; font-size: 13.5px; white-space: pre-wrap; }
table.checks { width: 100%; font-size: 13px; margin: 6px 0 4px; table-layout: fixed; }
table.checks th { text-align: left; white-space: nowrap; font: 600 11.5px "DejaVu Sans", Arial, sans-serif; color: var(--muted);
  text-transform: uppercase; letter-spacing: .04em; border-bottom: 1px solid var(--ink); padding: 4px 6px; }
table.checks td { border-bottom: 1px solid #ece8de; padding: 5px 6px; vertical-align: top;
  overflow-wrap: anywhere; }
table.checks td.num { text-align: right; white-space: nowrap; }
table.checks td.value { font-family: "DejaVu Sans Mono", "Liberation Mono", monospace; font-size: 11.5px; }
table.checks tr.fail td { background: var(--fail-bg); }
table.checks tr.fail td.result { color: var(--fail); font-weight: 700; }
table.checks td.result { color: var(--pass); font: 700 11px "DejaVu Sans", Arial, sans-serif; text-align: center; }
table.checks col.c-idx { width: 30px; } table.checks col.c-name { width: 30%; }
table.checks col.c-err { width: 80px; } table.checks col.c-tol { width: 92px; }
table.checks col.c-time { width: 70px; } table.checks col.c-res { width: 50px; }
table.checks td.idx { color: var(--muted); text-align: right; }
ul.notes { margin: 8px 0 4px; padding-left: 20px; font-size: 14px; }
ul.notes li { margin: 2px 0; }
.figures { display: flex; flex-wrap: wrap; gap: 16px; margin: 10px 0 4px; }
figure { margin: 0; max-width: 100%; }
figure img { display: block; max-width: 100%; max-height: 520px; border: 1px solid var(--rule); background: #fff; }
figcaption { font-size: 13px; color: var(--muted); margin-top: 4px; max-width: 560px; }
.missing { border: 1px dashed var(--rule); color: var(--muted); padding: 18px; font-size: 13px; }
footer { margin-top: 40px; color: var(--muted); font-size: 12.5px; border-top: 1px solid var(--rule);
  padding-top: 8px; }
)css";

std::string e(std::string_view s) { return htmlEscape(s); }

/// An HTML id for a study: its catalogue ID with anything outside [A-Za-z0-9._-] replaced.
std::string anchor(std::string_view id) {
  std::string a = "study-";
  for (char c : id) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    a += ok ? c : '_';
  }
  return a;
}

std::string badge(bool passed) {
  return passed ? R"(<span class="badge pass">PASS</span>)" : R"(<span class="badge fail">FAIL</span>)";
}

/// Why a study failed, in one line: its exception, or its first failed check.
std::string failureReason(const StudyResult& r) {
  if (!r.error.empty()) return "error: " + r.error;
  int failed = 0;
  const Check* first = nullptr;
  for (const auto& c : r.checks)
    if (!c.passed) {
      ++failed;
      if (!first) first = &c;
    }
  if (!first) return "no check passed";
  std::string why = "“" + first->name + "”: error " + formatShort(first->error) + " > tolerance " +
                    formatShort(first->tolerance);
  if (failed > 1) why += fmt::format(" (and {} more failed check{})", failed - 1, failed > 2 ? "s" : "");
  return why;
}

struct Chapter {
  std::string name;
  std::vector<const StudyResult*> results;
  int passed = 0;
};

std::vector<Chapter> byChapter(const std::vector<StudyResult>& results) {
  std::vector<Chapter> chapters;
  std::map<std::string, std::size_t> index;
  for (const auto& r : results) {
    const std::string name = r.study && !r.study->chapter.empty() ? r.study->chapter : "Other";
    auto [it, inserted] = index.try_emplace(name, chapters.size());
    if (inserted) chapters.push_back({name, {}, 0});
    Chapter& c = chapters[it->second];
    c.results.push_back(&r);
    c.passed += r.passed() ? 1 : 0;
  }
  return chapters;
}

void writeStudy(std::ostringstream& h, const StudyResult& r, const ReportInfo& info,
                const std::filesystem::path& reportDir) {
  const Study& s = *r.study;
  const bool ok = r.passed();
  int checksFailed = 0;
  for (const auto& c : r.checks) checksFailed += c.passed ? 0 : 1;
  h << "<article class=\"study " << (ok ? "pass" : "fail") << "\" id=\"" << e(anchor(s.id))
    << "\">\n<div class=\"study-head\">" << badge(ok) << "<h3>" << e(s.id) << "</h3></div>\n";
  h << "<p class=\"study-title\">" << e(s.title) << "</p>\n";
  std::string meta = e(s.source.empty() ? "no source" : s.source);
  meta += " · ran in " + e(scalarLabel(r));
  meta += fmt::format(" · {} check{}", r.checks.size(), r.checks.size() == 1 ? "" : "s");
  if (checksFailed) meta += fmt::format(", <b style=\"color:var(--fail)\">{} failed</b>", checksFailed);
  meta += " · " + e(formatSeconds(r.seconds));
  h << "<p class=\"study-meta\">" << meta << "</p>\n";
  if (!r.error.empty()) h << "<div class=\"error\"><b>Error:</b> " << e(r.error) << "</div>\n";
  if (!r.checks.empty()) {
    h << "<table class=\"checks\"><colgroup><col class=\"c-idx\"><col class=\"c-name\"><col>"
         "<col><col class=\"c-err\"><col class=\"c-tol\"><col class=\"c-time\"><col "
         "class=\"c-res\"></colgroup>\n<thead><tr><th>#</th><th>Check</th><th>Expected</th>"
         "<th>Got</th><th>Error</th><th>Tolerance</th><th>Time</th><th></th></tr></thead>\n<tbody>\n";
    int k = 0;
    for (const auto& c : r.checks) {
      h << "<tr class=\"" << (c.passed ? "pass" : "fail") << "\"><td class=\"idx\">" << ++k
        << "</td><td>" << e(c.name) << "</td><td class=\"value\">" << e(c.expected)
        << "</td><td class=\"value\">" << e(c.got) << "</td><td class=\"num mono\">"
        << "<span title=\"" << e(c.errorText) << "\">" << e(formatShort(c.error)) << "</span></td><td class=\"num mono\"><span title=\""
        << e(c.toleranceText) << "\">" << e(formatShort(c.tolerance)) << "</span>"
        << "</td><td class=\"num\">" << e(formatSeconds(c.seconds)) << "</td><td class=\"result\">"
        << (c.passed ? "PASS" : "FAIL") << "</td></tr>\n";
    }
    h << "</tbody></table>\n";
  }
  if (!r.notes.empty()) {
    h << "<ul class=\"notes\">\n";
    for (const auto& n : r.notes) h << "<li>" << e(n) << "</li>\n";
    h << "</ul>\n";
  }
  if (!r.figures.empty()) {
    h << "<div class=\"figures\">\n";
    int k = 0;
    for (const auto& f : r.figures) {
      ++k;
      std::error_code ec;
      const bool present = reportDir.empty() || std::filesystem::exists(reportDir / f.file, ec);
      h << "<figure>";
      if (present)
        h << "<img src=\"" << e(f.file) << "\" alt=\"" << e(f.caption) << "\" loading=\"lazy\">";
      else
        h << "<div class=\"missing\">" << (info.figures ? "figure file missing: " : "figures not made (--no-figures): ")
          << "<code>" << e(f.file) << "</code></div>";
      h << "<figcaption><b>Figure " << k << ".</b> " << e(f.caption) << "</figcaption></figure>\n";
    }
    h << "</div>\n";
  }
  h << "</article>\n";
}

}  // namespace

std::string reportHtml(const ReportInfo& info, const std::vector<StudyResult>& results,
                       const std::filesystem::path& reportDir) {
  const RunSummary sum = summarize(results);
  const int nStudies = sum.studiesPassed + sum.studiesFailed;
  const int nChecks = sum.checksPassed + sum.checksFailed;
  const auto chapters = byChapter(results);
  std::ostringstream h;
  const std::string verdict =
      sum.studiesFailed == 0
          ? fmt::format("ALL {} STUDIES PASSED", nStudies)
          : fmt::format("{} OF {} STUDIES FAILED", sum.studiesFailed, nStudies);

  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<title>soma report — " << e(verdict) << "</title>\n<style>" << kCss << "</style>\n"
    << "</head>\n<body>\n<main>\n<header>\n<h1>soma — reproduction report</h1>\n"
    << "<p class=\"subtitle\">J.M. Selig, <i>Geometric Fundamentals of Robotics</i>: each claim, "
       "soma’s value, the error, the tolerance and what it cost.</p>\n";
  h << "<div class=\"verdict " << (sum.studiesFailed ? "fail" : "pass") << "\">" << e(verdict)
    << "</div>\n<table class=\"meta\">\n";
  auto row = [&](std::string_view k, const std::string& vHtml) {
    h << "<tr><th>" << e(k) << "</th><td>" << vHtml << "</td></tr>\n";
  };
  row("Studies", fmt::format("<span class=\"counts\"><b class=\"pass\">{} passed</b>, <b "
                             "class=\"{}\">{} failed</b> of {}</span>",
                             sum.studiesPassed, sum.studiesFailed ? "fail" : "", sum.studiesFailed,
                             nStudies));
  row("Checks", fmt::format("<span class=\"counts\"><b class=\"pass\">{} passed</b>, <b "
                            "class=\"{}\">{} failed</b> of {}</span>",
                            sum.checksPassed, sum.checksFailed ? "fail" : "", sum.checksFailed,
                            nChecks));
  row("Total time", e(formatSeconds(info.seconds > 0 ? info.seconds : sum.seconds)));
  row("Scalar", e(info.scalar + (info.mpfrBits > 0 ? fmt::format(" ({} bits)", info.mpfrBits) : "")) +
                    " <span style=\"color:var(--muted)\">(each study's header says what it ran in: the "
                    "scalar-generic ones in this scalar, the others in double, the speed/accuracy studies in every rung)</span>");
  row("Date", e(info.date));
  row("Machine", e(info.machine));
  row("Compiler", e(info.compiler));
  row("soma", e(info.version) + (info.gitCommit.empty() ? std::string()
                                                        : " · commit <code>" + e(info.gitCommit) + "</code>"));
  if (!info.command.empty()) row("Command", "<code>" + e(info.command) + "</code>");
  h << "</table>\n</header>\n";

  if (sum.studiesFailed > 0) {
    h << "<section class=\"failed-list\">\n<h2>Failed studies (" << sum.studiesFailed
      << ")</h2>\n<ul>\n";
    for (const auto& r : results)
      if (!r.passed())
        h << "<li><a href=\"#" << e(anchor(r.study->id)) << "\"><code>" << e(r.study->id)
          << "</code></a> " << e(r.study->title) << "<br><span class=\"why\">"
          << e(failureReason(r)) << "</span></li>\n";
    h << "</ul>\n</section>\n";
  }

  h << "<nav class=\"toc\">\n<h2>Contents</h2>\n<ol>\n";
  for (std::size_t k = 0; k < chapters.size(); ++k) {
    const auto& c = chapters[k];
    h << "<li><a href=\"#ch-" << k + 1 << "\">" << e(c.name) << "</a><span class=\"tally\">"
      << c.passed << "/" << c.results.size() << " passed</span>\n<ul>\n";
    for (const StudyResult* r : c.results)
      h << "<li>" << badge(r->passed()) << "<a href=\"#" << e(anchor(r->study->id))
        << "\"><span class=\"id\">" << e(r->study->id) << "</span></a> — " << e(r->study->title)
        << "</li>\n";
    h << "</ul></li>\n";
  }
  h << "</ol>\n</nav>\n";
  h << speedAccuracySectionHtml(results);

  for (std::size_t k = 0; k < chapters.size(); ++k) {
    const auto& c = chapters[k];
    h << "<section class=\"chapter\" id=\"ch-" << k + 1 << "\">\n<h2>" << e(c.name)
      << "<span class=\"chapter-tally\">" << c.passed << " of " << c.results.size()
      << " passed</span></h2>\n";
    for (const StudyResult* r : c.results) writeStudy(h, *r, info, reportDir);
    h << "</section>\n";
  }
  if (results.empty()) h << "<p>No study was run.</p>\n";
  h << "<footer>Generated by soma " << e(info.version) << " on " << e(info.date)
    << ". Expected values come from the book or from an independent method; a check passes when "
       "its error is at most its tolerance. Data: <a href=\"report.json\">report.json</a>."
       "</footer>\n</main>\n</body>\n</html>\n";
  return h.str();
}

void writeReport(const std::filesystem::path& dir, const ReportInfo& info,
                 const std::vector<StudyResult>& results) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw std::runtime_error("cannot create report directory '" + dir.string() +
                             "': " + (ec ? ec.message() : "not a directory"));
  auto write = [&](const std::string& name, const std::string& text) {
    const fs::path path = dir / name, tmp = dir / (name + ".tmp");
    {
      std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
      if (!f) throw std::runtime_error("cannot write '" + tmp.string() + "'");
      f << text;
      f.flush();
      if (!f) throw std::runtime_error("cannot write '" + tmp.string() + "'");
    }
    fs::rename(tmp, path, ec);
    if (ec) throw std::runtime_error("cannot write '" + path.string() + "': " + ec.message());
  };
  write("report.json", reportJson(info, results));
  write("index.html", reportHtml(info, results, dir));
}

// ---- terminal ------------------------------------------------------------------------------
namespace {

std::string colored(std::string_view s, const char* code, bool on) {
  if (!on) return std::string(s);
  return fmt::format("\x1b[{}m{}\x1b[0m", code, s);
}

}  // namespace

std::string formatStudyText(const StudyResult& r, const TextOptions& o) {
  std::string out;
  const Study& s = *r.study;
  const bool ok = r.passed();
  out += colored(ok ? "PASS" : "FAIL", ok ? "1;32" : "1;31", o.color) + "  " +
         colored(s.id, "1", o.color) + " — " + s.title + "\n";
  std::string meta = "      " + (s.source.empty() ? std::string("no source") : s.source);
  if (!s.chapter.empty()) meta += " · " + s.chapter;
  meta += " · ran in " + scalarLabel(r);
  meta += " · " + formatSeconds(r.seconds) + "\n";
  out += meta;

  if (!r.checks.empty()) {
    // Column widths.
    const std::vector<std::string> heads = {"check", "expected", "got", "error", "tolerance", "time"};
    std::size_t wName = displayWidth(heads[0]), wExp = displayWidth(heads[1]),
                wGot = displayWidth(heads[2]), wErr = displayWidth(heads[3]),
                wTol = displayWidth(heads[4]), wTime = displayWidth(heads[5]);
    for (const auto& c : r.checks) {
      wName = std::max(wName, std::min(displayWidth(c.name), o.nameWidth));
      wExp = std::max(wExp, std::min(displayWidth(c.expected), o.valueWidth));
      wGot = std::max(wGot, std::min(displayWidth(c.got), o.valueWidth));
      wErr = std::max(wErr, formatShort(c.error).size());
      wTol = std::max(wTol, formatShort(c.tolerance).size());
      wTime = std::max(wTime, displayWidth(formatSeconds(c.seconds)));
    }
    const std::string indent = "      ";
    const std::string gap = "  ";
    auto cell = [&](const std::string& v, std::size_t w) {
      if (displayWidth(v) <= w) return padRight(v, w);
      return padRight(std::string(prefixOfWidth(v, w - 1)) + "…", w);
    };
    out += indent + padRight(heads[0], wName) + gap + padRight(heads[1], wExp) + gap +
           padRight(heads[2], wGot) + gap + padLeft(heads[3], wErr) + gap +
           padLeft(heads[4], wTol) + gap + padLeft(heads[5], wTime) + gap + "result\n";
    out += indent + std::string(wName + wExp + wGot + wErr + wTol + wTime + 6 * gap.size() + 6, '-') + "\n";
    for (const auto& c : r.checks) {
      std::string name = c.name;
      if (displayWidth(name) > wName) {  // long name: its own line, then the row
        out += indent + name + "\n";
        name.clear();
      }
      out += indent + padRight(name, wName) + gap + cell(c.expected, wExp) + gap +
             cell(c.got, wGot) + gap + padLeft(formatShort(c.error), wErr) + gap +
             padLeft(formatShort(c.tolerance), wTol) + gap + padLeft(formatSeconds(c.seconds), wTime) +
             gap + colored(c.passed ? "PASS" : "FAIL", c.passed ? "32" : "1;31", o.color) + "\n";
      if (displayWidth(c.expected) > wExp || displayWidth(c.got) > wGot) {
        out += indent + "    expected = " + c.expected + "\n";
        out += indent + "    got      = " + c.got + "\n";
      }
      // The columns show 3 digits; the scalar's own digits of error and tolerance follow when
      // they say more (long double, float128, mpfr, or a double the 3 digits round).
      if (c.errorText != formatShort(c.error) || c.toleranceText != formatShort(c.tolerance))
        out += indent + "    error = " + c.errorText + ", tolerance = " + c.toleranceText + "\n";
    }
  }
  if (!r.error.empty()) out += "      " + colored("error: ", "1;31", o.color) + r.error + "\n";
  for (const auto& n : r.notes) out += "      note: " + n + "\n";
  for (const auto& t : r.trades) {
    std::string table = tradeText(t);
    for (std::size_t a = 0; a < table.size();) {
      const std::size_t b = table.find('\n', a);
      out += "      " + table.substr(a, b - a) + "\n";
      a = b == std::string::npos ? table.size() : b + 1;
    }
  }
  for (const auto& f : r.figures) {
    const std::string path = o.outDir.empty() ? f.file : (o.outDir / f.file).string();
    out += "      figure: " + path + " — " + f.caption + "\n";
  }
  return out;
}

std::string formatSummaryLine(const RunSummary& s) {
  return fmt::format("{} passed, {} failed · {} checks, {} failed · {}", s.studiesPassed,
                     s.studiesFailed, s.checksPassed + s.checksFailed, s.checksFailed,
                     formatSeconds(s.seconds));
}

}  // namespace soma::studies

namespace soma::studies {

std::string formatStudyList(const std::vector<const Study*>& studies) {
  std::size_t wId = 2, wTitle = 5, wSource = 6;
  constexpr std::size_t maxTitle = 72;
  for (const Study* s : studies) {
    wId = std::max(wId, displayWidth(s->id));
    wTitle = std::max(wTitle, std::min(displayWidth(s->title), maxTitle));
    wSource = std::max(wSource, displayWidth(s->source));
  }
  auto fit = [](const std::string& v, std::size_t w) {
    if (displayWidth(v) <= w) return padRight(v, w);
    return padRight(std::string(prefixOfWidth(v, w - 1)) + "…", w);
  };
  std::string out = padRight("ID", wId) + "  " + padRight("title", wTitle) + "  " +
                    padRight("source", wSource) + "  scalars  chapter\n";
  out += std::string(wId + wTitle + wSource + 6, '-') + "  -------  -------\n";
  int generic = 0, ladder = 0;
  std::map<std::string, int> why;
  for (const Study* s : studies) {
    const RunsIn in = s->runsIn();
    generic += in == RunsIn::Scalar;
    ladder += in == RunsIn::Ladder;
    if (in == RunsIn::Double) ++why[s->whyDouble.empty() ? std::string(kWhyDouble) : s->whyDouble];
    out += padRight(s->id, wId) + "  " + fit(s->title, wTitle) + "  " + padRight(s->source, wSource) +
           "  " + (in == RunsIn::Scalar ? "all    " : in == RunsIn::Ladder ? "ladder " : "double ") + "  " +
           s->chapter + "\n";
  }
  out += fmt::format("{} stud{}: {} scalar-generic (they run in --scalar), {} speed/accuracy (they run every "
                     "rung, mpfr at --bits), {} in double:\n",
                     studies.size(), studies.size() == 1 ? "y" : "ies", generic, ladder,
                     int(studies.size()) - generic - ladder);
  std::vector<std::pair<std::string, int>> reasons(why.begin(), why.end());
  std::stable_sort(reasons.begin(), reasons.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  for (const auto& [text, n] : reasons) out += fmt::format("  {:>4} {}\n", n, text);
  return out;
}

std::string studyListJson(const std::vector<const Study*>& studies) {
  nlohmann::json a = nlohmann::json::array();
  for (const Study* s : studies)
    a.push_back({{"id", s->id},
                 {"title", s->title},
                 {"source", s->source},
                 {"chapter", s->chapter},
                 {"scalar_generic", s->runsIn() == RunsIn::Scalar},
                 {"runs_in", runsInText(*s)}});  // "--scalar", "every rung: …" or "double: <why>"
  return a.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace soma::studies
