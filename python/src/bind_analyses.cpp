// The analyses of a serial robot — cuspidality (analyseCuspidality, GF §5.2.3), cusp-count maps
// over two DH lengths (cuspMap), workspace maps (analyseWorkspace) — and planar Burmester
// synthesis (BurmesterSynthesis, GF §5.3), in double as the library runs them.
#include "common.hpp"
#include "robot_handle.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/geometry/cuspidal/cuspidality.hpp"
#include "soma/geometry/cuspidal/parameter_map.hpp"
#include "soma/geometry/cuspidal/workspace_analysis.hpp"
#include "soma/geometry/planar/burmester_synthesis.hpp"

#include <fmt/format.h>

namespace soma::python {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXd pointsMatrix(const std::vector<Eigen::Vector2d>& p) {
  MatrixXd m(p.size(), 2);
  for (std::size_t i = 0; i < p.size(); ++i) m.row(Eigen::Index(i)) = p[i].transpose();
  return m;
}
MatrixXd pathMatrix(const std::vector<JointVector<double>>& path) {
  MatrixXd m(path.size(), path.empty() ? 0 : path[0].size());
  for (std::size_t i = 0; i < path.size(); ++i) m.row(Eigen::Index(i)) = path[i].transpose();
  return m;
}

py::dict cuspidality(const RobotHandle& h, bool witness, int aspectGrid, int poses, double secondsPerPair) {
  if (aspectGrid < 8 || aspectGrid > 4096) throw InvalidInput("cuspidality: aspect_grid must be in 8..4096, got " + std::to_string(aspectGrid));
  if (poses < 1) throw InvalidInput("cuspidality: poses must be at least 1");
  if (!(secondsPerPair > 0)) throw InvalidInput("cuspidality: seconds_per_pair must be positive");
  CuspidalOptions o;
  o.witness = witness;
  o.aspectGrid = aspectGrid;
  o.poses = poses;
  o.secondsPerPair = secondsPerPair;
  const CuspidalAnalysis a = analyseCuspidality(h.robot(), o);
  py::dict d;
  d["cuspidal"] = a.cuspidal;
  d["six_r"] = a.sixR;
  d["method"] = a.method;
  d["seconds"] = a.seconds;
  if (a.sixR) {
    const Witness6R& w = a.witness6r;
    d["witness_found"] = w.found;
    d["poses_tried"] = w.posesTried;
    d["pairs_tried"] = w.pairsTried;
    if (w.found) {
      d["witness_pose"] = w.pose;
      d["witness_start"] = VectorXd(w.start);
      d["witness_goal"] = VectorXd(w.goal);
      d["witness_path"] = pathMatrix(w.path);
      d["witness_sign"] = w.sign;
      d["witness_min_signed_det"] = w.minSignedDet;
    }
    return d;
  }
  d["verdict_seconds"] = a.verdictSeconds;
  MatrixXd cusps(a.cusps.cusps.size(), 2);
  py::list postures;
  for (std::size_t i = 0; i < a.cusps.cusps.size(); ++i) {
    cusps.row(Eigen::Index(i)) << a.cusps.cusps[i].rho, a.cusps.cusps[i].z;
    postures.append(VectorXd(a.cusps.cusps[i].posture));
  }
  d["cusps"] = cusps;                     // (ρ, z) of each cusp point
  d["cusp_postures"] = postures;
  d["cusp_count"] = int(a.cusps.cusps.size());
  d["cusp_scalar"] = a.cusps.scalar;
  d["aspects"] = a.aspectMap.count();
  py::list images;
  for (const auto& b : a.branches) images.append(pointsMatrix(b.section));
  d["singular_images"] = images;
  if (a.witness.found) {
    d["witness_path"] = MatrixXd([&] {
      MatrixXd p(a.witness.path.size(), 3);
      for (std::size_t i = 0; i < a.witness.path.size(); ++i) p.row(Eigen::Index(i)) = a.witness.path[i].transpose();
      return p;
    }());
    d["witness_certified"] = a.witness.certified;
  }
  d["witness_found"] = a.witness.found;
  return d;
}

}  // namespace

void bindAnalyses(py::module_& m) {
  m.def("_cuspidality", &cuspidality, py::arg("robot"), py::arg("witness") = true, py::arg("aspect_grid") = 256,
        py::arg("poses") = 4, py::arg("seconds_per_pair") = 0.5);
  m.def(
      "_cusp_map",
      [](const RobotHandle& h, const std::string& x, const std::string& y, int threads) {
        const ParameterAxis ax = parseParameterAxis(x), ay = parseParameterAxis(y);
        const CuspMap c = cuspMap(h.robot(), ax, ay, threads);
        Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> counts(ay.n, ax.n);
        for (int j = 0; j < ay.n; ++j)
          for (int i = 0; i < ax.n; ++i) counts(j, i) = c.count(i, j);
        VectorXd xs(ax.n), ys(ay.n);
        for (int i = 0; i < ax.n; ++i) xs(i) = ax.value(i);
        for (int j = 0; j < ay.n; ++j) ys(j) = ay.value(j);
        py::dict d;
        d["x_name"] = ax.name;
        d["y_name"] = ay.name;
        d["x"] = xs;
        d["y"] = ys;
        d["counts"] = counts;
        d["histogram"] = c.histogram();
        d["escalated"] = c.escalated;
        d["decoupled"] = c.decoupled;
        d["threads"] = c.threads;
        d["seconds"] = c.seconds;
        return d;
      },
      py::arg("robot"), py::arg("x"), py::arg("y"), py::arg("threads") = 0);
  m.def(
      "_workspace",
      [](const RobotHandle& h, int samples, int grid, std::optional<VectorXd> start, std::optional<VectorXd> goal,
         double margin, double seconds) {
        if (samples < 1 || samples > 100000000) throw InvalidInput("workspace: samples must be in 1..1e8, got " + std::to_string(samples));
        if (grid < 2 || grid > 4096) throw InvalidInput("workspace: grid must be in 2..4096, got " + std::to_string(grid));
        WorkspaceOptions o;
        o.samples = samples;
        o.grid = grid;
        o.margin = margin;
        o.seconds = seconds;
        if (start.has_value() != goal.has_value()) throw InvalidInput("workspace: give both start and goal of the plan, or neither");
        if (start) {
          const int n = h.robot().dof();
          if (start->size() != n || goal->size() != n)
            throw InvalidInput(fmt::format("workspace: start and goal need {} joint values", n));
          o.plan = std::make_pair(JointVector<double>(*start), JointVector<double>(*goal));
        }
        const WorkspaceAnalysis a = analyseWorkspace(h.robot(), o);
        const WorkspaceMaps& w = a.maps;
        Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> hits(w.nZ, w.nRho);
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> dex(w.nZ, w.nRho);
        for (int j = 0; j < w.nZ; ++j)
          for (int i = 0; i < w.nRho; ++i) {
            hits(j, i) = w.hits[std::size_t(j) * w.nRho + i];
            dex(j, i) = w.dexterity[std::size_t(j) * w.nRho + i];
          }
        py::dict d;
        d["samples"] = w.samples;
        d["hits"] = hits;
        d["dexterity"] = dex;
        d["rho_max"] = w.rhoMax;
        d["z_min"] = w.zMin;
        d["z_max"] = w.zMax;
        d["points"] = pointsMatrix(w.points);
        d["mean_dexterity"] = w.meanDexterity;
        d["reached_fraction"] = w.reachedFraction;
        d["seconds"] = w.seconds;
        py::list boundary;
        for (const auto& b : a.boundary) boundary.append(pointsMatrix(b));
        d["boundary"] = boundary;
        if (a.plan) {
          d["plan_found"] = a.plan->found;
          d["plan_path"] = pathMatrix(a.plan->path);
          d["plan_min_sigma"] = a.plan->minSigma;
          d["plan_note"] = a.plan->note;
        }
        return d;
      },
      py::arg("robot"), py::arg("samples") = 200000, py::arg("grid") = 120, py::arg("start") = py::none(),
      py::arg("goal") = py::none(), py::arg("margin") = 0.05, py::arg("seconds") = 2.0);

  m.def(
      "burmester",
      [](const std::vector<std::array<double, 3>>& positions) {
        std::vector<SE2<double>> pos;
        for (const auto& p : positions) pos.emplace_back(p[2], Eigen::Vector2d(p[0], p[1]));
        const planar::BurmesterSynthesis<double> syn(pos);
        py::dict d;
        d["positions"] = int(pos.size());
        if (pos.size() != 5) {
          d["pairs"] = py::list();
          d["note"] = "fewer than five positions: every circle point has its centre (use the curves); pairs only for five";
          return d;
        }
        int complexCount = 0;
        double complexResidual = 0, algebraic = 0;
        std::string notes;
        const auto pairs = syn.burmesterPairs(&complexCount, &complexResidual, &algebraic, &notes);
        py::list out;
        for (const auto& p : pairs) {
          py::dict q;
          q["centre"] = Eigen::Vector2d(p.centre);
          q["circle"] = Eigen::Vector2d(p.circle);
          q["radius"] = p.radius;
          q["residual"] = p.residual;
          out.append(q);
        }
        d["pairs"] = out;
        d["complex_count"] = complexCount;
        d["complex_residual"] = complexResidual;
        d["algebraic_residual"] = algebraic;
        d["notes"] = notes;
        if (pairs.size() >= 2) {
          const auto fb = syn.fourBar(pairs[0], pairs[1]);
          const auto chk = syn.drive(pairs[0], pairs[1]);
          py::dict f;
          f["ground_pivots"] = py::make_tuple(Eigen::Vector2d(fb.c1()), Eigen::Vector2d(fb.c4()));
          f["lengths"] = py::make_tuple(fb.ground(), fb.crank(), fb.coupler(), fb.rocker());
          f["worst_translation_error"] = chk.worstTranslation;
          f["worst_angle_error"] = chk.worstAngle;
          f["same_circuit"] = chk.sameCircuit;
          f["reached"] = chk.reached;
          d["fourbar"] = f;
        }
        return d;
      },
      py::arg("positions"),
      "Burmester synthesis (GF §5.3): positions [(x, y, angle), ...] of a moving frame; for five, the real "
      "centre/circle-point pairs and the 4-bar of the first two driven through the five positions.");
}

}  // namespace soma::python
