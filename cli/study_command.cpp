// `soma study list [--json]` and `soma study run ID... [--scalar T] [--bits N] [--out DIR]
// [--no-figures] [--json]`: the registered studies, one per catalogue item (docs/cli.md).
#include "command.hpp"
#include "json_output.hpp"
#include "scalar_options.hpp"
#include "study_output.hpp"

#include "soma/studies/report.hpp"
#include "soma/studies/runner.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

namespace soma::cli {

namespace {

using namespace soma::studies;

class StudyCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "study";
    spec.help = "list or run the studies (one per catalogue item)";
    spec.requireSubcommand = true;
    list_ = &spec.subcommand("list", "every study: catalogue ID, title, source section");
    list_->flag("--json", listJson_, "print a JSON array");
    run_ = &spec.subcommand("run", "run studies by ID or glob ('GF-4.*'); print every check");
    run_->add("ids", ids_, "study IDs or shell globs").mustBeGiven();
    scalar_.declare(*run_);
    run_->add("--out", out_, "directory for figures (DIR/figures/)").withDefault();
    run_->flag("--no-figures", noFigures_, "skip figures");
    run_->flag("--json", runJson_, "print the results as JSON");
  }

  int run(const Spec&, const Invocation&) override {
    if (list_->parsed) {
      const auto studies = allStudies();
      std::cout << (listJson_ ? studyListJson(studies) + "\n" : formatStudyList(studies));
      return 0;
    }
    const ScalarKind kind = scalar_.apply();
    const auto selected = selectStudies(ids_);
    if (!noFigures_) requireWritableFolder(out_);
    RunOptions opt;
    opt.scalar = kind;
    opt.outDir = out_;
    opt.makeFigures = !noFigures_;
    TextOptions text;
    text.outDir = out_;
    text.color = useColor();
    const auto results = runStudies(selected, opt, [&](const StudyResult& r, std::size_t, std::size_t) {
      if (!runJson_) std::cout << formatStudyText(r, text) << std::flush;
    });
    const RunSummary sum = summarize(results);
    if (runJson_) {
      nlohmann::json arr = nlohmann::json::array();
      for (const auto& r : results) arr.push_back(nlohmann::json::parse(studyJson(r)));
      std::cout << jsonText(arr) << "\n";
    } else {
      std::cout << formatSummaryLine(sum) << "\n";
    }
    return sum.allPassed() ? 0 : 1;
  }

 private:
  Spec* list_ = nullptr;
  Spec* run_ = nullptr;
  bool listJson_ = false;
  std::vector<std::string> ids_;
  ScalarOptions scalar_;
  std::string out_ = "out/report";
  bool noFigures_ = false, runJson_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(StudyCommand, 10);

}  // namespace soma::cli
