// GF §11.5.2–11.5.4: Stewart–Gough platforms whose legs share joints (Faugère & Lazard 1995's
// combinatorial classes 6-5, 6-4, 5-5, 4-4, with 6-6, 6-3 and 3-3 octahedral): every leg–joint
// pattern of these classes enumerated (stewartPattern), one random platform of each solved by soma's
// parameter homotopy and, independently, by PHCpack's total-degree blackbox solver on the same leg
// quadrics; the two counts of finite regular solutions must agree with each other and with the
// class's count in stewart_class.hpp. Patterns that are architecturally singular are refused.
// Double precision (PHCpack's); the homotopy in the other scalars is tested in tests/geometry/parallel.
#include "gf11/common.hpp"
#include "soma/algebra/errors.hpp"
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/geometry/parallel/stewart_class.hpp"
#include "soma/geometry/study/constraint_quadrics.hpp"
#include "soma/studies/study.hpp"

#include "stewart_phc.hpp"

#include <fmt/format.h>

#include <future>
#include <thread>

#include <map>
#include <numbers>
#include <random>
#include <set>

namespace soma::studies::gf11::SOMA_UNITY_ID {  // this file's own names in a unity batch
namespace {

using S = double;


/// Every assignment of 6 legs to k joints (restricted growth strings: joint of leg i ≤ 1 + max before).
std::vector<std::array<int, 6>> assignments(int k) {
  std::vector<std::array<int, 6>> out;
  std::array<int, 6> c{};
  const auto rec = [&](auto&& self, int i, int used) -> void {
    if (i == 6) {
      if (used == k) out.push_back(c);
      return;
    }
    for (int v = 0; v <= std::min(used, k - 1); ++v) {
      c[static_cast<std::size_t>(i)] = v;
      self(self, i + 1, std::max(used, v + 1));
    }
  };
  rec(rec, 0, 0);
  return out;
}

/// A random platform of the incidence (b, q): joints uniform in a box, the legs' lengths from a
/// random posture (so that posture is a real solution).
StewartPlatform<S> platformOf(const std::array<int, 6>& b, const std::array<int, 6>& q, std::mt19937_64& g, SE3<S>* pose) {
  std::array<Vec3<S>, 6> B, Q;
  for (auto& v : B) v = Vec3<S>(uni<S>(g, -1, 1), uni<S>(g, -1, 1), uni<S>(g, -0.3, 0.3));
  for (auto& v : Q) v = Vec3<S>(uni<S>(g, -0.6, 0.6), uni<S>(g, -0.6, 0.6), uni<S>(g, -0.2, 0.2));
  StewartPlatform<S> P;
  for (std::size_t i = 0; i < 6; ++i) {
    P.base[i] = B[static_cast<std::size_t>(b[i])];
    P.platform[i] = Q[static_cast<std::size_t>(q[i])];
  }
  Vec6<S> xi;
  xi << uni<S>(g, -0.3, 0.3), uni<S>(g, -0.3, 0.3), uni<S>(g, -0.3, 0.3), uni<S>(g, -0.2, 0.2), uni<S>(g, -0.2, 0.2), uni<S>(g, 0.8, 1.2);
  *pose = SE3Tangent<S>(xi).exp();
  P.legs = stewartLegLengths<S>(P, *pose);
  return P;
}

/// PHCpack on the leg quadrics, the Study quadric and a random chart: finite regular solutions
/// (a ≠ 0). Re-run in double double (-b2) when the fixed-seed double run disagrees with `compare`.
struct PhcCount {
  int finite = 0;
  double seconds = 0;
  std::string how;
};
struct PhcJob {
  std::vector<std::string> equations;
  std::string tag;
  int compare = 0;
};
PhcJob phcJob(const StewartPlatform<S>& P, std::mt19937_64& g, const std::string& tag, int compare) {
  Eigen::VectorXd w(8);
  for (Eigen::Index i = 0; i < 8; ++i) w(i) = uni<S>(g, -1, 1);
  return PhcJob{stewart_phc::equations(P, w), tag, compare};
}
PhcCount phcCount(const PhcJob& job) {
  PhcCount out;
  for (const std::string opt : {"-b -0", "-b2 -0"}) {
    const PhcResult run = solveWithPhc(job.equations, stewart_phc::studyNames(), job.tag, opt);
    const int finite = stewart_phc::classify(run).finite;
    out.finite = finite;
    out.seconds += run.seconds;
    out.how = "phc " + opt;
    if (finite == job.compare) break;
  }
  return out;
}
/// The PHCpack runs, as many at a time as the machine has cores (each is one sequential `phc`
/// process: run one after another they were 160 s of the report's 340 s on 2 cores).
std::vector<PhcCount> phcCounts(const std::vector<PhcJob>& jobs) {
  const std::size_t width = std::max(1u, std::thread::hardware_concurrency());
  std::vector<PhcCount> out(jobs.size());
  for (std::size_t first = 0; first < jobs.size(); first += width) {
    std::vector<std::future<PhcCount>> running;
    for (std::size_t k = first; k < std::min(jobs.size(), first + width); ++k)
      running.push_back(std::async(std::launch::async, [&jobs, k] { return phcCount(jobs[k]); }));
    for (std::size_t k = 0; k < running.size(); ++k) out[first + k] = running[k].get();
  }
  return out;
}

// GF §11.5.2–11.5.4 (Faugère & Lazard 1995's classes); SOMA-11.5-stewart-classes
void stewartClasses(Context& c) {
  // Every incidence with (base, platform) distinct joints in the classes asked, up to renumbering.
  const std::vector<std::pair<int, int>> classes = {{6, 6}, {6, 5}, {6, 4}, {5, 5}, {4, 4}, {6, 3}, {3, 3}};
  std::map<std::string, std::pair<std::array<int, 6>, std::array<int, 6>>> patterns;
  std::map<std::string, std::string> refused;
  for (const auto& [nb, nq] : classes)
    for (const auto& b : assignments(nb))
      for (const auto& q : assignments(nq)) {
        const std::string key = stewartPattern(b, q);
        if (patterns.count(key) || refused.count(key)) continue;
        std::mt19937_64 g0(1);
        SE3<S> pose;
        const auto P = platformOf(b, q, g0, &pose);
        const auto cls = classifyStewart<S>(P);
        if (!cls.singular_reason.empty()) refused[key] = cls.singular_reason;
        else patterns[key] = {b, q};
      }
  std::map<std::string, int> table;
  for (const auto& k : kStewartClassCounts) table[k.pattern] = k.count;
  std::string rows = "pattern | class | table | homotopy | PHCpack | real | time (homotopy, PHCpack)\n";
  int agree = 0, tabulated = 0, defining = 0, total = 0;
  std::mt19937_64 g(1151);
  struct Solved {
    std::string key, name;
    SE3<S> pose;
    StewartForwardSolution<S> sol;
  };
  std::vector<Solved> solved;
  std::vector<PhcJob> jobs;
  for (const auto& [key, bq] : patterns) {
    SE3<S> pose;
    const auto P = platformOf(bq.first, bq.second, g, &pose);
    const auto cls = classifyStewart<S>(P);
    auto sol = solveStewartForward<S>(P);
    jobs.push_back(phcJob(P, g, "classes-" + std::to_string(jobs.size()), sol.complexCount()));
    solved.push_back({key, cls.name, pose, std::move(sol)});
  }
  const std::vector<PhcCount> phcs = phcCounts(jobs);
  for (std::size_t n = 0; n < solved.size(); ++n) {
    const std::string& key = solved[n].key;
    const SE3<S>& pose = solved[n].pose;
    const auto& sol = solved[n].sol;
    const int hom = sol.complexCount();
    const PhcCount& phc = phcs[n];
    const auto it = table.find(key);
    const int tab = it == table.end() ? -1 : it->second;
    ++total;
    agree += hom == phc.finite;
    tabulated += tab == hom;
    bool hit = false;
    for (const auto& h : sol.postures) hit = hit || (h.matrix() - pose.matrix()).norm() <= Tolerance<S>::input();
    defining += hit;
    rows += fmt::format("{} | {} | {} | {} | {} ({}) | {} | {:.3f} s, {:.1f} s\n", key, solved[n].name, tab < 0 ? "—" : std::to_string(tab),
                        hom, phc.finite, phc.how, sol.count(), sol.seconds, phc.seconds);
  }
  // A standard hexapod: planar base and platform, each 3-fold symmetric with the same leg
  // permutation (random radii and half-angles, leg lengths from a random posture).
  int hexapodAgree = 0, hexapodTab = 0;
  for (int t = 0; t < 2; ++t) {
    const double wb = uni<S>(g, 5, 25), wq = uni<S>(g, 25, 55), rq = uni<S>(g, 0.4, 0.8), phase = uni<S>(g, -10, 10);
    const double deg = std::numbers::pi / 180;
    StewartPlatform<S> P;
    std::array<Vec3<S>, 6> q;
    for (int k = 0; k < 3; ++k)
      for (int sg = 0; sg < 2; ++sg) {
        const double ab = (120 * k + (sg ? wb : -wb)) * deg, aq = (120 * k + 60 + (sg ? wq : -wq) + phase) * deg;
        P.base[std::size_t(2 * k + sg)] = Vec3<S>(std::cos(ab), std::sin(ab), 0);
        q[std::size_t(2 * k + sg)] = Vec3<S>(rq * std::cos(aq), rq * std::sin(aq), 0);
      }
    for (std::size_t i = 0; i < 6; ++i) P.platform[i] = q[(i + 5) % 6];
    Vec6<S> xi;
    xi << uni<S>(g, -0.3, 0.3), uni<S>(g, -0.3, 0.3), uni<S>(g, -0.3, 0.3), uni<S>(g, -0.2, 0.2), uni<S>(g, -0.2, 0.2), uni<S>(g, 0.8, 1.2);
    P.legs = stewartLegLengths<S>(P, SE3Tangent<S>(xi).exp());
    const auto cls = classifyStewart<S>(P);
    const auto sol = solveStewartForward<S>(P);
    const PhcCount phc = phcCount(phcJob(P, g, "hexapod", sol.complexCount()));
    hexapodAgree += sol.complexCount() == phc.finite;
    hexapodTab += cls.expected_count == sol.complexCount();
    rows += fmt::format("standard hexapod (half-angles {:.1f}°, {:.1f}°) | {} | {} | {} | {} ({}) | {} | {:.3f} s, {:.1f} s\n", wb, wq,
                        cls.name, cls.expected_count.value_or(-1), sol.complexCount(), phc.finite, phc.how, sol.count(),
                        sol.seconds, phc.seconds);
  }
  c.note(rows);
  c.checkEqual("standard hexapods (planar, 3-fold symmetric; 2 random): homotopy and PHCpack agree", 2, hexapodAgree);
  c.checkEqual("… and find the class's 28 (stewart_class.hpp), not the 40 of a general planar platform", 2, hexapodTab);
  std::string refusedRows = "pattern | refused because\n";
  for (const auto& [key, why] : refused) refusedRows += fmt::format("{} | {}\n", key, why);
  c.note(refusedRows);
  c.checkEqual("patterns of the classes 6-6, 6-5, 6-4, 5-5, 4-4, 6-3, 3-3 that are not architecturally singular", 18,
               static_cast<long long>(patterns.size()));
  c.checkEqual("… where soma's homotopy and PHCpack find the same number of finite regular solutions", total, agree);
  c.checkEqual("… where that number is the class's count in stewart_class.hpp", total, tabulated);
  c.checkEqual("… where the posture that defined the leg lengths is among the real ones", total, defining);
}

SOMA_STUDY({.id = "SOMA-11.5-stewart-classes",
            .title = "Stewart platforms with shared joints (6-5, 6-4, 5-5, 4-4, 6-3, 3-3): every class's count by the homotopy and PHCpack",
            .source = "GF §11.5.2–11.5.4; Faugère & Lazard 1995",
            .chapter = kChapter,
            .scalarGeneric = false,
            .run = stewartClasses,
            .whyDouble = "PHCpack (an external program) reads and solves the systems in double"});

}  // namespace
}  // namespace soma::studies::gf11::SOMA_UNITY_ID
