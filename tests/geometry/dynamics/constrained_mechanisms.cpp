// Constrained mechanisms of GF §14.2, §14.5, §14.6: freedom/constraint duality and the
// quadric-surface example (errata 4–6), the constrained rigid body (multipliers from the DAE = from
// a dual basis; Euler's equations about a fixed point), a 6R robot holding a pen on a table
// (simulated: drift and energy), the planar biped's vertical foot force (book α, corrected,
// erratum 10, = the full multiplier system; the printed α gives −λ_Rx), and the Stewart
// platform's inverse dynamics (α elimination = 24 × 24 multipliers; massless legs: the platform's
// Newton–Euler wrench = −Σ F_i × unit leg lines).
#include "soma/geometry/dynamics/biped_dynamics.hpp"
#include "soma/geometry/dynamics/holonomic_constraints.hpp"
#include "soma/geometry/dynamics/stewart_dynamics.hpp"

#include "serial_dynamics_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;

namespace {

using Q4 = Eigen::Matrix<double, 4, 1>;
Q4 qmul(const Q4& p, const Q4& q) {
  const Vec3<double> u = p.tail<3>(), v = q.tail<3>();
  Q4 r;
  r(0) = p(0) * q(0) - u.dot(v);
  r.tail<3>() = p(0) * v + q(0) * u + u.cross(v);
  return r;
}

// GF §14.2.1 lines 8908, 8922, 8924 as printed (errata 5, 6): the three quartics with factors 2
Vec3<double> quadricSurfaceQuarticsAsPrinted(double kx, double ky, const Q4& a, const Q4& b) {
  const double X = a(0) * b(1) - a(1) * b(0) + a(2) * b(3) - a(3) * b(2);
  const double Y = a(0) * b(2) - a(1) * b(3) - a(2) * b(0) + a(3) * b(1);
  const double Z = a(0) * b(3) + a(1) * b(2) - a(2) * b(1) - a(3) * b(0);
  const double na = a.squaredNorm(), n3 = a(0) * a(0) - a(1) * a(1) - a(2) * a(2) + a(3) * a(3);
  return Vec3<double>(2 * kx * X * X + 2 * ky * Y * Y - Z * na, kx * n3 * X + 2 * (a(0) * a(2) + a(1) * a(3)) * na,
                      ky * n3 * Y + 2 * (a(2) * a(3) - a(0) * a(1)) * na);
}

// GF §14.5 lines 9268–9282 as printed (erratum 10): λ_Ry with the x-based weights
// α_Rh = (x_Ra − x_Rk)/Δ, α_Rk = (x_h − x_Ra)/Δ, Δ = (x_Ra − x_Rk)(y_Ra − y_h) + (x_h − x_Ra)(y_Ra − y_Rk)
template <class S>
S verticalFootForceAlphaAsPrinted(const PlanarBiped<S>& b, const DynVector<S>& th, const DynVector<S>& thd,
                                  const DynVector<S>& thdd, const DynVector<S>& tau) {
  const auto j = b.jointCentres(th);
  const S xh = j[0](0), yh = j[0](1), xk = j[1](0), yk = j[1](1), xa = j[2](0), ya = j[2](1);
  const S D = (xa - xk) * (ya - yh) + (xh - xa) * (ya - yk);
  const DynVector<S> E = b.model().tree().inverseDynamics(th, thd, thdd);
  return (xa - xk) / D * (E(3) - tau(3)) + (xh - xa) / D * (E(4) - tau(4));
}

template <class S> BipedParameters<S> bipedParameters() {
  return {S(10), S(3) / S(10), S(1) / S(2), S(9) / S(20), S(4), S(7) / S(100), S(9) / S(20), S(3), S(1) / S(20), S(981) / S(100)};
}
template <class S> BipedPose<S> bipedHome() {
  using V2 = Eigen::Matrix<S, 2, 1>;
  return {V2(S(0), S(3) / S(4)), V2(S(1) / S(5), S(0)), V2(S(-1) / S(5), S(0)), S(0)};
}

template <class S> StewartDynamics<S> stewart(bool masslessLegs) {
  using std::cos;
  using std::sin;
  std::array<Vec3<S>, 6> base, plat;
  const S deg = S(3.14159265358979323846264338327950288L) / S(180);
  for (int k = 0; k < 3; ++k)
    for (int s = 0; s < 2; ++s) {
      const S a = S(120 * k) * deg + S(s ? 12 : -12) * deg, b = S(120 * k + 60) * deg + S(s ? -15 : 15) * deg;
      base[std::size_t(2 * k + s)] = Vec3<S>(cos(a), sin(a), S(0));
      plat[std::size_t(2 * k + s)] = Vec3<S>(cos(b) / S(2), sin(b) / S(2), S(0));
    }
  // the pairing of base and platform points: leg i from base point i to platform point i (rotated by one)
  std::array<Vec3<S>, 6> platPaired;
  for (int i = 0; i < 6; ++i) platPaired[std::size_t(i)] = plat[std::size_t((i + 5) % 6)];
  const SpatialInertia<S> P(S(5), Vec3<S>(S(0), S(0), S(1) / S(20)), Mat3<S>(Vec3<S>(S(3) / S(10), S(3) / S(10), S(1) / S(2)).asDiagonal()));
  const StewartLegInertia<S> leg = masslessLegs ? StewartLegInertia<S>{S(0), S(0), S(0), S(0), S(0), S(0)}
                                                : StewartLegInertia<S>{S(1), S(1) / S(5), S(1) / S(50), S(3) / S(2), S(3) / S(10), S(1) / S(25)};
  return StewartDynamics<S>(base, platPaired, P, leg, S(981) / S(100));
}
template <class S> SE3<S> stewartPose() {
  const Vec6<S> x = (Vec6<S>() << S(1) / S(20), S(-1) / S(25), S(1) / S(30), S(1) / S(50), S(-3) / S(100), S(1)).finished();
  return SE3Tangent<S>(Vec6<S>::Zero()).exp() * SE3<S>(SE3Tangent<S>(x).exp());
}

}  // namespace

TEMPLATE_TEST_CASE("freedoms and constraint wrenches annihilate each other (quadric surface, fixed point, pen)", "[constrained][holonomic]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1421);
  for (int c = 0; c < 3; ++c) {
    const S kx = uniform<S>(g, -2, 2), ky = uniform<S>(g, -2, 2), x = uniform<S>(g), y = uniform<S>(g);
    const Mat6X<S> Z = quadricSurfaceFreedoms<S>(kx, ky, x, y), W = quadricSurfaceWrenches<S>(kx, ky, x, y);
    CHECK((W.transpose() * Z).cwiseAbs().maxCoeff() < Tolerance<S>::identity(64) * S(20));
    const Mat6X<S> Wb = constraintWrenchBasis<S>(Z);
    CHECK(Wb.cols() == 3);
    CHECK((Wb.transpose() * Z).cwiseAbs().maxCoeff() < Tolerance<S>::identity(1024) * S(20));
    // the dual complement pairs to δ with W and stays dual after adding freedoms
    const Mat6X<S> Zc = dualComplement<S>(W);
    CHECK((W.transpose() * Zc - DynMatrix<S>::Identity(3, 3)).cwiseAbs().maxCoeff() < Tolerance<S>::identity(4096) * S(100));
  }
  // pen on a table (GF lines 8878–8888): W = Q₀ z (self-reciprocal)
  Mat6X<S> Z = Mat6X<S>::Zero(6, 3);
  Z(2, 0) = S(1);
  Z(3, 1) = S(1);
  Z(4, 2) = S(1);
  Mat6<S> Q0 = Mat6<S>::Zero();
  Q0.template topRightCorner<3, 3>().setIdentity();
  Q0.template bottomLeftCorner<3, 3>().setIdentity();
  CHECK(((Q0 * Z).transpose() * Z).cwiseAbs().maxCoeff() == S(0));
  Mat6X<S> dep = Z;
  dep.col(2) = dep.col(1);
  CHECK_THROWS_AS(constraintWrenchBasis<S>(dep), InvalidInput);
}

TEST_CASE("quadric-surface quartics: corrected ones vanish on an exact pose, printed ones do not (errata 5, 6)", "[constrained][holonomic]") {
  const double kx = 3.0 / 5, ky = -7.0 / 4, X0 = 1.0 / 3, Y0 = -2.0 / 5, Z0 = (kx * X0 * X0 + ky * Y0 * Y0) / 2;
  const Vec3<double> n = Vec3<double>(-kx * X0, -ky * Y0, 1).normalized(), k(0, 0, 1);
  const Vec3<double> ax = k.cross(n).normalized();
  const double ang = std::atan2(k.cross(n).norm(), k.dot(n)), spin = 2.0 / 7;
  Q4 r1, r2, t;
  r1 << std::cos(ang / 2), std::sin(ang / 2) * ax;
  r2 << std::cos(spin / 2), std::sin(spin / 2) * n;
  const Q4 a = qmul(r2, r1);
  t << 0, X0, Y0, Z0;
  const Q4 b = qmul(t, a) / 2;
  const Vec3<double> fixed = quadricSurfaceQuartics<double>(kx, ky, a, b);
  const Vec3<double> printed = quadricSurfaceQuarticsAsPrinted(kx, ky, a, b);
  CHECK(fixed.cwiseAbs().maxCoeff() < 1e-14);
  CHECK(printed.cwiseAbs().maxCoeff() > 1e-2);  // geometry_check.py: −0.053, −0.081, −0.283
}

TEMPLATE_TEST_CASE("constrained rigid body (fixed point): DAE λ = dual-basis λ, q̈ = Euler's equations", "[constrained][holonomic]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1422);
  Mat6X<S> Z = Mat6X<S>::Zero(6, 3);
  Z.template topRows<3>().setIdentity();  // (i, 0), (j, 0), (k, 0): rotations about the origin
  const SpatialInertia<S> N0(S(2), uniformVec<S, 3>(g), Mat3<S>(Vec3<S>(S(1), S(3) / S(2), S(2)).asDiagonal()));
  const ConstrainedRigidBody<S> body(N0, Z);
  const SE3<S> pose = SE3Tangent<S>((Vec6<S>() << uniformVec<S, 3>(g), Vec3<S>::Zero()).finished()).exp();
  Vec6<S> qd = Vec6<S>::Zero();
  qd.template head<3>() = uniformVec<S, 3>(g);
  const Vec6<S> F = (Vec6<S>() << uniformVec<S, 3>(g), S(0), S(0), S(-2) * S(981) / S(100)).finished();
  const auto [qdd, lambda] = body.solveMultipliers(pose, qd, F);
  const Vec6<S> qddReduced = body.acceleration(pose, qd, F);
  const S tol = Tolerance<S>::identity(4096) * S(100);
  CHECK((qdd - qddReduced).cwiseAbs().maxCoeff() < tol);
  // Euler about the fixed point: I_o ω̇ + ω × I_o ω = M_o
  const Mat6<S> N = body.inertia(pose);
  const Mat3<S> Io = N.template topLeftCorner<3, 3>();
  const Vec3<S> w = qd.template head<3>();
  const Vec3<S> wd = Io.inverse() * Vec3<S>(F.template head<3>() - w.cross(Io * w));
  CHECK((qdd.template head<3>() - wd).cwiseAbs().maxCoeff() < tol);
  CHECK(qdd.template tail<3>().cwiseAbs().maxCoeff() < tol);
  // λ by the dual basis, unchanged when freedoms are added to the complement (GF line 8976)
  const Mat6X<S> Zc = dualComplement<S>(body.wrenches());
  const DynVector<S> l1 = body.multipliersByDualBasis(pose, qd, qdd, F, Zc);
  const Mat6X<S> Zc2 = Zc + Z * DynMatrix<S>::Constant(3, 3, S(1) / S(3));
  const DynVector<S> l2 = body.multipliersByDualBasis(pose, qd, qdd, F, Zc2);
  CHECK((l1 - lambda).cwiseAbs().maxCoeff() < tol * S(10));
  CHECK((l2 - lambda).cwiseAbs().maxCoeff() < tol * S(10));
}

TEST_CASE("6R robot holding a pen on a table (GF §14.2.3): simulated 1 s, drift at rounding, energy by RK4 order", "[constrained][holonomic][simulation]") {
  auto& g = rng(1423);
  const RobotSpec r = randomRobot(g, 6);
  const SerialDynamics<double> robot = build<double>(r);
  std::vector<Vec6<double>> W(3, Vec6<double>::Zero());
  W[0](5) = 1;  // force along k through the origin
  W[1](0) = 1;  // couple about i
  W[2](1) = 1;  // couple about j
  const ConstrainedTree<double> m = constrainedSerialRobot<double>(robot, W);
  CHECK(m.freedomBasis(DynVector<double>::Zero(6)).cols() == 3);
  auto run = [&](double h, int steps, double* drift) {
    ConstrainedState<double> y{DynVector<double>::Zero(6), m.freedomBasis(DynVector<double>::Zero(6)) * Eigen::Vector3d(0.5, -0.3, 0.4)};
    const double e0 = m.totalEnergy(y);
    double de = 0;
    *drift = 0;
    for (int k = 0; k < steps; ++k) {
      y = m.rk4Step(y, h, DynVector<double>::Zero(6), true);
      de = std::max(de, std::abs(m.totalEnergy(y) - e0));
      *drift = std::max(*drift, m.positionResidual(y.theta).cwiseAbs().maxCoeff());
    }
    return de;
  };
  double d1 = 0, d2 = 0;
  const double e1 = run(0.004, 250, &d1), e2 = run(0.002, 500, &d2);
  CHECK(d1 < 1e-12);
  CHECK(d2 < 1e-12);
  CHECK(e1 / e2 > 8);  // RK4 (order 4) + a projection of order 5: halving h divides the error by ≈ 16
  CHECK(e1 < 1e-3);
}

TEMPLATE_TEST_CASE("biped: vertical foot force by the corrected α = full multiplier system — printed α gives −λ_Rx (erratum 10)",
                   "[constrained][biped]", float, double, long double, __float128, mpfr::mpreal) {
  using S = TestType;
  auto& g = rng(1424);
  const PlanarBiped<S> b(bipedParameters<S>(), bipedHome<S>());
  const int cases = std::is_same_v<S, mpfr::mpreal> ? 1 : 4;
  for (int c = 0; c < cases; ++c) {
    BipedPose<S> pose = bipedHome<S>();
    pose.hip += uniformVec<S, 2>(g, -0.08, 0.08);
    pose.torsoAngle = uniform<S>(g, -0.3, 0.3);
    const DynVector<S> th = b.angles(pose);
    CHECK(b.model().positionResidual(th).cwiseAbs().maxCoeff() < Tolerance<S>::identity(4096));
    const DynVector<S> thd = b.completeRates(th, uniformVec<S, 3>(g));
    const DynVector<S> thdd = b.completeAccelerations(th, thd, uniformVec<S, 3>(g));
    const DynVector<S> tau = b.torquesForMotion(th, thd, thdd);
    const DynVector<S> lam = b.footForces(th, thd, thdd, tau);
    const S ly = b.verticalFootForceAlpha(th, thd, thdd, tau);
    const S lxPrinted = verticalFootForceAlphaAsPrinted(b, th, thd, thdd, tau);
    using std::abs;
    const S tol = Tolerance<S>::identity(4096) * S(1000);
    CHECK(abs(ly - lam(1)) < tol);
    CHECK(abs(lxPrinted + lam(0)) < tol);
    CHECK(abs(lxPrinted - lam(1)) > S(1));
    // the foot forces carry the weight when nothing accelerates much: Σ λ_y ≈ m g ± inertial terms
    CHECK(isFinite(lam(3)));
  }
  // a straight right leg (ankle at full reach): the α system is singular → InvalidInput
  BipedPose<S> straight = bipedHome<S>();
  using std::sqrt;
  straight.rightAnkle = Eigen::Matrix<S, 2, 1>(S(1) / S(5), S(3) / S(4) - sqrt(S(81) / S(100) - S(1) / S(25)));
  const PlanarBiped<S> bs(bipedParameters<S>(), straight);
  CHECK_THROWS_AS(bs.verticalForceAlpha(DynVector<S>::Zero(7)), InvalidInput);
  BipedPose<S> far = bipedHome<S>();
  far.rightAnkle(0) = S(2);
  CHECK_THROWS_AS(PlanarBiped<S>(bipedParameters<S>(), far), InvalidInput);
}

TEMPLATE_TEST_CASE("Stewart inverse dynamics: α elimination = 24 × 24 multipliers — massless legs reproduce the platform wrench",
                   "[constrained][stewart]", float, double, long double, __float128, mpfr::mpreal) {
  using S = TestType;
  auto& g = rng(1425);
  const SE3<S> pose = stewartPose<S>();
  const Vec6<S> qd = uniformVec<S, 6>(g, -0.3, 0.3), qdd = uniformVec<S, 6>(g, -1, 1);
  const S tol = Tolerance<S>::identity(4096) * S(1000);
  {
    const StewartInverseDynamics<S> r = stewart<S>(false).inverseDynamics(pose, qd, qdd);
    CHECK((r.forcesAlpha - r.forcesMultipliers).cwiseAbs().maxCoeff() < tol * (S(1) + r.forcesAlpha.cwiseAbs().maxCoeff()));
    CHECK(r.residual < tol * S(10));
    // 18 constraints in 24 rates: rank 18, six freedoms (GF line 9361)
    const ConstrainedTree<S> m = stewart<S>(false).model(pose);
    CHECK(m.constraintRank(DynVector<S>::Zero(24)) == 18);
    CHECK((m.constraintMatrix(DynVector<S>::Zero(24)) * r.thetaDot).cwiseAbs().maxCoeff() < tol);
  }
  {
    const StewartDynamics<S> sd = stewart<S>(true);
    const StewartInverseDynamics<S> r = sd.inverseDynamics(pose, qd, qdd);
    const auto lines = sd.legLines(pose);
    Vec6<S> sum = Vec6<S>::Zero();
    for (int i = 0; i < 6; ++i) sum -= r.forcesAlpha(i) * lines[std::size_t(i)];
    CHECK((sum - r.platformWrench).cwiseAbs().maxCoeff() < tol * (S(1) + r.platformWrench.cwiseAbs().maxCoeff()));
  }
}

}  // namespace SOMA_UNITY_ID
