#pragma once
// A study reproduces one catalogue item (DESIGN §4): it computes, then records checks
// {name, expected, got, error, tolerance, seconds}; any failed check fails the study.
// Every number a check records is kept in the working scalar's digits (io::numberText: shortest
// round-trip text for float/double, 21/36/⌊p·log10 2⌋+2 digits for long double/float128/mpfr), so
// report.json and the terminal carry what the scalar computed (issue 22); error and tolerance are
// also kept as doubles, for sorting and plots.
#include "soma/algebra/scalar.hpp"
#include "soma/io/json_number.hpp"
#include "soma/studies/trade.hpp"

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

namespace soma::studies {

/// A ratio to three significant digits ("2.5e+08"), for the miss of a printed formula.
std::string missRatioText(double ratio);

struct Check {
  std::string name;      ///< what was checked, e.g. "log(exp(ξ)) = ξ, θ = π − 1e-8"
  std::string expected;  ///< the reference value as text (book value, identity, other method)
  std::string got;       ///< soma's value as text
  double error = 0;      ///< |got − expected| (or the residual of an identity), rounded to double
  double tolerance = 0;  ///< the check passes when error ≤ tolerance, rounded to double
  std::string errorText;      ///< error in the working scalar's digits (io::numberText)
  std::string toleranceText;  ///< tolerance in the working scalar's digits
  double seconds = 0;    ///< wall time since the previous check (the work that produced it)
  bool passed = false;
};

struct Figure {
  std::string file;     ///< path relative to the report directory, e.g. "figures/GF-4.4-helix.png"
  std::string caption;  ///< one sentence a reader of a paper can follow
};

/// What a running study writes to. Created by the runner; one per study run.
class Context {
 public:
  Context(ScalarKind scalar, std::filesystem::path reportDir, bool makeFigures);

  ScalarKind scalar() const { return scalar_; }
  bool makeFigures() const { return makeFigures_; }

  /// A numeric check: passes when |got − expected| ≤ tolerance. Values printed in full precision.
  template <class S>
  bool checkNear(const std::string& name, const S& expected, const S& got, const S& tolerance) {
    using std::abs;
    const S err = abs(got - expected);
    return record(name, io::numberText(expected), io::numberText(got), toDouble(err), toDouble(tolerance),
                  isFinite(err) && err <= tolerance, io::numberText(err), io::numberText(tolerance));
  }
  /// A residual check of an identity: passes when 0 ≤ residual ≤ tolerance. A residual is a norm or
  /// an absolute difference: a negative one (a signed quantity passed by mistake) fails.
  template <class S>
  bool checkResidual(const std::string& name, const S& residual, const S& tolerance) {
    return record(name, "0", io::numberText(residual), toDouble(residual), toDouble(tolerance),
                  isFinite(residual) && residual >= S(0) && residual <= tolerance, io::numberText(residual),
                  io::numberText(tolerance));
  }
  /// An exact check (a count, a classification): passes when expected == got.
  bool checkEqual(const std::string& name, long long expected, long long got);
  bool checkEqual(const std::string& name, const std::string& expected, const std::string& got);
  /// The book's printed formula fails, as its erratum says, by far more than rounding: passes when
  /// `residual` exceeds kPrintedMissFactor · `threshold`, where `threshold` is the rounding bound of
  /// the computation (the tolerance the corrected formula meets, k·ε·scale; 0 for exact arithmetic or
  /// a count). A miss of a few ulps is not an erratum (issue 27). Recorded as "<name> [as printed]",
  /// expected "fails (erratum <erratum>)", got "residual <value> = <ratio>× the rounding bound
  /// <threshold>", tolerance kPrintedMissFactor · threshold.
  static constexpr double kPrintedMissFactor = 1e3;
  template <class S>
  bool checkPrintedFails(const std::string& name, const std::string& erratum, const S& residual,
                         const std::type_identity_t<S>& threshold) {
    const S bound = S(threshold), far = S(kPrintedMissFactor) * bound;
    const bool passed = isFinite(residual) && residual > far;
    std::string got = "residual " + io::numberText(residual);
    if (bound > S(0))
      got += " = " + missRatioText(toDouble(residual) / toDouble(bound)) + "× the rounding bound " + io::numberText(bound);
    else
      got += " (exact computation: rounding bound 0)";
    if (!passed) got += "; an erratum must miss by more than " + missRatioText(kPrintedMissFactor) + "× the rounding bound";
    return record(name + " [as printed]", "fails (erratum " + erratum + ")", got, toDouble(residual), toDouble(far), passed,
                  io::numberText(residual), io::numberText(far));
  }
  /// A check whose error the study computed itself (e.g. a printed formula failing by design,
  /// recorded as `expected: "fails (erratum E4.8)"`). errorText/toleranceText: the two numbers in
  /// the working scalar's digits; empty = the double's shortest text.
  bool record(const std::string& name, const std::string& expected, const std::string& got,
              double error, double tolerance, bool passed, std::string errorText = {},
              std::string toleranceText = {});
  /// The same with error and tolerance in the scalar S they were computed in.
  template <class S>
  bool recordIn(const std::string& name, const std::string& expected, const std::string& got,
                const S& error, const std::type_identity_t<S>& tolerance, bool passed) {
    return record(name, expected, got, toDouble(error), toDouble(tolerance), passed,
                  io::numberText(error), io::numberText(S(tolerance)));
  }
  /// A speed/accuracy table (trade.hpp): shown under the study and gathered in the report's
  /// "speed vs accuracy" section. With a figure file name and figures on, its figure too
  /// (tradeFigure: time against error, one point per rung), registered with the caption.
  void trade(TradeTable table, const std::string& figureFile = {}, const std::string& caption = {});
  const std::vector<TradeTable>& trades() const { return trades_; }

  /// Absolute path for a figure file name (under <reportDir>/figures/); register it with figure().
  std::filesystem::path figurePath(const std::string& fileName) const;
  void figure(const std::string& fileName, const std::string& caption);
  /// Free text shown under the study in the report (method, erratum, what was measured).
  void note(const std::string& text);

  const std::vector<Check>& checks() const { return checks_; }
  const std::vector<Figure>& figures() const { return figures_; }
  const std::vector<std::string>& notes() const { return notes_; }
  bool passed() const;

 private:
  ScalarKind scalar_;
  std::filesystem::path reportDir_;
  bool makeFigures_;
  std::chrono::steady_clock::time_point last_;
  std::vector<Check> checks_;
  std::vector<Figure> figures_;
  std::vector<std::string> notes_;
  std::vector<TradeTable> trades_;
};

/// What `--scalar` does for a study (`soma study list`'s `runs_in`, the report header).
enum class RunsIn {
  Scalar,  ///< scalar-generic: runs in the asked scalar (--scalar, --bits)
  Double,  ///< runs in double whatever is asked; Study::whyDouble says why
  Ladder,  ///< a speed/accuracy study: runs every rung itself (mpfr at --bits), --scalar aside
};

/// The reason a SOMA_STUDY_DOUBLE study gives when its chapter or file does not give its own
/// (a `kWhyDouble` in the chapter's or the file's namespace hides this one).
inline constexpr const char* kWhyDouble = "not converted yet: its body is written in double";

struct Study {
  std::string id;       ///< catalogue ID, e.g. "GF-4.4.2-se3-log"
  std::string title;    ///< one line
  std::string source;   ///< "GF §4.4.2" (section; the book does not number equations)
  std::string chapter;  ///< report section, e.g. "GF 4 — Lie algebra"
  bool scalarGeneric = false;  ///< honours --scalar; otherwise it runs in double
  std::function<void(Context&)> run;
  /// Not scalar-generic: why it runs in double (a double-only dependency, figures of a
  /// double-only library part, not converted yet); shown by `soma study list` and the report.
  std::string whyDouble = {};
  /// A speed/accuracy study (RunsIn::Ladder): it runs every rung of the ladder itself.
  bool ladder = false;
  RunsIn runsIn() const { return ladder ? RunsIn::Ladder : scalarGeneric ? RunsIn::Scalar : RunsIn::Double; }
};
/// "--scalar", "every rung (…)" or "double: <why>": the `runs_in` of `soma study list --json`.
std::string runsInText(const Study& s);

/// All registered studies, sorted by id.
const std::vector<Study>& registry();
const Study* findStudy(const std::string& id);
void registerStudy(Study s);
/// The root of the source tree the studies were built from (its example robots are under
/// studies/robots/): SOMA_SOURCE_DIR, set for study.cpp by studies/CMakeLists.txt.
std::filesystem::path sourceRoot();

struct Registrar {
  explicit Registrar(Study s) { registerStudy(std::move(s)); }
};

/// Result of running one study.
struct StudyResult {
  const Study* study = nullptr;
  ScalarKind scalar = ScalarKind::Double;
  std::vector<Check> checks;
  std::vector<Figure> figures;
  std::vector<std::string> notes;
  std::vector<TradeTable> trades;
  int mpfrBits = 0;   ///< the mpfr precision of the run (the asked --bits)
  double seconds = 0;
  std::string error;  ///< an exception thrown by the study (counts as a failure)
  bool passed() const;
};

/// Run one study; exceptions are caught and reported as a failure.
StudyResult runStudy(const Study& s, ScalarKind scalar, const std::filesystem::path& reportDir,
                     bool makeFigures);

}  // namespace soma::studies

#define SOMA_STUDY_CONCAT2(a, b) a##b
#define SOMA_STUDY_CONCAT(a, b) SOMA_STUDY_CONCAT2(a, b)
/// Register a study at static-initialisation time. The general form names every field:
///   SOMA_STUDY({.id = "GF-2.1-U1-unit-complex", .title = ..., .source = "GF §2.1",
///               .chapter = "GF 2 — Lie groups", .scalarGeneric = true, .run = [](Context& c){...}});
#define SOMA_STUDY(...)                                                                   \
  static const ::soma::studies::Registrar SOMA_STUDY_CONCAT(somaStudyRegistrar_, __COUNTER__){ \
      ::soma::studies::Study __VA_ARGS__}
/// The short form, in a chapter file that defines `kChapter` (its report section), for a study
/// whose body FN(Context&) (a function or a lambda) runs in double:
///   SOMA_STUDY_DOUBLE("GF-6.1-meet-condition", "Two lines meet iff …", "GF §6.1", meetCondition);
#define SOMA_STUDY_DOUBLE(ID, TITLE, SOURCE, ...)                                                    \
  SOMA_STUDY({.id = ID, .title = TITLE, .source = SOURCE, .chapter = kChapter, .scalarGeneric = false, \
              .run = __VA_ARGS__, .whyDouble = kWhyDouble})
/// The short form for a study whose body is the function template FN<S>(Context&), run in the
/// scalar asked for (--scalar):
///   SOMA_STUDY_SCALAR("GF-4.4.2-se3-log", "…", "GF §4.4.2", se3Log);
#define SOMA_STUDY_SCALAR(ID, TITLE, SOURCE, FN)                                                          \
  SOMA_STUDY({.id = ID, .title = TITLE, .source = SOURCE, .chapter = kChapter, .scalarGeneric = true, \
              .run = [](::soma::studies::Context& c) { ::soma::withScalar(c.scalar(), [&]<class S>() { FN<S>(c); }); }})
