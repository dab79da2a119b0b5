// `soma report [--out DIR] [--only GLOB]... [--scalar T] [--bits N] [--no-figures]`: run the
// studies and write DIR/index.html, DIR/report.json and the figures (docs/cli.md).
#include "command.hpp"
#include "scalar_options.hpp"
#include "study_output.hpp"

#include "soma/studies/report.hpp"
#include "soma/studies/runner.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <iostream>

namespace soma::cli {

namespace {

using namespace soma::studies;

class ReportCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "report";
    spec.help = "run studies and write DIR/index.html, report.json, figures";
    spec.add("--out", out_, "output directory").withDefault();
    spec.add("--only", only_, "only studies matching these IDs or globs (repeatable)");
    scalar_.declare(spec);
    spec.flag("--no-figures", noFigures_, "skip figures");
  }

  int run(const Spec&, const Invocation& call) override {
    const ScalarKind kind = scalar_.apply();
    const bool figures = !noFigures_;
    const auto selected = selectStudies(only_);
    requireWritableFolder(out_);
    RunOptions opt;
    opt.scalar = kind;
    opt.outDir = out_;
    opt.makeFigures = figures;
    const bool color = useColor();
    const auto t0 = std::chrono::steady_clock::now();
    const auto results = runStudies(selected, opt, [&](const StudyResult& r, std::size_t k, std::size_t n) {
      const bool ok = r.passed();
      const std::string tag =
          color ? (ok ? "\033[1;32mPASS\033[0m" : "\033[1;31mFAIL\033[0m") : (ok ? "PASS" : "FAIL");
      std::cout << fmt::format("[{:>3}/{}] {}  {}  ({})\n", k + 1, n, tag, r.study->id, formatSeconds(r.seconds))
                << std::flush;
      if (!ok) {
        TextOptions text;
        text.outDir = out_;
        text.color = color;
        std::cout << formatStudyText(r, text);
      }
    });
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const ReportInfo info = collectReportInfo(kind, call.commandLine, secs, figures);
    writeReport(out_, info, results);
    const RunSummary sum = summarize(results);
    std::cout << formatSummaryLine(sum) << "\n";
    std::cout << "report: " << (std::filesystem::absolute(out_) / "index.html").string() << "\n";
    return sum.allPassed() ? 0 : 1;
  }

 private:
  std::vector<std::string> only_;
  ScalarOptions scalar_;
  std::string out_ = "out/report";
  bool noFigures_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(ReportCommand, 20);

}  // namespace soma::cli
