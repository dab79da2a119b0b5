#include "soma/studies/report.hpp"

#include "report_page.hpp"
#include "soma/studies/source_index.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <sys/utsname.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
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

std::string studyAnchor(std::string_view id) {
  std::string a = "study-";
  for (char c : id) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    a += ok ? c : '_';
  }
  return a;
}

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

using detail::kReportCss;

constexpr const char* kLunrPath = "/usr/share/javascript/lunr/lunr.min.js";
constexpr const char* kThreePath = "/usr/share/javascript/three/three.min.js";
constexpr const char* kOrbitControlsPath = "/usr/share/javascript/three/examples/js/controls/OrbitControls.js";

std::string e(std::string_view s) { return htmlEscape(s); }

std::string anchor(std::string_view id) { return studyAnchor(id); }

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

/// A file:// address for a path relative to the source tree (links to a study's code and row).
std::string fileUrl(const std::filesystem::path& root, const std::string& rel) {
  const std::string p = (root / rel).lexically_normal().generic_string();
  std::string out = "file://";
  for (unsigned char c : p) {
    if (std::isalnum(c) || std::strchr("/-._~", c)) out += static_cast<char>(c);
    else out += fmt::format("%{:02X}", c);
  }
  return out;
}

/// The erratum label a check names in "fails (erratum X)": "E4.8" as is, "GF11-7" as "E11.7",
/// a bare number n as "E<chapter>.n" for a GF study and "<prefix>-En" otherwise (SB-E3).
std::string checkErratumLabel(const std::string& studyId, const std::string& expected) {
  const std::string key = "(erratum ";
  const auto at = expected.find(key);
  if (at == std::string::npos) return {};
  std::size_t i = at + key.size(), j = i;
  while (j < expected.size() && expected[j] != ')' && expected[j] != ',' && expected[j] != ' ' &&
         expected[j] != ';')
    ++j;
  std::string x = expected.substr(i, j - i);
  if (x.empty()) return {};
  auto digits = [](const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  if (x[0] == 'E') {  // "E4.8", "E4.11-type"
    std::size_t k = 1;
    while (k < x.size() && (std::isdigit(static_cast<unsigned char>(x[k])) || x[k] == '.')) ++k;
    return x.substr(0, k);
  }
  if (x.rfind("GF", 0) == 0) {  // "GF11-7"
    const auto dash = x.find('-');
    if (dash != std::string::npos && digits(x.substr(2, dash - 2)) && digits(x.substr(dash + 1)))
      return "E" + std::to_string(std::stoi(x.substr(2, dash - 2))) + "." + x.substr(dash + 1);
    return x;
  }
  if (digits(x)) {
    if (studyId.rfind("GF-", 0) == 0) {
      std::size_t k = 3;
      while (k < studyId.size() && std::isdigit(static_cast<unsigned char>(studyId[k]))) ++k;
      if (k > 3) return "E" + studyId.substr(3, k - 3) + "." + x;
    }
    const auto dash = studyId.find('-');
    return (dash == std::string::npos ? std::string() : studyId.substr(0, dash) + "-") + "E" + x;
  }
  return x;
}

/// Inline markdown of escaped text: `code` and **bold**.
std::string inlineMarkdown(std::string_view text) {
  const std::string s = e(text);
  std::string out;
  bool code = false, bold = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '`') {
      out += code ? "</code>" : "<code>";
      code = !code;
    } else if (!code && s.compare(i, 2, "**") == 0) {
      out += bold ? "</b>" : "<b>";
      bold = !bold;
      ++i;
    } else {
      out += s[i];
    }
  }
  if (code) out += "</code>";
  if (bold) out += "</b>";
  return out;
}

std::vector<std::string> tableCells(std::string_view row) {
  std::vector<std::string> out;
  std::string cur;
  std::size_t i = row.find('|');
  for (++i; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') cur += '|', ++i;
    else if (row[i] == '|') out.push_back(cur), cur.clear();
    else cur += row[i];
  }
  if (cur.find_first_not_of(" \t") != std::string::npos) out.push_back(cur);
  for (auto& c : out) {
    const auto b = c.find_first_not_of(" \t"), en = c.find_last_not_of(" \t");
    c = b == std::string::npos ? std::string() : c.substr(b, en - b + 1);
  }
  return out;
}

bool tableSeparator(std::string_view l) {
  return l.find("-") != std::string_view::npos && l.find_first_not_of("|-: \t") == std::string_view::npos;
}

}  // namespace

std::string markdownHtml(std::string_view text) {
  std::vector<std::string_view> lines;
  for (std::size_t i = 0; i <= text.size();) {
    const auto n = text.find('\n', i);
    const std::size_t end = n == std::string_view::npos ? text.size() : n;
    lines.push_back(text.substr(i, end - i));
    i = end + 1;
    if (n == std::string_view::npos) break;
  }
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  std::string out;
  std::string para;
  auto flush = [&] {
    const auto b = para.find_first_not_of('\n'), en = para.find_last_not_of('\n');
    if (b != std::string::npos) out += "<span>" + inlineMarkdown(para.substr(b, en - b + 1)) + "</span>";
    para.clear();
  };
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::string_view l = lines[k];
    const bool table = !l.empty() && l.front() == '|' && k + 1 < lines.size() && tableSeparator(lines[k + 1]);
    if (!table) {
      if (!para.empty()) para += '\n';
      para += l;
      continue;
    }
    flush();
    out += "<table class=\"md\"><thead><tr>";
    for (const auto& c : tableCells(l)) out += "<th>" + inlineMarkdown(c) + "</th>";
    out += "</tr></thead><tbody>\n";
    k += 2;
    for (; k < lines.size() && !lines[k].empty() && lines[k].front() == '|'; ++k) {
      out += "<tr>";
      for (const auto& c : tableCells(lines[k])) out += "<td>" + inlineMarkdown(c) + "</td>";
      out += "</tr>\n";
    }
    out += "</tbody></table>";
    --k;
  }
  flush();
  // Line breaks inside a paragraph.
  std::string result;
  for (char c : out) result += c == '\n' ? std::string("<br>") : std::string(1, c);
  return result;
}

namespace {

/// What the page knows beyond the results: the source index and each study's errata.
struct Page {
  const ReportInfo& info;
  std::filesystem::path reportDir;
  std::filesystem::path root;
  SourceIndex src;
  std::map<std::string, std::vector<std::string>> errataOf;  // study ID → labels
};

std::string scalarTags(const StudyResult& r) {
  return std::string(scalarName(r.scalar)) + (r.study->scalarGeneric ? " scalar-generic" : " double-only");
}

void writeStudy(std::ostringstream& h, const StudyResult& r, const Page& page) {
  const Study& s = *r.study;
  const bool ok = r.passed();
  int checksFailed = 0;
  for (const auto& c : r.checks) checksFailed += c.passed ? 0 : 1;
  std::string errata;
  if (auto it = page.errataOf.find(s.id); it != page.errataOf.end())
    for (const auto& l : it->second) errata += (errata.empty() ? "" : " ") + l;
  h << "<article class=\"study " << (ok ? "pass" : "fail") << "\" id=\"" << e(anchor(s.id))
    << "\" data-id=\"" << e(s.id) << "\" data-chapter=\"" << e(s.chapter.empty() ? "Other" : s.chapter)
    << "\" data-verdict=\"" << (ok ? "pass" : "fail") << "\" data-source=\"" << e(s.source)
    << "\" data-scalar=\"" << e(scalarTags(r)) << "\" data-errata=\"" << e(errata) << "\">\n<div class=\"study-head\">"
    << badge(ok) << "<h3>" << e(s.id) << "</h3>";
  if (!errata.empty())
    for (const auto& l : page.errataOf.at(s.id)) h << "<span class=\"tag\">" << e(l) << "</span>";
  h << "</div>\n<p class=\"study-title\">" << e(s.title) << "</p>\n";
  std::string meta = e(s.source.empty() ? "no source" : s.source);
  meta += " · ran in " + e(scalarLabel(r));
  meta += fmt::format(" · {} check{}", r.checks.size(), r.checks.size() == 1 ? "" : "s");
  if (checksFailed) meta += fmt::format(", <b style=\"color:var(--fail)\">{} failed</b>", checksFailed);
  meta += " · " + e(formatSeconds(r.seconds));
  h << "<p class=\"study-meta\">" << meta << "</p>\n";
  const auto code = page.src.code.find(s.id);
  const auto row = page.src.papers.find(s.id);
  if (code != page.src.code.end() || row != page.src.papers.end()) {
    h << "<p class=\"links\">";
    if (code != page.src.code.end())
      h << "source <a class=\"code\" href=\"" << e(fileUrl(page.root, code->second.file)) << "\"><code>"
        << e(code->second.file) << ":" << code->second.line << "</code></a>";
    if (row != page.src.papers.end())
      h << "papers <a class=\"paper\" href=\"" << e(fileUrl(page.root, row->second.file)) << "\"><code>"
        << e(row->second.file) << ":" << row->second.line << "</code></a>";
    h << "</p>\n";
  }
  if (!r.error.empty()) h << "<div class=\"error\"><b>Error:</b> " << e(r.error) << "</div>\n";
  if (!r.checks.empty()) {
    h << "<table class=\"checks\"><colgroup><col class=\"c-idx\"><col class=\"c-name\"><col>"
         "<col><col class=\"c-err\"><col class=\"c-tol\"><col class=\"c-time\"><col "
         "class=\"c-res\"></colgroup>\n<thead><tr><th>#</th><th>Check</th><th>Expected</th>"
         "<th>Got</th><th>Error</th><th>Tolerance</th><th>Time</th><th></th></tr></thead>\n<tbody>\n";
    int k = 0;
    for (const auto& c : r.checks) {
      h << "<tr class=\"" << (c.passed ? "pass" : "fail") << "\"><td class=\"idx\">" << ++k
        << "</td><td class=\"cname\">" << e(c.name) << "</td><td class=\"value\">" << e(c.expected)
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
    for (const auto& n : r.notes) h << "<li>" << markdownHtml(n) << "</li>\n";
    h << "</ul>\n";
  }
  if (!r.figures.empty()) {
    h << "<div class=\"figures\">\n";
    int k = 0;
    for (const auto& f : r.figures) {
      ++k;
      std::error_code ec;
      const bool present = page.reportDir.empty() || std::filesystem::exists(page.reportDir / f.file, ec);
      h << "<figure>";
      if (present) {
        h << "<a class=\"fig\" href=\"" << e(f.file) << "\" data-caption=\"" << e(f.caption)
          << "\" title=\"open full size\"><img src=\"" << e(f.file) << "\" alt=\"" << e(f.caption)
          << "\" loading=\"lazy\"></a>";
      } else {
        h << "<div class=\"missing\">" << (page.info.figures ? "figure file missing: " : "figures not made (--no-figures): ")
          << "<code>" << e(f.file) << "</code></div>";
      }
      h << "<figcaption><b>Figure " << k << ".</b> " << e(f.caption);
      if (present) {
        h << " <span class=\"fig-links\"><a href=\"" << e(f.file) << "\">full size</a>";
        // The vector form beside the raster one (render/svg.hpp writes the 2-D plots as SVG).
        std::filesystem::path svg = f.file;
        svg.replace_extension(".svg");
        if (svg.generic_string() != f.file && !page.reportDir.empty() &&
            std::filesystem::exists(page.reportDir / svg, ec))
          h << "<a href=\"" << e(svg.generic_string()) << "\">SVG</a>";
        // The interactive 3-D view of the same scene (render/scene_js.hpp, viewer.html).
        std::string js = f.file;
        if (js.size() > 4 && js.compare(js.size() - 4, 4, ".png") == 0) {
          js = js.substr(0, js.size() - 4) + ".scene.js";
          if (!page.reportDir.empty() && std::filesystem::exists(page.reportDir / js, ec))
            h << "<a class=\"view3d\" href=\"viewer.html?scene=" << e(js) << "\">3-D view</a>";
        }
        h << "</span>";
      }
      h << "</figcaption></figure>\n";
    }
    h << "</div>\n";
  }
  h << "</article>\n";
}

/// The errata index: every erratum papers/ records, where the book says it, what soma found (the
/// check that shows the printed form failing, from this run), the study and the papers/ entry.
void writeErrata(std::ostringstream& h, const Page& page, const std::vector<StudyResult>& results) {
  std::map<std::string, const StudyResult*> byId;
  for (const auto& r : results) byId[r.study->id] = &r;
  h << "<section class=\"errata\" id=\"errata\">\n<h2>Errata index<span class=\"chapter-tally\">"
    << page.src.errata.size() << " errata in papers/</span></h2>\n";
  if (page.src.errata.empty()) {
    h << "<p>No papers/ folder was found under <code>" << e(page.root.string()) << "</code>.</p>\n</section>\n";
    return;
  }
  h << "<p class=\"chapter-summary\">Every erratum the papers/ files record (the catalogue's numbering; a "
       "numbered list in <code>chNN.md</code> is shown as E<i>NN.n</i>): the entry, the section of the "
       "book of each study that settles it, and the check of this run that shows the printed form failing "
       "where the study records one.</p>\n";
  h << "<table class=\"errata\"><colgroup><col class=\"e-label\"><col class=\"e-where\"><col><col "
       "class=\"e-found\"><col class=\"e-study\"></colgroup>\n<thead><tr><th>Erratum</th><th>Where</th>"
       "<th>What papers/ says</th><th>What soma found (this run)</th><th>Study</th></tr></thead>\n<tbody>\n";
  for (const Erratum& er : page.src.errata) {
    h << "<tr data-erratum=\"" << e(er.label) << "\"><td class=\"label\">" << e(er.label) << "</td><td>";
    std::vector<std::string> sections;
    for (const auto& id : er.studies)
      if (auto it = byId.find(id); it != byId.end() && !it->second->study->source.empty() &&
                                   std::find(sections.begin(), sections.end(), it->second->study->source) == sections.end())
        sections.push_back(it->second->study->source);
    for (const auto& s : sections) h << e(s) << "<br>";
    h << "<a href=\"" << e(fileUrl(page.root, er.place.file)) << "\"><code>" << e(er.place.file) << ":"
      << er.place.line << "</code></a></td><td>" << inlineMarkdown(er.text) << "</td><td>";
    bool any = false;
    for (const auto& id : er.studies) {
      auto it = byId.find(id);
      if (it == byId.end()) continue;
      for (const auto& c : it->second->checks)
        if (checkErratumLabel(id, c.expected) == er.label) {
          h << (any ? "<br>" : "") << (c.passed ? "" : "<b style=\"color:var(--fail)\">FAIL</b> ") << e(c.name)
            << ": " << e(c.got) << " (threshold " << e(formatShort(c.tolerance)) << ")";
          any = true;
        }
    }
    if (!any) h << "<span style=\"color:var(--muted)\">see the study's checks</span>";
    h << "</td><td>";
    for (const auto& id : er.studies) {
      auto it = byId.find(id);
      if (it == byId.end()) {
        h << "<code>" << e(id) << "</code> (not run)<br>";
        continue;
      }
      h << badge(it->second->passed()) << " <a href=\"#" << e(anchor(id)) << "\"><code>" << e(id)
        << "</code></a><br>";
    }
    if (er.studies.empty()) h << "<span style=\"color:var(--muted)\">no study named</span>";
    h << "</td></tr>\n";
  }
  h << "</tbody></table>\n</section>\n";
}

}  // namespace

std::string reportHtml(const ReportInfo& info, const std::vector<StudyResult>& results,
                       const std::filesystem::path& reportDir, const std::vector<ReportSection>& sections) {
  const RunSummary sum = summarize(results);
  const int nStudies = sum.studiesPassed + sum.studiesFailed;
  const int nChecks = sum.checksPassed + sum.checksFailed;
  const auto chapters = byChapter(results);
  std::vector<std::string> ids;  // every registered study, so that --only still names them all
  for (const auto& s : registry()) ids.push_back(s.id);
  for (const auto& r : results)
    if (std::find(ids.begin(), ids.end(), r.study->id) == ids.end()) ids.push_back(r.study->id);
  Page page{info, reportDir, sourceRoot(), indexSources(sourceRoot(), ids), {}};
  auto addErratum = [&](const std::string& id, const std::string& label) {
    auto& v = page.errataOf[id];
    if (std::find(v.begin(), v.end(), label) == v.end()) v.push_back(label);
  };
  for (const auto& r : results)
    for (const auto& c : r.checks)
      if (const std::string l = checkErratumLabel(r.study->id, c.expected); !l.empty()) addErratum(r.study->id, l);
  for (const auto& er : page.src.errata)
    for (const auto& id : er.studies) addErratum(id, er.label);

  std::ostringstream h;
  const std::string verdict =
      sum.studiesFailed == 0
          ? fmt::format("ALL {} STUDIES PASSED", nStudies)
          : fmt::format("{} OF {} STUDIES FAILED", sum.studiesFailed, nStudies);

  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<title>soma report — " << e(verdict) << "</title>\n<style>" << kReportCss << "</style>\n"
    << "</head>\n<body>\n";

  // The sidebar: search, filters and the contents (a chapter per collapsible list).
  h << "<aside class=\"sidebar\">\n<div class=\"brand\">soma report</div>\n<div class=\"filters\">\n"
    << "<label for=\"f-q\">Search (ID, title, checks, notes)</label><input type=\"search\" id=\"f-q\" "
       "placeholder=\"e.g. cylindroid, GF-6.5, E4.8\" autocomplete=\"off\">\n"
    << "<label for=\"f-chapter\">Chapter</label><select id=\"f-chapter\"><option value=\"\">all chapters</option>";
  for (const auto& c : chapters) h << "<option value=\"" << e(c.name) << "\">" << e(c.name) << "</option>";
  h << "</select>\n<label for=\"f-verdict\">Verdict</label><select id=\"f-verdict\"><option value=\"\">passed "
       "and failed</option><option value=\"pass\">passed</option><option value=\"fail\">failed</option></select>\n"
    << "<label for=\"f-erratum\">Erratum</label><select id=\"f-erratum\"><option value=\"\">any study</option>"
       "<option value=\"*\">settles an erratum</option></select>\n"
    << "<label for=\"f-scalar\">Scalar</label><select id=\"f-scalar\"><option value=\"\">any scalar</option></select>\n"
    << "<button type=\"button\" class=\"clear\" id=\"f-clear\">clear</button>\n"
    << "<div id=\"match-count\">" << results.size() << " studies</div>\n</div>\n";
  h << "<nav class=\"toc\">\n<h2>Contents</h2>\n<div class=\"top\"><a href=\"#summary\">Summary</a>";
  for (const auto& s : sections) h << "<a href=\"#" << e(s.id) << "\">" << e(s.title) << "</a>";
  h << "<a href=\"#errata\">Errata index (" << page.src.errata.size() << ")</a></div>\n";
  for (std::size_t k = 0; k < chapters.size(); ++k) {
    const auto& c = chapters[k];
    const bool failing = c.passed != static_cast<int>(c.results.size());
    h << "<details" << (failing ? " open" : "") << "><summary><a href=\"#ch-" << k + 1 << "\">" << e(c.name)
      << "</a> <span class=\"tally\"><span class=\"shown\">" << c.results.size() << "</span> · " << c.passed
      << "/" << c.results.size() << " passed</span></summary>\n<ul>\n";
    for (const StudyResult* r : c.results)
      h << "<li data-id=\"" << e(r->study->id) << "\">" << badge(r->passed()) << "<a href=\"#"
        << e(anchor(r->study->id)) << "\" title=\"" << e(r->study->title) << "\"><span class=\"id\">"
        << e(r->study->id) << "</span></a></li>\n";
    h << "</ul></details>\n";
  }
  h << "</nav>\n</aside>\n<main>\n";

  h << "<header id=\"summary\">\n<h1>soma — reproduction report</h1>\n"
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
  row("Errata", fmt::format("{} in papers/ (<a href=\"#errata\">index</a>); {} studies settle one",
                            page.src.errata.size(), page.errataOf.size()));
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

  // Sections a caller adds (ReportSection), then the errata index; hidden while filtering.
  h << "<div class=\"hide-when-filtering\">\n";
  h << speedAccuracySectionHtml(results);
  for (const auto& s : sections)
    h << "<section class=\"extra\" id=\"" << e(s.id) << "\">\n<h2>" << e(s.title) << "</h2>\n" << s.html
      << "\n</section>\n";
  writeErrata(h, page, results);
  h << "</div>\n";

  for (std::size_t k = 0; k < chapters.size(); ++k) {
    const auto& c = chapters[k];
    int checks = 0, checksFailed = 0, figures = 0, errata = 0;
    double seconds = 0;
    std::map<std::string, int> papers;
    for (const StudyResult* r : c.results) {
      checks += static_cast<int>(r->checks.size());
      for (const auto& ch : r->checks) checksFailed += ch.passed ? 0 : 1;
      figures += static_cast<int>(r->figures.size());
      seconds += r->seconds;
      if (auto it = page.errataOf.find(r->study->id); it != page.errataOf.end()) errata += 1;
      if (auto it = page.src.papers.find(r->study->id); it != page.src.papers.end()) ++papers[it->second.file];
    }
    h << "<section class=\"chapter\" id=\"ch-" << k + 1 << "\">\n<h2>" << e(c.name)
      << "<span class=\"chapter-tally\">" << c.passed << " of " << c.results.size()
      << " passed</span></h2>\n<p class=\"chapter-summary\"><b>" << c.passed << " of " << c.results.size()
      << "</b> studies passed · <b>" << checks - checksFailed << " of " << checks << "</b> checks · "
      << errata << " stud" << (errata == 1 ? "y settles" : "ies settle") << " an erratum · " << figures
      << " figure" << (figures == 1 ? "" : "s") << " · " << e(formatSeconds(seconds));
    for (const auto& [file, n] : papers)
      h << " · <a href=\"" << e(fileUrl(page.root, file)) << "\"><code>" << e(file) << "</code></a>";
    h << "</p>\n";
    for (const StudyResult* r : c.results) writeStudy(h, *r, page);
    h << "</section>\n";
  }
  if (results.empty()) h << "<p>No study was run.</p>\n";
  h << "<footer>Generated by soma " << e(info.version) << " on " << e(info.date)
    << ". Expected values come from the book or from an independent method; a check passes when "
       "its error is at most its tolerance. Data: <a href=\"report.json\">report.json</a>. Search: "
       "lunr.js (MIT licence), copied beside this page."
       "</footer>\n</main>\n"
    << "<div id=\"lightbox\" role=\"dialog\"><div class=\"bar\"><button type=\"button\">close (Esc)</button>"
       "<span class=\"caption\"></span><a class=\"file\" href=\"#\">open the file</a></div><img alt=\"\"></div>\n"
    << "<script src=\"lunr.min.js\"></script>\n<script>" << detail::kReportScript << "</script>\n"
    << "</body>\n</html>\n";
  return h.str();
}

void writeReport(const std::filesystem::path& dir, const ReportInfo& info,
                 const std::vector<StudyResult>& results, const std::vector<ReportSection>& sections) {
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
  // The search library beside the page, so that the folder opens from disk without a server
  // (Debian's libjs-lunr; without it the page falls back to plain substring search).
  // The 3-D viewer (figures with a .scene.js beside them): Debian's libjs-three and its orbit
  // controls beside the page.
  auto copy = [&](const fs::path& from, const std::string& name) {
    if (!fs::exists(from, ec)) return false;
    std::ifstream in(from, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    write(name, text.str());
    return true;
  };
  copy(kLunrPath, "lunr.min.js");
  if (copy(kThreePath, "three.min.js") && copy(kOrbitControlsPath, "OrbitControls.js"))
    write("viewer.html", std::string(detail::kViewerHtml));
  write("report.json", reportJson(info, results));
  write("index.html", reportHtml(info, results, dir, sections));
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
