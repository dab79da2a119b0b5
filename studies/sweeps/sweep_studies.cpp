// The two design-space studies of `soma sweep` (issue 26; papers/benchmarks/sweeps.md): each runs a
// sweep file of examples/sweeps/ through the sweep library (runSweep: TBB threads, rows written in
// point order), reads its rows back (io::readSweepRows), checks them against an independent method
// and draws the map. The rows (CSV and JSON Lines) are left beside the figures for a reader to reuse.
#include "soma/geometry/cuspidal/cusps.hpp"
#include "soma/geometry/cuspidal/parameter_map.hpp"
#include "soma/geometry/cuspidal/singular_set.hpp"
#include "soma/geometry/serial/ik.hpp"
#include "soma/io/scene_file.hpp"
#include "soma/io/sweep_file.hpp"
#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"
#include "soma/studies/cuspidal_figures.hpp"
#include "soma/studies/study.hpp"
#include "soma/sweep/sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

const char* kChapter = "soma — design-space sweeps";

/// Run `sweep` into a fresh folder (the report's figures folder, or a temporary one when figures
/// are off) and read its rows back, in point order.
std::vector<io::SweepRow> runRows(Context& c, const io::SweepFile& sweep, const std::string& folder,
                                  std::filesystem::path& where) {
  where = c.makeFigures() ? c.figurePath(folder) : std::filesystem::temp_directory_path() / ("soma-" + folder);
  std::filesystem::remove_all(where);  // a study computes every point (no resume from an earlier run)
  const sweep::SweepSummary s = sweep::runSweep(sweep, {.out = where});
  std::vector<io::SweepRow> rows = io::readSweepRows(sweep, s.jsonl);
  c.checkEqual("rows written, one per point, in point order", (long long)sweep.points(), (long long)rows.size());
  long long ordered = 0, ok = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ordered += rows[i].point == i;
    ok += rows[i].status == "ok";
  }
  c.checkEqual("rows in point order", (long long)rows.size(), ordered);
  c.checkEqual("every point computed (status ok)", (long long)rows.size(), ok);
  c.note(fmt::format("{} points on {} TBB threads in {:.2f} s; rows: {}", s.points, s.threads, s.seconds,
                     c.makeFigures() ? "figures/" + folder + "/" + sweep.csv + " and " + sweep.jsonl : "(not kept)"));
  if (!c.makeFigures()) std::filesystem::remove_all(where);
  return rows;
}

/// Keep every `stride`-th value of a grid parameter (the report's coarser grid of a study's sweep).
void thin(io::SweepParameter& p, std::size_t stride) {
  std::vector<double> v;
  for (std::size_t i = 0; i < p.values.size(); i += stride) v.push_back(p.values[i]);
  p.values = v;
}

// ---- SOMA-sweep-cusp-map-orthogonal-3r ---------------------------------------------------------
// Baili, Wenger and Chablat (2004) classify orthogonal 3R arms by the number of cusp points of
// their workspace section; GF §5.2.3 explains why a cusp makes an arm cuspidal. The sweep's
// quantity is the scene's `cuspidal` output (findCuspsAdaptive: the algebraic count, escalating
// its precision per arm); the second method counts the image reversals of the traced singular
// curves (singular_set.hpp), which shares nothing with it but the robot.
void cuspMapSweep(Context& c) {
  io::SweepFile sweep = io::readSweep(sourceRoot() / "examples/sweeps/cusp_map_study.json");
  // The study's 39 × 28 grid (papers/benchmarks/sweeps.md) every other value: 20 × 14 arms.
  thin(sweep.parameters[0], 2);
  thin(sweep.parameters[1], 2);
  std::filesystem::path where;
  const std::vector<io::SweepRow> rows = runRows(c, sweep, "sweep_cusp_map", where);
  const auto column = [&](const std::string& name) {
    for (std::size_t k = 0; k < sweep.quantities.size(); ++k)
      if (sweep.quantities[k].name == name) return k;
    throw InvalidInput("cusp_map_study.json has no quantity " + name);
  };
  const std::size_t cuspsAt = column("cusps");

  const SerialRobot<double> base = io::readRobot<double>(sourceRoot() / "studies/robots/cusp3r_orthogonal_wenger.json").robot;
  const io::SweepParameter &pa = sweep.parameters[0], &pb = sweep.parameters[1];
  CuspMap m;
  m.x = {.name = "a2 = d3 (Wenger's notation)", .isA = true, .row = 1, .min = pa.values.front(), .max = pa.values.back(),
         .n = int(pa.values.size())};
  m.y = {.name = "a3 = d4", .isA = true, .row = 2, .min = pb.values.front(), .max = pb.values.back(), .n = int(pb.values.size())};
  m.counts.assign(pa.values.size() * pb.values.size(), -1);
  // Grid point i: the first parameter slowest (io/sweep_file.hpp).
  for (const io::SweepRow& r : rows) {
    const std::size_t ia = r.point / pb.values.size(), ib = r.point % pb.values.size();
    m.counts[ib * pa.values.size() + ia] = std::stoi(r.values[cuspsAt]);
  }
  std::map<int, int> hist;
  for (int k : m.counts) ++hist[k];
  // Second method at every arm of the grid (traced image reversals); the figure labels every third.
  // The traced method does not count a reversal at a node of det J = 0 (two singular curves
  // crossing: with r3 = 0 and a3 > a2 the other curves cross two lines of det J ≡ 0, each mapped
  // to one point of the section). Where the methods differ, the difference must be the algebraic
  // cusps lying at such a point's image (within 1 % of the arm's length scale), nothing else.
  std::vector<MapCheckPoint> checks;
  int agree = 0, explained = 0, differ = 0;
  double farthest = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double a2 = rows[k].parameters[0], a3 = rows[k].parameters[1];
    const SerialRobot<double> arm = mapArm(base, m.x, a2, m.y, a3);
    const std::vector<SingularBranch> branches = traceSingularCurves(arm, detJSeries(arm));
    const int traced = int(imageReversals(branches).size());
    const int swept = std::stoi(rows[k].values[cuspsAt]);
    agree += traced == swept;
    if (k % 3 == 0 || traced != swept) checks.push_back({a2, a3, swept, traced});
    if (traced == swept) continue;
    ++differ;
    std::vector<Eigen::Vector2d> nodes;  // images of the lines θ3 = c (a branch whose image is one point)
    for (const SingularBranch& b : branches)
      if (b.closed && (b.section.back() - b.section.front()).norm() <= Tolerance<double>::sqrtEpsilon() * (1 + b.section.front().norm()))
        nodes.push_back(b.section.front());
    const CuspAnalysis<double> alg = findCuspsAdaptive(arm);
    int atNode = 0;
    for (const auto& q : alg.cusps)
      for (const auto& v : nodes)
        if (std::hypot(q.rho - v(0), q.z - v(1)) <= 0.01 * alg.frame.scale) {
          ++atNode;
          farthest = std::max(farthest, std::hypot(q.rho - v(0), q.z - v(1)) / alg.frame.scale);
          break;
        }
    explained += int(alg.cusps.size()) == swept && swept - traced == atNode;
  }
  c.checkEqual("the sweep's cusp count = the traced count (image reversals of the singular curves), or they differ "
               "by the cusps at the image of a node of det J = 0 (within 1 % of L), at every arm",
               (long long)rows.size(), agree + explained);
  c.note(fmt::format("The methods agree at {} of {} arms; at {} they differ by a pair of algebraic cusps beside the "
                     "image of a line of det J ≡ 0 (farthest {:.2g} L from it), a node where the traced method does "
                     "not count reversals: the 4-cusp cells in the 2-cusp domain near a3 = 2.85.",
                     agree, rows.size(), differ, farthest));
  // The literature arm (d2, d3, d4, r2, r3) = (1, 2, 1.5, 1, 0) has 4 cusps (Wenger; Baili et al.):
  // the same sweep at that one point.
  io::SweepFile one = sweep;
  one.parameters[0].values = {2.0};
  one.parameters[1].values = {1.5};
  const io::SweepRow wenger = sweep::evaluatePoint(one, 0);
  c.checkEqual("the literature arm (1, 2, 1.5, 1, 0): 4 cusps (Baili, Wenger, Chablat 2004)", "4",
               wenger.values.empty() ? wenger.message : wenger.values[cuspsAt]);
  std::string counts;
  for (const auto& [k, n] : hist) counts += fmt::format("{}{} arms with {} cusps", counts.empty() ? "" : ", ", n, k);
  c.note(fmt::format("{} arms (d2, d3, d4, r2, r3) = (1, a2, a3, 1, 0), a2 = {} … {}, a3 = {} … {}: {}. The domains by "
                     "number of cusps (0, 2, 4) are those of Baili, Wenger and Chablat's classification; the full "
                     "39 × 28 map is `soma sweep examples/sweeps/cusp_map_study.json` (papers/benchmarks/sweeps.md).",
                     rows.size(), pa.values.front(), pa.values.back(), pb.values.front(), pb.values.back(), counts));
  if (c.makeFigures()) {
    for (const std::string f : {"sweep_cusp_map.png", "sweep_cusp_map.svg"})
      plotCuspMap(m, "soma sweep: cusp points of orthogonal 3R arms (1, a2, a3, 1, 0)", c.figurePath(f), checks);
    c.figure("sweep_cusp_map.png",
             fmt::format("Number of cusp points of {} orthogonal 3R arms computed by `soma sweep` "
                         "(examples/sweeps/cusp_map_study.json, every other grid value); the numbers are the traced "
                         "count (checked at every arm, shown at every third; black: it agrees).",
                         rows.size()));
  }
}

// ---- SOMA-sweep-random-6r-real-postures --------------------------------------------------------
// How many of the 16 complex postures of a general 6R (GF §11.5) are real, over random robots at
// one pose. The sweep's quantity is the general-6R eigenproblem's count. Real solutions of a real
// system come with their complex conjugates, so the real count is even (16 − real = conjugate
// pairs); a Ceres multi-start search (a numerical method sharing nothing with the eigenproblem)
// must find no posture the eigenproblem missed.
void random6rSweep(Context& c) {
  io::SweepFile sweep = io::readSweep(sourceRoot() / "examples/sweeps/random_6r_study.json");
  // Each sample is drawn from its own stream (the seed and the point index): these are the first
  // 2000 of the study's 20000 robots.
  sweep.samples = 2000;
  std::filesystem::path where;
  const std::vector<io::SweepRow> rows = runRows(c, sweep, "sweep_random_6r", where);
  std::size_t realAt = 0, certifiedAt = 0;
  for (std::size_t k = 0; k < sweep.quantities.size(); ++k) {
    if (sweep.quantities[k].name == "real") realAt = k;
    if (sweep.quantities[k].name == "certified") certifiedAt = k;
  }
  std::map<int, int> hist;
  long long even = 0, certified = 0, bounded = 0;
  for (const io::SweepRow& r : rows) {
    const int n = std::stoi(r.values[realAt]);
    ++hist[n];
    even += n % 2 == 0;
    bounded += n >= 0 && n <= 16;
    certified += r.values[certifiedAt] == "true";
  }
  c.checkEqual("every real count is even (complex postures come in conjugate pairs)", (long long)rows.size(), even);
  c.checkEqual("every real count is at most the 16 complex postures", (long long)rows.size(), bounded);
  c.checkEqual("every answer certified (16 complex solutions, nothing added numerically)", (long long)rows.size(), certified);

  // A numerical search on 24 robots with real postures: every posture it finds is one of the
  // eigenproblem's (joint vectors compared modulo 2π).
  int robots = 0, found = 0, matched = 0;
  double worstMatch = 0, closestPair = 1e300;
  const auto wrapped = [](const JointVector<double>& p, const JointVector<double>& q) {
    double d = 0;
    for (Eigen::Index k = 0; k < p.size(); ++k) d = std::max(d, std::abs(std::remainder(p(k) - q(k), 2 * M_PI)));
    return d;
  };
  for (std::size_t k = 0; k < rows.size() && robots < 24; ++k) {
    if (std::stoi(rows[k].values[realAt]) == 0) continue;
    ++robots;
    const io::SceneFile scene = io::sweepPointScene(sweep, k);
    const SerialRobot<double> robot = io::sceneRobot<double>(*scene.entity("arm")).robot;
    const SE3<double> pose = io::scenePose<double>(*scene.entity("goal"));
    const IkSolution<double> eig = solveIk(robot, pose, {.method = IkMethod::General6R});
    const IkSolution<double> num = solveIk(robot, pose, {.method = IkMethod::Ceres});
    for (std::size_t a = 0; a < eig.postures.size(); ++a)
      for (std::size_t b = a + 1; b < eig.postures.size(); ++b)
        closestPair = std::min(closestPair, wrapped(eig.postures[a], eig.postures[b]));
    for (const auto& q : num.postures) {
      ++found;
      double best = 1e300;
      for (const auto& p : eig.postures) best = std::min(best, wrapped(p, q));
      worstMatch = std::max(worstMatch, std::min(best, M_PI));
      // Both postures have residuals at rounding level; distinct postures of these robots lie far
      // apart (the closest pair is printed), so sqrt(ε) tells the same posture from another.
      matched += best <= Tolerance<double>::sqrtEpsilon();
    }
  }
  c.checkEqual(fmt::format("every posture a Ceres multi-start finds on {} robots is one of the eigenproblem's", robots),
               (long long)found, (long long)matched);
  c.note(fmt::format("Ceres found {} postures on {} robots; the farthest from an eigenproblem posture {:.3g} rad; the "
                     "closest two distinct eigenproblem postures {:.3g} rad apart.",
                     found, robots, worstMatch, closestPair));
  std::string counts;
  for (const auto& [n, k] : hist)
    counts += fmt::format("{}{} real: {} ({:.1f} %)", counts.empty() ? "" : ", ", n, k, 100.0 * k / double(rows.size()));
  c.note(fmt::format("{} random 6R robots (a ∈ [0.1, 0.6], α ∈ [−1.5, 1.5], d ∈ [−0.4, 0.4], seed {}) at one pose: {}. "
                     "The 20000-robot run is `soma sweep examples/sweeps/random_6r_study.json` (papers/benchmarks/sweeps.md).",
                     rows.size(), sweep.seed, counts));
  if (c.makeFigures()) {
    render::Plot plot;
    plot.title = fmt::format("soma sweep: real postures of {} random 6R robots at one pose (16 complex each)", rows.size());
    plot.x.label = "real postures";
    plot.y.label = "share of the robots (%)";
    plot.x.min = -1;
    plot.x.max = 17;
    plot.x.ticks = {0, 2, 4, 6, 8, 10, 12, 14, 16};
    plot.y.min = 0;
    std::vector<double> xs, ys;
    for (const auto& [n, k] : hist) {
      const double share = 100.0 * k / double(rows.size());
      plot.add("", {double(n), double(n)}, {0.0, share}, render::palette::blue).width = 14;
      xs.push_back(n);
      ys.push_back(share);
      render::PlotText t;
      t.x = n;
      t.y = share;
      t.text = fmt::format("{:.1f} %", share);
      t.pixelHeight = 22;
      t.hAlign = render::HAlign::Center;
      t.dx = 0;
      t.dy = -10;
      plot.texts.push_back(t);
    }
    plot.y.max = 1.15 * *std::max_element(ys.begin(), ys.end());
    for (const std::string f : {"sweep_random_6r.png", "sweep_random_6r.svg"}) render::renderPlot(plot, c.figurePath(f));
    c.figure("sweep_random_6r.png",
             fmt::format("How many of the 16 complex postures are real, over {} random 6R robots at one pose "
                         "(examples/sweeps/random_6r_study.json, its first {} samples), computed by `soma sweep`.",
                         rows.size(), rows.size()));
  }
}

}  // namespace

SOMA_STUDY({.id = "SOMA-sweep-cusp-map-orthogonal-3r",
            .title = "soma sweep: cusp-count map of orthogonal 3R arms over (a2, a3), traced cross-check",
            .source = "GF §5.2.3; Baili, Wenger, Chablat 2004", .chapter = kChapter, .run = cuspMapSweep,
            .whyDouble = "a sweep: each point's scene runs in the scalar its file asks for (double), findCusps escalates per arm itself"});
SOMA_STUDY({.id = "SOMA-sweep-random-6r-real-postures",
            .title = "soma sweep: how many of the 16 postures are real over random 6R robots, checked by a numerical search",
            .source = "GF §11.5", .chapter = kChapter, .run = random6rSweep,
            .whyDouble = "a sweep: each point's scene runs in the scalar its file asks for (double); the eigenproblem escalates itself"});

}  // namespace soma::studies::SOMA_UNITY_ID
