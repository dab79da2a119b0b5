#pragma once
// Selecting and running studies (DESIGN §4, §6): glob patterns over study IDs, natural order
// (GF-2 < GF-10), a run over a selection with a progress callback, and the tallies.
#include "soma/studies/study.hpp"

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace soma::studies {

/// Shell-style glob over a whole study ID: `*` any run of characters, `?` one character,
/// `[abc]` / `[a-z]` / `[!a-z]` a character class; `\x` matches x literally. Case-sensitive.
bool globMatch(std::string_view pattern, std::string_view text);
/// True when the pattern contains a glob metacharacter (`*`, `?` or `[`).
bool isGlob(std::string_view pattern);

/// Natural order of IDs and chapter names: runs of digits compare as numbers, so
/// "GF-2.1-x" < "GF-4.4-y" < "GF-10.1-z" and "GF 9 — …" < "GF 10 — …".
bool naturalLess(std::string_view a, std::string_view b);

/// A selection pattern that names no registered study (unknown ID, or a glob matching nothing).
class SelectionError : public std::invalid_argument {
 public:
  SelectionError(const std::string& pattern, const std::string& message)
      : std::invalid_argument(message), pattern_(pattern) {}
  const std::string& pattern() const { return pattern_; }

 private:
  std::string pattern_;
};

/// The studies named by `patterns` (exact IDs or globs), each once, in natural ID order.
/// An empty pattern list selects every study. Throws SelectionError naming the first pattern
/// that matches nothing (with a "did you mean" hint when an ID differs only in case).
std::vector<const Study*> selectStudies(const std::vector<std::string>& patterns,
                                        const std::vector<Study>& from = registry());

/// Every registered study in natural ID order (what `soma study list` prints).
std::vector<const Study*> allStudies(const std::vector<Study>& from = registry());

struct RunOptions {
  ScalarKind scalar = ScalarKind::Double;
  std::filesystem::path outDir = "out/report";  ///< figures go to outDir/figures/
  bool makeFigures = true;
};

/// Called after each study finishes: its result, its index (0-based) and the number of studies.
using ProgressFn = std::function<void(const StudyResult&, std::size_t index, std::size_t count)>;

/// Run the studies in order (runStudy catches what a study throws). Optional progress callback.
std::vector<StudyResult> runStudies(const std::vector<const Study*>& studies,
                                    const RunOptions& options, const ProgressFn& progress = {});

struct RunSummary {
  int studiesPassed = 0, studiesFailed = 0;
  int checksPassed = 0, checksFailed = 0;
  double seconds = 0;  ///< sum of the studies' wall times
  bool allPassed() const { return studiesFailed == 0; }
};
RunSummary summarize(const std::vector<StudyResult>& results);

}  // namespace soma::studies
