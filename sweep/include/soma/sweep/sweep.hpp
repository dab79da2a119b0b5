#pragma once
// Sweeps over a family of scenes (DESIGN §5, issue 26): a sweep file (io/sweep_file.hpp) names a
// base scene, the parameters to vary and the quantities to record; runSweep computes every point
// (each a scene graph evaluating only the outputs the quantities name) and writes one row per
// point, in point order, as CSV and JSON Lines:
//   io::SweepFile s = io::readSweep("cusps.json");
//   SweepSummary r = runSweep(s, {.out = "out/cusps"});
// On one machine the points run on TBB threads; launched by mpirun (Open MPI, when soma was built
// with SOMA_MPI) rank 0 hands out chunks of points to the other ranks as they ask (dynamic load
// balancing: points differ in cost by orders of magnitude), computes points itself between
// messages, and writes the rows in point order: the same rows as one process. Rows are appended
// one write(2) each as soon as every earlier point is done, so a killed sweep leaves a prefix of
// the rows (and perhaps a partial last line): rerun with the same --out, it keeps the complete
// rows, drops a partial line and computes only the points not written.
#include "soma/io/sweep_file.hpp"

#include <cstddef>
#include <filesystem>
#include <iosfwd>

namespace soma::sweep {

struct SweepOptions {
  std::filesystem::path out = "out/sweep";  ///< the rows' folder (created): sweep.json, the CSV and JSONL
  int threads = 0;                          ///< TBB threads per process (0: TBB's default)
  std::ostream* progress = nullptr;         ///< points done, rate and time left, about once a second
  double progressSeconds = 1.0;             ///< the interval between progress lines
};

struct SweepSummary {
  std::size_t points = 0;    ///< the sweep's points
  std::size_t skipped = 0;   ///< already written by an earlier run (resume)
  std::size_t computed = 0;  ///< computed by this run
  std::size_t failed = 0;    ///< rows whose status is not "ok" (those kept from an earlier run too)
  int ranks = 1;             ///< MPI processes (1 without mpirun)
  int threads = 1;           ///< TBB threads of this process
  double seconds = 0;        ///< wall time of this run
  bool writer = true;        ///< this process wrote the rows (rank 0)
  std::filesystem::path csv, jsonl;
};

/// One point's row: its scene built and evaluated (only the outputs the quantities name). A point
/// whose scene or solver fails is a row with status "error" and the message, not an exception.
io::SweepRow evaluatePoint(const io::SweepFile& sweep, std::size_t i);

/// Every point not yet written to `options.out`, in parallel; the rows in point order. InvalidInput
/// when --out holds the rows of another sweep (its sweep.json differs) or cannot be written.
/// Under mpirun (mpiLaunched()) every rank calls it; rank 0 writes and returns the summary.
SweepSummary runSweep(const io::SweepFile& sweep, const SweepOptions& options);

/// Whether this process was started by mpirun (Open MPI's or a PMI's environment) and soma has MPI.
bool mpiLaunched();
/// This process's rank as mpirun's environment gives it (before MPI_Init), 0 without mpirun: every
/// rank meets a bad sweep file alike, and only rank 0 says so.
int mpiLaunchRank();
/// Whether soma was built with MPI (SOMA_MPI).
bool mpiAvailable();

}  // namespace soma::sweep
