// `soma sweep SWEEP.json [--out DIR] [--threads N] [--quiet]` (issue 26): every point of a sweep
// (io/sweep_file.hpp), one row per point in DIR's CSV and JSON Lines, in point order; progress on
// stderr. Under `mpirun -np N soma sweep …` the ranks share the points (soma/sweep/sweep.hpp).
// Rerun with the same --out: the points already written are skipped. Exit 0 when every row is
// "ok", 1 when a point failed its check or its computation, 2 for a bad sweep file or --out.
#include "command.hpp"

#include "soma/io/sweep_file.hpp"
#include "soma/sweep/sweep.hpp"

#include <fmt/format.h>
#include <iostream>

namespace soma::cli {

namespace {

class SweepCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "sweep";
    spec.help = "a sweep file's points (a scene with parameters varied): one row per point, CSV and JSON Lines; "
                "also under mpirun -np N";
    spec.add("sweep", file_, "sweep JSON: {\"base\", \"parameters\", \"quantities\", ...} (docs/cli.md)").mustBeGiven();
    spec.add("--out", out_, "the rows' folder (created; rerun with the same one to resume)").withDefault();
    spec.add("--threads", threads_, "TBB threads per process (default 0: all cores)").within(0, 1024);
    spec.flag("--quiet", quiet_, "no progress lines on stderr");
  }
  int run(const Spec&, const Invocation&) override {
    try {
      return runSweepFile();
    } catch (const std::exception&) {
      // Under mpirun every rank reads the same file and meets the same defect: rank 0 says it
      // (main prints the message), the other ranks exit 2 without repeating it.
      if (sweep::mpiLaunchRank() > 0) return 2;
      throw;
    }
  }

 private:
  int runSweepFile() {
    const io::SweepFile s = io::readSweep(file_);
    sweep::SweepOptions o;
    o.out = out_;
    o.threads = threads_;
    o.progress = quiet_ ? nullptr : &std::cerr;
    const sweep::SweepSummary r = sweep::runSweep(s, o);
    if (!r.writer) return 0;  // an MPI worker: rank 0 reports
    std::cout << fmt::format("sweep: {}   {} points: {} already written, {} computed, {} not ok   {:.3g} s on {} rank{} x {} thread{}\n",
                             file_, r.points, r.skipped, r.computed, r.failed, r.seconds, r.ranks, r.ranks == 1 ? "" : "s",
                             r.threads, r.threads == 1 ? "" : "s");
    std::cout << fmt::format("rows: {}  {}\n", r.csv.string(), r.jsonl.string());
    return r.failed == 0 ? 0 : 1;
  }

  std::string file_, out_ = "out/sweep";
  int threads_ = 0;
  bool quiet_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(SweepCommand, 97);

}  // namespace soma::cli
