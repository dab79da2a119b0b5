// Studies of GF chapter 6, §6.1–6.4: Plücker coordinates, the Klein quadric, its 2-planes, the
// action of SE(3) on lines, invariant forms, pitch quadrics, isotropy, directed lines (double).
#include "gf06/common.hpp"

#include <Eigen/SVD>

namespace soma::studies::gf06::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// GF §6.1, GF-6.1-point-line-distance
void pointLineDistance(Context& c) {
  auto g = rng(61);
  double worstBook = 0, worstBrute = 0, worstPerp = 0;
  for (int k = 0; k < 200; ++k) {
    const V3 q1 = rv(g, -3, 3), q2 = rv(g, -3, 3), a = rv(g, -3, 3);
    const V3 w = q2 - q1;
    const V3 res = w.cross((q1 - a).cross(w)) / w.squaredNorm();  // book: q_λ − a
    const L l = L::throughPoints(q1, q2);
    worstBook = std::max(worstBook, std::abs(res.norm() - l.distanceTo(a)));
    worstPerp = std::max(worstPerp, std::abs(res.dot(w)) / w.norm());
    // Brute force: golden-section search on |q₁ + λω − a|² (another method).
    double lo = -50, hi = 50;
    const double gr = (std::sqrt(5.0) - 1) / 2;
    auto f = [&](double t) { return (q1 + t * w - a).squaredNorm(); };
    for (int it = 0; it < 200; ++it) {
      const double x1 = hi - gr * (hi - lo), x2 = lo + gr * (hi - lo);
      if (f(x1) < f(x2)) hi = x2;
      else lo = x1;
    }
    worstBrute = std::max(worstBrute, std::abs(std::sqrt(f((lo + hi) / 2)) - l.distanceTo(a)));
  }
  c.checkResidual("book ω×((q₁−a)×ω)/|ω|² vs Plücker |a×ω − v|/|ω| (200 random)", worstBook, tolId(256));
  c.checkResidual("the residual is ⟂ ω", worstPerp, tolId(256));
  c.checkResidual("vs golden-section minimisation of |q₁ + λω − a|", worstBrute, 1e-7);
  const L l = L::throughPoints(V3(1, 2, 3), V3(-1, 0, 2));
  c.checkNear("a on the line: distance 0", 0.0, l.distanceTo(l.pointAt(0.37)), tolId(64));
  // Nearly coincident points (|ω| = 1e-8) and a line at 1e8 from the origin.
  const L tiny = L::throughPoints(V3(0, 0, 1), V3(1e-8, 0, 1));
  c.checkNear("|ω| = 1e-8: distance of (0, 5, 1) is 5", 5.0, tiny.distanceTo(V3(0, 5, 1)), tolId(64));
  const L far = L::pointDirection(V3(0, 1e8, 0), V3(1, 0, 0));
  c.checkNear("line at y = 1e8: distance of (7, 1e8 + 3, 4) is 5 (relative to 1e8)", 5.0,
              far.distanceTo(V3(7, 1e8 + 3, 4)), 1e8 * tolId(64));
}

// GF §6.1, GF-6.1-meet-condition
void meetCondition(Context& c) {
  auto g = rng(62);
  double worstMeet = 0, worstBookForm = 0, minSkew = 1e300;
  for (int k = 0; k < 200; ++k) {
    const L a = L::pointDirection(rv(g, -2, 2), rv(g));
    const V3 p = a.pointAt(uni(g));
    const L b = L::pointDirection(p, rv(g));
    worstMeet = std::max(worstMeet, std::abs(reciprocalProduct(a.normalized().coords(), b.normalized().coords())));
    // Book: q_a·(ω_a × ω_b) = q_b·(ω_a × ω_b).
    const V3 n = a.direction().cross(b.direction());
    worstBookForm = std::max(worstBookForm, std::abs(a.foot().dot(n) - p.dot(n)));
    const L s = L::pointDirection(rv(g, -2, 2), rv(g));
    minSkew = std::min(minSkew, std::abs(relation(a, s).signedDistance));
    if (!meet(a, s) != (relation(a, s).kind == LineRelationKind::Skew)) minSkew = -1;
  }
  c.checkResidual("lines through a common point: ω_a·v_b + v_a·ω_b = 0 (200)", worstMeet, tolId(256));
  c.checkResidual("book form q_a·(ω_a×ω_b) = q_b·(ω_a×ω_b)", worstBookForm, tolId(256));
  c.record("random pairs are skew (meet() false, distance > 0) — smallest distance", "> 0", num(minSkew), 0, 0, minSkew > 0);
  const L x = L::pointDirection(V3(0, 0, 0), V3(1, 0, 0));
  const L par = L::pointDirection(V3(0, 3, 0), V3(-2, 0, 0));
  c.checkNear("antiparallel lines 3 apart: product 0 (meet at infinity)", 0.0, reciprocalProduct(x.coords(), par.coords()), 0.0);
  c.checkNear("… their distance", 3.0, distance(x, par), tolId());
  c.checkEqual("identical lines: relation", "Coincident",
               relation(x, L(V6(-4 * x.coords()))).kind == LineRelationKind::Coincident ? "Coincident" : "other");
  c.checkEqual("lines through the origin (v = 0) intersect", "Intersecting",
               relation(x, L::pointDirection(V3::Zero(), V3(1, 1, 0))).kind == LineRelationKind::Intersecting ? "Intersecting" : "other");
}

// GF §6.1, GF-6.1-same-line
void sameLine(Context& c) {
  auto g = rng(63);
  int ok = 0, rejected = 0;
  for (int k = 0; k < 100; ++k) {
    const L a = L::pointDirection(rv(g, -2, 2), rv(g));
    const double gam = uni(g, -3, 3);
    if (L(V6(gam * a.coords())).sameAs(a)) ++ok;
    if (!L::pointDirection(V3(a.foot() + 1e-6 * a.direction().unitOrthogonal()), a.direction()).sameAs(a)) ++rejected;
  }
  c.checkEqual("γs is the same line for random γ ∈ [−3, 3] (incl. γ < 0)", 100, ok);
  c.checkEqual("a line moved by 1e-6 is not", 100, rejected);
  const L t = L::throughPoints(V3(1, 1, 1), V3(1 + 1e-8, 1, 1));
  c.checkEqual("tiny |ω| = 1e-8: same as the unit line along x through (1,1,1)", 1,
               t.sameAs(L::pointDirection(V3(1, 1, 1), V3(1, 0, 0)), 1e-7) ? 1 : 0);
}

// GF §6.2, GF-6.2-plucker-two-points (E6.1, E6.2)
void twoPoints(Context& c) {
  auto g = rng(64);
  double worstA = 0, worstRescale = 0, worstBookV = 0, worstBookW = 0;
  for (int k = 0; k < 100; ++k) {
    const V3 q1 = rv(g, -2, 2), q2 = rv(g, -2, 2);
    Vec4<double> x, y;
    x << 1, q1;
    y << 1, q2;
    // p_ij = x_i y_j − x_j y_i (E6.2: the printed "x_i y_i − x_j y_i" is a typo).
    auto p = [&](int i, int j) { return x(i) * y(j) - x(j) * y(i); };
    const V6 gen = six(V3(p(0, 1), p(0, 2), p(0, 3)), V3(p(2, 3), p(3, 1), p(1, 2)));
    worstA = std::max(worstA, (gen - L::throughPoints(q1, q2).coords()).norm());
    // The printed table: ω = q₁ − q₂, v = q₁ × q₂ — convention B: same moment, opposite direction.
    const V6 book = six(V3(q1 - q2), V3(q1.cross(q2)));
    worstBookV = std::max(worstBookV, (book.tail<3>() - gen.tail<3>()).norm());
    worstBookW = std::max(worstBookW, (book.head<3>() + gen.head<3>()).norm());
    // Two other points of the line: p' = (ad − bc) p.
    const double a = uni(g), b = uni(g), cc = uni(g), d = uni(g);
    const Vec4<double> x2 = a * x + b * y, y2 = cc * x + d * y;
    const V6 l2 = L::throughHomogeneousPoints(x2, y2).coords();
    worstRescale = std::max(worstRescale, (l2 - (a * d - b * cc) * gen).norm());
  }
  c.checkResidual("p_ij = x_i y_j − x_j y_i equals (q₂ − q₁; q₁ × q₂) (convention A)", worstA, tolId(64));
  c.checkResidual("printed table: moments agree", worstBookV, tolId(64));
  c.checkResidual("printed table: direction is −(q₂ − q₁) (convention B, E6.1)", worstBookW, tolId(64));
  c.checkResidual("other points x' = ax + by, y' = cx + dy: p' = (ad − bc)p", worstRescale, tolId(256));
  bool threw = false;
  try {
    L::throughPoints(V3(1, 2, 3), V3(1, 2, 3));
  } catch (const InvalidInput&) { threw = true; }
  c.checkEqual("coincident points are rejected (InvalidInput)", 1, threw ? 1 : 0);
  c.checkNear("one point at the origin: v = 0", 0.0, L::throughPoints(V3::Zero(), V3(1, 2, 3)).moment().norm(), 0.0);
}

// GF §6.2, GF-6.2-klein-quadric
void kleinQuadric(Context& c) {
  auto g = rng(65);
  double worst = 0, minRandom = 1e300;
  for (int k = 0; k < 1000; ++k) {
    worst = std::max(worst, kleinDefect(L::throughPoints(rv(g, -5, 5), rv(g, -5, 5)).coords()));
    minRandom = std::min(minRandom, kleinDefect(V6(six(rv(g), rv(g)))));
  }
  c.checkResidual("p01p23 + p02p31 + p03p12 = 0 on 1000 joins (relative)", worst, tolId(16));
  c.record("random 6-vectors are off the quadric (smallest relative defect of 1000)", "> 1e-6", num(minRandom), 0, 0, minRandom > 1e-6);
  const L inf(V3::Zero(), V3(0, 0, 2));
  c.checkEqual("(0, 0, 0; 0, 0, 2) is accepted as the line at infinity", 1, inf.isAtInfinity() ? 1 : 0);
  bool threw = false;
  try {
    L(V3(1, 0, 0), V3(1, 1, 0));
  } catch (const InvalidInput&) { threw = true; }
  c.checkEqual("(1, 0, 0; 1, 1, 0) (ω·v = 1) is rejected", 1, threw ? 1 : 0);
  const L l = L::throughPoints(V3(1, 2, 3), V3(-2, 0, 1));
  for (const double s : {1e-8, 1e8})
    c.checkResidual("scale invariance: defect of " + num(s) + "·s", kleinDefect(V6(s * l.coords())), tolId(16));
}

// GF §6.2, GF-6.2-points-on-line (E6.1)
void pointsOnLine(Context& c) {
  auto g = rng(66);
  double worst = 0, worstRound = 0, bookFoot = 0;
  for (int k = 0; k < 100; ++k) {
    const V3 q1 = rv(g, -2, 2), q2 = rv(g, -2, 2);
    const L l = L::throughPoints(q1, q2);
    const V3 f = l.foot();
    worst = std::max(worst, (f.cross(l.direction()) - l.moment()).norm());  // q × ω = v
    const double lam = (q1 - f).dot(l.direction()) / l.direction().squaredNorm();
    worstRound = std::max(worstRound, (l.pointAt(lam) - q1).norm());
    const V3 fb = l.moment().cross(l.direction()) / l.direction().squaredNorm();  // printed (B)
    bookFoot = std::max(bookFoot, (fb.cross(l.direction()) - l.moment()).norm());
  }
  c.checkResidual("foot ω×v/|ω|² satisfies q × ω = v (convention A)", worst, tolId(64));
  c.checkResidual("join → foot + λω reaches q₁", worstRound, tolId(64));
  c.checkPrintedFails("printed foot (v × ω)/|ω|² under convention A", "E6.1", bookFoot, 1e-6);
}

// GF §6.3, GF-6.3-klein-2planes (E6.8)
void klein2Planes(Context& c) {
  auto g = rng(67);
  double antisym = 0, alphaRes = 0, betaRes = 0;
  for (int k = 0; k < 50; ++k) {
    const Mat3<double> m = SO3d::fromAxisAngle(ru(g), uni(g, 0.1, 3.0)).matrix();
    const Mat3<double> up = (m + Mat3<double>::Identity()).inverse() * (m - Mat3<double>::Identity());
    antisym = std::max(antisym, (up + up.transpose()).norm());
    const V3 u(up(2, 1), up(0, 2), up(1, 0));
    for (int j = 0; j < 3; ++j) {
      const L l = L::pointDirection(u, rv(g));  // through u₊
      alphaRes = std::max(alphaRes, ((Mat3<double>::Identity() - m) * l.direction() + (Mat3<double>::Identity() + m) * l.moment()).norm());
    }
    // β-plane: M = −R (det −1), U₋ = (M − I)⁻¹(M + I), lines in the plane u₋·q = −1.
    const Mat3<double> mb = -m;
    const Mat3<double> um = (mb - Mat3<double>::Identity()).inverse() * (mb + Mat3<double>::Identity());
    const V3 uu(um(2, 1), um(0, 2), um(1, 0));
    const V3 p0 = -uu / uu.squaredNorm();  // a point of the plane
    for (int j = 0; j < 3; ++j) {
      const V3 d = uu.cross(rv(g));
      const L l = L::pointDirection(V3(p0 + uu.cross(rv(g))), d);
      betaRes = std::max(betaRes, ((Mat3<double>::Identity() - mb) * l.direction() + (Mat3<double>::Identity() + mb) * l.moment()).norm() /
                                      (1 + l.moment().norm()));
      betaRes = std::max(betaRes, (uu.cross(l.moment()) - l.direction()).norm() / (1 + l.moment().norm()));
    }
  }
  c.checkResidual("U₊ = (M + I)⁻¹(M − I) is antisymmetric (50 rotations)", antisym, tolId(256));
  c.checkResidual("lines through u₊ satisfy (I − M)ω + (I + M)v = 0 (α-plane)", alphaRes, tolId(1024));
  c.checkResidual("lines in u₋·q = −1 satisfy it for M = −R and ω = u₋ × v (β-plane)", betaRes, tolId(1024));
  const double dI = (Mat3<double>::Identity() * 2).determinant();
  const double dPi = (SO3d::fromAxisAngle(V3(0, 0, 1), pi<double>()).matrix() + Mat3<double>::Identity()).determinant();
  c.checkNear("det(M + I) at M = I (rotation by 0) is 8: regular, u₊ = 0 (E6.8)", 8.0, dI, 0.0);
  c.checkNear("det(M + I) at rotation by π is 0 (parallel lines)", 0.0, dPi, tolId());
  c.note("E6.8: the book says M + I₃ is singular for rotations by 0 or π; only π is singular "
         "(M = I gives u₊ = 0, the star of lines through the origin).");
}

// GF §6.4, GF-6.4-adjoint-on-lines (E6.1)
void adjointOnLines(Context& c) {
  auto g = rng(68);
  double worst = 0, worstInv = 0, bookT = 0;
  for (int k = 0; k < 100; ++k) {
    const V3 q = rv(g, -2, 2), w = rv(g);
    const SE3d x = SE3Tangent<double>(six(rv(g, -3, 3), rv(g, -3, 3))).exp();
    const L l = L::pointDirection(q, w);
    const V6 s = lineAction(x) * l.coords();
    worst = std::max(worst, (s - L::pointDirection(x.act(q), V3(x.so3().act(w))).coords()).norm());
    worstInv = std::max(worstInv, std::abs(kleinValue(s)) + std::abs(s.head<3>().squaredNorm() - w.squaredNorm()));
    // Printed "T x = x × t": Ad' = [[R,0],[−TR,R]].
    Mat6<double> ad = lineAction(x);
    ad.bottomLeftCorner<3, 3>() = -skew(x.translation()) * x.rotation().matrix();
    bookT = std::max(bookT, (ad * l.coords() - L::pointDirection(x.act(q), V3(x.so3().act(w))).coords()).norm());
  }
  c.checkResidual("Ad(R,t)·line(q, ω) = line(Rq + t, Rω), T x = t × x (100 random)", worst, tolId(256));
  c.checkResidual("ω·v and ω·ω invariant", worstInv, tolId(256));
  c.checkPrintedFails("with the printed T x = x × t", "E6.1", bookT, 1e-6);
  // Extremes: rotation by π, pure translation, |t| = 1e8, a line at infinity.
  const L l = L::pointDirection(V3(1, 2, 3), V3(0, 1, 1));
  const SE3d rpi(SO3d::fromAxisAngle(V3(1, 0, 0), pi<double>()), V3(0, 0, 0));
  c.checkResidual("rotation by π about x", (lineAction(rpi) * l.coords() - L::pointDirection(rpi.act(V3(1, 2, 3)), V3(0, -1, -1)).coords()).norm(), tolId(64));
  const SE3d tr(SO3d::Identity(), V3(1e8, 0, 0));
  c.checkResidual("translation by 1e8: relative error", (l.transformed(tr).coords() - L::pointDirection(V3(1e8 + 1, 2, 3), V3(0, 1, 1)).coords()).norm() / 1e8, tolId(64));
  const L inf = L::atInfinity(V3(0, 0, 1));
  c.checkResidual("a line at infinity (0; n) is only rotated", (inf.transformed(tr).coords() - inf.coords()).norm(), 0.0);
}

// GF §6.4, GF-6.4-reciprocal-product-example
void reciprocalExample(Context& c) {
  const double l = 1.7, phi = 0.9;
  const V6 s1 = six(V3(1, 0, 0), V3::Zero());
  const V3 d(std::cos(phi), std::sin(phi), 0);
  const V6 s2 = six(d, V3(l * V3(0, 0, 1).cross(d)));
  c.checkNear("ω₁·v₂ + v₁·ω₂ = −l sin φ (l = 1.7, φ = 0.9)", -l * std::sin(phi), reciprocalProduct(s1, s2), tolId());
  c.checkNear("s₁ᵀQ₀s₂ = 2 × that (Q₀ counts both terms once each... = ω₁·v₂ + v₁·ω₂)", -l * std::sin(phi),
              double(s1.dot(kleinFormQ0<double>() * s2)), tolId());
  c.checkNear("relation(): signed distance l along ω₁ × ω₂", l, relation(L(s1), L(s2)).signedDistance, tolId());
  auto g = rng(69);
  double worst = 0;
  for (int k = 0; k < 100; ++k) {
    const L a = L::pointDirection(rv(g, -2, 2), rv(g)).normalized(), b = L::pointDirection(rv(g, -2, 2), rv(g)).normalized();
    const LineRelation<double> r = relation(a, b);
    const SE3d x = SE3Tangent<double>(six(rv(g), rv(g))).exp();
    worst = std::max(worst, std::abs(reciprocalProduct(a.coords(), b.coords()) + r.signedDistance * std::sin(r.angle)));
    worst = std::max(worst, std::abs(reciprocalProduct(a.transformed(x).coords(), b.transformed(x).coords()) - reciprocalProduct(a.coords(), b.coords())));
  }
  c.checkResidual("unit lines: ⟨a, b⟩ = −d sin α and Ad-invariant (100 random)", worst, tolId(256));
  for (const double ph : {0.0, pi<double>()}) {
    const V3 dd(std::cos(ph), std::sin(ph), 0);
    c.checkNear("φ = " + num(ph) + ": product 0 for l = 1.7", 0.0, reciprocalProduct(s1, six(dd, V3(l * V3(0, 0, 1).cross(dd)))), tolId());
  }
  c.checkNear("l = 0: product 0", 0.0, reciprocalProduct(s1, six(d, V3::Zero())), 0.0);
  c.checkNear("φ = π/2: product −l", -l, reciprocalProduct(s1, six(V3(0, 1, 0), V3(l * V3(0, 0, 1).cross(V3(0, 1, 0))))), tolId());
}

// GF §6.4, GF-6.4-invariant-bilinear-forms
void invariantForms(Context& c) {
  auto g = rng(70);
  // Unknown: symmetric 6×6 X (21 entries). Equations: Adᵀ X Ad − X = 0 for 3 random g.
  std::vector<std::pair<int, int>> idx;
  for (int i = 0; i < 6; ++i)
    for (int j = i; j < 6; ++j) idx.push_back({i, j});
  Eigen::MatrixXd a(3 * 36, 21);
  for (int k = 0; k < 3; ++k) {
    const Mat6<double> ad = SE3Tangent<double>(six(rv(g, -2, 2), rv(g, -2, 2))).exp().adjoint();
    for (int u = 0; u < 21; ++u) {
      Mat6<double> e = Mat6<double>::Zero();
      e(idx[u].first, idx[u].second) = e(idx[u].second, idx[u].first) = 1;
      const Mat6<double> r = ad.transpose() * e * ad - e;
      for (int i = 0; i < 36; ++i) a(k * 36 + i, u) = r(i / 6, i % 6);
    }
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
  const auto sv = svd.singularValues();
  int nullity = 0;
  for (int i = 0; i < sv.size(); ++i)
    if (sv(i) <= Tolerance<double>::rank() * sv(0) * 64) ++nullity;
  c.checkEqual("dimension of invariant symmetric forms (null space, 3 random g)", 2, nullity);
  c.record("gap: smallest non-null singular value / largest", "> 1e-6", num(sv(sv.size() - 3) / sv(0)), 0, 0, sv(sv.size() - 3) / sv(0) > 1e-6);
  const Mat6<double> ad = SE3Tangent<double>(six(rv(g), rv(g))).exp().adjoint();
  c.checkResidual("Q₀ is invariant", (ad.transpose() * kleinFormQ0<double>() * ad - kleinFormQ0<double>()).norm(), tolId(256));
  c.checkResidual("Q∞ is invariant", (ad.transpose() * kleinFormQinf<double>() * ad - kleinFormQinf<double>()).norm(), tolId(256));
}

// GF §6.4, GF-6.4-pitch-quadrics
void pitchQuadrics(Context& c) {
  auto g = rng(71);
  double worstInv = 0, worstQ = 0;
  for (int k = 0; k < 100; ++k) {
    const double h = uni(g, -3, 3);
    const V6 s = screwFromAxis(L::pointDirection(rv(g, -2, 2), ru(g)), h, uni(g, 0.5, 2));
    const SE3d x = SE3Tangent<double>(six(rv(g, -2, 2), rv(g, -2, 2))).exp();
    worstInv = std::max(worstInv, std::abs(screwPitch(V6(lineAction(x) * s)) - h));
    worstQ = std::max(worstQ, std::abs(double(s.dot(pitchQuadric(h) * s))) / s.squaredNorm());
  }
  c.checkResidual("pitch(Ad(g)s) = pitch(s) (100 random)", worstInv, tolId(1024));
  c.checkResidual("sᵀQ_p s = 0 for the screw of pitch p", worstQ, tolId(1024));
  const V6 s = screwFromAxis(L::pointDirection(V3(1, 0, 0), V3(0, 0, 1)), 0.5);
  c.checkNear("sᵀQ_p s = 2|ω|²(h − p): h = 0.5, p = −1", 3.0, double(s.dot(pitchQuadric(-1.0) * s)), tolId());
  c.checkNear("p = 0: a line", 0.0, screwPitch(L::pointDirection(V3(1, 2, 3), V3(0, 1, 0)).coords()), 0.0);
  c.checkEqual("ω = 0: pitch ∞", "inf", std::isinf(screwPitch(six(V3::Zero(), V3(0, 0, 1)))) ? "inf" : "finite");
  const V6 inf = six(V3::Zero(), V3(1, 2, 3));
  c.checkResidual("(0; v) lies on every Q_p (p = −2, 0, 7)",
                  std::abs(double(inf.dot(pitchQuadric(-2.0) * inf))) + std::abs(double(inf.dot(pitchQuadric(0.0) * inf))) +
                      std::abs(double(inf.dot(pitchQuadric(7.0) * inf))), 0.0);
  c.checkNear("|ω| = 1e-8 with v fixed: pitch 1e8 (→ ∞)", 1e8, screwPitch(six(V3(1e-8, 0, 0), V3(1, 0, 0))), 1e8 * tolId());
}

// GF §6.4, GF-6.4-isotropy (E6.1)
void isotropy(Context& c) {
  auto g = rng(72);
  double worstA = 0, worstB = 0, worstInf = 0;
  for (int k = 0; k < 100; ++k) {
    const V3 w = ru(g), r = rv(g, -2, 2);
    const double p = uni(g, -1, 1), th = uni(g, -3, 3), lam = uni(g, -5, 5);
    const V6 s = six(w, V3(r.cross(w) + p * w));
    const SO3d rot = SO3d::fromAxisAngle(w, th);
    const SE3d a(rot, V3((Mat3<double>::Identity() - rot.matrix()) * r + lam * w));
    const SE3d b(rot, V3((rot.matrix() - Mat3<double>::Identity()) * r + lam * w));
    worstA = std::max(worstA, (lineAction(a) * s - s).norm());
    worstB = std::max(worstB, (lineAction(b) * s - s).norm());
    // (0; v): rotations about v with any translation.
    const V3 v = rv(g);
    const SE3d ci(SO3d::fromAxisAngle(v.normalized(), th), rv(g, -9, 9));
    worstInf = std::max(worstInf, (lineAction(ci) * six(V3::Zero(), v) - six(V3::Zero(), v)).norm());
  }
  c.checkResidual("t = (I − R)r + λω fixes (ω; r×ω + pω) (convention A; 100 random)", worstA, tolId(256));
  c.checkPrintedFails("printed t = (R − I)r + λω", "E6.1", worstB, 1e-6);
  c.checkResidual("(0; v) is fixed by rotations about v and every translation", worstInf, tolId(256));
}

// GF §6.4, GF-6.4-directed-lines
void directedLines(Context& c) {
  const L l = L::throughPoints(V3(1, 2, 3), V3(3, 2, 1));
  const L u = l.normalized();
  c.checkNear("ω·ω = 1 after normalisation", 1.0, u.direction().squaredNorm(), tolId());
  c.checkNear("ω·v = 0", 0.0, kleinValue(u.coords()), tolId());
  c.checkResidual("the other representative is (−ω; −v), the reversed line", (u.reversed().coords() + u.coords()).norm(), 0.0);
  c.checkNear("both describe one line (sameAs)", 1.0, u.sameAs(u.reversed()) ? 1.0 : 0.0, 0.0);
  bool threw = false;
  try {
    L::atInfinity(V3(0, 0, 1)).normalized();
  } catch (const InvalidInput&) { threw = true; }
  c.checkEqual("normalising a line at infinity throws InvalidInput", 1, threw ? 1 : 0);
}

SOMA_STUDY_DOUBLE("GF-6.1-point-line-distance", "Distance from a point to a line: book formula, Plücker form, minimisation", "GF §6.1", pointLineDistance);
SOMA_STUDY_DOUBLE("GF-6.1-meet-condition", "Two lines meet iff ω_a·v_b + v_a·ω_b = 0", "GF §6.1", meetCondition);
SOMA_STUDY_DOUBLE("GF-6.1-same-line", "Same line iff the Plücker vectors are proportional", "GF §6.1", sameLine);
SOMA_STUDY_DOUBLE("GF-6.2-plucker-two-points", "Plücker coordinates of the join of two points (E6.1, E6.2)", "GF §6.2", twoPoints);
SOMA_STUDY_DOUBLE("GF-6.2-klein-quadric", "Lines lie on the Klein quadric; lines at infinity", "GF §6.2", kleinQuadric);
SOMA_STUDY_DOUBLE("GF-6.2-points-on-line", "Points of a line from its Plücker coordinates (E6.1)", "GF §6.2", pointsOnLine);
SOMA_STUDY_DOUBLE("GF-6.3-klein-2planes", "2-planes in the Klein quadric: α-planes (stars) and β-planes (plane fields) (E6.8)", "GF §6.3", klein2Planes);
SOMA_STUDY_DOUBLE("GF-6.4-adjoint-on-lines", "SE(3) acts on lines by the adjoint representation (E6.1)", "GF §6.4", adjointOnLines);
SOMA_STUDY_DOUBLE("GF-6.4-reciprocal-product-example", "Reciprocal product of two lines = −d sin α", "GF §6.4", reciprocalExample);
SOMA_STUDY_DOUBLE("GF-6.4-invariant-bilinear-forms", "The invariant symmetric forms of Ad are spanned by Q₀ and Q∞", "GF §6.4", invariantForms);
SOMA_STUDY_DOUBLE("GF-6.4-pitch-quadrics", "Pitch p = ω·v/ω·ω and the pitch quadrics Q_p", "GF §6.4", pitchQuadrics);
SOMA_STUDY_DOUBLE("GF-6.4-isotropy", "Isotropy groups of screws (E6.1)", "GF §6.4", isotropy);
SOMA_STUDY_DOUBLE("GF-6.4-directed-lines", "Directed lines double-cover lines", "GF §6.4", directedLines);

}  // namespace
}  // namespace soma::studies::gf06::SOMA_UNITY_ID
