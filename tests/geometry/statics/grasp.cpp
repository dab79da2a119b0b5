// GF §12.5–12.6: force and form closure, ungrippable surfaces, friction cones, second-order contact.
#include "soma/geometry/statics/grasp.hpp"

#include "../../support/scalars.hpp"

#include <cmath>
#include <limits>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::rng;
using soma::test::uniform;
using soma::test::uniformVec;

namespace {
template <class S> using VecD = Eigen::Matrix<S, Eigen::Dynamic, 1>;
template <class S> using MatD = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
template <class S> S tolId(int k = 256) { return Tolerance<S>::identity(k); }

/// Wrenches of normals sampled on a parametric surface x(u, v) (normal = x_u × x_v, finite differences
/// avoided: the callers give the analytic normal).
template <class S, class F> WrenchSet<S> sampleSurface(F surf, int n, std::mt19937_64& g) {
  std::vector<Vec3<S>> p, nn;
  for (int i = 0; i < n; ++i) {
    const auto [x, nrm] = surf(uniform<S>(g), uniform<S>(g));
    p.push_back(x);
    nn.push_back(nrm.normalized());
  }
  return contactNormalWrenches<S>(p, nn);
}
template <class S> std::pair<Vec3<S>, Vec3<S>> ellipsoid(const S& u, const S& v, const S& a, const S& b, const S& c) {
  using std::cos;
  using std::sin;
  const S th = S(3) * u, ph = S(1.4) * v;
  const Vec3<S> x(a * cos(ph) * cos(th), b * cos(ph) * sin(th), c * sin(ph));
  return {x, Vec3<S>(-x.x() / (a * a), -x.y() / (b * b), -x.z() / (c * c))};
}
}  // namespace

TEMPLATE_TEST_CASE("linear program: a textbook optimum, infeasible, unbounded, bad sizes", "[statics][lp]",
                   SOMA_TEST_SCALARS) {
  using S = TestType;
  // min −x − y s.t. x + 2y + s₁ = 4, 3x + y + s₂ = 6 → (1.6, 1.2), −2.8
  MatD<S> A(2, 4);
  A << S(1), S(2), S(1), S(0), S(3), S(1), S(0), S(1);
  VecD<S> b(2), c(4);
  b << S(4), S(6);
  c << S(-1), S(-1), S(0), S(0);
  const auto r = minimiseLinearProgram<S>(c, A, b);
  REQUIRE(r.status == LinearProgramResult<S>::Status::Optimal);
  CHECK(abs(r.value + S(14) / S(5)) <= tolId<S>());
  CHECK(abs(r.x(0) - S(8) / S(5)) <= tolId<S>());
  CHECK(abs(r.x(1) - S(6) / S(5)) <= tolId<S>());
  // x + y = −1, x, y ≥ 0: infeasible
  MatD<S> A2(1, 2);
  A2 << S(1), S(1);
  VecD<S> b2(1), c2(2);
  b2 << S(-1);
  c2 << S(1), S(0);
  CHECK(minimiseLinearProgram<S>(c2, A2, b2).status == LinearProgramResult<S>::Status::Infeasible);
  // x − y = 1, min −x: unbounded
  A2 << S(1), S(-1);
  b2 << S(1);
  c2 << S(-1), S(0);
  CHECK(minimiseLinearProgram<S>(c2, A2, b2).status == LinearProgramResult<S>::Status::Unbounded);
  CHECK_THROWS_AS(minimiseLinearProgram<S>(c, A2, b2), InvalidInput);
}

TEMPLATE_TEST_CASE("GF-12.5 positive spanning: e₁…e₆, −Σe has margin 1/(6 + √6) — both sides of the boundary",
                   "[statics][closure]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::sqrt;
  WrenchSet<S> W = WrenchSet<S>::Zero(6, 7);
  for (int i = 0; i < 6; ++i) W(i, i) = S(1), W(i, 6) = S(-1);
  const auto ps = positiveSpan<S>(W);
  CHECK(ps.spans);
  CHECK(ps.rank == 6);
  CHECK(abs(ps.margin - S(1) / (S(6) + sqrt(S(6)))) <= tolId<S>(1024));
  CHECK(formClosure<S>(W).closed);
  // six never positively span
  CHECK_FALSE(positiveSpan<S>(WrenchSet<S>(W.leftCols(6))).spans);
  CHECK_FALSE(formClosure<S>(WrenchSet<S>(W.leftCols(6))).closed);
  // seventh = −(e₂ + … + e₆) + ε e₁: spans for ε < 0 only
  for (const double eps : {-0.02, 0.0, 0.02}) {
    WrenchSet<S> V = W;
    V(0, 6) = scalarCast<S>(eps);
    CHECK(positiveSpan<S>(V).spans == (eps < 0));
    const auto fc = formClosure<S>(V);
    CHECK(fc.closed == (eps < 0));
    if (eps >= 0) {  // the escape velocity breaks no contact
      CHECK((V.transpose() * fc.escape).minCoeff() >= -tolId<S>(1024));
      CHECK(fc.escape.norm() > S(0.5));
    }
  }
  CHECK_THROWS_AS(positiveSpan<S>(WrenchSet<S>(5, 3)), InvalidInput);
  WrenchSet<S> Z = W;
  Z.col(0).setZero();
  CHECK_THROWS_AS(positiveSpan<S>(Z), InvalidInput);
}

TEST_CASE("GF-12.5 form closure (dual LP) agrees with positive spanning (primal LP) on random sets",
          "[statics][closure]") {
  using S = double;
  auto& g = rng(1251);
  int agree = 0, closed = 0, total = 0;
  for (int m = 6; m <= 12; ++m)
    for (int t = 0; t < 30; ++t) {
      WrenchSet<S> W(6, m);
      for (int j = 0; j < m; ++j) W.col(j) = uniformVec<S, 6>(g);
      const bool a = positiveSpan<S>(W).spans, b = formClosure<S>(W).closed;
      agree += a == b;
      closed += a;
      ++total;
    }
  CHECK(agree == total);
  CHECK(closed > 10);          // both outcomes occur
  CHECK(closed < total - 10);
}

TEMPLATE_TEST_CASE("GF-12.5 ungrippable surfaces: normal-line ranks and the symmetry screw", "[statics][ungrippable]",
                   double, long double, __float128) {
  using S = TestType;
  using std::cos;
  using std::sin;
  auto& g = rng(1252);
  const int n = 40;
  auto rankOf = [](const WrenchSet<S>& W) { return wrenchSpan<S>(W).rank; };
  // sphere, plane: rank 3; circular cylinder: 4
  CHECK(rankOf(sampleSurface<S>([](S u, S v) { return ellipsoid<S>(u, v, S(1), S(1), S(1)); }, n, g)) == 3);
  CHECK(rankOf(sampleSurface<S>([](S u, S v) { return std::pair<Vec3<S>, Vec3<S>>{Vec3<S>(u, v, S(0)), Vec3<S>::UnitZ()}; }, n, g)) == 3);
  CHECK(rankOf(sampleSurface<S>([](S u, S v) {
          return std::pair<Vec3<S>, Vec3<S>>{Vec3<S>(cos(S(3) * u), sin(S(3) * u), v), Vec3<S>(-cos(S(3) * u), -sin(S(3) * u), S(0))};
        }, n, g)) == 4);
  // torus (revolution about z): rank 5, annihilated screw = rotation about z
  const auto torus = wrenchSpan<S>(sampleSurface<S>([](S u, S v) {
    const S th = S(3) * u, ph = S(3) * v;
    const Vec3<S> c(S(2) * cos(th), S(2) * sin(th), S(0)), d(cos(ph) * cos(th), cos(ph) * sin(th), sin(ph));
    return std::pair<Vec3<S>, Vec3<S>>{Vec3<S>(c + S(0.5) * d), Vec3<S>(-d)};
  }, n, g));
  CHECK(torus.rank == 5);
  REQUIRE(torus.annihilatedScrews.size() == 1);
  const VecD<S> sz = torus.annihilatedScrews[0];
  CHECK(abs(abs(sz(2)) - S(1)) <= tolId<S>(1 << 12));
  // helicoid (u cos v, u sin v, p v), p = 0.3: rank 5, screw (k, p k)
  const S p = S(3) / S(10);
  const auto heli = wrenchSpan<S>(sampleSurface<S>([p](S u, S v) {
    const S r = S(0.5) + u, t = S(3) * v;
    const Vec3<S> xu(cos(t), sin(t), S(0)), xv(-r * sin(t), r * cos(t), p);
    return std::pair<Vec3<S>, Vec3<S>>{Vec3<S>(r * cos(t), r * sin(t), p * t), Vec3<S>(xu.cross(xv))};
  }, n, g));
  CHECK(heli.rank == 5);
  REQUIRE(heli.annihilatedScrews.size() == 1);
  const VecD<S> sh = heli.annihilatedScrews[0];
  CHECK(abs(sh(5) / sh(2) - p) <= tolId<S>(1 << 12));
  CHECK(sh.template segment<2>(0).norm() + sh.template segment<2>(3).norm() <= tolId<S>(1 << 12));
  // general cylinder over a non-circular curve (x, y) = (u, u³ − u): rank 5, screw = translation along z
  const auto ext = wrenchSpan<S>(sampleSurface<S>([](S u, S v) {
    return std::pair<Vec3<S>, Vec3<S>>{Vec3<S>(u, u * u * u - u, v), Vec3<S>(S(3) * u * u - S(1), S(-1), S(0))};
  }, n, g));
  CHECK(ext.rank == 5);
  REQUIRE(ext.annihilatedScrews.size() == 1);
  CHECK(abs(abs(ext.annihilatedScrews[0](5)) - S(1)) <= tolId<S>(1 << 12));
  // generic ellipsoid: rank 6; a → b: the sixth singular value goes to 0 — both sides
  CHECK(rankOf(sampleSurface<S>([](S u, S v) { return ellipsoid<S>(u, v, S(1.5), S(1), S(0.7)); }, n, g)) == 6);
  CHECK(rankOf(sampleSurface<S>([](S u, S v) { return ellipsoid<S>(u, v, S(1.05), S(1), S(0.7)); }, n, g)) == 6);
  const S tiny = Tolerance<S>::rank() / S(100);
  CHECK(rankOf(sampleSurface<S>([tiny](S u, S v) { return ellipsoid<S>(u, v, S(1) + tiny, S(1), S(0.7)); }, n, g)) == 5);
}

TEMPLATE_TEST_CASE("GF-12.5 contact normal wrench: bad input", "[statics][closure]", SOMA_TEST_SCALARS) {
  using S = TestType;
  CHECK_THROWS_AS(contactNormalWrench<S>(Vec3<S>::Zero(), Vec3<S>(S(1), S(1), S(0))), InvalidInput);
  CHECK_THROWS_AS(contactNormalWrenches<S>({Vec3<S>::Zero()}, {}), InvalidInput);
  CHECK_THROWS_AS(frictionConeEdges<S>(Vec3<S>::Zero(), Vec3<S>::UnitZ(), S(-0.1), 4), InvalidInput);
  CHECK_THROWS_AS(frictionConeEdges<S>(Vec3<S>::Zero(), Vec3<S>::UnitZ(), S(0.5), 2), InvalidInput);
  CHECK_THROWS_AS(standardFrictionWrench<S>(S(-1), S(0.1), S(0)), InvalidInput);
}

TEMPLATE_TEST_CASE("GF-12.6 friction cones: zero moment at the contact, semi-angle atan μ, μ > 1 allowed",
                   "[statics][friction]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::atan2;
  auto& g = rng(1261);
  for (const double mu : {0.0, 0.3, 2.5}) {
    const Vec3<S> p = uniformVec<S, 3>(g), n = soma::test::unitVec3<S>(g);
    const S m = scalarCast<S>(mu);
    const WrenchSet<S> E = frictionConeEdges<S>(p, n, m, 8);
    for (int j = 0; j < 8; ++j) {
      const Wrench<S> W(Vec6<S>(E.col(j)));
      CHECK((W.moment() - p.cross(W.force())).norm() <= tolId<S>());  // a line through p
      const Vec3<S> f = W.force();
      CHECK(abs(atan2(f.cross(n).norm(), f.dot(n)) - atan2(m, S(1))) <= tolId<S>(1024));
    }
    CHECK(wrenchSpan<S>(E).rank == (mu == 0.0 ? 1 : 3));  // lines through p: an α-plane (rank 3)
  }
  // standard form: moment zero, |f_t| = γ F
  const Wrench<S> W = standardFrictionWrench<S>(S(2), S(0.4), S(1));
  CHECK(W.moment().norm() == S(0));
  CHECK(abs(W.force().template head<2>().norm() - S(0.8)) <= tolId<S>());
}

TEMPLATE_TEST_CASE("GF-12.6 two fingers never suffice, three do", "[statics][friction]", SOMA_TEST_SCALARS) {
  using S = TestType;
  using std::cos;
  using std::sin;
  auto& g = rng(1262);
  const Vec3<S> p1 = uniformVec<S, 3>(g), p2 = uniformVec<S, 3>(g);
  WrenchSet<S> E(6, 16);
  E << frictionConeEdges<S>(p1, soma::test::unitVec3<S>(g), S(5), 8), frictionConeEdges<S>(p2, soma::test::unitVec3<S>(g), S(5), 8);
  const Vec3<S> d = (p2 - p1).normalized();
  const Vec6<S> s = SE3Tangent<S>(d, Vec3<S>(p1.cross(d))).coeffs();  // rotation about the joining line
  CHECK((E.transpose() * s).cwiseAbs().maxCoeff() <= tolId<S>(1024));
  CHECK(wrenchSpan<S>(E).rank == 5);
  CHECK_FALSE(positiveSpan<S>(E).spans);
  // three fingers on the equator of the unit sphere, normals to the centre
  WrenchSet<S> T(6, 24);
  for (int i = 0; i < 3; ++i) {
    const S th = S(2) * pi<S>() * S(i) / S(3);
    const Vec3<S> q(cos(th), sin(th), S(0));
    T.middleCols(8 * i, 8) = frictionConeEdges<S>(q, Vec3<S>(-q), S(0.5), 8);
  }
  CHECK(wrenchSpan<S>(T).rank == 6);
  CHECK(positiveSpan<S>(T).spans);
  // frictionless (μ = 0) the same three fingers hold nothing out of the plane
  for (int i = 0; i < 3; ++i) {
    const S th = S(2) * pi<S>() * S(i) / S(3);
    const Vec3<S> q(cos(th), sin(th), S(0));
    T.middleCols(8 * i, 8) = frictionConeEdges<S>(q, Vec3<S>(-q), S(0), 8);
  }
  CHECK(wrenchSpan<S>(T).rank == 2);
}

TEMPLATE_TEST_CASE("GF-12.6 dual friction cone: ω is free (erratum E12.2)", "[statics][friction]", SOMA_TEST_SCALARS) {
  using S = TestType;
  auto& g = rng(1263);
  const S mu = S(0.6);
  // GF §12.6 lines 7605–7607 as printed (erratum E12.2): only ω = 0 and v_z ≥ μ|v_t|
  const auto inDualAsPrinted = [&](const SE3Tangent<S>& s) { return s.ang().squaredNorm() == S(0) && inDualFrictionCone<S>(s, mu); };
  int inCorrected = 0, inPrinted = 0;
  for (int i = 0; i < 200; ++i) {
    const SE3Tangent<S> s(uniformVec<S, 3>(g), uniformVec<S, 3>(g));
    const bool dual = inDualFrictionCone<S>(s, mu);
    // s is in the dual iff it pairs ≥ 0 with every cone wrench (dense sample of the boundary)
    S worst = std::numeric_limits<S>::infinity();
    for (int k = 0; k < 64; ++k) {
      const S th = S(2) * pi<S>() * S(k) / S(64);
      worst = std::min<S>(worst, standardFrictionWrench<S>(S(1), mu, th)(s));
    }
    // the sampled boundary misses the exact minimum by at most 1 − cos(π/64) of μ|v_t|
    const S slack = mu * s.lin().template head<2>().norm() * (S(1) - std::cos(3.14159 / 64));
    if (dual) CHECK(worst >= -tolId<S>());
    else CHECK(worst < slack);
    inCorrected += dual;
    inPrinted += inDualAsPrinted(s);
  }
  CHECK(inCorrected > 20);
  CHECK(inPrinted == 0);  // random ω ≠ 0: the printed set misses every one of them
  // ω = 0 slice: printed and corrected agree
  CHECK(inDualAsPrinted(SE3Tangent<S>(Vec3<S>::Zero(), Vec3<S>(S(0.1), S(0), S(1)))));
}

TEMPLATE_TEST_CASE("GF-12.6 planar two-finger grasp: criterion = LP on random contacts, and at the cone edge",
                   "[statics][planar]", double, long double) {
  using S = TestType;
  using std::cos;
  using std::sin;
  auto& g = rng(1264);
  int agree = 0, closed = 0;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const Vec2<S> p1 = uniformVec<S, 2>(g), p2 = uniformVec<S, 2>(g);
    const S a1 = uniform<S>(g, -3.2, 3.2), a2 = uniform<S>(g, -3.2, 3.2), mu = uniform<S>(g, 0.1, 1.5);
    const Vec2<S> n1(cos(a1), sin(a1)), n2(cos(a2), sin(a2));
    WrenchSet<S> W(3, 4);
    W << planarFrictionConeEdges<S>(p1, n1, mu), planarFrictionConeEdges<S>(p2, n2, mu);
    const bool lp = positiveSpan<S>(W).spans, geo = planarTwoFingerForceClosure<S>(p1, n1, p2, n2, mu);
    agree += lp == geo;
    closed += geo;
  }
  CHECK(agree == n);
  CHECK(closed > 10);
  // on both sides of the cone edge: n₁ at atan μ ± δ from the joining line
  const S mu = S(0.5), edge = std::atan2(S(0.5), S(1));
  for (const double dl : {-1e-3, 1e-3}) {
    const S a = edge + scalarCast<S>(dl);
    const Vec2<S> p1(S(0), S(0)), p2(S(1), S(0)), n1(cos(a), sin(a)), n2(S(-1), S(0));
    const bool inside = dl < 0;
    CHECK(planarTwoFingerForceClosure<S>(p1, n1, p2, n2, mu) == inside);
    WrenchSet<S> W(3, 4);
    W << planarFrictionConeEdges<S>(p1, n1, mu), planarFrictionConeEdges<S>(p2, n2, mu);
    CHECK(positiveSpan<S>(W).spans == inside);
  }
  // pointing away from each other also closes; the same direction does not
  const Vec2<S> o(S(0), S(0)), x(S(1), S(0));
  CHECK(planarTwoFingerForceClosure<S>(o, Vec2<S>(-x), x, x, S(0.2)));
  CHECK_FALSE(planarTwoFingerForceClosure<S>(o, x, x, x, S(0.2)));
  CHECK_THROWS_AS(planarTwoFingerForceClosure<S>(o, x, o, Vec2<S>(-x), S(0.2)), InvalidInput);
}

TEMPLATE_TEST_CASE("GF-12.5 second-order contact: f(θ) = Φ(e^{θs}·0) = −2 v_z θ + q θ² + O(θ³)",
                   "[statics][contact]", double, long double, __float128) {
  using S = TestType;
  auto& g = rng(1255);
  for (int i = 0; i < 10; ++i) {
    const S kx = uniform<S>(g, -2, 2), ky = uniform<S>(g, -2, 2);
    Vec6<S> c = uniformVec<S, 6>(g);
    const SE3Tangent<S> s(c);
    auto f = [&](const S& th) {
      const Vec3<S> q = SE3Tangent<S>(Vec6<S>(th * c)).exp().translation();
      return kx * q.x() * q.x() + ky * q.y() * q.y() - S(2) * q.z();
    };
    // central differences: f'(0) and f''(0)/2
    const S h = S(1) / S(1000);
    const S d1 = (f(h) - f(-h)) / (S(2) * h), d2 = (f(h) - S(2) * f(S(0)) + f(-h)) / (S(2) * h * h);
    CHECK(abs(d1 + S(2) * c(5)) <= S(1e-4));
    // with v_z ≠ 0 the second-order term also has −ω·... ; set v_z = 0 for the printed form
    c(5) = S(0);
    const SE3Tangent<S> s0(c);
    const S e2 = (f(h) - S(2) * f(S(0)) + f(-h)) / (S(2) * h * h);
    CHECK(abs(e2 - secondOrderContactForm<S>(kx, ky, s0)) <= S(1e-4));
    (void)s;
    (void)d2;
  }
}

TEMPLATE_TEST_CASE("GF-12.5 object motion at a curved contact: first order, then second order (erratum E12.3)",
                   "[statics][contact]", SOMA_TEST_SCALARS) {
  using S = TestType;
  const S kx = S(1), ky = S(-0.5);
  auto mk = [](double wx, double wy, double wz, double vx, double vy, double vz) {
    return SE3Tangent<S>(Vec3<S>(scalarCast<S>(wx), scalarCast<S>(wy), scalarCast<S>(wz)),
                         Vec3<S>(scalarCast<S>(vx), scalarCast<S>(vy), scalarCast<S>(vz)));
  };
  CHECK(classifyObjectMotion<S>(kx, ky, mk(0, 0, 0, 0, 0, -1)) == ContactMotion::Separates);
  CHECK(classifyObjectMotion<S>(kx, ky, mk(0, 0, 0, 0, 0, 1)) == ContactMotion::Penetrates);
  // v_z = 0: the printed "v_z < 0" rejects it, but a slide along y on the saddle (k_y < 0) separates
  CHECK(classifyObjectMotion<S>(kx, ky, mk(0, 0, 0, 0, 1, 0)) == ContactMotion::Separates);
  CHECK(classifyObjectMotion<S>(kx, ky, mk(0, 0, 0, 1, 0, 0)) == ContactMotion::Penetrates);
  // a roll about the contact point (v = 0) keeps contact to second order
  CHECK(classifyObjectMotion<S>(kx, ky, mk(1, 0.3, 0.2, 0, 0, 0)) == ContactMotion::ThirdOrder);
  // both sides of the first-order threshold
  const double rk = toDouble(Tolerance<S>::rank());
  CHECK(classifyObjectMotion<S>(kx, ky, mk(0, 0, 0, 1, 0, -rk * 16)) == ContactMotion::Separates);
  CHECK(classifyObjectMotion<S>(kx, ky, mk(0, 0, 0, 1, 0, -rk / 16)) == ContactMotion::Penetrates);
  CHECK_THROWS_AS(classifyObjectMotion<S>(kx, ky, mk(0, 0, 0, 0, 0, 0)), InvalidInput);
}

}  // namespace SOMA_UNITY_ID
