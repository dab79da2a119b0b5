// GF §15.2–15.4: loop mobility (Table 15.1, Bennett), the geodesic control laws in closed loop, and
// the hybrid-control projectors with their transformation laws.
#include "soma/geometry/riemannian/geodesic_control.hpp"
#include "soma/geometry/riemannian/hybrid_control.hpp"
#include "soma/geometry/riemannian/mobility.hpp"

#include "../dynamics/serial_dynamics_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;
using soma::test::unitVec3;

namespace {
template <class S> Vec6<S> lineScrew(const Vec3<S>& w, const Vec3<S>& r) {
  Vec6<S> s;
  s << w, Vec3<S>(r.cross(w));
  return s;
}
template <class S> S maxAbs(const DgMatrix<S>& m) { return m.cwiseAbs().maxCoeff(); }

// GF §15.3 line 9816 as printed (erratum E15.5): the accelerating law term by term with γ(1 − λt)
// and the index Γ^l_ik: τ_i = Σ_jk (B_ijk − A_ilΓ^l_ik)θ̇_jθ̇_k + C_i + A_ilW_l(γ(1 − λt)s_d − λq̇₆)
template <class S>
DgVector<S> acceleratingTorqueAsPrinted(const SerialDynamics<S>& robot, const JointSpaceGeometry<S>& geo,
                                        const GeodesicController<S>& c, const DgVector<S>& th, const DgVector<S>& td, const S& t) {
  const int n = robot.dof();
  const ScrewMatrix<S> J = geo.screws(th);
  const Vec6<S> a = c.gamma * (S(1) - c.lambda * t) * c.sd - c.lambda * Vec6<S>(J * td);
  const auto B = robot.coriolisTensor(th);
  const DgMatrix<S> A = robot.massMatrix(th);
  const auto G = geo.christoffelBook(th);
  DgVector<S> tau = robot.gravityTorque(th) + A * (geo.coScrews(J) * a);
  for (int i = 0; i < n; ++i) {
    tau(i) += td.dot(B[std::size_t(i)] * td);
    for (int l = 0; l < n; ++l)
      for (int k = 0; k < n; ++k) tau(i) -= A(i, l) * G[std::size_t(l)](i, k) * td.sum() * td(k);
  }
  return tau;
}
}  // namespace

TEMPLATE_TEST_CASE("GF §15.2 Table 15.1: ten screw systems, each closed under the bracket", "[riemannian][mobility]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const auto rows = table15_1<S>(S(3) / S(2));
  REQUIRE(rows.size() == 10);
  const int dims[10] = {1, 1, 1, 2, 2, 3, 3, 3, 3, 4};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    INFO(rows[i].group);
    CHECK(screwSystemDimension(rows[i].basis) == dims[i]);
    CHECK(isSubalgebra(rows[i].basis));
    CHECK(completionAlgebra(rows[i].basis).cols() == dims[i]);
  }
  // negative control: two skew revolute lines generate all of se(3)
  const std::vector<Vec6<S>> skew = {lineScrew<S>(Vec3<S>::UnitX(), Vec3<S>::Zero()),
                                     lineScrew<S>(Vec3<S>::UnitY(), Vec3<S>(S(0), S(0), S(1)))};
  CHECK_FALSE(isSubalgebra(skew));
  CHECK(completionAlgebra(skew).cols() == 6);
  CHECK_THROWS_AS(table15_1<S>(S(0)), InvalidInput);
}

TEMPLATE_TEST_CASE("GF §15.2: planar and spherical 4R have m = n − dim Δ∞ = 1 — the Bennett loop has mobility 1 although "
                   "Kutzbach and the completion group give −2",
                   "[riemannian][mobility]", double, long double, __float128) {
  using S = TestType;
  CHECK(kutzbachGrubler(4, 4, 4) == -2);
  CHECK(kutzbachGrubler(4, 4, 4, 3) == 1);
  // planar 4R: parallel z axes through the vertices of a quadrilateral
  const Vec3<S> z = Vec3<S>::UnitZ();
  const std::vector<Vec6<S>> planar = {lineScrew<S>(z, Vec3<S>(S(0), S(0), S(0))), lineScrew<S>(z, Vec3<S>(S(1), S(0), S(0))),
                                       lineScrew<S>(z, Vec3<S>(S(1), S(2), S(0))), lineScrew<S>(z, Vec3<S>(S(-1), S(1), S(0)))};
  CHECK(completionAlgebra(planar).cols() == 3);
  CHECK(completionMobility(planar) == 1);
  const LoopTrace<S> tp = traceLoop<S>(planar, S(1) / S(20), 20);
  CHECK(tp.kernelDimension == 1);
  CHECK(tp.closed);
  // Bennett: a = 1, α = 0.5, β = 1.1, closed at θ₁ = 0.7
  const auto bennett = bennettLoop<S>(S(1), S(1) / S(2), S(11) / S(10), S(7) / S(10));
  CHECK(screwSystemDimension(bennett) == 3);
  CHECK(infinitesimalMobility(bennett) == 1);
  CHECK(completionAlgebra(bennett).cols() == 6);
  CHECK(completionMobility(bennett) == -2);
  const LoopTrace<S> tb = traceLoop<S>(bennett, S(1) / S(20), 40);  // 2 rad of joint-space arc
  CHECK(tb.kernelDimension == 1);
  CHECK(tb.closed);
  CHECK(tb.maxResidual <= Tolerance<S>::identity(1024));
  CHECK((tb.path.back() - tb.path.front()).norm() > S(1));  // it really moved
  // perturb one twist: the 4 screws become independent, the loop is rigid (Kutzbach's answer)
  auto bent = bennettLoop<S>(S(1), S(1) / S(2), S(11) / S(10), S(7) / S(10));
  bent[3](2) += S(1) / S(20);
  bent[3].template head<3>().normalize();
  CHECK(infinitesimalMobility(bent) == 0);
  CHECK(traceLoop<S>(bent, S(1) / S(20), 5).kernelDimension == 0);
}

TEMPLATE_TEST_CASE("GF §15.3: the velocity-tracking law's twist error decays as e^{-λt} — geodesic law keeps the twist",
                   "[riemannian][control]", double, long double) {
  using S = TestType;
  auto& g = rng(1530);
  const SerialDynamics<S> robot = soma::test::build<S>(soma::test::randomRobot(g, 6));
  const JointSpaceGeometry<S> geo = jointSpaceGeometryOf(robot);
  DgVector<S> th0 = soma::test::randomJoints<S>(g, 6, -0.5, 0.5), td0 = soma::test::randomJoints<S>(g, 6, -0.2, 0.2);
  const Vec6<S> X0 = geo.screws(th0) * td0;
  // geodesic law: q̇₆ stays X0 (a helix)
  GeodesicController<S> c;
  const auto geoRun = simulateGeodesicControl<S>(robot, c, DgVector<S>(), th0, td0, S(1) / S(500), 500, 500);
  CHECK((geoRun.back().twist - X0).cwiseAbs().maxCoeff() < S(1e-9));
  // velocity tracking to s_d: error e(t) = e(0) e^{−λt} exactly (the closed loop is q̈₆ = λ(s_d − q̇₆))
  c.law = GeodesicLaw::VelocityTracking;
  c.lambda = S(2);
  // (a desired twist near X0 and 0.5 s: far from the singularities the helix eventually reaches)
  c.sd = X0 + Vec6<S>(S(1) / S(50), S(0), S(-1) / S(100), S(1) / S(100), S(1) / S(50), S(0));
  const auto run = simulateGeodesicControl<S>(robot, c, DgVector<S>(), th0, td0, S(1) / S(500), 250, 50);
  const S e0 = (run.front().twist - c.sd).norm();
  for (const auto& smp : run) {
    using std::exp;
    const S e = (smp.twist - c.sd).norm();
    CHECK(abs(e - e0 * exp(-c.lambda * smp.t)) <= S(1e-8) * e0);
  }
  // with plant friction μ compensated by the law, the closed loop is the same
  DgVector<S> mu(6);
  mu << S(0.5), S(0.3), S(0.4), S(0.2), S(0.1), S(0.25);
  GeodesicController<S> cf = c;
  cf.friction = mu;
  const auto runF = simulateGeodesicControl<S>(robot, cf, mu, th0, td0, S(1) / S(500), 250, 50);
  CHECK((runF.back().theta - run.back().theta).cwiseAbs().maxCoeff() < S(1e-10));
  // uncompensated friction: the tracking is visibly off
  const auto runU = simulateGeodesicControl<S>(robot, c, mu, th0, td0, S(1) / S(500), 250, 50);
  CHECK((runU.back().twist - c.sd).norm() > S(1e-3));
  // accelerating geodesic (corrected): from rest, q̇₆ = γ t s_d
  GeodesicController<S> ca;
  ca.law = GeodesicLaw::Accelerating;
  ca.gamma = S(7) / S(10);
  ca.lambda = S(2);
  ca.sd = X0 / X0.norm() / S(2);
  const auto acc = simulateGeodesicControl<S>(robot, ca, DgVector<S>(), th0, DgVector<S>(DgVector<S>::Zero(6)), S(1) / S(500), 250, 250);
  CHECK((acc.back().twist - ca.gamma * acc.back().t * ca.sd).cwiseAbs().maxCoeff() < S(1e-8));
  const TorqueLaw<S> printedLaw = [&](const DgVector<S>& th, const DgVector<S>& td, const S& t) {
    return acceleratingTorqueAsPrinted(robot, geo, ca, th, td, t);
  };
  const auto accP = simulateClosedLoop<S>(robot, printedLaw, DgVector<S>(), th0, DgVector<S>(DgVector<S>::Zero(6)), S(1) / S(500), 250, 250);
  CHECK((accP.back().twist - ca.gamma * accP.back().t * ca.sd).cwiseAbs().maxCoeff() > S(1e-2));
}

TEMPLATE_TEST_CASE("GF §15.4.3: dual-basis projectors are idempotent and complementary — transformation laws hold",
                   "[riemannian][hybrid]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1540);
  const S tol = Tolerance<S>::identity(4096);
  const int trials = std::is_same_v<S, mpfr::mpreal> ? 1 : 4;
  for (int t = 0; t < trials; ++t) {
    const int n = 1 + t % 5;
    DgMatrix<S> Z(6, n), Sp(6, 6 - n);
    for (int i = 0; i < n; ++i) Z.col(i) = uniformVec<S, 6>(g);
    for (int i = 0; i < 6 - n; ++i) Sp.col(i) = uniformVec<S, 6>(g);
    const HybridProjectors<S> p = dualBasisProjectors<S>(Z, Sp);
    const Mat6<S> AB = p.motionProjector(), XY = p.wrenchProjector();
    const S sc = S(1) + maxAbs<S>(DgMatrix<S>(AB)) + maxAbs<S>(DgMatrix<S>(XY));
    CHECK(maxAbs<S>(DgMatrix<S>(AB * AB - AB)) <= tol * sc * sc);
    CHECK(maxAbs<S>(DgMatrix<S>(XY * XY - XY)) <= tol * sc * sc);
    CHECK(maxAbs<S>(DgMatrix<S>(p.B * p.A - DgMatrix<S>::Identity(n, n))) <= tol * sc);
    CHECK(maxAbs<S>(DgMatrix<S>(p.Y * p.X - DgMatrix<S>::Identity(6 - n, 6 - n))) <= tol * sc);
    CHECK(maxAbs<S>(DgMatrix<S>(p.X.transpose() * p.A)) <= tol * sc);                          // constraint wrenches do no work on freedoms
    CHECK(maxAbs<S>(DgMatrix<S>(AB + XY.transpose() - Mat6<S>::Identity())) <= tol * sc);     // complementary
    // a random rigid motion: transformed bases give the transformed operators
    const Mat6<S> H = SE3<S>::Random(g).adjoint();
    const Mat6<S> Hi = H.inverse();
    const HybridProjectors<S> pt = transformedProjectors<S>(p, H);
    const HybridProjectors<S> pb = dualBasisProjectors<S>(DgMatrix<S>(Hi * Z), DgMatrix<S>(Hi * Sp));
    CHECK(maxAbs<S>(DgMatrix<S>(pt.motionProjector() - pb.motionProjector())) <= S(16) * tol * sc);
    CHECK(maxAbs<S>(DgMatrix<S>(pt.wrenchProjector() - pb.wrenchProjector())) <= S(16) * tol * sc);
    CHECK(maxAbs<S>(DgMatrix<S>(pt.motionProjector() - Hi * AB * H)) <= S(16) * tol * sc);
    CHECK(maxAbs<S>(DgMatrix<S>(pt.wrenchProjector() - H.transpose() * XY * Hi.transpose())) <= S(16) * tol * sc);
  }
  DgMatrix<S> Z = DgMatrix<S>::Zero(6, 2), Sp = DgMatrix<S>::Zero(6, 4);
  Z(0, 0) = Z(1, 1) = S(1);
  Sp(0, 0) = S(1);  // not a complement
  CHECK_THROWS_AS(dualBasisProjectors<S>(Z, Sp), InvalidInput);
}

TEMPLATE_TEST_CASE("GF §15.4.3 peg in hole: AB = diag(0,0,1,0,0,1), XY = diag(1,1,0,1,1,0) — shifted origin (erratum E15.8)",
                   "[riemannian][hybrid]", SOMA_TEST_SCALARS) {
  using S = TestType;
  DgMatrix<S> Z = DgMatrix<S>::Zero(6, 2), Sp = DgMatrix<S>::Zero(6, 4);
  Z(2, 0) = Z(5, 1) = S(1);
  Sp(0, 0) = Sp(1, 1) = Sp(3, 2) = Sp(4, 3) = S(1);
  const HybridProjectors<S> p = dualBasisProjectors<S>(Z, Sp);
  Mat6<S> AB = Mat6<S>::Zero(), XY = Mat6<S>::Zero();
  AB(2, 2) = AB(5, 5) = S(1);
  XY(0, 0) = XY(1, 1) = XY(3, 3) = XY(4, 4) = S(1);
  const S tol = Tolerance<S>::identity(16);
  CHECK(maxAbs<S>(DgMatrix<S>(p.motionProjector() - AB)) <= tol);
  CHECK(maxAbs<S>(DgMatrix<S>(p.wrenchProjector() - XY)) <= tol);
  const S r = S(3) / S(2);
  const Mat6<S> H = SE3<S>(SO3<S>::Identity(), Vec3<S>(r, S(0), S(0))).adjoint();
  CHECK(H(4, 2) == -r);  // the book's H: H₅₃ = −r, H₆₂ = r
  CHECK(H(5, 1) == r);
  const HybridProjectors<S> pt = transformedProjectors<S>(p, H);
  Mat6<S> XYt = XY;
  XYt(1, 5) = -r;
  XYt(2, 4) = -r;
  CHECK(maxAbs<S>(DgMatrix<S>(pt.wrenchProjector() - XYt)) <= tol);
  Mat6<S> ABt = AB;
  ABt(4, 2) = r;
  ABt(5, 1) = r;
  CHECK(maxAbs<S>(DgMatrix<S>(pt.motionProjector() - ABt)) <= tol);
}

TEMPLATE_TEST_CASE("GF §15.4.4: N6-orthonormal projectors — the pinned body's reaction is N6 II(V,V)", "[riemannian][hybrid]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1544);
  const Vec3<S> d = uniformVec<S, 3>(g, 0.2, 0.5);
  const Mat3<S> R = SO3<S>::Random(g).matrix();
  const Vec3<S> c = uniformVec<S, 3>(g, -0.5, 0.5);
  const S m = uniform<S>(g, 1, 3);
  const SpatialInertia<S> body(m, c, Mat3<S>(R * Vec3<S>(d(0) + d(1), d(1) + d(2), d(2) + d(0)).asDiagonal() * R.transpose()));
  const Mat6<S> N = body.matrix();
  // pinned at the origin: the freedoms are the rotations about the origin, (e_k, 0)
  DgMatrix<S> Z = DgMatrix<S>::Zero(6, 3);
  Z(0, 0) = Z(1, 1) = Z(2, 2) = S(1);
  const HybridProjectors<S> p = n6Projectors<S>(Z, N);
  const S tol = Tolerance<S>::identity(4096);
  const Mat6<S> AB = p.motionProjector(), XY = p.wrenchProjector();
  CHECK(maxAbs<S>(DgMatrix<S>(AB - p.A * p.A.transpose() * N)) <= tol);
  CHECK(maxAbs<S>(DgMatrix<S>(XY - N * p.Y.transpose() * p.Y)) <= tol * S(16));
  CHECK(maxAbs<S>(DgMatrix<S>(XY - p.X * p.X.transpose() * N.inverse())) <= tol * S(64));
  CHECK(maxAbs<S>(DgMatrix<S>(AB * AB - AB)) <= tol * S(16));
  CHECK(maxAbs<S>(DgMatrix<S>(p.A.transpose() * N * p.A - DgMatrix<S>::Identity(3, 3))) <= tol);
  // free rotation about the pin (Euler's equations about the origin): the total wrench is the
  // reaction, a pure force m(ω̇ × c + ω × (ω × c)) through the origin, and equals N6 II(V, V)
  const Vec3<S> w = uniformVec<S, 3>(g);
  const Mat3<S> Io = body.inertiaAboutOrigin();
  const Vec3<S> wd = Io.ldlt().solve(Vec3<S>(-w.cross(Io * w)));
  Vec6<S> V, Vd;
  V << w, Vec3<S>::Zero();
  Vd << wd, Vec3<S>::Zero();
  const Vec6<S> total = rigidBodyWrench<S>(N, V, Vd);
  const Vec3<S> F = m * (wd.cross(c) + w.cross(w.cross(c)));
  CHECK(total.template head<3>().cwiseAbs().maxCoeff() <= tol * S(16));
  CHECK((total.template tail<3>() - F).cwiseAbs().maxCoeff() <= tol * S(16));
  CHECK((secondFundamentalWrench<S>(p, N, V, Vd) - total).cwiseAbs().maxCoeff() <= tol * S(64));
  // the multipliers reproduce it: Σ λ_j W_j = N6 II(V, V)
  const DgVector<S> lam = constraintMultipliers<S>(p, N, V, Vd);
  CHECK((p.X * lam - total).cwiseAbs().maxCoeff() <= tol * S(64));
  CHECK_THROWS_AS(n6Projectors<S>(Z, Mat6<S>(-N)), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
