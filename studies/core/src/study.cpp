#include "soma/studies/study.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace soma::studies {

std::string missRatioText(double ratio) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", ratio);
  return buf;
}

Context::Context(ScalarKind scalar, std::filesystem::path reportDir, bool makeFigures)
    : scalar_(scalar), reportDir_(std::move(reportDir)), makeFigures_(makeFigures),
      last_(std::chrono::steady_clock::now()) {}

bool Context::record(const std::string& name, const std::string& expected, const std::string& got,
                     double error, double tolerance, bool passed, std::string errorText,
                     std::string toleranceText) {
  const auto now = std::chrono::steady_clock::now();
  const double secs = std::chrono::duration<double>(now - last_).count();
  if (errorText.empty()) errorText = io::numberText(error);
  if (toleranceText.empty()) toleranceText = io::numberText(tolerance);
  checks_.push_back({name, expected, got, error, tolerance, std::move(errorText), std::move(toleranceText),
                     secs, passed});
  last_ = std::chrono::steady_clock::now();
  return passed;
}

bool Context::checkEqual(const std::string& name, long long expected, long long got) {
  return record(name, std::to_string(expected), std::to_string(got),
                double(got > expected ? got - expected : expected - got), 0.0, expected == got);
}

bool Context::checkEqual(const std::string& name, const std::string& expected,
                         const std::string& got) {
  return record(name, expected, got, expected == got ? 0.0 : 1.0, 0.0, expected == got);
}

std::filesystem::path Context::figurePath(const std::string& fileName) const {
  const auto dir = reportDir_ / "figures";
  std::filesystem::create_directories(dir);
  return dir / fileName;
}

void Context::figure(const std::string& fileName, const std::string& caption) {
  figures_.push_back({"figures/" + fileName, caption});
}

void Context::note(const std::string& text) { notes_.push_back(text); }

void Context::trade(TradeTable table, const std::string& figureFile, const std::string& caption) {
  if (makeFigures_ && !figureFile.empty() && tradeFigure(table, figurePath(figureFile)) > 0) {
    figure(figureFile, caption);
    table.figure = "figures/" + figureFile;
  }
  trades_.push_back(std::move(table));
}

std::string runsInText(const Study& s) {
  switch (s.runsIn()) {
    case RunsIn::Scalar: return "--scalar";
    case RunsIn::Ladder: return "every rung: float, double, long double, float128, mpfr at --bits (a speed/accuracy study)";
    case RunsIn::Double: break;
  }
  return "double: " + (s.whyDouble.empty() ? std::string(kWhyDouble) : s.whyDouble);
}

bool Context::passed() const {
  return std::all_of(checks_.begin(), checks_.end(), [](const Check& c) { return c.passed; });
}

namespace {
std::vector<Study>& mutableRegistry() {
  static std::vector<Study> r;
  return r;
}
}  // namespace

void registerStudy(Study s) {
  auto& r = mutableRegistry();
  if (std::any_of(r.begin(), r.end(), [&](const Study& x) { return x.id == s.id; }))
    throw std::logic_error("study registered twice: " + s.id);
  const auto pos = std::lower_bound(r.begin(), r.end(), s.id,
                                    [](const Study& a, const std::string& id) { return a.id < id; });
  r.insert(pos, std::move(s));
}

const std::vector<Study>& registry() { return mutableRegistry(); }

std::filesystem::path sourceRoot() { return std::filesystem::path(SOMA_SOURCE_DIR); }

const Study* findStudy(const std::string& id) {
  for (const auto& s : registry())
    if (s.id == id) return &s;
  return nullptr;
}

bool StudyResult::passed() const {
  return error.empty() && !checks.empty() &&
         std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.passed; });
}

StudyResult runStudy(const Study& s, ScalarKind scalar, const std::filesystem::path& reportDir,
                     bool makeFigures) {
  StudyResult r;
  r.study = &s;
  r.scalar = s.scalarGeneric ? scalar : ScalarKind::Double;
  r.mpfrBits = mpfrBits();  // before the run: a study may change the precision for a reference
  Context ctx(r.scalar, reportDir, makeFigures);
  const auto t0 = std::chrono::steady_clock::now();
  try {
    s.run(ctx);
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.checks = ctx.checks();
  r.figures = ctx.figures();
  r.notes = ctx.notes();
  r.trades = ctx.trades();
  if (r.checks.empty() && r.error.empty()) r.error = "the study recorded no check";
  return r;
}

}  // namespace soma::studies
