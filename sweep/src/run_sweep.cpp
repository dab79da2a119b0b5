// The sweep's points on TBB threads and MPI ranks, the rows in point order (sweep.hpp, issue 26).
#include "soma/sweep/sweep.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/scene/scene_graph.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#ifdef SOMA_HAVE_MPI
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <map>
#include <mutex>
#include <ostream>
#include <sstream>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

namespace soma::sweep {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string fileText(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeAll(int fd, const std::string& text, const fs::path& file) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw InvalidInput(file.string() + ": cannot write a row (" + std::strerror(errno) + ")");
    done += std::size_t(n);
  }
}

// The two row files, open for appending after the rows kept.
struct RowFiles {
  int csv = -1, jsonl = -1;
  fs::path csvPath, jsonlPath;
  RowFiles() = default;
  RowFiles(const RowFiles&) = delete;
  RowFiles& operator=(const RowFiles&) = delete;
  ~RowFiles() {
    if (csv >= 0) ::close(csv);
    if (jsonl >= 0) ::close(jsonl);
  }
};

int openAt(const fs::path& f, std::size_t keep) {
  const int fd = ::open(f.c_str(), O_WRONLY | O_CREAT, 0644);
  if (fd < 0) throw InvalidInput(f.string() + ": cannot open for writing (" + std::strerror(errno) + ")");
  if (::ftruncate(fd, off_t(keep)) != 0 || ::lseek(fd, 0, SEEK_END) < 0) {
    ::close(fd);
    throw InvalidInput(f.string() + ": cannot truncate to the complete rows (" + std::strerror(errno) + ")");
  }
  return fd;
}

// The rows folder: sweep.json says which sweep its rows belong to; the complete rows of points
// 0, 1, ... k−1 in both files are kept, anything after them (a partial line) is cut. Returns k;
// `notOk` counts the kept rows whose status is not "ok".
std::size_t prepare(const io::SweepFile& s, const fs::path& out, RowFiles& f, std::size_t& notOk) {
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec || !fs::is_directory(out)) throw InvalidInput("--out " + out.string() + ": cannot create the folder (" + ec.message() + ")");
  const fs::path meta = out / "sweep.json";
  const std::string fingerprint = s.fingerprint + "\n";
  if (fs::exists(meta)) {
    if (fileText(meta) != fingerprint)
      throw InvalidInput("--out " + out.string() + ": holds the rows of another sweep (" + meta.string() +
                         " differs from " + s.origin + " and its base); give another --out or remove that folder");
  } else {
    const fs::path tmp = out / ("sweep.json." + std::to_string(::getpid()) + ".partial");
    {
      std::ofstream o(tmp, std::ios::binary);
      o << fingerprint;
      if (!o) throw InvalidInput("--out " + out.string() + ": cannot write " + tmp.string());
    }
    fs::rename(tmp, meta, ec);
    if (ec) throw InvalidInput("--out " + out.string() + ": cannot write " + meta.string() + " (" + ec.message() + ")");
  }
  f.csvPath = out / s.csv;
  f.jsonlPath = out / s.jsonl;
  // JSON Lines: the end offset of each complete row, in point order.
  const std::string jl = fileText(f.jsonlPath);
  std::vector<std::size_t> jEnd{0};
  std::vector<bool> jOk;
  for (std::size_t pos = 0;;) {
    const std::size_t nl = jl.find('\n', pos);
    if (nl == std::string::npos) break;
    const auto p = io::sweepJsonLinePoint(jl.substr(pos, nl + 1 - pos));
    if (!p || *p != jEnd.size() - 1 || *p >= s.points()) break;
    jOk.push_back(jl.substr(pos, nl + 1 - pos).find("\"status\":\"ok\"") != std::string::npos);
    pos = nl + 1;
    jEnd.push_back(pos);
  }
  // CSV: the header, then rows starting with their point.
  const std::string cs = fileText(f.csvPath);
  const std::string header = io::sweepCsvHeader(s);
  std::vector<std::size_t> cEnd;
  if (cs.compare(0, header.size(), header) == 0) {
    cEnd.push_back(header.size());
    for (std::size_t pos = header.size(); cEnd.size() < jEnd.size();) {
      const std::size_t nl = cs.find('\n', pos);
      const std::string lead = std::to_string(cEnd.size() - 1) + ",";
      if (nl == std::string::npos || cs.compare(pos, lead.size(), lead) != 0) break;
      pos = nl + 1;
      cEnd.push_back(pos);
    }
  }
  const std::size_t k = cEnd.empty() ? 0 : std::min(jEnd.size(), cEnd.size()) - 1;
  notOk = std::size_t(std::count(jOk.begin(), jOk.begin() + std::ptrdiff_t(k), false));
  f.jsonl = openAt(f.jsonlPath, jEnd[k]);
  f.csv = openAt(f.csvPath, cEnd.empty() ? 0 : cEnd[k]);
  if (cEnd.empty()) writeAll(f.csv, header, f.csvPath);
  return k;
}

// Rank 0's writer: rows arrive in any order and are appended in point order, each row one write
// per file; a progress line about once a second.
class Writer {
 public:
  Writer(RowFiles& f, std::size_t first, std::size_t end, const SweepOptions& o)
      : files_(f), next_(first), first_(first), end_(end), options_(o), t0_(Clock::now()), last_(t0_) {}

  void add(std::size_t point, std::string jsonl, std::string csv, bool ok) {
    const std::lock_guard<std::mutex> lock(mutex_);
    pending_.emplace(point, Row{std::move(jsonl), std::move(csv), ok});
    while (!pending_.empty() && pending_.begin()->first == next_) {
      const Row& r = pending_.begin()->second;
      writeAll(files_.jsonl, r.jsonl, files_.jsonlPath);
      writeAll(files_.csv, r.csv, files_.csvPath);
      failed_ += r.ok ? 0 : 1;
      pending_.erase(pending_.begin());
      ++next_;
    }
    if (options_.progress && std::chrono::duration<double>(Clock::now() - last_).count() >= options_.progressSeconds) {
      last_ = Clock::now();
      report();
    }
  }
  void finish() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (options_.progress) report();
  }
  [[nodiscard]] std::size_t failed() const { return failed_; }
  [[nodiscard]] std::size_t written() const { return next_ - first_; }

 private:
  struct Row {
    std::string jsonl, csv;
    bool ok;
  };
  void report() {
    const double t = since(t0_);
    const std::size_t done = next_ - first_, total = end_ - first_;
    const double rate = t > 0 ? double(done) / t : 0;
    const std::string left = done == total ? "0 s left"
                             : rate > 0    ? std::to_string(long(std::ceil(double(total - done) / rate))) + " s left"
                                           : "time left unknown";
    char pct[16];
    std::snprintf(pct, sizeof pct, "%.1f", total ? 100.0 * double(done) / double(total) : 100.0);
    char r[32];
    std::snprintf(r, sizeof r, "%.3g", rate);
    *options_.progress << "sweep: " << next_ << "/" << end_ << " points (" << pct << " % of this run), " << r
                       << " points/s, " << left << (failed_ ? ", " + std::to_string(failed_) + " not ok" : "") << "\n";
    options_.progress->flush();
  }

  RowFiles& files_;
  std::mutex mutex_;
  std::map<std::size_t, Row> pending_;
  std::size_t next_, first_, end_, failed_ = 0;
  const SweepOptions& options_;
  Clock::time_point t0_, last_;
};

// Points taken one at a time from `next` (below `end`) by every thread of a TBB arena, each
// row handed to `sink`. Each point is isolated: a thread waiting in a solver's own parallel loop
// takes no other point meanwhile.
template <class Sink>
void computePoints(const io::SweepFile& s, std::atomic<std::size_t>& next, std::size_t end, int threads, Sink&& sink) {
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    const int n = arena.max_concurrency();
    tbb::parallel_for(0, n, [&](int) {
      for (;;) {
        const std::size_t i = next.fetch_add(1);
        if (i >= end) break;
        io::SweepRow row;
        tbb::this_task_arena::isolate([&] { row = evaluatePoint(s, i); });
        sink(std::move(row));
      }
    }, tbb::simple_partitioner());
  });
}

int concurrency(int threads) {
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.initialize();
  return arena.max_concurrency();
}

SweepSummary runLocal(const io::SweepFile& s, const SweepOptions& o) {
  const auto t0 = Clock::now();
  RowFiles files;
  SweepSummary sum;
  sum.points = s.points();
  std::size_t keptNotOk = 0;
  sum.skipped = prepare(s, o.out, files, keptNotOk);
  sum.csv = files.csvPath;
  sum.jsonl = files.jsonlPath;
  sum.threads = concurrency(o.threads);
  Writer w(files, sum.skipped, sum.points, o);
  std::atomic<std::size_t> next{sum.skipped};
  computePoints(s, next, sum.points, o.threads, [&](io::SweepRow&& r) {
    w.add(r.point, io::sweepJsonLine(s, r), io::sweepCsvLine(s, r), r.status == "ok");
  });
  w.finish();
  sum.computed = w.written();
  sum.failed = keptNotOk + w.failed();
  sum.seconds = since(t0);
  return sum;
}

#ifdef SOMA_HAVE_MPI
// The messages: a worker asks with the rows of its last chunk (kRows), rank 0 answers with the
// next chunk [begin, end) (kWork) or with kStop when every point is handed out.
constexpr int kRows = 1, kWork = 2, kStop = 3;
constexpr char kField = '\x1f', kRecord = '\x1e';

std::string packRows(const io::SweepFile& s, std::vector<io::SweepRow>& rows) {
  std::sort(rows.begin(), rows.end(), [](const io::SweepRow& a, const io::SweepRow& b) { return a.point < b.point; });
  std::string out;
  for (const io::SweepRow& r : rows)
    out += std::to_string(r.point) + kField + (r.status == "ok" ? "1" : "0") + kField + io::sweepJsonLine(s, r) + kField +
           io::sweepCsvLine(s, r) + kRecord;
  return out;
}

void unpackRows(const std::string& text, Writer& w) {
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t end = text.find(kRecord, pos);
    const std::size_t a = text.find(kField, pos), b = text.find(kField, a + 1), c = text.find(kField, b + 1);
    w.add(std::stoull(text.substr(pos, a - pos)), text.substr(b + 1, c - b - 1), text.substr(c + 1, end - c - 1),
          text.substr(a + 1, b - a - 1) == "1");
    pos = end + 1;
  }
}

std::string receiveText(int source, int tag, int* from) {
  MPI_Status st;
  MPI_Probe(source, tag, MPI_COMM_WORLD, &st);
  int n = 0;
  MPI_Get_count(&st, MPI_CHAR, &n);
  std::string text(std::size_t(n), '\0');
  MPI_Recv(text.data(), n, MPI_CHAR, st.MPI_SOURCE, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  if (from) *from = st.MPI_SOURCE;
  return text;
}

SweepSummary runMpi(const io::SweepFile& s, const SweepOptions& o, int rank, int size) {
  const auto t0 = Clock::now();
  SweepSummary sum;
  sum.points = s.points();
  sum.ranks = size;
  sum.threads = concurrency(o.threads);
  sum.writer = rank == 0;
  // Rank 0 prepares the folder and tells every rank whether it can go on.
  RowFiles files;
  std::string error;
  unsigned long long first = 0;
  std::size_t keptNotOk = 0;
  if (rank == 0) {
    try {
      first = prepare(s, o.out, files, keptNotOk);
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  int errorSize = int(error.size());
  MPI_Bcast(&errorSize, 1, MPI_INT, 0, MPI_COMM_WORLD);
  error.resize(std::size_t(errorSize));
  MPI_Bcast(error.data(), errorSize, MPI_CHAR, 0, MPI_COMM_WORLD);
  if (errorSize > 0) throw InvalidInput(error);
  MPI_Bcast(&first, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  sum.skipped = std::size_t(first);
  sum.csv = files.csvPath;
  sum.jsonl = files.jsonlPath;

  if (rank != 0) {
    // A worker: ask, compute the chunk on this rank's threads, send its rows with the next ask.
    std::string rows;
    for (;;) {
      MPI_Send(rows.data(), int(rows.size()), MPI_CHAR, 0, kRows, MPI_COMM_WORLD);
      MPI_Status st;
      MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
      if (st.MPI_TAG == kStop) {
        MPI_Recv(nullptr, 0, MPI_CHAR, 0, kStop, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        break;
      }
      unsigned long long range[2];
      MPI_Recv(range, 2, MPI_UNSIGNED_LONG_LONG, 0, kWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      std::vector<io::SweepRow> done;
      std::mutex m;
      std::atomic<std::size_t> next{std::size_t(range[0])};
      computePoints(s, next, std::size_t(range[1]), o.threads, [&](io::SweepRow&& r) {
        const std::lock_guard<std::mutex> lock(m);
        done.push_back(std::move(r));
      });
      sum.computed += done.size();
      rows = packRows(s, done);
    }
    sum.seconds = since(t0);
    return sum;
  }

  // Rank 0: hands out chunks from the same counter its own threads take points from, writes.
  Writer w(files, sum.skipped, sum.points, o);
  std::atomic<std::size_t> next{sum.skipped};
  std::exception_ptr localError;  // a row that cannot be written: rethrown once the workers stopped
  std::thread local([&] {
    try {
      computePoints(s, next, sum.points, o.threads, [&](io::SweepRow&& r) {
        w.add(r.point, io::sweepJsonLine(s, r), io::sweepCsvLine(s, r), r.status == "ok");
      });
    } catch (...) {
      localError = std::current_exception();
    }
  });
  int active = size - 1;
  while (active > 0) {
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, kRows, MPI_COMM_WORLD, &flag, &st);
    if (!flag) {
      // Open MPI's blocking receive spins a core: poll instead, the points take longer than this.
      std::this_thread::sleep_for(std::chrono::microseconds(500));
      continue;
    }
    int from = 0;
    unpackRows(receiveText(st.MPI_SOURCE, kRows, &from), w);
    // Guided chunks: a quarter of each rank's share of what is left, at least one point.
    const std::size_t left = sum.points - std::min(sum.points, next.load());
    const std::size_t chunk = std::clamp<std::size_t>(left / (4 * std::size_t(size)), 1, 4096);
    const std::size_t begin = next.fetch_add(chunk);
    if (begin >= sum.points) {
      MPI_Send(nullptr, 0, MPI_CHAR, from, kStop, MPI_COMM_WORLD);
      --active;
      continue;
    }
    unsigned long long range[2] = {begin, std::min(begin + chunk, sum.points)};
    MPI_Send(range, 2, MPI_UNSIGNED_LONG_LONG, from, kWork, MPI_COMM_WORLD);
  }
  local.join();
  if (localError) std::rethrow_exception(localError);
  w.finish();
  sum.computed = w.written();
  sum.failed = keptNotOk + w.failed();
  sum.seconds = since(t0);
  return sum;
}
#endif

}  // namespace

bool mpiAvailable() {
#ifdef SOMA_HAVE_MPI
  return true;
#else
  return false;
#endif
}

bool mpiLaunched() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

int mpiLaunchRank() {
  for (const char* v : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
    if (const char* r = std::getenv(v)) return std::atoi(r);
  return 0;
}

io::SweepRow evaluatePoint(const io::SweepFile& s, std::size_t i) {
  io::SweepRow row;
  row.point = i;
  row.parameters = s.point(i);
  const auto t0 = Clock::now();
  try {
    scene::SceneGraph graph(io::sweepPointScene(s, i));
    const scene::SceneResult r = graph.evaluate(s.outputs);
    std::vector<std::string> json;
    for (const std::string& name : s.outputs) json.push_back(r.output(name)->json);
    io::sweepRowValues(s, json, row);
    row.status = r.ok() ? "ok" : "check-failed";
  } catch (const std::exception& e) {
    row.values.clear();
    row.residual = 0;
    row.status = "error";
    row.message = e.what();
  }
  row.seconds = since(t0);
  return row;
}

SweepSummary runSweep(const io::SweepFile& s, const SweepOptions& o) {
  if (!mpiLaunched()) return runLocal(s, o);
#ifdef SOMA_HAVE_MPI
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  }
  // Finalised on every path out (an InvalidInput from the folder reaches every rank alike).
  struct Finalise {
    ~Finalise() {
      int done = 0;
      MPI_Finalized(&done);
      if (!done) MPI_Finalize();
    }
  } finalise;
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size == 1) return runLocal(s, o);
  try {
    return runMpi(s, o, rank, size);
  } catch (const InvalidInput&) {
    throw;
  } catch (const std::exception& e) {
    // A rank failing half-way would leave the others waiting: stop them all.
    std::fprintf(stderr, "soma sweep: rank %d: %s\n", rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, 2);
    throw;
  }
#else
  const char* n = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (n && std::atoi(n) > 1)
    throw InvalidInput("soma sweep under mpirun -np " + std::string(n) +
                       ": this soma was built without MPI (SOMA_MPI off); every rank would run the whole sweep into the same --out");
  return runLocal(s, o);
#endif
}

}  // namespace soma::sweep
