// Studies of GF §15.3 (double): geodesic control of a 6R robot — the geodesic law (helical end-effector
// motion), Jacobi fields and sectional curvature (erratum E15.11), the velocity-tracking law (erratum
// E15.6), friction compensation, the accelerating geodesic (errata E15.4, E15.5), and the figure of a
// helical end-effector path under the geodesic control law.
#include "gf13/common.hpp"  // the PUMA 560 model (puma())
#include "gf15/common.hpp"

#include "soma/render/render.hpp"

namespace soma::studies::gf15::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

namespace rd = soma::render;

struct Setup {
  SerialDynamics<double> robot;
  DV th0, td0;
};
Setup setup(std::uint64_t seed) {
  auto g = std::mt19937_64(seed);
  SerialDynamics<double> r = randomRobot(g);
  const DV th = rvec(g, 6, -0.5, 0.5), td = rvec(g, 6, -0.2, 0.2);
  return {r, th, td};
}

void geodesicLaw(Context& ctx) {
  const Setup s = setup(1531);
  const JointSpaceGeometry<double> geo = jointSpaceGeometryOf(s.robot);
  const V6 X = geo.screws(s.th0) * s.td0;
  GeodesicController<double> c;
  const auto run = simulateGeodesicControl<double>(s.robot, c, DV(), s.th0, s.td0, 0.002, 1000, 50);
  double drift0 = 0, pose = 0;
  for (const auto& smp : run) {
    drift0 = std::max(drift0, (smp.twist - X).cwiseAbs().maxCoeff());
    pose = std::max(pose, (smp.pose.matrix() - SE3Tangent<double>(V6(smp.t * X)).exp().compose(run.front().pose).matrix()).cwiseAbs().maxCoeff());
  }
  ctx.checkResidual("τ = (B − AΓ)θ̇θ̇ + C, plant of ch. 13 (g = 9.81), RK4 2 s: max |q̇₆(t) − q̇₆(0)|", drift0, 1e-9);
  ctx.checkResidual("the end effector follows ρ(t) = e^{tX}ρ(0), a helix of pitch " + toString(X.head<3>().dot(X.tail<3>()) / X.head<3>().squaredNorm(), 4), pose, 1e-9);
  // the same law with the printed gravity sign of ch. 13 (C_i = +s_iᵀN̄_ig, ch13 erratum 1): gravity doubled
  DV th = s.th0, v = s.td0;
  auto acc = [&](const DV& a, const DV& b) {
    const DV tau = geodesicControlTorque<double>(s.robot, geo, c, a, b, 0) - 2 * s.robot.gravityTorque(a);
    return DV(s.robot.forwardDynamics(a, b, tau));
  };
  const double h = 0.002;
  double drift = 0;
  try {
    for (int k = 0; k < 50; ++k) {
      const DV a1 = acc(th, v), v2 = v + h / 2 * a1, a2 = acc(DV(th + h / 2 * v), v2), v3 = v + h / 2 * a2, a3 = acc(DV(th + h / 2 * v2), v3),
               v4 = v + h * a3, a4 = acc(DV(th + h * v3), v4);
      th += h / 6 * (v + 2 * v2 + 2 * v3 + v4);
      v += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    }
    drift = (V6(geo.screws(th) * v) - X).cwiseAbs().maxCoeff();
  } catch (const InvalidInput&) {
    drift = 1e300;  // driven into a singularity
  }
  ctx.checkPrintedFails("the law with ch. 13's printed C_i = +s_iᵀN̄_ig (0.1 s): twist drift", "ch13 E1", drift, 1e-6);
}

void curvatureStability(Context& ctx) {
  auto g = std::mt19937_64(1532);
  const InvariantMetric<double> Q0{1, 0}, Qi{0, 1};
  double r = 0, inv = 0;
  for (int t = 0; t < 20; ++t) {
    const V6 X = rv6(g), Y = rv6(g), Z = rv6(g), W = rv6(g);
    r = std::max(r, (curvatureFromConnection<double>(X, Y, Z) - curvature<double>(X, Y, Z)).cwiseAbs().maxCoeff());
    inv = std::max(inv, abs(Q0(br(br(X, Y), Z), W) - Q0(br(X, Y), br(Z, W))));
  }
  ctx.checkResidual("R(X,Y)Z = −∇_X∇_YZ + ∇_Y∇_XZ + ∇_[X,Y]Z = ¼[[X,Y],Z] (20 random triples)", r, 1e-14);
  ctx.checkResidual("invariance step Q0([[X,Y],Z], W) = Q0([X,Y],[Z,W])", inv, 1e-14);
  // Jacobi fields along e^{tX}: z(t) = log(e^{−tX}e^{t(X+εY)})/ε in the left-invariant frame; the Jacobi
  // equation ∇_X∇_XZ + R(X,Z)X = 0 reduces to z̈ + [X, ż] = 0
  const V6 X = rv6(g), Y = rv6(g);
  const double eps = 1e-6;
  auto z = [&](double t) { return V6((SE3Tangent<double>(V6(-t * X)).exp().compose(SE3Tangent<double>(V6(t * (X + eps * Y))).exp())).log().coeffs() / eps); };
  double jac = 0;
  for (double t : {0.3, 0.8, 1.5}) {
    const double h = 1e-2;
    const V6 zd = (z(t + h) - z(t - h)) / (2 * h), zdd = (z(t + h) - 2 * z(t) + z(t - h)) / (h * h);
    jac = std::max(jac, (zdd + br(X, zd)).cwiseAbs().maxCoeff());
  }
  ctx.checkResidual("geodesic variation satisfies the Jacobi equation z̈ + [X, ż] = 0 (finite differences)", jac, 1e-4);
  // sectional curvature: commuting directions give 0; Q0 is indefinite so both signs occur; Q_inf ≥ 0
  const V6 rotX = lineScrew(V3(1, 0, 0), V3::Zero()), transX(0, 0, 0, 1, 0, 0), rotY = lineScrew(V3(0, 1, 0), V3::Zero());
  ctx.checkNear("K(X, Z) = 0 for commuting X, Z (a rotation and the translation along its axis)", 0.0, sectionalCurvature<double>(Q0, rotX, transX), 0.0);
  ctx.checkNear("K_inf(rot x, rot y) = ¼|[X,Z]|²_inf = ¼ > 0", 0.25, sectionalCurvature<double>(Qi, rotX, rotY), 1e-15);
  double kmin = 1e9, kmax = -1e9;
  for (int t = 0; t < 200; ++t) {
    const double k = sectionalCurvature<double>(Q0, rv6(g), rv6(g));
    kmin = std::min(kmin, k);
    kmax = std::max(kmax, k);
  }
  ctx.checkEqual("Q0 (indefinite): sectional curvatures of both signs among 200 random planes", 1, (kmin < 0 && kmax > 0) ? 1 : 0);
  // erratum E15.11: SO(3) is a subgroup, totally geodesic (∇_XY = ½[X,Y] ∈ so(3)) but NOT flat
  const V6 a = lineScrew(unit3(g), V3::Zero()), b = lineScrew(unit3(g), V3::Zero());
  const V6 nab = biinvariantCovariant<double>(a, b);
  ctx.checkResidual("so(3) is totally geodesic: the v-part of ∇_XY for rotations about 0", nab.tail<3>().norm(), 1e-16);
  ctx.checkPrintedFails("\"a subgroup is flat\": |R(X,Y)Y| for two rotations about the origin", "E15.11", curvature<double>(a, b, b).norm(), 1e-6);
}

void velocityTracking(Context& ctx) {
  const Setup s = setup(1533);
  const JointSpaceGeometry<double> geo = jointSpaceGeometryOf(s.robot);
  const V6 X0 = geo.screws(s.th0) * s.td0;
  GeodesicController<double> c;
  c.law = GeodesicLaw::VelocityTracking;
  c.lambda = 2;
  c.sd = X0 + V6(0.02, 0, -0.01, 0.01, 0.02, 0);
  const auto run = simulateGeodesicControl<double>(s.robot, c, DV(), s.th0, s.td0, 0.002, 250, 25);
  // fit ln e(t) = ln e(0) − λ_fit t by least squares
  double st = 0, sy = 0, stt = 0, sty = 0;
  const int n = int(run.size());
  for (const auto& smp : run) {
    const double y = std::log((smp.twist - c.sd).norm());
    st += smp.t;
    sy += y;
    stt += smp.t * smp.t;
    sty += smp.t * y;
  }
  const double slope = (n * sty - st * sy) / (n * stt - st * st);
  // Bound: the closed loop makes ė = −λe exactly; RK4 (h = 2 ms) multiplies e by the degree-4 Taylor
  // polynomial of e^{−λh}, so the per-step rate is off by (λh)⁵/(120h) = λ⁵h⁴/120 = 4.3e-12 s⁻¹; the
  // log-linear fit adds ε·|ln e|/t_span ≈ 1e-14. kRateBound allows 10× the RK4 term for the coupling of
  // e to the rest of the plant's state (whose RK4 error enters through the law).
  const double kRateBound = 10 * std::pow(c.lambda, 5) * std::pow(0.002, 4) / 120;
  ctx.checkNear("fitted decay rate of |q̇₆ − s_d| (λ = 2; ≤ 10·λ⁵h⁴/120, RK4 at h = 2 ms)", 2.0, -slope, kRateBound);
  // decomposition q̇₆ = a_d s_d + Σ a_i z_i (z_i: a fixed complement): a_d(t) = 1 + (a_d(0) − 1)e^{−λt} (E15.6)
  DM Bm(6, 6);
  Bm.col(0) = c.sd;
  const DM comp = detail::smallComplement<double>(DM(c.sd.normalized()));
  Bm.rightCols(5) = comp;
  const DM Bi = Bm.inverse();
  const double ad0 = (Bi * DV(run.front().twist))(0);
  double errC = 0, errP = 0, other = 0;
  for (const auto& smp : run) {
    const DV a = Bi * DV(smp.twist);
    errC = std::max(errC, abs(a(0) - (1 + (ad0 - 1) * std::exp(-c.lambda * smp.t))));
    errP = std::max(errP, abs(a(0) - 1));
    for (int i = 1; i < 6; ++i) other = std::max(other, abs(a(i) - (Bi * DV(run.front().twist))(i) * std::exp(-c.lambda * smp.t)));
  }
  ctx.checkResidual("a_d(t) = 1 + (a_d(0) − 1)e^{−λt} (a_d(0) = " + toString(ad0, 6) + ")", errC, 1e-9);
  ctx.checkResidual("a_i(t) = a_i(0)e^{−λt}", other, 1e-9);
  ctx.checkPrintedFails("a_d(t) = 1 for all t", "E15.6", errP, 1e-6);
}

void friction(Context& ctx) {
  const Setup s = setup(1534);
  const JointSpaceGeometry<double> geo = jointSpaceGeometryOf(s.robot);
  GeodesicController<double> c;
  c.law = GeodesicLaw::VelocityTracking;
  c.lambda = 2;
  c.sd = V6(geo.screws(s.th0) * s.td0) + V6(0.02, 0, -0.01, 0.01, 0.02, 0);
  DV mu(6);
  mu << 0.5, 0.3, 0.4, 0.2, 0.1, 0.25;
  const auto ref = simulateGeodesicControl<double>(s.robot, c, DV(), s.th0, s.td0, 0.002, 250, 250);
  GeodesicController<double> cf = c;
  cf.friction = mu;
  const auto comp = simulateGeodesicControl<double>(s.robot, cf, mu, s.th0, s.td0, 0.002, 250, 250);
  const auto raw = simulateGeodesicControl<double>(s.robot, c, mu, s.th0, s.td0, 0.002, 250, 250);
  ctx.checkResidual("plant with friction μθ̇, law with +μ_iθ̇_i: |θ(0.5) − θ_frictionless(0.5)|", maxAbs(DV(comp.back().theta - ref.back().theta)), 1e-12);
  ctx.checkPrintedFails("control: friction not compensated, |θ − θ_frictionless|", "— control", maxAbs(DV(raw.back().theta - ref.back().theta)), 1e-12);
}

/// The accelerating law as printed, term by term: τ_i = Σ_jk (B_ijk − A_ilΓ^l_ik)θ̇_jθ̇_k + C_i
/// + A_ilW_l(γ(1 − λt)s_d − λθ̇_js_j) (+ μ_iθ̇_i), Γ the book's symbols, W_l the rows of J⁻¹.
// GF §15.3 line 9816 as printed (erratum E15.5)
DV acceleratingTorqueAsPrinted(const SerialDynamics<double>& robot, const JointSpaceGeometry<double>& geo,
                               const GeodesicController<double>& c, const DV& theta, const DV& thetaDot, double t) {
  const int n = robot.dof();
  const ScrewMatrix<double> J = geo.screws(theta);
  const DM W = geo.coScrews(J);
  const V6 a = c.gamma * (1 - c.lambda * t) * c.sd - c.lambda * V6(J * thetaDot);
  const auto B = robot.coriolisTensor(theta);
  const DM A = robot.massMatrix(theta);
  const auto G = geo.christoffelBook(theta);
  const double sumTd = thetaDot.sum();
  DV tau = robot.gravityTorque(theta) + A * (W * a);
  for (int i = 0; i < n; ++i) {
    double v = thetaDot.dot(B[std::size_t(i)] * thetaDot);
    for (int l = 0; l < n; ++l)
      for (int k = 0; k < n; ++k) v -= A(i, l) * G[std::size_t(l)](i, k) * sumTd * thetaDot(k);
    tau(i) += v;
  }
  if (c.friction.size() == n) tau += c.friction.cwiseProduct(thetaDot);
  return tau;
}

void accelerating(Context& ctx) {
  const Setup s = setup(1535);
  const JointSpaceGeometry<double> geo = jointSpaceGeometryOf(s.robot);
  GeodesicController<double> c;
  c.law = GeodesicLaw::Accelerating;
  c.gamma = 0.7;
  c.lambda = 2;
  const V6 X0 = geo.screws(s.th0) * s.td0;
  c.sd = X0 / X0.norm() / 2;
  const DV zero = DV::Zero(6);
  const auto run = simulateGeodesicControl<double>(s.robot, c, DV(), s.th0, zero, 0.002, 250, 25);
  double e = 0;
  for (const auto& smp : run) e = std::max(e, (smp.twist - c.gamma * smp.t * c.sd).cwiseAbs().maxCoeff());
  ctx.checkResidual("corrected law γ(1 + λt)s_d − λθ̇_js_j, Γ^l_jk: from rest q̇₆(t) = γt s_d (0.5 s)", e, 1e-9);
  const TorqueLaw<double> printedLaw = [&](const DV& th, const DV& v, const double& t) {
    return acceleratingTorqueAsPrinted(s.robot, geo, c, th, v, t);
  };
  const auto bad = simulateClosedLoop<double>(s.robot, printedLaw, DV(), s.th0, zero, 0.002, 250, 25);
  double eb = 0;
  for (const auto& smp : bad) eb = std::max(eb, (smp.twist - c.gamma * smp.t * c.sd).cwiseAbs().maxCoeff());
  ctx.checkPrintedFails("the printed law γ(1 − λt), Γ^l_ik: |q̇₆ − γt s_d|", "E15.5", eb, 1e-6);
  // the scalar reduction v̇ = γ(1 ± λt) − λv, v(0) = 0, γ = 0.7, λ = 2, 3 s: target γt = 2.1
  auto scalar = [](double sgn) {
    double v = 0, t = 0;
    const double h = 1e-4, gm = 0.7, lm = 2;
    auto f = [&](double tt, double vv) { return gm * (1 + sgn * lm * tt) - lm * vv; };
    for (int k = 0; k < 30000; ++k, t += h) {
      const double k1 = f(t, v), k2 = f(t + h / 2, v + h / 2 * k1), k3 = f(t + h / 2, v + h / 2 * k2), k4 = f(t + h, v + h * k3);
      v += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return v;
  };
  ctx.checkNear("scalar reduction, corrected: v(3) = γ·3 = 2.1", 2.1, scalar(1), 1e-10);
  ctx.checkPrintedFails("scalar reduction, printed γ(1 − λt): |v(3) − 2.1| (v(3) = " + toString(scalar(-1), 4) + ")", "E15.5", abs(scalar(-1) - 2.1), 1e-6);
  // E15.4: the path is the POSITION q₆(t) = e^{γt²s_d/2}: its spatial velocity is γt s_d
  double vel = 0;
  for (double t : {0.3, 1.0, 2.0}) {
    const Mat4<double> dq = cdiff([&](double u) { return Mat4<double>(SE3Tangent<double>(V6(c.gamma * (t + u) * (t + u) / 2 * c.sd)).exp().matrix()); }, 1e-3);
    const Mat4<double> q = SE3Tangent<double>(V6(c.gamma * t * t / 2 * c.sd)).exp().matrix();
    vel = std::max(vel, (SE3Tangent<double>::vee(Mat4<double>(dq * q.inverse())).coeffs() - c.gamma * t * c.sd).cwiseAbs().maxCoeff());
  }
  ctx.checkResidual("q₆(t) = e^{γt²s_d/2} has spatial velocity q̇₆q₆⁻¹ = γt s_d (finite differences)", vel, 1e-10);
  const double t = 1.0;
  const Mat4<double> q = SE3Tangent<double>(V6(c.gamma * t * t / 2 * c.sd)).exp().matrix();
  const Mat4<double> qdd = [&] {
    const double h = 1e-3;
    auto Q = [&](double u) { return Mat4<double>(SE3Tangent<double>(V6(c.gamma * u * u / 2 * c.sd)).exp().matrix()); };
    return Mat4<double>((Q(t + h) - 2 * Q(t) + Q(t - h)) / (h * h));
  }();
  // bound of the second difference at h = 1e-3: truncation h²/12·|q⁗| ≲ 1e-7 (|q⁗| ≲ 1 for γ = 0.7, t = 1) plus
  // rounding 4ε|q|/h² ≈ 1e-9: 1e-6
  ctx.checkPrintedFails("\"q̈₆ = e^{γt²s_d/2}\": |d²q₆/dt² − e^{γt²s_d/2}| at t = 1", "E15.4", (qdd - q).cwiseAbs().maxCoeff(), 1e-6);
}

void helixFigure(Context& ctx) {
  // the PUMA 560 (ch. 13 inertias, g = 9.81) started with the joint rates that give the end effector the
  // twist X of a pitch-0.05 m/rad screw about the base z axis, 1.5 rad/s: one full turn (4.19 s)
  const SerialDynamics<double> robot = soma::studies::gf13::puma();
  const JointSpaceGeometry<double> geo = jointSpaceGeometryOf(robot);
  DV th0(6);
  th0 << 0.2, -0.6, 0.8, 0.3, 0.9, -0.4;
  V6 X;
  X << 0, 0, 1.5, 0, 0, 0.05 * 1.5;
  const DV td = geo.coScrews(geo.screws(th0)) * X;
  GeodesicController<double> c;
  const int steps = int(std::lround(2 * pi<double>() / 1.5 / 0.002));
  const auto run = simulateGeodesicControl<double>(robot, c, DV(), th0, td, 0.002, steps, 5);
  double drift = 0;
  for (const auto& smp : run) drift = std::max(drift, (smp.twist - X).cwiseAbs().maxCoeff());
  ctx.checkResidual("PUMA 560, one turn (" + toString(steps * 0.002, 4) + " s) under the geodesic law: max |q̇₆ − X|", drift, 1e-9);
  // the end-effector point (tool point = home origin carried by ρ) and the screw axis of X
  const V3 w = X.head<3>(), v = X.tail<3>();
  const double pitch = w.dot(v) / w.squaredNorm();
  const V3 axisPoint = w.cross(v) / w.squaredNorm();  // v = r × ω + pω ⇒ r = ω × v/|ω|²
  double radiusErr = 0, r0 = -1;
  std::vector<V3> pts;
  for (const auto& smp : run) {
    const V3 p = smp.pose.translation();
    pts.push_back(p);
    const V3 d = p - axisPoint;
    const double rad = (d - d.dot(w.normalized()) * w.normalized()).norm();
    if (r0 < 0) r0 = rad;
    radiusErr = std::max(radiusErr, abs(rad - r0));
  }
  ctx.checkResidual("the tool point stays at constant distance from the screw axis of X (a helix)", radiusErr, 1e-8);
  ctx.note("Screw of X: pitch " + toString(pitch, 4) + " m/rad, |ω| = " + toString(w.norm(), 4) + " rad/s, helix radius " + toString(r0, 4) + " m.");
  if (!ctx.makeFigures()) return;
  rd::Scene sc;
  sc.title = "Geodesic control (GF §15.3): PUMA 560 end effector on a helix";
  rd::Tube path;
  path.p = pts;
  path.radius = 0.008;
  path.c = rd::palette::blue;
  sc.add(path);
  const V3 u = w.normalized();
  const double sMin = (pts.front() - axisPoint).dot(u), sMax = (pts.back() - axisPoint).dot(u);
  rd::Polyline axis;
  axis.p = {V3(axisPoint + (std::min(sMin, sMax) - 0.3) * u), V3(axisPoint + (std::max(sMin, sMax) + 0.3) * u)};
  axis.c = rd::palette::darkGrey;
  axis.dashed = true;
  sc.add(axis);
  // the end-effector frame every 0.5 s
  for (std::size_t k = 0; k < run.size(); k += 50) {
    const auto& P = run[k].pose;
    const rd::Color cols[3] = {rd::palette::vermillion, rd::palette::bluishGreen, rd::palette::blue};
    for (int a = 0; a < 3; ++a) sc.add(rd::Arrow{P.translation(), V3(P.translation() + 0.12 * P.rotation().col(a)), cols[a], 0.008});
  }
  rd::Label l0;
  l0.at = pts.front();
  l0.text = "t = 0";
  l0.pixelHeight = 24;
  sc.add(l0);
  rd::Label l1;
  l1.at = pts.back();
  l1.text = "t = " + toString(steps * 0.002, 3) + " s";
  l1.pixelHeight = 24;
  sc.add(l1);
  rd::Label la;
  la.at = axis.p.back();
  la.text = "screw axis, pitch " + toString(pitch, 3) + " m/rad";
  la.pixelHeight = 24;
  sc.add(la);
  rd::renderPng(sc, V3(1, -1.2, 0.45), {1200, 950}, ctx.figurePath("gf15_helical_path.png"));
  ctx.figure("gf15_helical_path.png", "End-effector path of the PUMA 560 (ch. 13 inertias, g = 9.81) under the geodesic control "
                                      "law τ = (B − AΓ)θ̇θ̇ + C, started with the twist of a pitch-0.05 m/rad screw about the base z axis "
                                      "(dashed): one turn of the helix; end-effector frames every 0.5 s.");
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-15.3-geodesic-control-law", "τ = (B − AΓ)θ̇θ̇ + C makes the closed loop a geodesic: helical motion", "GF §15.3", geodesicLaw);
SOMA_STUDY_DOUBLE("GF-15.3-curvature-stability", "Jacobi fields, R = ¼[[X,Y],Z], sectional curvature (erratum E15.11)", "GF §15.3", curvatureStability);
SOMA_STUDY_DOUBLE("GF-15.3-velocity-tracking-law", "q̈₆ = λ(s_d − q̇₆): errors decay as e^{−λt} (erratum E15.6)", "GF §15.3", velocityTracking);
SOMA_STUDY_DOUBLE("GF-15.3-friction-compensation", "Viscous friction compensated: the closed loop is the frictionless one", "GF §15.3", friction);
SOMA_STUDY_DOUBLE("GF-15.3-accelerating-geodesic", "Accelerating along a geodesic: q̇₆ = γt s_d (errata E15.4, E15.5)", "GF §15.3", accelerating);
SOMA_STUDY_DOUBLE("GF-15-fig-helical-path", "Derived figure: a helical end-effector path under the geodesic control law", "GF §15.3", helixFigure);

}  // namespace soma::studies::gf15::SOMA_UNITY_ID
