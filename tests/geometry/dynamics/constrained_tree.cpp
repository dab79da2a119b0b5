// Tree and constrained-tree dynamics (GF §14.1–14.4): tree combinatorics (Fig. 14.1), the recursive
// up/down pass over a tree against the serial RNE on a chain and against the joint equations, the
// mass-matrix assembly and the power balance on a branched tree; the printed passes (errata 2, 3)
// fail; the planar 4-bar: corrected α (erratum 8), the α-equation torque = Lagrange-multiplier
// torque = power balance, free-motion energy with an order-derived bound, singular postures.
#include "soma/geometry/dynamics/constrained_tree.hpp"
#include "soma/geometry/dynamics/fourbar_dynamics.hpp"
#include "soma/geometry/dynamics/tree_dynamics.hpp"

#include "serial_dynamics_support.hpp"

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::test;

namespace {

template <class S> TreeDynamics<S> treeOf(const RobotSpec& r, const std::vector<int>& parent) {
  const SerialDynamics<S> chain = build<S>(r);
  std::vector<Vec6<S>> s;
  std::vector<Mat6<S>> N;
  for (int i = 0; i < chain.dof(); ++i) {
    s.push_back(chain.homeScrews()[std::size_t(i)].coeffs());
    N.push_back(chain.homeInertias()[std::size_t(i)]);
  }
  return TreeDynamics<S>(TreeTopology(parent), s, N, Vec3<S>(S(0), S(0), -scalarCast<S>(r.gravity)));
}

template <class S> DynVector<S> randomState(std::mt19937_64& g, int n, double r = 1.5) {
  DynVector<S> v(n);
  for (int i = 0; i < n; ++i) v(i) = uniform<S>(g, -r, r);
  return v;
}

template <class S> S relErr(const DynVector<S>& a, const DynVector<S>& b) {
  return (a - b).cwiseAbs().maxCoeff() / (S(1) + b.cwiseAbs().maxCoeff());
}

template <class S> FourBarDynamics<S> crankRocker() {  // the invented Grashof crank–rocker of fourbar_check.py
  const std::array<PlanarLink<S>, 3> links{PlanarLink<S>{S(1), S(1) / S(2), S(1) / S(10), S(1) / S(10)},
                                           PlanarLink<S>{S(2), S(1), S(-1) / S(5), S(4) / S(5)},
                                           PlanarLink<S>{S(3) / S(2), S(9) / S(10), S(3) / S(20), S(9) / S(20)}};
  return FourBarDynamics<S>(S(1), S(11) / S(5), S(9) / S(5), S(5) / S(2), links);
}

// GF §14.1.3 box, lines 8824 and 8838 as printed (errata 2, 3): the up/down pass in home coordinates
// with the parent's angle in the down pass (downSlip) or the parent's velocity for its acceleration.
template <class S>
DynVector<S> treePassAsPrinted(const TreeDynamics<S>& t, const DynVector<S>& th, const DynVector<S>& thd,
                               const DynVector<S>& thdd, bool downSlip) {
  const TreeTopology& topo = t.topology();
  const auto& s0 = t.homeScrews();
  const auto& N0 = t.homeInertias();
  const auto n = std::size_t(t.dof());
  std::vector<Mat6<S>> Hinv(n);
  std::vector<Vec6<S>> v(n), a(n), P(n);
  for (int i : topo.breadthFirst()) {
    const auto k = std::size_t(i);
    const int p = topo.parent(i);
    Hinv[k] = SE3Tangent<S>(Vec6<S>(-th(i) * s0[k])).exp().adjoint();
    const Vec6<S> vp = p < 0 ? Vec6<S>::Zero() : v[std::size_t(p)];
    const Vec6<S> ap = p < 0 ? Vec6<S>(-t.gravityScrew()) : a[std::size_t(p)];
    v[k] = thd(i) * s0[k] + Hinv[k] * vp;
    a[k] = thdd(i) * s0[k] + thd(i) * screwBracket(v[k], s0[k]) + Hinv[k] * (downSlip ? ap : vp);
    P[k] = N0[k] * a[k] + coadjoint(SE3Tangent<S>(v[k]), Vec6<S>(N0[k] * v[k]));
  }
  DynVector<S> tau(t.dof());
  const auto& order = topo.breadthFirst();
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const auto k = std::size_t(*it);
    for (int c : topo.children(*it)) {
      const auto kc = std::size_t(c);
      const Mat6<S> X = downSlip ? Mat6<S>(SE3Tangent<S>(Vec6<S>(-th(*it) * s0[kc])).exp().adjoint()) : Hinv[kc];
      P[k] += X.transpose() * P[kc];
    }
    tau(*it) = P[k].dot(s0[k]);
  }
  return tau;
}

// GF §14.4 line 9177 as printed (erratum 8): α₁ = d₁d₄ sin θ₂ − d₂d₄ sin(θ₁+θ₂)
template <class S> Eigen::Matrix<S, 4, 1> alphaAsPrinted(const FourBarDynamics<S>& fb, const FourBarPosture<S>& p) {
  using std::sin;
  const auto& d = fb.lengths();
  Eigen::Matrix<S, 4, 1> a = fb.alpha(p);
  a(0) = d[0] * d[3] * sin(p.theta2) - d[1] * d[3] * sin(p.theta1 + p.theta2);
  return a;
}
// GF §14.4 line 9195 with the printed α (erratum 8): α₁τ = q̈₁ᵀN₁α₁s₁ + q̈₂ᵀN₂(α₁s₁ + α₂s₂) − q̈₃ᵀN₃α₄s₄
template <class S> S torqueAlphaAsPrinted(const FourBarDynamics<S>& fb, const S& t1, const S& t1d, const S& t1dd) {
  const FourBarMotion<S> m = fb.motion(t1, t1d, t1dd);
  const auto s = fb.screws(m.posture);
  const Eigen::Matrix<S, 4, 1> a = alphaAsPrinted(fb, m.posture);
  return (m.twistDot[0].dot(m.inertia[0] * (a(0) * s[0])) + m.twistDot[1].dot(m.inertia[1] * PVec<S>(a(0) * s[0] + a(1) * s[1])) -
          m.twistDot[2].dot(m.inertia[2] * (a(3) * s[3]))) / a(0);
}

}  // namespace

TEST_CASE("tree topology of Fig. 14.1: ancestry, partial order, nested form — cycles rejected", "[constrained][tree]") {
  const TreeTopology t = TreeTopology::fromBookParents({0, 1, 1, 3, 3, 4});
  CHECK(t.ancestry(5) == std::vector<int>{0, 2, 3, 5});  // book: (1, 3, 4, 6)
  CHECK(t.precedes(2, 5));
  CHECK_FALSE(t.precedes(1, 5));
  CHECK_FALSE(t.precedes(5, 2));
  CHECK(t.level(5) == 4);
  CHECK(t.leaves() == std::vector<int>{1, 4, 5});
  CHECK(t.subtree(2) == std::vector<int>{2, 3, 4, 5});
  CHECK(t.nested() == "(1(2, 3(4(6), 5)))");  // GF §14.3.1 line 9044
  CHECK_THROWS_AS(TreeTopology({1, 2, 0}), InvalidInput);       // a 3-cycle never reaches the ground
  CHECK_THROWS_AS(TreeTopology({-1, 1}), InvalidInput);         // self-loop
  CHECK_THROWS_AS(TreeTopology({-1, 5}), InvalidInput);         // out of range
  CHECK_THROWS_AS(TreeTopology(std::vector<int>{}), InvalidInput);
}

TEMPLATE_TEST_CASE("tree up/down pass on a chain = serial RNE of GF §13.3", "[constrained][tree]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1401);
  const int cases = std::is_same_v<S, mpfr::mpreal> ? 1 : 4;
  for (int c = 0; c < cases; ++c) {
    const RobotSpec r = randomRobot(g, 5, c % 2 == 1);
    const SerialDynamics<S> chain = build<S>(r);
    const TreeDynamics<S> tree = treeOf<S>(r, {-1, 0, 1, 2, 3});
    const DynVector<S> th = randomState<S>(g, 5, 3), thd = randomState<S>(g, 5), thdd = randomState<S>(g, 5);
    const DynVector<S> ref = chain.inverseDynamics(th, thd, thdd);
    CHECK(relErr<S>(tree.inverseDynamics(th, thd, thdd), ref) < Tolerance<S>::identity(4096));
    CHECK(relErr<S>(tree.inverseDynamicsSpatial(th, thd, thdd), ref) < Tolerance<S>::identity(4096));
  }
}

TEMPLATE_TEST_CASE("branched tree (Fig. 14.1): recursive = joint equations = A θ̈ + bias — printed passes fail",
                   "[constrained][tree]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1402);
  const RobotSpec r = randomRobot(g, 6);
  const TreeDynamics<S> tree = treeOf<S>(r, {-1, 0, 0, 2, 2, 3});
  const DynVector<S> th = randomState<S>(g, 6, 3), thd = randomState<S>(g, 6), thdd = randomState<S>(g, 6);
  const DynVector<S> rec = tree.inverseDynamics(th, thd, thdd);
  const DynVector<S> spatial = tree.inverseDynamicsSpatial(th, thd, thdd);
  const DynVector<S> bias = tree.inverseDynamicsSpatial(th, thd, DynVector<S>::Zero(6));
  const DynVector<S> assembled = tree.massMatrix(th) * thdd + bias;
  CHECK(relErr<S>(rec, spatial) < Tolerance<S>::identity(4096));
  CHECK(relErr<S>(assembled, spatial) < Tolerance<S>::identity(4096));
  // the mass matrix is symmetric and zero between unrelated joints (1 and 2 are siblings)
  const DynMatrix<S> A = tree.massMatrix(th);
  CHECK(A(1, 2) == S(0));
  CHECK(A(1, 5) == S(0));
  // errata 2 and 3: the printed down-pass transform and the printed parent term are wrong
  CHECK(relErr<S>(treePassAsPrinted(tree, th, thd, thdd, true), spatial) > S(1) / S(100));
  CHECK(relErr<S>(treePassAsPrinted(tree, th, thd, thdd, false), spatial) > S(1) / S(100));
}

TEST_CASE("branched tree: power balance θ̇ᵀτ = d(E_K + E_P)/dt along a trajectory (Lagrangian check)", "[constrained][tree]") {
  using Q = __float128;
  auto& g = rng(1403);
  const RobotSpec r = randomRobot(g, 6);
  const TreeDynamics<Q> tree = treeOf<Q>(r, {-1, 0, 0, 2, 2, 3});
  const DynVector<Q> th = randomState<Q>(g, 6, 3), thd = randomState<Q>(g, 6), thdd = randomState<Q>(g, 6);
  auto E = [&](const Q& t) {
    const DynVector<Q> a = th + t * thd + (t * t / Q(2)) * thdd, b = thd + t * thdd;
    return tree.kineticEnergy(a, b) + tree.potentialEnergy(a);
  };
  const Q dEdt = centralDiff8<Q>(E, Q(1) / Q(256));
  const Q power = thd.dot(tree.inverseDynamics(th, thd, thdd));
  CHECK(double(fabsq(dEdt - power) / (1 + fabsq(power))) < 1e-15);
}

TEMPLATE_TEST_CASE("tree: massless intermediate links (a ball joint as three revolutes) and bad inputs", "[constrained][tree][edge]",
                   float, double) {
  using S = TestType;
  std::vector<Vec6<S>> s(3, Vec6<S>::Zero());
  s[0](0) = S(1);
  s[1](1) = S(1);
  s[2](2) = S(1);
  std::vector<Mat6<S>> N{Mat6<S>::Zero(), Mat6<S>::Zero(),
                         SpatialInertia<S>(S(2), Vec3<S>(S(0), S(0), S(-1)), Mat3<S>(Vec3<S>(S(1), S(1), S(1) / S(2)).asDiagonal())).matrix()};
  const TreeDynamics<S> ball(TreeTopology({-1, 0, 1}), s, N, Vec3<S>(S(0), S(0), S(-10)));
  DynVector<S> z = DynVector<S>::Zero(3);
  // hanging straight down: no torque; tilted about x: gravity torque m g l sin θ
  CHECK(ball.inverseDynamics(z, z, z).cwiseAbs().maxCoeff() < Tolerance<S>::identity(64) * S(20));
  z(0) = S(1) / S(2);
  using std::sin;
  CHECK(ball.inverseDynamics(z, DynVector<S>::Zero(3), DynVector<S>::Zero(3))(0) ==
        Approx(double(S(20) * sin(S(1) / S(2)))).epsilon(1e-5));
  std::vector<Vec6<S>> bad = s;
  bad[0](0) = S(2);
  CHECK_THROWS_AS(TreeDynamics<S>(TreeTopology({-1, 0, 1}), bad, N, Vec3<S>::Zero()), InvalidInput);
  CHECK_THROWS_AS(ball.inverseDynamics(DynVector<S>::Zero(2), DynVector<S>::Zero(3), DynVector<S>::Zero(3)), InvalidInput);
}

TEMPLATE_TEST_CASE("4-bar: corrected α annihilates the loop screws, the printed α does not (erratum 8)", "[constrained][fourbar]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  const FourBarDynamics<S> fb = crankRocker<S>();
  for (int k = 0; k < 8; ++k) {
    const FourBarPosture<S> p = fb.posture(S(k) * S(3) / S(4) + S(1) / S(10));
    const auto s = fb.screws(p);
    const Eigen::Matrix<S, 4, 1> a = fb.alpha(p), b = alphaAsPrinted(fb, p);
    const PVec<S> ra = a(0) * s[0] + a(1) * s[1] + a(2) * s[2] + a(3) * s[3];
    const PVec<S> rb = b(0) * s[0] + b(1) * s[1] + b(2) * s[2] + b(3) * s[3];
    CHECK(ra.cwiseAbs().maxCoeff() < Tolerance<S>::identity(256) * S(20));
    using std::abs;
    using std::sin;
    // printed residual = (d₁(d₄ − d₂) sin θ₂, 0, 0): d₄ − d₂ = 0.3
    CHECK(abs(rb(0) - S(3) / S(10) * sin(p.theta2)) < Tolerance<S>::identity(256) * S(20));
  }
}

TEMPLATE_TEST_CASE("4-bar torque: α-equation = Lagrange multipliers (3-D constrained tree) = printed α fails", "[constrained][fourbar]",
                   float, double, long double, __float128) {
  using S = TestType;
  const FourBarDynamics<S> fb = crankRocker<S>();
  const S home = S(3) / S(10);
  const ConstrainedTree<S> model = fb.constrainedTree(home);
  DynMatrix<S> B = DynMatrix<S>::Zero(3, 1);
  B(0, 0) = S(1);
  const double in[5][3] = {{0.3, 1.2, -0.7}, {1.4, -0.8, 2.0}, {2.6, 2.5, 0.3}, {4.0, 1.0, 1.0}, {5.5, -1.7, -1.1}};
  S worstPrinted(0);
  for (const auto& x : in) {
    const S t1 = scalarCast<S>(x[0]), t1d = scalarCast<S>(x[1]), t1dd = scalarCast<S>(x[2]);
    const S tauA = fb.torqueAlpha(t1, t1d, t1dd);
    const auto st = fb.treeState(home, fb.motion(t1, t1d, t1dd));
    // the tree state satisfies the constraints (positions, velocities, accelerations)
    CHECK(model.positionResidual(st[0]).cwiseAbs().maxCoeff() < Tolerance<S>::identity(4096) * S(10));
    CHECK((model.constraintMatrix(st[0]) * st[1]).cwiseAbs().maxCoeff() < Tolerance<S>::identity(4096) * S(10));
    const DynVector<S> accRes = model.constraintMatrix(st[0]) * st[2] + model.accelerationBias(st[0], st[1]);
    CHECK(accRes.cwiseAbs().maxCoeff() < Tolerance<S>::identity(4096) * S(100));
    const ConstrainedForces<S> f = model.inverseDynamicsMultipliers(st[0], st[1], st[2], B);
    const ConstrainedForces<S> fa = model.inverseDynamicsAlpha(st[0], st[1], st[2], B);
    using std::abs;
    CHECK(abs(f.actuators(0) - tauA) < Tolerance<S>::identity(4096) * S(100) * (S(1) + abs(tauA)));
    CHECK(abs(fa.actuators(0) - tauA) < Tolerance<S>::identity(4096) * S(100) * (S(1) + abs(tauA)));
    CHECK(f.residual < Tolerance<S>::identity(4096) * S(100));
    // the multipliers by dual vectors (GF §14.3.2) equal the least-squares ones
    DynVector<S> tau = DynVector<S>::Zero(3);
    tau(0) = tauA;
    CHECK(relErr<S>(model.multipliersByDualVectors(st[0], st[1], st[2], tau), f.lambda) < Tolerance<S>::identity(4096) * S(100));
    worstPrinted = std::max(worstPrinted, S(abs(torqueAlphaAsPrinted(fb, t1, t1d, t1dd) - tauA)));
  }
  CHECK(worstPrinted > S(1) / S(10));  // fourbar_check.py: 0.285
}

TEST_CASE("4-bar torque = virtual work (power balance τθ̇₁ = dE_K/dt, 8th-order differences in __float128)", "[constrained][fourbar]") {
  using Q = __float128;
  const FourBarDynamics<Q> fb = crankRocker<Q>();
  const double in[3][3] = {{0.3, 1.2, -0.7}, {2.6, 2.5, 0.3}, {5.5, -1.7, -1.1}};
  for (const auto& x : in) {
    const Q t1 = x[0], t1d = x[1], t1dd = x[2];
    const Q dE = centralDiff8<Q>([&](const Q& t) { return fb.kineticEnergy(t1 + t1d * t + t1dd * t * t / 2, t1d + t1dd * t); },
                                 Q(1) / Q(512));
    CHECK(double(fabsq(dE / t1d - fb.torqueAlpha(t1, t1d, t1dd))) < 1e-14);
  }
}

TEST_CASE("4-bar free motion: energy error of RK4 scales like h⁴ — the 3-D DAE with projection keeps drift at rounding",
          "[constrained][fourbar][simulation]") {
  const FourBarDynamics<double> fb = crankRocker<double>();
  auto run = [&](double h, int steps) {
    std::array<double, 2> y{0.3, 2.0};
    const double e0 = fb.kineticEnergy(y[0], y[1]);
    double worst = 0;
    for (int k = 0; k < steps; ++k) {
      y = fb.rk4Step(y, h, 0.0);
      worst = std::max(worst, std::abs(fb.kineticEnergy(y[0], y[1]) - e0));
    }
    return worst / e0;
  };
  const double e1 = run(0.01, 200), e2 = run(0.005, 400);
  // RK4 is order 4: over the same 2 s, halving h divides the energy error by 2⁴ = 16 (accepted 8…32)
  CHECK(e1 / e2 > 8);
  CHECK(e1 / e2 < 32);
  CHECK(e1 < 1e-4);
  // the same motion as a constrained tree (Lagrange multipliers in the null space), RK4 + projection
  const ConstrainedTree<double> m = fb.constrainedTree(0.3);
  const auto st = fb.treeState(0.3, fb.motion(0.3, 2.0, 0.0));
  ConstrainedState<double> y{st[0], st[1]};
  const double E0 = m.totalEnergy(y);
  double drift = 0, de = 0;
  for (int k = 0; k < 200; ++k) {
    y = m.rk4Step(y, 0.01, DynVector<double>::Zero(3), true);
    drift = std::max(drift, m.positionResidual(y.theta).cwiseAbs().maxCoeff());
    de = std::max(de, std::abs(m.totalEnergy(y) - E0) / E0);
  }
  CHECK(drift < 1e-12);
  CHECK(de < 1e-4);
  // both models agree on where the crank is after 2 s (same initial state, same h)
  std::array<double, 2> yb{0.3, 2.0};
  for (int k = 0; k < 200; ++k) yb = fb.rk4Step(yb, 0.01, 0.0);
  CHECK(std::abs(std::remainder(y.theta(0) + 0.3 - yb[0], 2 * M_PI)) < 1e-5);
}

TEMPLATE_TEST_CASE("4-bar singular and impossible postures: InvalidInput, never NaN", "[constrained][fourbar][edge]", float, double,
                   __float128) {
  using S = TestType;
  using std::acos;
  const std::array<PlanarLink<S>, 3> links{PlanarLink<S>{S(1), S(1), S(0), S(1) / S(10)}, PlanarLink<S>{S(1), S(1) / S(2), S(0), S(1) / S(10)},
                                           PlanarLink<S>{S(1), S(1) / S(2), S(0), S(1) / S(10)}};
  // non-Grashof (d₁ = 2, d₂ = 1.2, d₃ = 1, d₄ = 2.5): the crank stops where coupler and rocker align,
  // |P₂P₄| = d₂ + d₃ = 2.2, cos θ₁ = (4 + 6.25 − 4.84)/10
  const FourBarDynamics<S> fb(S(2), S(6) / S(5), S(1), S(5) / S(2), links);
  const S lim = acos((S(4) + S(25) / S(4) - S(121) / S(25)) / S(10));
  const S inside = lim - S(1) / S(20), outside = lim + S(1) / S(20);
  const S tau = fb.torqueAlpha(inside, S(1), S(0));
  CHECK(isFinite(tau));
  CHECK(fb.singularityMeasure(fb.posture(inside)) > S(1) / S(100));
  CHECK(fb.singularityMeasure(fb.posture(lim)) < Tolerance<S>::input());
  CHECK_THROWS_AS(fb.torqueAlpha(lim, S(1), S(0)), InvalidInput);    // folded: reported singular
  CHECK_THROWS_AS(fb.posture(outside), InvalidInput);                // cannot close
  CHECK_THROWS_AS(FourBarDynamics<S>(S(-1), S(1), S(1), S(1), links), InvalidInput);
  // a regular posture of the constrained tree: C (2 × 3) has rank 2, one freedom
  const ConstrainedTree<S> m = fb.constrainedTree(inside);
  CHECK(m.constraintRank(DynVector<S>::Zero(3)) == 2);
}

}  // namespace SOMA_UNITY_ID
