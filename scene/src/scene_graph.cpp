// The scene graph's wiring (scene_graph.hpp): each node built once, on demand, traced.
#include "soma/scene/scene_graph.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/geometry/cuspidal/cuspidality.hpp"
#include "soma/geometry/cuspidal/workspace_analysis.hpp"
#include "soma/geometry/dynamics/clifford_dynamics.hpp"
#include "soma/geometry/dynamics/quintic_trajectory.hpp"
#include "soma/geometry/dynamics/robot_dynamics.hpp"
#include "soma/geometry/lines/cylindroid.hpp"
#include "soma/geometry/planar/burmester_synthesis.hpp"
#include "soma/geometry/lines/screw_axis.hpp"
#include "soma/geometry/parallel/solve_stewart.hpp"
#include "soma/geometry/screws/identification.hpp"
#include "soma/geometry/serial/ik.hpp"
#include "soma/io/scene_output.hpp"
#include "soma/render/plot.hpp"
#include "soma/render/renderer.hpp"
#include "soma/render/svg.hpp"
#include "soma/scene/tessellation.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <fstream>
#include <memory>

#include <unistd.h>

namespace soma::scene {

bool SceneResult::ok() const {
  for (const OutputResult& o : outputs)
    if (!o.ok) return false;
  return true;
}

const OutputResult* SceneResult::output(std::string_view name) const {
  for (const OutputResult& o : outputs)
    if (o.name == name) return &o;
  return nullptr;
}

bool SceneResult::built(std::string_view id) const {
  for (const TraceEntry& t : trace)
    if (t.id == id) return true;
  return false;
}

std::string outputNodeId(const io::SceneOutput& o) { return std::string(io::sceneOutputKindName(o.kind)) + ":" + o.name; }

namespace {

// "[double]", "[mpfr256]": an entity read in two scalars is two nodes.
template <class S> std::string scalarTag() {
  std::string s(scalarName<S>());
  if constexpr (std::is_same_v<S, mpreal>) s += std::to_string(mpfr::mpreal::get_default_prec());
  return "[" + s + "]";
}

// The shortest decimal that reads back as x ("9.81").
std::string shortest(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string via(const std::string& reason, const std::string& id) { return reason + " via " + id; }

template <class S> bool withinSqrtEps(const S& r) { return r <= Tolerance<S>::sqrtEpsilon(); }

template <class S> std::vector<double> doubles(const JointVector<S>& q) {
  std::vector<double> v;
  for (int i = 0; i < q.size(); ++i) v.push_back(toDouble(q(i)));
  return v;
}

// The figure's extent for lines, screws and cylindroid patches (world units: the scenes' metres).
constexpr double kFigureHalfLength = 1.0;

}  // namespace

SceneGraph::SceneGraph(io::SceneFile scene) : scene_(std::move(scene)) {}

template <class T, class F> const T& SceneGraph::node(const std::string& id, const std::string& reason, F&& build) {
  if (const auto it = nodes_.find(id); it != nodes_.end()) return *std::any_cast<const std::shared_ptr<T>&>(it->second);
  const auto t0 = std::chrono::steady_clock::now();
  auto value = std::make_shared<T>(build(id));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  nodes_.emplace(id, value);
  if (trace_) trace_->push_back({id, seconds, reason});
  return *value;
}

template <class S> const io::RobotFile<S>& SceneGraph::robot(const std::string& name, const std::string& reason) {
  return node<io::RobotFile<S>>("robot:" + name + scalarTag<S>(), reason,
                                [&](const std::string&) { return io::sceneRobot<S>(*scene_.entity(name)); });
}

template <class S> const SE3<S>& SceneGraph::pose(const std::string& name, const std::string& reason) {
  return node<SE3<S>>("pose:" + name + scalarTag<S>(), reason,
                      [&](const std::string&) { return io::scenePose<S>(*scene_.entity(name)); });
}

template <class S> const StewartPlatform<S>& SceneGraph::platform(const std::string& name, const std::string& reason) {
  return node<StewartPlatform<S>>("platform:" + name + scalarTag<S>(), reason,
                                  [&](const std::string&) { return io::scenePlatform<S>(*scene_.entity(name)); });
}

template <class S> const Vec6<S>& SceneGraph::screw(const std::string& name, const std::string& reason) {
  return node<Vec6<S>>("screw:" + name + scalarTag<S>(), reason,
                       [&](const std::string&) { return io::sceneScrew<S>(*scene_.entity(name)); });
}

template <class S> OutputResult SceneGraph::compute(const io::SceneOutput& o, const std::string& reason) {
  OutputResult r;
  r.name = o.name;
  switch (o.kind) {
    case io::SceneOutputKind::Ik: {
      const auto& rf = robot<S>(o.robot, reason);
      const auto& target = pose<S>(o.pose, reason);
      IkOptions options;
      const auto m = parseIkMethod(o.method);
      if (!m) throw InvalidInput(o.where + ".method: \"" + o.method + "\" is not one of " + ikMethodNames());
      options.method = *m;
      const IkSolution<S> sol = solveIk<S>(rf.robot, target, options);
      for (const S& e : sol.residuals) r.ok = r.ok && withinSqrtEps(e);
      r.json = io::ikOutputJson<S>(o, rf, sol, r.ok);
      for (const JointVector<S>& q : sol.postures) r.joints.push_back(doubles(q));
      break;
    }
    case io::SceneOutputKind::Fk: {
      const auto& rf = robot<S>(o.robot, reason);
      const JointVector<S> q = io::sceneJoints<S>(o, rf);
      const auto t0 = std::chrono::steady_clock::now();
      const SE3<S> g = rf.robot.fk(q);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      r.json = io::fkOutputJson<S>(o, rf, q, g, seconds);
      r.joints.push_back(doubles(q));
      break;
    }
    case io::SceneOutputKind::Stewart: {
      const auto& P = platform<S>(o.platform, reason);
      StewartOptions options;
      const auto m = parseStewartMethod(o.method);
      if (!m) throw InvalidInput(o.where + ".method: \"" + o.method + "\" is not one of " + stewartMethodNames());
      options.method = *m;
      const StewartSolution<S> sol = solveStewart<S>(P, options);
      for (const S& e : sol.residuals) r.ok = r.ok && withinSqrtEps(e);
      r.json = io::stewartOutputJson<S>(o, P, sol, r.ok);
      for (const SE3<S>& g : sol.postures) r.poses.push_back(SE3<double>(SO3<double>::fromMatrix(castMatrix<double>(Mat3<S>(g.rotation()))),
                                                                        castMatrix<double>(Vec3<S>(g.translation()))));
      break;
    }
    case io::SceneOutputKind::Workspace: {
      // GF §5.2.3 in double: the reachability and dexterity maps, the 3R singular boundary.
      if constexpr (std::is_same_v<S, double>) {
        const auto& rf = robot<double>(o.robot, reason);
        WorkspaceOptions options;
        options.samples = o.samples;
        options.grid = o.grid;
        const auto t0 = std::chrono::steady_clock::now();
        const WorkspaceAnalysis a = analyseWorkspace(rf.robot, options);
        io::WorkspaceRecord w;
        w.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        w.samples = a.maps.samples;
        w.grid = o.grid;
        w.rhoMax = a.maps.rhoMax;
        w.zMin = a.maps.zMin;
        w.zMax = a.maps.zMax;
        w.reachedCells = int(std::count_if(a.maps.hits.begin(), a.maps.hits.end(), [](int h) { return h > 0; }));
        w.reachedFraction = a.maps.reachedFraction;
        w.meanDexterity = a.maps.meanDexterity;
        w.boundaryCurves = int(a.boundary.size());
        for (const auto& c : a.boundary) w.boundaryPoints += int(c.size());
        r.ok = w.reachedCells > 0;
        r.json = io::workspaceOutputJson(o, w);
      }
      break;
    }
    case io::SceneOutputKind::Dynamics: {
      const auto& rf = robot<S>(o.robot, reason);
      const std::string modelId = "dynamics-model:" + o.robot + (o.payload.empty() ? "" : "+" + o.payload) +
                                  "[g=" + shortest(o.gravity) + "]" + scalarTag<S>();
      const SerialDynamics<S>& dyn = node<SerialDynamics<S>>(modelId, reason, [&](const std::string& id) {
        // The robot file's link inertias (double) in S, each in its link's home frame (GF §13.2.2).
        std::vector<SpatialInertia<S>> links;
        for (const SpatialInertia<double>& l : rf.links)
          links.emplace_back(S(l.mass()), Vec3<S>(castMatrix<S>(l.centreOfMass())), Mat3<S>(castMatrix<S>(l.inertiaAboutCentre())));
        SerialDynamics<S> d = serialDynamicsOf<S>(rf.robot, links, S(o.gravity));
        if (o.payload.empty()) return d;
        // The payload's com and inertia are in the last link's frame: its home inertia (GF §13.2.3).
        const SpatialInertia<S>& body = node<SpatialInertia<S>>("rigid-body:" + o.payload + scalarTag<S>(), via(reason, id),
                                                                [&](const std::string&) { return io::sceneRigidBody<S>(*scene_.entity(o.payload)); });
        JointVector<S> q0(rf.robot.dof());
        for (int i = 0; i < rf.robot.dof(); ++i) q0(i) = -rf.robot.joints()[std::size_t(i)].offset;
        return d.withPayload(body.transformed(rf.robot.frames(q0)[std::size_t(rf.robot.dof())]));
      });
      const auto ends = io::sceneTrajectoryEnds<S>(o, rf);
      const JointVector<S>& from = ends.first;
      const JointVector<S>& to = ends.second;
      // The dynamics variable is θ = q + offset (robot_dynamics.hpp).
      DynVector<S> offset(rf.robot.dof());
      for (int i = 0; i < rf.robot.dof(); ++i) offset(i) = rf.robot.joints()[std::size_t(i)].offset;
      const DynVector<S> th0 = DynVector<S>(from) + offset, th1 = DynVector<S>(to) + offset;
      io::DynamicsRecord d;
      d.scalar = std::string(scalarName<S>());
      d.bits = o.bits;
      d.maxAbsTorque.assign(std::size_t(rf.robot.dof()), 0.0);
      const S T(o.duration);
      double seconds = 0;
      S worst(0);
      using std::abs;
      for (int k = 0; k <= o.steps; ++k) {
        const TrajectorySample<S> x = quinticSample<S>(th0, th1, T, k == o.steps ? T : S(T * S(k) / S(o.steps)));
        const auto t0 = std::chrono::steady_clock::now();
        const DynVector<S> tau = dyn.inverseDynamics(x.theta, x.thetaDot, x.thetaDDot);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        // The closed form A θ̈ + B θ̇θ̇ + C (GF §13.2.2), an independent method: the residual.
        const DynVector<S> closed = dyn.inverseDynamicsClosedForm(x.theta, x.thetaDot, x.thetaDDot);
        const S scale = std::max(S(1), S(tau.cwiseAbs().maxCoeff()));
        worst = std::max(worst, S((tau - closed).cwiseAbs().maxCoeff() / scale));
        d.times.push_back(toDouble(x.t));
        JointVector<S> q = x.theta - offset;
        const double unit = rf.degrees ? 180.0 / pi<double>() : 1.0;
        std::vector<double> qd;
        for (int i = 0; i < q.size(); ++i)
          qd.push_back(toDouble(q(i)) * (rf.robot.joints()[std::size_t(i)].type == JointType::Revolute ? unit : 1.0));
        d.joints.push_back(qd);
        d.torques.push_back(doubles(JointVector<S>(tau)));
        for (int i = 0; i < tau.size(); ++i) d.maxAbsTorque[std::size_t(i)] = std::max(d.maxAbsTorque[std::size_t(i)], std::abs(toDouble(tau(i))));
      }
      d.seconds = seconds;
      d.residual = toDouble(worst);
      r.ok = withinSqrtEps(worst);
      if (o.cl062) {
        // Cl(0,6,2) (SB §5) only when the output asks for that form: its own node.
        const auto& momenta = node<std::pair<std::vector<std::vector<double>>, double>>(
            "momenta-cl062:" + o.name + scalarTag<S>(), reason, [&](const std::string&) {
              namespace cd = clifford_dynamics;
              const TrajectorySample<S> x = quinticSample<S>(th0, th1, T, S(T / S(2)));
              const ChainConfiguration<S> c = dyn.configuration(x.theta);
              const std::vector<Vec6<S>> v = dyn.linkVelocities(c, x.thetaDot);
              std::pair<std::vector<std::vector<double>>, double> out{{}, 0.0};
              S res(0);
              for (std::size_t i = 0; i < v.size(); ++i) {
                const Vec6<S> lp = cd::coScrewOf(cd::momentum(cd::inertiaElement(c.inertias[i]), cd::screwElement(SE3Tangent<S>(v[i]))));
                const Vec6<S> direct = c.inertias[i] * v[i];
                res = std::max(res, S((lp - direct).norm() / std::max(S(1), S(direct.norm()))));
                out.first.push_back(doubles(JointVector<S>(lp)));
              }
              out.second = toDouble(res);
              return out;
            });
        d.momenta = momenta.first;
        d.momentaResidual = momenta.second;
        r.ok = r.ok && momenta.second <= toDouble(Tolerance<S>::sqrtEpsilon());
      }
      r.json = io::dynamicsOutputJson(o, d, r.ok);
      break;
    }
    case io::SceneOutputKind::Figure: break;  // SceneGraph::figure, in double
    case io::SceneOutputKind::Report: break;  // SceneGraph::report
    case io::SceneOutputKind::Burmester: {
      // GF §5.4 in double: the Burmester pairs of 5 positions.
      if constexpr (std::is_same_v<S, double>) {
        const io::PlanarScene& m = node<io::PlanarScene>("planar-mechanism:" + o.mechanism + "[double]", reason,
                                                         [&](const std::string&) { return io::scenePlanarMechanism(*scene_.entity(o.mechanism)); });
        std::vector<SE2<double>> positions;
        for (const io::PlanarPosition& p : m.positions) positions.push_back(SE2<double>(p.angle, Vec2<double>(p.x, p.y)));
        const auto t0 = std::chrono::steady_clock::now();
        const planar::BurmesterSynthesis<double> bs(positions);
        int complexPairs = 0;
        const std::vector<planar::BurmesterPair<double>> pairs = bs.burmesterPairs(&complexPairs);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::vector<io::BurmesterPairRecord> rec;
        double worst = 0;
        for (const planar::BurmesterPair<double>& p : pairs) {
          rec.push_back({{p.centre(0), p.centre(1)}, {p.circle(0), p.circle(1)}, p.radius, p.residual});
          r.pairs.push_back({p.centre(0), p.centre(1), p.circle(0), p.circle(1), p.radius});
          worst = std::max(worst, p.residual);
        }
        r.ok = withinSqrtEps(worst);
        r.json = io::burmesterOutputJson(o, rec, complexPairs, worst, seconds, r.ok);
      }
      break;
    }
    case io::SceneOutputKind::Cuspidal: {
      // GF §5.2.3 in double (the analysis escalates its cusp points itself when ill-conditioned).
      if constexpr (std::is_same_v<S, double>) {
        const auto& rf = robot<double>(o.robot, reason);
        CuspidalOptions options;
        options.witness = o.witness;
        const CuspidalAnalysis a = analyseCuspidality(rf.robot, options);
        io::CuspidalRecord c;
        c.method = a.method;
        c.cuspidal = a.cuspidal;
        c.sixR = a.sixR;
        c.cuspCount = int(a.cusps.cusps.size());
        c.aspectCount = a.aspectMap.count();
        c.witnessFound = a.witness.found;
        c.witnessCertified = a.witness.certified;
        c.witnessPoints = int(a.witness.path.size());
        c.witnessNote = a.witness.note;
        c.seconds = a.seconds;
        if (a.sixR) {
          // 6R: the witness is witness6r (a spherical-wrist robot's `witness` is its positioning
          // arm's, three joints: not this robot's).
          const Witness6R& w6 = a.witness6r;
          c.witnessFound = w6.found;
          c.witnessCertified = false;
          c.witnessPoints = int(w6.path.size());
          c.witnessNote = w6.note;
          if (w6.found) {
            c.witnessTarget = {w6.pose.translation()(0), w6.pose.translation()(1), w6.pose.translation()(2)};
            c.witnessStart = doubles(w6.start);
            c.witnessGoal = doubles(w6.goal);
            c.residual = std::max(w6.startResidual, w6.goalResidual);
            r.joints = {c.witnessStart, c.witnessGoal};
            for (const JointVector<double>& q : w6.path) r.path.push_back(doubles(q));
          }
        } else if (a.witness.found) {
          c.witnessTarget = {a.witness.target(0), a.witness.target(1), a.witness.target(2)};
          c.witnessStart = doubles(a.witness.start);
          c.witnessGoal = doubles(a.witness.goal);
          c.residual = std::max(a.witness.startResidual, a.witness.goalResidual);
          r.joints = {c.witnessStart, c.witnessGoal};
          for (const Eigen::Vector3d& q : a.witness.path) r.path.push_back({q(0), q(1), q(2)});
        }
        r.ok = withinSqrtEps(c.residual);
        r.json = io::cuspidalOutputJson(o, c);
      }
      break;
    }
    case io::SceneOutputKind::ScrewSystem: {
      // The 6-vector form (GF ch. 8): no Clifford algebra is built for a screw-system question.
      ScrewMatX<S> generators(6, Eigen::Index(o.screws.size()));
      for (std::size_t i = 0; i < o.screws.size(); ++i) generators.col(Eigen::Index(i)) = screw<S>(o.screws[i], reason);
      const auto t0 = std::chrono::steady_clock::now();
      const ScrewSystemIdentification<S> id = identifyScrewSystem<S>(generators);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      r.ok = withinSqrtEps(id.frameResidual);
      r.json = io::screwSystemOutputJson<S>(o, id, seconds, r.ok);
      break;
    }
    case io::SceneOutputKind::Cylindroid: {
      const Vec6<S>& a = screw<S>(o.screws[0], reason);
      const Vec6<S>& b = screw<S>(o.screws[1], reason);
      const auto t0 = std::chrono::steady_clock::now();
      const Cylindroid<S> c = [&] {
        try {
          return Cylindroid<S>(a, b);
        } catch (const InvalidInput& e) {
          throw InvalidInput(o.where + ".screws: " + e.what());
        }
      }();
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      // The pencil's pitch distribution at each given screw reproduces that screw's own pitch
      // (GF §6.5.2, GF-6.5.2-cylindroid-principal-form), relative to the larger pitch in size.
      using std::abs;
      S residual(0);
      for (const Vec6<S>* s : {&a, &b}) {
        const S h = screwPitch(*s);
        const S scale = std::max(S(1), std::max(abs(c.pitchMax()), abs(c.pitchMin())));
        residual = std::max(residual, S(abs(c.pitch(c.angleOf(*s)) - h) / scale));
      }
      r.ok = withinSqrtEps(residual);
      r.json = io::cylindroidOutputJson<S>(o, c, residual, seconds, r.ok);
      break;
    }
  }
  return r;
}

const OutputResult& SceneGraph::output(const io::SceneOutput& o, const std::string& reason) {
  return node<OutputResult>(outputNodeId(o), reason, [&](const std::string& id) {
    for (const std::string& n : o.needs) (void)output(*scene_.output(n), via(reason, id));
    if (o.kind == io::SceneOutputKind::Figure) return figure(o, via(reason, id));
    if (o.kind == io::SceneOutputKind::Report) return report(o, via(reason, id));
    if (o.kind == io::SceneOutputKind::Cuspidal || o.kind == io::SceneOutputKind::Burmester ||
        o.kind == io::SceneOutputKind::Workspace)
      return compute<double>(o, via(reason, id));  // analyses in double
    setMpfrBits(o.bits);
    return withScalar(o.scalar, [&]<class S>() { return compute<S>(o, via(reason, id)); });
  });
}

OutputResult SceneGraph::figure2d(const io::SceneOutput& o, const std::string& reason) {
  render::Plot plot;
  plot.equalAspect = true;
  plot.x.label = "x";
  plot.y.label = "y";
  plot.title = scene_.origin.empty() ? o.name : std::filesystem::path(scene_.origin).filename().string() + ": " + o.name;
  std::vector<std::string> names;
  std::size_t colour = 0;
  auto circle = [](double cx, double cy, double r, std::vector<double>& xs, std::vector<double>& ys) {
    for (int k = 0; k <= 120; ++k) {
      xs.push_back(cx + r * std::cos(2 * pi<double>() * k / 120));
      ys.push_back(cy + r * std::sin(2 * pi<double>() * k / 120));
    }
  };
  for (const io::SceneEntity& e : scene_.entities) {
    if (e.kind != io::SceneEntityKind::PlanarMechanism) continue;
    if (!o.draw.empty() && std::find(o.draw.begin(), o.draw.end(), e.name) == o.draw.end()) continue;
    names.push_back(e.name);
    const io::PlanarScene& m = node<io::PlanarScene>("planar-mechanism:" + e.name + "[double]", reason,
                                                     [&](const std::string&) { return io::scenePlanarMechanism(e); });
    if (m.fourbar) {
      // GF §5.3: the ground pivots, the crank at its angle, the circles the moving pivots keep to.
      const io::PlanarFourBarInput& f = *m.fourbar;
      const Vec2<double> c2 = f.c1 + f.crank * Vec2<double>(std::cos(f.crankAngle), std::sin(f.crankAngle));
      plot.add(e.name + ": ground pivots", {f.c1(0), f.c4(0)}, {f.c1(1), f.c4(1)}, render::palette::black).markers = true;
      plot.series.back().line = false;
      plot.add(e.name + ": crank", {f.c1(0), c2(0)}, {f.c1(1), c2(1)}, render::palette::blue);
      std::vector<double> xs, ys;
      circle(f.c1(0), f.c1(1), f.crank, xs, ys);
      plot.add("", xs, ys, render::palette::skyBlue).dashed = true;
      xs.clear(), ys.clear();
      circle(f.c4(0), f.c4(1), f.rocker, xs, ys);
      plot.add("", xs, ys, render::palette::skyBlue).dashed = true;
      continue;
    }
    // The positions: each frame's origin and its x axis (a tenth of the positions' extent).
    std::vector<double> xs, ys;
    double lo = 1e300, hi = -1e300;
    for (const io::PlanarPosition& p : m.positions) {
      xs.push_back(p.x), ys.push_back(p.y);
      lo = std::min({lo, p.x, p.y}), hi = std::max({hi, p.x, p.y});
    }
    const double tick = std::max(0.1 * (hi - lo), 1e-3);
    render::PlotSeries& pos = plot.add(e.name + ": positions", xs, ys, render::palette::black);
    pos.markers = true;
    pos.markerRadius = 6;
    for (const io::PlanarPosition& p : m.positions)
      plot.add("", {p.x, p.x + tick * std::cos(p.angle)}, {p.y, p.y + tick * std::sin(p.angle)}, render::palette::black);
    // The Burmester pairs of the burmester outputs using it (GF §5.4): centre, circle, the circle
    // point at each position.
    for (const io::SceneOutput& u : scene_.outputs) {
      if (u.kind != io::SceneOutputKind::Burmester || u.mechanism != e.name) continue;
      const OutputResult& b = output(u, reason);
      for (const OutputResult::Pair2d& q : b.pairs) {
        const render::Color c = render::palette::cycle(colour++);
        std::vector<double> cx, cy;
        circle(q.cx, q.cy, q.radius, cx, cy);
        plot.add("", cx, cy, c);
        std::vector<double> px, py;
        for (const io::PlanarPosition& p : m.positions) {
          const Vec2<double> w = SE2<double>(p.angle, Vec2<double>(p.x, p.y)).act(Vec2<double>(q.px, q.py));
          px.push_back(w(0)), py.push_back(w(1));
        }
        render::PlotSeries& s = plot.add("", px, py, c);
        s.line = false;
        s.markers = true;
        render::PlotSeries& centre = plot.add("", {q.cx}, {q.cy}, c);
        centre.line = false;
        centre.markers = true;
        centre.markerRadius = 9;
      }
    }
  }
  const bool svg = !o.svg.empty();
  const std::filesystem::path file = svg ? o.svg : o.png;
  const auto t0 = std::chrono::steady_clock::now();
  const std::filesystem::path partial = file.string() + "." + std::to_string(::getpid()) + ".partial";
  try {
    if (svg) render::renderPlotSvg(plot, partial, o.width, o.height);
    else render::renderPlotPng(plot, partial, o.width, o.height);
  } catch (const std::exception& x) {
    std::error_code ec;
    std::filesystem::remove(partial, ec);
    throw InvalidInput(o.where + (svg ? ".svg" : ".png") + ": cannot write " + file.string() + " (" + x.what() + ")");
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  pending_.push_back({outputNodeId(o), partial, file});
  OutputResult r;
  r.name = o.name;
  r.json = io::figureOutputJson(o, names, seconds);
  return r;
}

OutputResult SceneGraph::figure(const io::SceneOutput& o, const std::string& reason) {
  // 2-D when it asks for SVG or draws planar mechanisms only.
  bool planar = !o.draw.empty();
  for (const std::string& d : o.draw) planar = planar && scene_.entity(d)->kind == io::SceneEntityKind::PlanarMechanism;
  if (planar || !o.svg.empty()) return figure2d(o, reason);
  auto drawn = [&](const std::string& name) {
    if (o.draw.empty()) return true;
    for (const std::string& d : o.draw)
      if (d == name) return true;
    return false;
  };
  render::Scene all;
  std::vector<std::string> names;
  for (const io::SceneEntity& e : scene_.entities) {
    // A pose is drawn by the robot reaching it; a planar mechanism has its own 2-D figure (soma planar).
    if (!drawn(e.name) || e.kind == io::SceneEntityKind::Pose || e.kind == io::SceneEntityKind::PlanarMechanism) continue;
    names.push_back(e.name);
    const render::Scene& part = node<render::Scene>("tessellation:" + e.name, reason, [&](const std::string& id) {
      const std::string why = via(reason, id);
      switch (e.kind) {
        case io::SceneEntityKind::Robot: {
          const auto& rf = robot<double>(e.name, why);
          std::vector<JointVector<double>> postures;  // those of the ik, fk and cuspidal outputs using it
          std::vector<std::vector<JointVector<double>>> paths;  // cuspidal witness paths
          // One output per question: the same postures asked in two scalars are drawn once, from
          // the first such output in the scene.
          std::vector<std::string> asked;
          for (const io::SceneOutput& u : scene_.outputs)
            if ((u.kind == io::SceneOutputKind::Ik || u.kind == io::SceneOutputKind::Fk ||
                 u.kind == io::SceneOutputKind::Cuspidal) && u.robot == e.name) {
              const std::string question = std::string(io::sceneOutputKindName(u.kind)) + ":" + u.pose + ":" + u.joints;
              if (std::find(asked.begin(), asked.end(), question) != asked.end()) continue;
              asked.push_back(question);
              const OutputResult& out = output(u, why);
              for (const auto& q : out.joints)
                postures.push_back(Eigen::Map<const JointVector<double>>(q.data(), Eigen::Index(q.size())));
              if (!out.path.empty()) {
                std::vector<JointVector<double>> path;
                for (const auto& q : out.path) path.push_back(Eigen::Map<const JointVector<double>>(q.data(), Eigen::Index(q.size())));
                paths.push_back(std::move(path));
              }
            }
          return robotTessellation(rf.robot, postures, paths, e.name);
        }
        case io::SceneEntityKind::Platform: {
          const auto& P = platform<double>(e.name, why);
          std::vector<SE3<double>> postures;
          for (const io::SceneOutput& u : scene_.outputs)
            if (u.kind == io::SceneOutputKind::Stewart && u.platform == e.name)
              for (const auto& g : output(u, why).poses) postures.push_back(g);
          return platformTessellation(P, postures, e.name);
        }
        case io::SceneEntityKind::Line:
          return lineTessellation(io::sceneLine<double>(e), kFigureHalfLength, e.name);
        case io::SceneEntityKind::Screw:
          return screwTessellation(screw<double>(e.name, why), kFigureHalfLength, e.name);
        case io::SceneEntityKind::Point: return pointTessellation(io::scenePoint<double>(e), e.name);
        case io::SceneEntityKind::LinearComplex: {
          // Its axis (a line at infinity, for an infinite-pitch complex, is not drawn).
          const LinearComplex<double> c = io::sceneLinearComplex<double>(e);
          if (c.isInfinitePitch()) return render::Scene{};
          return screwTessellation(c.screw(), kFigureHalfLength, e.name);
        }
        case io::SceneEntityKind::Regulus: {
          // Twelve of its lines (GF §6.5.1).
          const ThreeLineRegulus<double> rg = io::sceneRegulus<double>(scene_, e);
          render::Scene out;
          for (int k = 0; k < 12; ++k) {
            const PluckerLine<double> l(rg.member(double(k) * pi<double>() / 12));
            if (!l.isAtInfinity()) merge(out, lineTessellation(l, kFigureHalfLength, k == 0 ? e.name : std::string()));
          }
          return out;
        }
        case io::SceneEntityKind::Cylindroid:
          return cylindroidTessellation(io::sceneCylindroid<double>(scene_, e), kFigureHalfLength, e.name);
        case io::SceneEntityKind::RuledSurface: {
          // Sixteen of its rulings over its range (GF §9.4).
          const io::SceneRuledSurface<double> rs = io::sceneRuledSurface<double>(scene_, e);
          render::Scene out;
          for (int k = 0; k <= 16; ++k) {
            const PluckerLine<double> l(rs.surface.coords(rs.t0 + (rs.t1 - rs.t0) * k / 16));
            if (!l.isAtInfinity()) merge(out, lineTessellation(l, kFigureHalfLength, k == 0 ? e.name : std::string()));
          }
          return out;
        }
        case io::SceneEntityKind::ScrewSystem: {
          const Eigen::Matrix<double, 6, Eigen::Dynamic> g = io::sceneScrewSystem<double>(scene_, e);
          render::Scene out;
          for (Eigen::Index k = 0; k < g.cols(); ++k)
            merge(out, screwTessellation(Vec6<double>(g.col(k)), kFigureHalfLength, k == 0 ? e.name : std::string()));
          return out;
        }
        case io::SceneEntityKind::RigidBody:
          return pointTessellation(io::sceneRigidBody<double>(e).centreOfMass(), e.name);
        case io::SceneEntityKind::Pose:
        case io::SceneEntityKind::PlanarMechanism: break;
      }
      return render::Scene{};
    });
    merge(all, part);
  }
  // The cylindroid of every cylindroid output whose two screws are drawn (once per pair of screws:
  // the same pencil in two scalars is one surface).
  std::vector<std::vector<std::string>> pencils;
  for (const io::SceneOutput& u : scene_.outputs) {
    if (u.kind != io::SceneOutputKind::Cylindroid || !drawn(u.screws[0]) || !drawn(u.screws[1])) continue;
    if (std::find(pencils.begin(), pencils.end(), u.screws) != pencils.end()) continue;
    pencils.push_back(u.screws);
    const render::Scene& part = node<render::Scene>("tessellation:" + u.name, reason, [&](const std::string& id) {
      const std::string why = via(reason, id);
      return cylindroidTessellation(Cylindroid<double>(screw<double>(u.screws[0], why), screw<double>(u.screws[1], why)),
                                    kFigureHalfLength, u.name);
    });
    merge(all, part);
  }
  all.axes = true;
  all.title = scene_.origin.empty() ? o.name : std::filesystem::path(scene_.origin).filename().string() + ": " + o.name;
  render::RenderOptions options;
  options.width = o.width;
  options.height = o.height;
  const auto t0 = std::chrono::steady_clock::now();
  // "<png>.<pid>.partial": two processes drawing the same figure do not write into one file.
  const std::filesystem::path partial = o.png.string() + "." + std::to_string(::getpid()) + ".partial";
  try {
    render::renderPng(all, options, partial);
  } catch (const std::exception& e) {
    std::error_code ec;
    std::filesystem::remove(partial, ec);
    throw InvalidInput(o.where + ".png: cannot write " + o.png.string() + " (" + e.what() + ")");
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  pending_.push_back({outputNodeId(o), partial, o.png});
  OutputResult r;
  r.name = o.name;
  r.json = io::figureOutputJson(o, names, seconds);
  return r;
}

OutputResult SceneGraph::report(const io::SceneOutput& o, const std::string& reason) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::string> shown;
  for (const std::string& n : o.reported) shown.push_back(output(*scene_.output(n), reason).json);  // built as its needs
  const std::filesystem::path partial = o.html.string() + "." + std::to_string(::getpid()) + ".partial";
  {
    std::ofstream out(partial);
    out << io::sceneReportHtml(scene_, o, shown);
    if (!out) {
      std::error_code ec;
      std::filesystem::remove(partial, ec);
      throw InvalidInput(o.where + ".html: cannot write " + o.html.string());
    }
  }
  pending_.push_back({outputNodeId(o), partial, o.html});
  OutputResult r;
  r.name = o.name;
  r.json = io::reportOutputJson(o, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return r;
}

SceneResult SceneGraph::run(const std::vector<const io::SceneOutput*>& outputs) {
  SceneResult result;
  trace_ = &result.trace;
  pending_.clear();
  try {
    for (const io::SceneOutput* o : outputs) result.outputs.push_back(output(*o, "output " + o->name));
    // Every output succeeded: the figures take their names.
    for (const Pending& p : pending_) {
      std::filesystem::rename(p.partial, p.final);
      result.written.push_back(p.final);
    }
  } catch (...) {
    for (const Pending& p : pending_) {
      std::error_code ec;
      std::filesystem::remove(p.partial, ec);
      nodes_.erase(p.node);  // built again (and written) by the next evaluation that asks
    }
    pending_.clear();
    trace_ = nullptr;
    throw;
  }
  pending_.clear();
  trace_ = nullptr;
  return result;
}

SceneResult SceneGraph::evaluate(const std::vector<std::string>& names) {
  for (const std::string& n : names)
    if (!scene_.output(n)) throw InvalidInput("--only: the scene " + scene_.origin + " has no output named \"" + n + "\"");
  std::vector<const io::SceneOutput*> asked;
  for (const io::SceneOutput& o : scene_.outputs) {
    bool a = names.empty();
    for (const std::string& n : names) a = a || n == o.name;
    if (a) asked.push_back(&o);
  }
  return run(asked);
}

SceneResult SceneGraph::render(const std::filesystem::path& png, int width, int height) {
  io::SceneOutput o;
  o.name = "render";
  o.kind = io::SceneOutputKind::Figure;
  o.where = "--png";
  o.png = png;
  o.width = width;
  o.height = height;
  // Not a node of the scene's: each call draws again (its tessellations are shared).
  nodes_.erase(outputNodeId(o));
  return run({&o});
}

}  // namespace soma::scene
