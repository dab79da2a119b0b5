// Studies of GF chapter 6, §6.1–6.4: Plücker coordinates, the Klein quadric, its 2-planes, the
// action of SE(3) on lines, invariant forms, pitch quadrics, isotropy, directed lines. Every
// study is a function template run in the asked scalar (--scalar); the random inputs are drawn in
// double and cast (the same lines on every rung).
#include "gf06/common.hpp"

#include "soma/algebra/small_linalg.hpp"

namespace soma::studies::gf06::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using std::abs;
using std::max;
using std::min;
using std::sqrt;

// GF §6.1, GF-6.1-point-line-distance
template <class S> void pointLineDistance(Context& c) {
  auto g = rng(61);
  S worstBook(0), worstBrute(0), worstPerp(0);
  // Golden-section steps until the bracket on λ ∈ [−50, 50] is below √ε·100 (200 at least).
  int steps = 0;
  for (S b(100); b > Tolerance<S>::sqrtEpsilon(); b *= (sqrt(S(5)) - S(1)) / S(2)) ++steps;
  steps = max(steps, 200);
  for (int k = 0; k < 200; ++k) {
    const Vec3<S> q1 = rv<S>(g, -3, 3), q2 = rv<S>(g, -3, 3), a = rv<S>(g, -3, 3);
    const Vec3<S> w = q2 - q1;
    const Vec3<S> res = w.cross(Vec3<S>((q1 - a).cross(w))) / w.squaredNorm();  // book: q_λ − a
    const Ln<S> l = Ln<S>::throughPoints(q1, q2);
    worstBook = max(worstBook, S(abs(S(res.norm() - l.distanceTo(a)))));
    worstPerp = max(worstPerp, S(abs(res.dot(w)) / w.norm()));
    // Brute force: golden-section search on |q₁ + λω − a|² (another method).
    S lo(-50), hi(50);
    const S gr = (sqrt(S(5)) - S(1)) / S(2);
    auto f = [&](const S& t) { return Vec3<S>(q1 + t * w - a).squaredNorm(); };
    for (int it = 0; it < steps; ++it) {
      const S x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo);
      if (f(x1) < f(x2)) hi = x2;
      else lo = x1;
    }
    worstBrute = max(worstBrute, S(abs(S(sqrt(f((lo + hi) / S(2))) - l.distanceTo(a)))));
  }
  c.checkResidual("book ω×((q₁−a)×ω)/|ω|² vs Plücker |a×ω − v|/|ω| (200 random)", worstBook, tolId<S>(256));
  c.checkResidual("the residual is ⟂ ω", worstPerp, tolId<S>(256));
  // Golden section stops where the comparisons of f hit rounding: λ is off by δ with δ²|ω|² ≲ εf, so
  // the distance is off by ≲ εd/2, plus the rounding of |q₁ + λω − a| (≲ 30ε in [−3, 3]³): 256ε.
  c.checkResidual("vs golden-section minimisation of |q₁ + λω − a| (bound 256ε)", worstBrute, tolId<S>(256));
  const Ln<S> l = Ln<S>::throughPoints(Vec3<S>(S(1), S(2), S(3)), Vec3<S>(S(-1), S(0), S(2)));
  c.checkNear("a on the line: distance 0", S(0), l.distanceTo(l.pointAt(S(37) / S(100))), tolId<S>(64));
  // Nearly coincident points (|ω| = 1e-8; √ε in float, where 1e-8 is below the spacing of S at 1 and
  // throughPoints rightly refuses the two points) and a line at 1e8 from the origin.
  const S e8 = tenTo<S>(8), h = max(tenTo<S>(-8), Tolerance<S>::sqrtEpsilon());
  const Ln<S> tiny = Ln<S>::throughPoints(Vec3<S>(S(0), S(0), S(1)), Vec3<S>(h, S(0), S(1)));
  c.checkNear("|ω| = " + num(h) + ": distance of (0, 5, 1) is 5", S(5), tiny.distanceTo(Vec3<S>(S(0), S(5), S(1))), tolId<S>(64));
  const Ln<S> far = Ln<S>::pointDirection(Vec3<S>(S(0), e8, S(0)), Vec3<S>(S(1), S(0), S(0)));
  // (in float 1e8 + 3 rounds to 1e8: the input's own rounding is within 1e8·ε)
  c.checkNear("line at y = 1e8: distance of (7, 1e8 + 3, 4) is 5 (relative to 1e8)", S(5),
              far.distanceTo(Vec3<S>(S(7), S(e8 + S(3)), S(4))), S(e8 * tolId<S>(64)));
}

// GF §6.1, GF-6.1-meet-condition
template <class S> void meetCondition(Context& c) {
  auto g = rng(62);
  S worstMeet(0), worstBookForm(0), minSkew(1000);  // 1000: above any distance of lines through [−2, 2]³
  for (int k = 0; k < 200; ++k) {
    const Ln<S> a = Ln<S>::pointDirection(rv<S>(g, -2, 2), rv<S>(g));
    const Vec3<S> p = a.pointAt(uni<S>(g));
    const Ln<S> b = Ln<S>::pointDirection(p, rv<S>(g));
    worstMeet = max(worstMeet, S(abs(reciprocalProduct(a.normalized().coords(), b.normalized().coords()))));
    // Book: q_a·(ω_a × ω_b) = q_b·(ω_a × ω_b).
    const Vec3<S> n = a.direction().cross(b.direction());
    worstBookForm = max(worstBookForm, S(abs(S(a.foot().dot(n) - p.dot(n)))));
    const Ln<S> s = Ln<S>::pointDirection(rv<S>(g, -2, 2), rv<S>(g));
    minSkew = min(minSkew, S(abs(relation(a, s).signedDistance)));
    if (!meet(a, s) != (relation(a, s).kind == LineRelationKind::Skew)) minSkew = S(-1);
  }
  c.checkResidual("lines through a common point: ω_a·v_b + v_a·ω_b = 0 (200)", worstMeet, tolId<S>(256));
  c.checkResidual("book form q_a·(ω_a×ω_b) = q_b·(ω_a×ω_b)", worstBookForm, tolId<S>(256));
  c.recordIn("random pairs are skew (meet() false, distance > 0) — smallest distance", "> 0", io::numberText(minSkew), minSkew,
             S(0), minSkew > S(0));
  const Ln<S> x = Ln<S>::pointDirection(Vec3<S>::Zero(), Vec3<S>(S(1), S(0), S(0)));
  const Ln<S> par = Ln<S>::pointDirection(Vec3<S>(S(0), S(3), S(0)), Vec3<S>(S(-2), S(0), S(0)));
  c.checkNear("antiparallel lines 3 apart: product 0 (meet at infinity)", S(0), reciprocalProduct(x.coords(), par.coords()), S(0));
  c.checkNear("… their distance", S(3), distance(x, par), tolId<S>());
  c.checkEqual("identical lines: relation", "Coincident",
               relation(x, Ln<S>(Vec6<S>(S(-4) * x.coords()))).kind == LineRelationKind::Coincident ? "Coincident" : "other");
  c.checkEqual("lines through the origin (v = 0) intersect", "Intersecting",
               relation(x, Ln<S>::pointDirection(Vec3<S>::Zero(), Vec3<S>(S(1), S(1), S(0)))).kind == LineRelationKind::Intersecting
                   ? "Intersecting"
                   : "other");
}

// GF §6.1, GF-6.1-same-line
template <class S> void sameLine(Context& c) {
  auto g = rng(63);
  int ok = 0, rejected = 0;
  // the offset: 1e-6, or √ε where 1e-6 is below sameAs's tolerance 64ε (float)
  const S em6 = max(tenTo<S>(-6), Tolerance<S>::sqrtEpsilon());
  for (int k = 0; k < 100; ++k) {
    const Ln<S> a = Ln<S>::pointDirection(rv<S>(g, -2, 2), rv<S>(g));
    const S gam = uni<S>(g, -3, 3);
    if (Ln<S>(Vec6<S>(gam * a.coords())).sameAs(a)) ++ok;
    if (!Ln<S>::pointDirection(Vec3<S>(a.foot() + em6 * a.direction().unitOrthogonal()), a.direction()).sameAs(a)) ++rejected;
  }
  c.checkEqual("γs is the same line for random γ ∈ [−3, 3] (incl. γ < 0)", 100, ok);
  c.checkEqual("a line moved by " + num(em6) + " is not", 100, rejected);
  // ω = fl(1 + h) − 1 carries the rounding of 1 + h, ε/2 absolute, i.e. ε/(2h) relative; sameAs at
  // 4ε/h (h = 1e-8, or √ε where 1e-8 is below the spacing of S at 1: float).
  const S h = max(tenTo<S>(-8), Tolerance<S>::sqrtEpsilon());
  const Ln<S> t = Ln<S>::throughPoints(Vec3<S>(S(1), S(1), S(1)), Vec3<S>(S(S(1) + h), S(1), S(1)));
  c.checkEqual("tiny |ω| = " + num(h) + ": same as the unit line along x through (1,1,1) (to 4ε/|ω|)", 1,
               t.sameAs(Ln<S>::pointDirection(Vec3<S>(S(1), S(1), S(1)), Vec3<S>(S(1), S(0), S(0))),
                        S(S(4) * Tolerance<S>::epsilon() / h))
                   ? 1
                   : 0);
}

// GF §6.2, GF-6.2-plucker-two-points (E6.1, E6.2)
template <class S> void twoPoints(Context& c) {
  auto g = rng(64);
  S worstA(0), worstRescale(0), worstBookV(0), worstBookW(0);
  for (int k = 0; k < 100; ++k) {
    const Vec3<S> q1 = rv<S>(g, -2, 2), q2 = rv<S>(g, -2, 2);
    Vec4<S> x, y;
    x << S(1), q1;
    y << S(1), q2;
    // p_ij = x_i y_j − x_j y_i (E6.2: the printed "x_i y_i − x_j y_i" is a typo).
    auto p = [&](int i, int j) { return S(x(i) * y(j) - x(j) * y(i)); };
    const Vec6<S> gen = six(Vec3<S>(p(0, 1), p(0, 2), p(0, 3)), Vec3<S>(p(2, 3), p(3, 1), p(1, 2)));
    worstA = max(worstA, S((gen - Ln<S>::throughPoints(q1, q2).coords()).norm()));
    // The printed table: ω = q₁ − q₂, v = q₁ × q₂ — convention B: same moment, opposite direction.
    const Vec6<S> book = six(Vec3<S>(q1 - q2), Vec3<S>(q1.cross(q2)));
    worstBookV = max(worstBookV, S((book.template tail<3>() - gen.template tail<3>()).norm()));
    worstBookW = max(worstBookW, S((book.template head<3>() + gen.template head<3>()).norm()));
    // Two other points of the line: p' = (ad − bc) p.
    const S a = uni<S>(g), b = uni<S>(g), cc = uni<S>(g), d = uni<S>(g);
    const Vec4<S> x2 = a * x + b * y, y2 = cc * x + d * y;
    const Vec6<S> l2 = Ln<S>::throughHomogeneousPoints(x2, y2).coords();
    worstRescale = max(worstRescale, S((l2 - (a * d - b * cc) * gen).norm()));
  }
  c.checkResidual("p_ij = x_i y_j − x_j y_i equals (q₂ − q₁; q₁ × q₂) (convention A)", worstA, tolId<S>(64));
  c.checkResidual("printed table: moments agree", worstBookV, tolId<S>(64));
  c.checkResidual("printed table: direction is −(q₂ − q₁) (convention B, E6.1)", worstBookW, tolId<S>(64));
  c.checkResidual("other points x' = ax + by, y' = cx + dy: p' = (ad − bc)p", worstRescale, tolId<S>(256));
  bool threw = false;
  try {
    Ln<S>::throughPoints(Vec3<S>(S(1), S(2), S(3)), Vec3<S>(S(1), S(2), S(3)));
  } catch (const InvalidInput&) { threw = true; }
  c.checkEqual("coincident points are rejected (InvalidInput)", 1, threw ? 1 : 0);
  c.checkNear("one point at the origin: v = 0", S(0),
              S(Ln<S>::throughPoints(Vec3<S>::Zero(), Vec3<S>(S(1), S(2), S(3))).moment().norm()), S(0));
}

// GF §6.2, GF-6.2-klein-quadric
template <class S> void kleinQuadric(Context& c) {
  auto g = rng(65);
  S worst(0), minRandom(2);  // the relative defect |ω·v|/(|ω||v|) is ≤ 1 (Cauchy–Schwarz)
  for (int k = 0; k < 1000; ++k) {
    const Vec3<S> p1 = rv<S>(g, -5, 5), p2 = rv<S>(g, -5, 5);
    worst = max(worst, kleinDefect(Ln<S>::throughPoints(p1, p2).coords()));
    const Vec3<S> w = rv<S>(g), v = rv<S>(g);
    minRandom = min(minRandom, kleinDefect(six(w, v)));
  }
  c.checkResidual("p01p23 + p02p31 + p03p12 = 0 on 1000 joins (relative)", worst, tolId<S>(16));
  c.recordIn("random 6-vectors are off the quadric (smallest relative defect of 1000)", "> 1e-6", io::numberText(minRandom),
             minRandom, tenTo<S>(-6), minRandom > tenTo<S>(-6));
  const Ln<S> inf(Vec3<S>::Zero(), Vec3<S>(S(0), S(0), S(2)));
  c.checkEqual("(0, 0, 0; 0, 0, 2) is accepted as the line at infinity", 1, inf.isAtInfinity() ? 1 : 0);
  bool threw = false;
  try {
    Ln<S>(Vec3<S>(S(1), S(0), S(0)), Vec3<S>(S(1), S(1), S(0)));
  } catch (const InvalidInput&) { threw = true; }
  c.checkEqual("(1, 0, 0; 1, 1, 0) (ω·v = 1) is rejected", 1, threw ? 1 : 0);
  const Ln<S> l = Ln<S>::throughPoints(Vec3<S>(S(1), S(2), S(3)), Vec3<S>(S(-2), S(0), S(1)));
  for (const int k : {-8, 8})
    c.checkResidual("scale invariance: defect of " + num(tenTo<S>(k)) + "·s", kleinDefect(Vec6<S>(tenTo<S>(k) * l.coords())),
                    tolId<S>(16));
}

// GF §6.2, GF-6.2-points-on-line (E6.1)
template <class S> void pointsOnLine(Context& c) {
  auto g = rng(66);
  S worst(0), worstRound(0), bookFoot(0);
  for (int k = 0; k < 100; ++k) {
    const Vec3<S> q1 = rv<S>(g, -2, 2), q2 = rv<S>(g, -2, 2);
    const Ln<S> l = Ln<S>::throughPoints(q1, q2);
    const Vec3<S> f = l.foot();
    worst = max(worst, S((f.cross(l.direction()) - l.moment()).norm()));  // q × ω = v
    const S lam = (q1 - f).dot(l.direction()) / l.direction().squaredNorm();
    worstRound = max(worstRound, S((l.pointAt(lam) - q1).norm()));
    const Vec3<S> fb = l.moment().cross(l.direction()) / l.direction().squaredNorm();  // printed (B)
    bookFoot = max(bookFoot, S((fb.cross(l.direction()) - l.moment()).norm()));
  }
  c.checkResidual("foot ω×v/|ω|² satisfies q × ω = v (convention A)", worst, tolId<S>(64));
  c.checkResidual("join → foot + λω reaches q₁", worstRound, tolId<S>(64));
  c.checkPrintedFails("printed foot (v × ω)/|ω|² under convention A", "E6.1", bookFoot, tolId<S>(64));
}

// GF §6.3, GF-6.3-klein-2planes (E6.8)
template <class S> void klein2Planes(Context& c) {
  auto g = rng(67);
  const Mat3<S> id = Mat3<S>::Identity();
  S antisym(0), alphaRes(0), betaRes(0);
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> axis = ru<S>(g);
    const Mat3<S> m = SO3<S>::fromAxisAngle(axis, uni<S>(g, 0.1, 3.0)).matrix();
    const Mat3<S> up = Mat3<S>(m + id).inverse() * (m - id);
    antisym = max(antisym, S((up + up.transpose()).norm()));
    const Vec3<S> u(up(2, 1), up(0, 2), up(1, 0));
    for (int j = 0; j < 3; ++j) {
      const Ln<S> l = Ln<S>::pointDirection(u, rv<S>(g));  // through u₊
      alphaRes = max(alphaRes, S(((id - m) * l.direction() + (id + m) * l.moment()).norm()));
    }
    // β-plane: M = −R (det −1), U₋ = (M − I)⁻¹(M + I), lines in the plane u₋·q = −1.
    const Mat3<S> mb = -m;
    const Mat3<S> um = Mat3<S>(mb - id).inverse() * (mb + id);
    const Vec3<S> uu(um(2, 1), um(0, 2), um(1, 0));
    const Vec3<S> p0 = -uu / uu.squaredNorm();  // a point of the plane
    for (int j = 0; j < 3; ++j) {
      const Vec3<S> d = uu.cross(rv<S>(g));
      const Vec3<S> off = uu.cross(rv<S>(g));
      const Ln<S> l = Ln<S>::pointDirection(Vec3<S>(p0 + off), d);
      betaRes = max(betaRes, S(((id - mb) * l.direction() + (id + mb) * l.moment()).norm() / (S(1) + l.moment().norm())));
      betaRes = max(betaRes, S((uu.cross(l.moment()) - l.direction()).norm() / (S(1) + l.moment().norm())));
    }
  }
  c.checkResidual("U₊ = (M + I)⁻¹(M − I) is antisymmetric (50 rotations)", antisym, tolId<S>(256));
  c.checkResidual("lines through u₊ satisfy (I − M)ω + (I + M)v = 0 (α-plane)", alphaRes, tolId<S>(1024));
  c.checkResidual("lines in u₋·q = −1 satisfy it for M = −R and ω = u₋ × v (β-plane)", betaRes, tolId<S>(1024));
  const S dI = Mat3<S>(id * S(2)).determinant();
  const S dPi = Mat3<S>(SO3<S>::fromAxisAngle(Vec3<S>(S(0), S(0), S(1)), pi<S>()).matrix() + id).determinant();
  c.checkNear("det(M + I) at M = I (rotation by 0) is 8: regular, u₊ = 0 (E6.8)", S(8), dI, S(0));
  c.checkNear("det(M + I) at rotation by π is 0 (parallel lines)", S(0), dPi, tolId<S>());
  c.note("E6.8: the book says M + I₃ is singular for rotations by 0 or π; only π is singular "
         "(M = I gives u₊ = 0, the star of lines through the origin).");
}

// GF §6.4, GF-6.4-adjoint-on-lines (E6.1)
template <class S> void adjointOnLines(Context& c) {
  auto g = rng(68);
  S worst(0), worstInv(0), bookT(0);
  for (int k = 0; k < 100; ++k) {
    const Vec3<S> q = rv<S>(g, -2, 2), w = rv<S>(g);
    const Vec3<S> tw = rv<S>(g, -3, 3), tv = rv<S>(g, -3, 3);
    const SE3<S> x = SE3Tangent<S>(six(tw, tv)).exp();
    const Ln<S> l = Ln<S>::pointDirection(q, w);
    const Vec6<S> s = lineAction(x) * l.coords();
    const Vec6<S> moved = Ln<S>::pointDirection(x.act(q), Vec3<S>(x.so3().act(w))).coords();
    worst = max(worst, S((s - moved).norm()));
    worstInv = max(worstInv, S(abs(kleinValue(s)) + abs(S(s.template head<3>().squaredNorm() - w.squaredNorm()))));
    // Printed "T x = x × t": Ad' = [[R,0],[−TR,R]].
    Mat6<S> ad = lineAction(x);
    ad.template bottomLeftCorner<3, 3>() = -skew(Vec3<S>(x.translation())) * x.rotation().matrix();
    bookT = max(bookT, S((ad * l.coords() - moved).norm()));
  }
  c.checkResidual("Ad(R,t)·line(q, ω) = line(Rq + t, Rω), T x = t × x (100 random)", worst, tolId<S>(256));
  c.checkResidual("ω·v and ω·ω invariant", worstInv, tolId<S>(256));
  c.checkPrintedFails("with the printed T x = x × t", "E6.1", bookT, tolId<S>(256));
  // Extremes: rotation by π, pure translation, |t| = 1e8, a line at infinity.
  const Vec3<S> q(S(1), S(2), S(3)), d(S(0), S(1), S(1));
  const Ln<S> l = Ln<S>::pointDirection(q, d);
  const SE3<S> rpi(SO3<S>::fromAxisAngle(Vec3<S>(S(1), S(0), S(0)), pi<S>()), Vec3<S>::Zero());
  c.checkResidual("rotation by π about x",
                  S((lineAction(rpi) * l.coords() - Ln<S>::pointDirection(rpi.act(q), Vec3<S>(S(0), S(-1), S(-1))).coords()).norm()),
                  tolId<S>(64));
  const S e8 = tenTo<S>(8);
  const SE3<S> tr(SO3<S>::Identity(), Vec3<S>(e8, S(0), S(0)));
  c.checkResidual("translation by 1e8: relative error",
                  S((l.transformed(tr).coords() - Ln<S>::pointDirection(Vec3<S>(S(e8 + S(1)), S(2), S(3)), d).coords()).norm() / e8),
                  tolId<S>(64));
  const Ln<S> inf = Ln<S>::atInfinity(Vec3<S>(S(0), S(0), S(1)));
  c.checkResidual("a line at infinity (0; n) is only rotated", S((inf.transformed(tr).coords() - inf.coords()).norm()), S(0));
}

// GF §6.4, GF-6.4-reciprocal-product-example
template <class S> void reciprocalExample(Context& c) {
  using std::cos;
  using std::sin;
  const S l = S(17) / S(10), phi = S(9) / S(10);
  const Vec3<S> ez(S(0), S(0), S(1));
  const Vec6<S> s1 = six(Vec3<S>(S(1), S(0), S(0)), Vec3<S>(Vec3<S>::Zero()));
  const Vec3<S> d(cos(phi), sin(phi), S(0));
  const Vec6<S> s2 = six(d, Vec3<S>(l * ez.cross(d)));
  c.checkNear("ω₁·v₂ + v₁·ω₂ = −l sin φ (l = 1.7, φ = 0.9)", S(-l * sin(phi)), reciprocalProduct(s1, s2), tolId<S>());
  c.checkNear("s₁ᵀQ₀s₂ = 2 × that (Q₀ counts both terms once each... = ω₁·v₂ + v₁·ω₂)", S(-l * sin(phi)),
              S(s1.dot(kleinFormQ0<S>() * s2)), tolId<S>());
  c.checkNear("relation(): signed distance l along ω₁ × ω₂", l, relation(Ln<S>(s1), Ln<S>(s2)).signedDistance, tolId<S>());
  auto g = rng(69);
  S worst(0);
  for (int k = 0; k < 100; ++k) {
    const Vec3<S> pa = rv<S>(g, -2, 2), da = rv<S>(g);
    const Ln<S> a = Ln<S>::pointDirection(pa, da).normalized();
    const Vec3<S> pb = rv<S>(g, -2, 2), db = rv<S>(g);
    const Ln<S> b = Ln<S>::pointDirection(pb, db).normalized();
    const LineRelation<S> r = relation(a, b);
    const Vec3<S> xw = rv<S>(g), xv = rv<S>(g);
    const SE3<S> x = SE3Tangent<S>(six(xw, xv)).exp();
    worst = max(worst, S(abs(S(reciprocalProduct(a.coords(), b.coords()) + r.signedDistance * sin(r.angle)))));
    worst = max(worst, S(abs(S(reciprocalProduct(a.transformed(x).coords(), b.transformed(x).coords()) -
                               reciprocalProduct(a.coords(), b.coords())))));
  }
  c.checkResidual("unit lines: ⟨a, b⟩ = −d sin α and Ad-invariant (100 random)", worst, tolId<S>(256));
  for (const S& ph : {S(0), pi<S>()}) {
    const Vec3<S> dd(cos(ph), sin(ph), S(0));
    c.checkNear("φ = " + num(ph) + ": product 0 for l = 1.7", S(0), reciprocalProduct(s1, six(dd, Vec3<S>(l * ez.cross(dd)))),
                tolId<S>());
  }
  c.checkNear("l = 0: product 0", S(0), reciprocalProduct(s1, six(d, Vec3<S>(Vec3<S>::Zero()))), S(0));
  const Vec3<S> ey(S(0), S(1), S(0));
  c.checkNear("φ = π/2: product −l", S(-l), reciprocalProduct(s1, six(ey, Vec3<S>(l * ez.cross(ey)))), tolId<S>());
}

// GF §6.4, GF-6.4-invariant-bilinear-forms
template <class S> void invariantForms(Context& c) {
  using MatXS = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
  auto g = rng(70);
  // Unknown: symmetric 6×6 X (21 entries). Equations: Adᵀ X Ad − X = 0 for 3 random g.
  std::vector<std::pair<int, int>> idx;
  for (int i = 0; i < 6; ++i)
    for (int j = i; j < 6; ++j) idx.push_back({i, j});
  MatXS a(3 * 36, 21);
  for (int k = 0; k < 3; ++k) {
    const Vec3<S> tw = rv<S>(g, -2, 2), tv = rv<S>(g, -2, 2);
    const Mat6<S> ad = SE3Tangent<S>(six(tw, tv)).exp().adjoint();
    for (int u = 0; u < 21; ++u) {
      Mat6<S> e = Mat6<S>::Zero();
      e(idx[u].first, idx[u].second) = e(idx[u].second, idx[u].first) = S(1);
      const Mat6<S> r = ad.transpose() * e * ad - e;
      for (int i = 0; i < 36; ++i) a(k * 36 + i, u) = r(i / 6, i % 6);
    }
  }
  // Singular values by soma's one-sided Jacobi (small_linalg.hpp; Eigen's JacobiSVD for five
  // scalars would cost this file several times its compile time), descending.
  const std::vector<S> sv = detail::smallSingularValues<S>(a);
  const int n = int(sv.size());
  int nullity = 0;
  for (int i = 0; i < n; ++i)
    if (sv[std::size_t(i)] <= Tolerance<S>::rank() * sv[0] * S(64)) ++nullity;
  c.checkEqual("dimension of invariant symmetric forms (null space, 3 random g)", 2, nullity);
  const S gap = sv[std::size_t(n - 3)] / sv[0];
  c.recordIn("gap: smallest non-null singular value / largest", "> 1e-6", io::numberText(gap), gap, tenTo<S>(-6), gap > tenTo<S>(-6));
  const Vec3<S> tw = rv<S>(g), tv = rv<S>(g);
  const Mat6<S> ad = SE3Tangent<S>(six(tw, tv)).exp().adjoint();
  c.checkResidual("Q₀ is invariant", S((ad.transpose() * kleinFormQ0<S>() * ad - kleinFormQ0<S>()).norm()), tolId<S>(256));
  c.checkResidual("Q∞ is invariant", S((ad.transpose() * kleinFormQinf<S>() * ad - kleinFormQinf<S>()).norm()), tolId<S>(256));
}

// GF §6.4, GF-6.4-pitch-quadrics
template <class S> void pitchQuadrics(Context& c) {
  using std::isinf;
  auto g = rng(71);
  S worstInv(0), worstQ(0);
  for (int k = 0; k < 100; ++k) {
    const S h = uni<S>(g, -3, 3);
    const Vec3<S> p = rv<S>(g, -2, 2), dir = ru<S>(g);
    const S amp = uni<S>(g, 0.5, 2);
    const Vec6<S> s = screwFromAxis(Ln<S>::pointDirection(p, dir), h, amp);
    const Vec3<S> tw = rv<S>(g, -2, 2), tv = rv<S>(g, -2, 2);
    const SE3<S> x = SE3Tangent<S>(six(tw, tv)).exp();
    worstInv = max(worstInv, S(abs(S(screwPitch(Vec6<S>(lineAction(x) * s)) - h))));
    worstQ = max(worstQ, S(abs(S(s.dot(pitchQuadric(h) * s))) / s.squaredNorm()));
  }
  c.checkResidual("pitch(Ad(g)s) = pitch(s) (100 random)", worstInv, tolId<S>(1024));
  c.checkResidual("sᵀQ_p s = 0 for the screw of pitch p", worstQ, tolId<S>(1024));
  const Vec6<S> s = screwFromAxis(Ln<S>::pointDirection(Vec3<S>(S(1), S(0), S(0)), Vec3<S>(S(0), S(0), S(1))), S(1) / S(2));
  c.checkNear("sᵀQ_p s = 2|ω|²(h − p): h = 0.5, p = −1", S(3), S(s.dot(pitchQuadric(S(-1)) * s)), tolId<S>());
  c.checkNear("p = 0: a line", S(0), screwPitch(Ln<S>::pointDirection(Vec3<S>(S(1), S(2), S(3)), Vec3<S>(S(0), S(1), S(0))).coords()),
              S(0));
  c.checkEqual("ω = 0: pitch ∞", "inf", isinf(screwPitch(six(Vec3<S>(Vec3<S>::Zero()), Vec3<S>(S(0), S(0), S(1))))) ? "inf" : "finite");
  const Vec6<S> inf = six(Vec3<S>(Vec3<S>::Zero()), Vec3<S>(S(1), S(2), S(3)));
  c.checkResidual("(0; v) lies on every Q_p (p = −2, 0, 7)",
                  S(abs(S(inf.dot(pitchQuadric(S(-2)) * inf))) + abs(S(inf.dot(pitchQuadric(S(0)) * inf))) +
                    abs(S(inf.dot(pitchQuadric(S(7)) * inf)))),
                  S(0));
  const S em8 = tenTo<S>(-8);
  c.checkNear("|ω| = 1e-8 with v fixed: pitch 1e8 (→ ∞)", tenTo<S>(8), screwPitch(six(Vec3<S>(em8, S(0), S(0)), Vec3<S>(S(1), S(0), S(0)))),
              S(tenTo<S>(8) * tolId<S>()));
}

// GF §6.4, GF-6.4-isotropy (E6.1)
template <class S> void isotropy(Context& c) {
  auto g = rng(72);
  const Mat3<S> id = Mat3<S>::Identity();
  S worstA(0), worstB(0), worstInf(0);
  for (int k = 0; k < 100; ++k) {
    const Vec3<S> w = ru<S>(g), r = rv<S>(g, -2, 2);
    const S p = uni<S>(g, -1, 1), th = uni<S>(g, -3, 3), lam = uni<S>(g, -5, 5);
    const Vec6<S> s = six(w, Vec3<S>(r.cross(w) + p * w));
    const SO3<S> rot = SO3<S>::fromAxisAngle(w, th);
    const SE3<S> a(rot, Vec3<S>((id - rot.matrix()) * r + lam * w));
    const SE3<S> b(rot, Vec3<S>((rot.matrix() - id) * r + lam * w));
    worstA = max(worstA, S((lineAction(a) * s - s).norm()));
    worstB = max(worstB, S((lineAction(b) * s - s).norm()));
    // (0; v): rotations about v with any translation.
    const Vec3<S> v = rv<S>(g);
    const SO3<S> rv0 = SO3<S>::fromAxisAngle(Vec3<S>(v.normalized()), th);
    const SE3<S> ci(rv0, rv<S>(g, -9, 9));
    const Vec6<S> v6 = six(Vec3<S>(Vec3<S>::Zero()), v);
    worstInf = max(worstInf, S((lineAction(ci) * v6 - v6).norm()));
  }
  c.checkResidual("t = (I − R)r + λω fixes (ω; r×ω + pω) (convention A; 100 random)", worstA, tolId<S>(256));
  c.checkPrintedFails("printed t = (R − I)r + λω", "E6.1", worstB, tolId<S>(256));
  c.checkResidual("(0; v) is fixed by rotations about v and every translation", worstInf, tolId<S>(256));
}

// GF §6.4, GF-6.4-directed-lines
template <class S> void directedLines(Context& c) {
  const Ln<S> l = Ln<S>::throughPoints(Vec3<S>(S(1), S(2), S(3)), Vec3<S>(S(3), S(2), S(1)));
  const Ln<S> u = l.normalized();
  c.checkNear("ω·ω = 1 after normalisation", S(1), S(u.direction().squaredNorm()), tolId<S>());
  c.checkNear("ω·v = 0", S(0), kleinValue(u.coords()), tolId<S>());
  c.checkResidual("the other representative is (−ω; −v), the reversed line", S((u.reversed().coords() + u.coords()).norm()), S(0));
  c.checkEqual("both describe one line (sameAs)", 1, u.sameAs(u.reversed()) ? 1 : 0);
  bool threw = false;
  try {
    Ln<S>::atInfinity(Vec3<S>(S(0), S(0), S(1))).normalized();
  } catch (const InvalidInput&) { threw = true; }
  c.checkEqual("normalising a line at infinity throws InvalidInput", 1, threw ? 1 : 0);
}

SOMA_STUDY_SCALAR("GF-6.1-point-line-distance", "Distance from a point to a line: book formula, Plücker form, minimisation", "GF §6.1", pointLineDistance);
SOMA_STUDY_SCALAR("GF-6.1-meet-condition", "Two lines meet iff ω_a·v_b + v_a·ω_b = 0", "GF §6.1", meetCondition);
SOMA_STUDY_SCALAR("GF-6.1-same-line", "Same line iff the Plücker vectors are proportional", "GF §6.1", sameLine);
SOMA_STUDY_SCALAR("GF-6.2-plucker-two-points", "Plücker coordinates of the join of two points (E6.1, E6.2)", "GF §6.2", twoPoints);
SOMA_STUDY_SCALAR("GF-6.2-klein-quadric", "Lines lie on the Klein quadric; lines at infinity", "GF §6.2", kleinQuadric);
SOMA_STUDY_SCALAR("GF-6.2-points-on-line", "Points of a line from its Plücker coordinates (E6.1)", "GF §6.2", pointsOnLine);
SOMA_STUDY_SCALAR("GF-6.3-klein-2planes", "2-planes in the Klein quadric: α-planes (stars) and β-planes (plane fields) (E6.8)", "GF §6.3", klein2Planes);
SOMA_STUDY_SCALAR("GF-6.4-adjoint-on-lines", "SE(3) acts on lines by the adjoint representation (E6.1)", "GF §6.4", adjointOnLines);
SOMA_STUDY_SCALAR("GF-6.4-reciprocal-product-example", "Reciprocal product of two lines = −d sin α", "GF §6.4", reciprocalExample);
SOMA_STUDY_SCALAR("GF-6.4-invariant-bilinear-forms", "The invariant symmetric forms of Ad are spanned by Q₀ and Q∞", "GF §6.4", invariantForms);
SOMA_STUDY_SCALAR("GF-6.4-pitch-quadrics", "Pitch p = ω·v/ω·ω and the pitch quadrics Q_p", "GF §6.4", pitchQuadrics);
SOMA_STUDY_SCALAR("GF-6.4-isotropy", "Isotropy groups of screws (E6.1)", "GF §6.4", isotropy);
SOMA_STUDY_SCALAR("GF-6.4-directed-lines", "Directed lines double-cover lines", "GF §6.4", directedLines);

}  // namespace
}  // namespace soma::studies::gf06::SOMA_UNITY_ID
