#include "soma/studies/runner.hpp"

#include <algorithm>
#include <cctype>

namespace soma::studies {

namespace {

// Match one character class starting at p[i] == '['; on success sets `matched` and returns the
// index just past ']'. Returns npos when the class is not closed (then '[' is literal).
std::size_t matchClass(std::string_view p, std::size_t i, char c, bool& matched) {
  std::size_t j = i + 1;
  bool negate = false;
  if (j < p.size() && (p[j] == '!' || p[j] == '^')) {
    negate = true;
    ++j;
  }
  bool found = false;
  bool first = true;
  while (j < p.size() && (p[j] != ']' || first)) {
    first = false;
    char lo = p[j];
    if (lo == '\\' && j + 1 < p.size()) lo = p[++j];
    char hi = lo;
    if (j + 2 < p.size() && p[j + 1] == '-' && p[j + 2] != ']') {
      hi = p[j + 2];
      if (hi == '\\' && j + 3 < p.size()) hi = p[++j + 2];
      j += 2;
    }
    if (lo <= c && c <= hi) found = true;
    ++j;
  }
  if (j >= p.size()) return std::string_view::npos;
  matched = found != negate;
  return j + 1;
}

}  // namespace

bool globMatch(std::string_view p, std::string_view t) {
  // Iterative matcher with one backtrack point for the last '*' (linear in practice).
  std::size_t pi = 0, ti = 0;
  std::size_t starP = std::string_view::npos, starT = 0;
  while (ti < t.size()) {
    if (pi < p.size()) {
      const char pc = p[pi];
      if (pc == '*') {
        starP = pi++;
        starT = ti;
        continue;
      }
      if (pc == '?') {
        ++pi;
        ++ti;
        continue;
      }
      if (pc == '[') {
        bool matched = false;
        const std::size_t next = matchClass(p, pi, t[ti], matched);
        if (next != std::string_view::npos) {
          if (matched) {
            pi = next;
            ++ti;
            continue;
          }
        } else if (t[ti] == '[') {  // unclosed '[' is a literal
          ++pi;
          ++ti;
          continue;
        }
      } else {
        char lit = pc;
        std::size_t adv = 1;
        if (pc == '\\' && pi + 1 < p.size()) {
          lit = p[pi + 1];
          adv = 2;
        }
        if (lit == t[ti]) {
          pi += adv;
          ++ti;
          continue;
        }
      }
    }
    if (starP == std::string_view::npos) return false;
    pi = starP + 1;
    ti = ++starT;
  }
  while (pi < p.size() && p[pi] == '*') ++pi;
  return pi == p.size();
}

bool isGlob(std::string_view pattern) {
  return pattern.find_first_of("*?[") != std::string_view::npos;
}

bool naturalLess(std::string_view a, std::string_view b) {
  auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (isDigit(a[i]) && isDigit(b[j])) {
      std::size_t i2 = i, j2 = j;
      while (i2 < a.size() && isDigit(a[i2])) ++i2;
      while (j2 < b.size() && isDigit(b[j2])) ++j2;
      // Compare the numbers without converting (any length): skip leading zeros, then by length.
      std::size_t ia = i, jb = j;
      while (ia + 1 < i2 && a[ia] == '0') ++ia;
      while (jb + 1 < j2 && b[jb] == '0') ++jb;
      const auto na = a.substr(ia, i2 - ia), nb = b.substr(jb, j2 - jb);
      if (na.size() != nb.size()) return na.size() < nb.size();
      if (na != nb) return na < nb;
      i = i2;
      j = j2;
    } else {
      if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
      ++i;
      ++j;
    }
  }
  if ((a.size() - i) != (b.size() - j)) return (a.size() - i) < (b.size() - j);
  return a < b;  // equal under natural order (e.g. "01" vs "1"): fall back to plain order
}

std::vector<const Study*> allStudies(const std::vector<Study>& from) {
  std::vector<const Study*> out;
  out.reserve(from.size());
  for (const auto& s : from) out.push_back(&s);
  std::stable_sort(out.begin(), out.end(),
                   [](const Study* x, const Study* y) { return naturalLess(x->id, y->id); });
  return out;
}

std::vector<const Study*> selectStudies(const std::vector<std::string>& patterns,
                                        const std::vector<Study>& from) {
  const auto all = allStudies(from);
  if (patterns.empty()) return all;
  std::vector<bool> chosen(all.size(), false);
  for (const auto& pat : patterns) {
    bool any = false;
    for (std::size_t k = 0; k < all.size(); ++k) {
      if (isGlob(pat) ? globMatch(pat, all[k]->id) : all[k]->id == pat) {
        chosen[k] = true;
        any = true;
      }
    }
    if (any) continue;
    // Nothing matched: build a helpful message.
    auto lower = [](std::string s) {
      for (auto& ch : s) ch = char(std::tolower(static_cast<unsigned char>(ch)));
      return s;
    };
    std::string hint;
    const std::string lp = lower(pat);
    for (const Study* s : all) {
      if (isGlob(pat) ? globMatch(lp, lower(s->id)) : lower(s->id) == lp) {
        hint = " (did you mean '" + s->id + "'?)";
        break;
      }
    }
    if (hint.empty() && !isGlob(pat)) {
      // A prefix of an ID ("GF-2.1") is a common slip: suggest the glob.
      for (const Study* s : all)
        if (s->id.rfind(pat, 0) == 0) {
          hint = " (did you mean '" + pat + "*'?)";
          break;
        }
    }
    if (hint.empty()) hint = "; `soma study list` shows the IDs";
    throw SelectionError(pat, isGlob(pat) ? "no study matches '" + pat + "'" + hint
                                          : "unknown study '" + pat + "'" + hint);
  }
  std::vector<const Study*> out;
  for (std::size_t k = 0; k < all.size(); ++k)
    if (chosen[k]) out.push_back(all[k]);
  return out;
}

std::vector<StudyResult> runStudies(const std::vector<const Study*>& studies,
                                    const RunOptions& options, const ProgressFn& progress) {
  std::vector<StudyResult> results;
  results.reserve(studies.size());
  for (std::size_t k = 0; k < studies.size(); ++k) {
    results.push_back(runStudy(*studies[k], options.scalar, options.outDir, options.makeFigures));
    if (progress) progress(results.back(), k, studies.size());
  }
  return results;
}

RunSummary summarize(const std::vector<StudyResult>& results) {
  RunSummary s;
  for (const auto& r : results) {
    (r.passed() ? s.studiesPassed : s.studiesFailed) += 1;
    for (const auto& c : r.checks) (c.passed ? s.checksPassed : s.checksFailed) += 1;
    s.seconds += r.seconds;
  }
  return s;
}

}  // namespace soma::studies
