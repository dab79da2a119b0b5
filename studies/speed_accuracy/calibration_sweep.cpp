// SOMA-6R-calibration-sweep (issue 20 item 1): industrial arms as calibration leaves them — every
// DH parameter perturbed by a relative error ε ∈ {1e-9, 1e-6, 1e-3, 1e-1} of the length scale
// (lengths) or in radians (angles), so that axes nearly, not exactly, meet or are parallel — and
// solveIk on 100 poses each: completeness (the posture that generated the pose, random joints →
// forward kinematics, is among the answers), the real counts, certification, the method and the
// escalations. The perturbed robots are general 6R robots (GF §11.5: 16 complex postures).
// A sweep in the scalar asked for (--scalar), not a ladder study: it times no rung against another;
// solveIk<S> escalates to the next wider scalar by itself (the 'escalated' column).
#include "soma/geometry/serial/ik.hpp"
#include "soma/algebra/wrap_angle.hpp"
#include "soma/studies/scalar_draws.hpp"
#include "soma/studies/study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

namespace soma::studies::SOMA_UNITY_ID {
namespace {
using draws::frac;
using draws::maxOf;

struct Arm {
  const char* name;
  const char* kind;
  long rows[6][3];  ///< a (µm), α (degrees), d (µm); θ offsets 0 — exact in every scalar
};

// Standard DH (A_i = Rz(θ_i)·Tz(d_i)·Tx(a_i)·Rx(α_i)) from the makers' published dimensions.
const Arm kArms[] = {
    {"PUMA 560", "axes 4-6 meet (Pieper)",
     {{0, 90, 0}, {431800, 0, 0}, {20300, -90, 150050}, {0, 90, 431800}, {0, -90, 0}, {0, 0, 56250}}},
    {"UR5", "axes 2, 3, 4 parallel (Pieper)",
     {{0, 90, 89159}, {-425000, 0, 0}, {-392250, 0, 0}, {0, 90, 109150}, {0, -90, 94650}, {0, 0, 82300}}},
    {"KUKA KR 6 R900-type", "axes 4-6 meet (Pieper)",
     {{25000, 90, 400000}, {455000, 0, 0}, {35000, 90, 0}, {0, -90, 420000}, {0, 90, 0}, {0, 0, 80000}}},
    // Kinova Jaco-type curved wrist (60° between consecutive wrist axes, d5 ≠ 0): not Pieper.
    {"Kinova Jaco-type (curved wrist)", "no three axes meet or are parallel",
     {{0, 90, 275500}, {410000, 180, 0}, {0, 90, -9800}, {0, 60, -250080}, {0, 60, -85560}, {0, 180, -202780}}},
    // ABB IRB 140 dimensions with the tool flange's axis 6 offset 0.05 m from axis 5: axes 2 ∥ 3
    // and axes 4, 5 meet, but no triple: not Pieper.
    {"ABB IRB 140-type, offset wrist", "axes 2, 3 parallel, 4, 5 meet",
     {{70000, -90, 352000}, {360000, 0, 0}, {0, -90, 0}, {0, 90, 380000}, {50000, -90, 0}, {0, 0, 65000}}},
};

template <class S> SerialRobot<S> perturbed(const Arm& arm, const S& eps, std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(-1, 1);
  long Lum = 0;
  for (const auto& r : arm.rows) Lum = std::max({Lum, std::abs(r[0]), std::abs(r[2])});
  const S L = frac<S>(Lum, 1000000);
  auto U = [&] { return scalarCast<S>(u(g)); };
  std::vector<DHRow<S>> dh(6);
  for (int i = 0; i < 6; ++i)
    dh[i] = {JointType::Revolute, S(frac<S>(arm.rows[i][0], 1000000) + eps * L * U()),
             S(S(arm.rows[i][1]) * pi<S>() / S(180) + eps * U()), S(frac<S>(arm.rows[i][2], 1000000) + eps * L * U()),
             S(eps * U())};
  return SerialRobot<S>::fromDH(dh, DHConvention::Standard, SE3<S>(), SE3<S>(), arm.name);
}

template <class S> struct Cell {
  int poses = 0, found = 0, certified = 0, odd = 0, overCount = 0, escalated = 0, maxCount = 0, completed = 0;
  std::map<int, int> counts;
  std::map<std::string, int> methods;
  std::vector<double> seconds;
  S worst = 0;
  std::vector<std::string> missed;  ///< the first poses whose generating posture is not among the answers
};

// GF §11.5 (16 complex postures of a general 6R); SOMA-6R-calibration-sweep. Runs in the scalar asked
// for: the DH rows (exact in µm and degrees), the perturbations and the poses in S, solveIk<S> (which
// escalates to the next wider scalar itself when an eigenproblem's answer may be short).
template <class S> void sweep(Context& ctx) {
  const long levels[] = {1000000000, 1000000, 1000, 10};  // ε = 1/level
  constexpr int kPoses = 100;
  std::mt19937_64 g(20261202);
  std::uniform_real_distribution<double> uq(-3.1, 3.1);
  // the generating posture is "found" within 1e-6 rad, or 64 √ε where answers accepted at a residual
  // of √ε (the check below) are good only to about that (float: 2.2e-2)
  const S same = maxOf(S(1e-6), S(S(64) * Tolerance<S>::sqrtEpsilon()));
  std::string table =
      "robot | ε | poses | completeness | certified | real counts (count×poses) | odd | > 16 | completed by search | escalated | "
      "median ms | worst residual\n";
  std::string misses;
  for (const auto& arm : kArms) {
    for (long level : levels) {
      const S eps = frac<S>(1, level);
      const SerialRobot<S> robot = perturbed<S>(arm, eps, g);
      Cell<S> c;
      for (int k = 0; k < kPoses; ++k) {
        JointVector<S> q(6);
        for (int i = 0; i < 6; ++i) q(i) = scalarCast<S>(uq(g));
        const SE3<S> pose = robot.fk(q);
        const IkSolution<S> sol = solveIk(robot, pose);
        ++c.poses;
        bool hit = false;
        for (std::size_t j = 0; j < sol.count(); ++j) {
          S d = 0;
          using std::abs;
          for (int i = 0; i < 6; ++i) d = maxOf(d, S(abs(wrapAngle(S(sol.postures[j](i) - q(i))))));
          hit = hit || d < same;
          c.worst = maxOf(c.worst, sol.residuals[j]);
        }
        c.found += hit;
        if (!hit && c.missed.size() < 3) {
          std::string qs;
          for (int i = 0; i < 6; ++i) qs += (i ? ", " : "") + toString(toDouble(q(i)), 17);
          c.missed.push_back("pose " + std::to_string(k) + " (q = (" + qs + ")): " + std::to_string(sol.count()) +
                             " answers by " + sol.method + (sol.solved_in.empty() ? "" : " in " + sol.solved_in));
        }
        c.certified += sol.certified;
        const int n = int(sol.count());
        c.counts[n]++;
        c.odd += n % 2;
        c.overCount += n > 16;
        c.maxCount = std::max(c.maxCount, n);
        c.methods[sol.method]++;
        c.escalated += !sol.solved_in.empty() && sol.solved_in != scalarName<S>();
        for (const auto& note : sol.notes) c.completed += note.find("numerical completion") != std::string::npos;
        c.seconds.push_back(sol.seconds);
      }
      std::sort(c.seconds.begin(), c.seconds.end());
      std::string counts, methods;
      for (const auto& [n, m] : c.counts) counts += (counts.empty() ? "" : " ") + std::to_string(n) + "×" + std::to_string(m);
      for (const auto& [n, m] : c.methods) methods += (methods.empty() ? "" : ", ") + n + " " + std::to_string(m);
      char buf[640];
      std::snprintf(buf, sizeof buf, "%s (%s) | %.0e | %d | %.4f | %d | %s | %d | %d | %d | %d | %.3f | %.1e\n", arm.name,
                    methods.c_str(), toDouble(eps), c.poses, double(c.found) / c.poses, c.certified, counts.c_str(), c.odd, c.overCount,
                    c.completed, c.escalated, 1e3 * c.seconds[c.seconds.size() / 2], toDouble(c.worst));
      table += buf;
      for (const std::string& m : c.missed) misses += std::string(arm.name) + ", ε = " + toString(toDouble(eps), 1) + ": " + m + "\n";
      char id[160];
      std::snprintf(id, sizeof id, "%s, ε = %.0e: ", arm.name, toDouble(eps));
      // Completeness: the generating posture is among the answers of every pose.
      ctx.checkEqual(std::string(id) + "generating posture found (of " + std::to_string(kPoses) + " poses)", kPoses, c.found);
      // A count above the 16 complex postures of a general 6R cannot be a posture count.
      ctx.checkEqual(std::string(id) + "poses with more than 16 postures", 0, c.overCount);
      ctx.checkResidual(std::string(id) + "worst residual (√ε)", c.worst, Tolerance<S>::sqrtEpsilon());
    }
  }
  ctx.note(table);
  if (!misses.empty()) ctx.note("Generating postures not among the answers (the first three per cell; q in radians):\n" + misses);
  ctx.note("Each robot's every DH parameter (a, α, d, θ offset) is perturbed by ε·u, u uniform in [−1, 1] (lengths "
           "times the robot's largest DH length), one perturbed robot per (robot, ε); the poses are forward "
           "kinematics of uniform random joints in (−3.1, 3.1) (seed 20261202). 'completeness' is the fraction of "
           "poses whose generating posture is among the answers (within max(1e-6, 64√ε) rad); 'certified' counts answers the "
           "eigenproblem certifies complete; 'completed by search' counts answers the Ceres search completed "
           "(uncertified); 'escalated' counts re-solves in a wider scalar than the one asked for (" +
           std::string(scalarName<S>()) + "). Times are wall time on a shared machine.");
}

}  // namespace

SOMA_STUDY({.id = "SOMA-6R-calibration-sweep",
            .title = "Calibrated industrial arms (DH perturbed by 1e-9 … 1e-1): every posture found, counts and certification",
            .source = "GF §11.5",
            .chapter = "soma — inverse kinematics",
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { sweep<S>(c); }); }});

}  // namespace soma::studies::SOMA_UNITY_ID
