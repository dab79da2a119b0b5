// Studies of GF §6.5: reguli, the conic-to-quadric construction, the cylindroid, the fixed axode
// and the curvature-axis surfaces, in the asked scalar (--scalar). Figures are in gf06/figures.cpp
// (double: soma::render).
#include "gf06/common.hpp"

namespace soma::studies::gf06::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using std::abs;
using std::cos;
using std::max;
using std::min;
using std::sin;
using std::sqrt;

/// k/10 in S (the book's and the study's decimal inputs, correctly rounded).
template <class S> S tenths(int k) { return S(k) / S(10); }
template <class S> Vec3<S> v10(int a, int b, int c) { return Vec3<S>(tenths<S>(a), tenths<S>(b), tenths<S>(c)); }

// GF §6.5.1, GF-6.5.1-regulus
template <class S> void regulus(Context& c) {
  S klein(0), planes(0), onQuadric(0), printed(0), crossMeet(0), minSame(1000), reflect(0);
  for (const int thk : {3, 19, -24, 30}) {
    const S th = tenths<S>(thk);
    const Vec6<S> a = bookRegulusLine(1, th), b = bookRegulusLine(2, th);
    // Recompute from the book's points with p_ij = x_i y_j − x_j y_i, order (w, x, y, z).
    Vec4<S> x, y1, y2;
    x << S(0), cos(th), sin(th), S(1);
    y1 << S(1), -sin(th), cos(th), S(0);
    y2 << S(1), sin(th), -cos(th), S(0);
    auto pl = [](const Vec4<S>& p, const Vec4<S>& q) {
      auto P = [&](int i, int j) { return S(p(i) * q(j) - p(j) * q(i)); };
      return six(Vec3<S>(P(0, 1), P(0, 2), P(0, 3)), Vec3<S>(P(2, 3), P(3, 1), P(1, 2)));
    };
    printed = max(printed, S((pl(x, y1) - a).norm() + (pl(x, y2) - b).norm()));
    klein = max(klein, S(abs(kleinValue(a)) + abs(kleinValue(b))));
    planes = max(planes, S(abs(S(a(0) - a(3))) + abs(S(a(1) - a(4))) + abs(S(a(2) + a(5))) + abs(S(b(0) + b(3))) +
                           abs(S(b(1) + b(4))) + abs(S(b(2) - b(5)))));
    for (const S& mu : {S(-2), S(1) / S(2), S(3)}) {
      const Vec3<S> p = Ln<S>(a).pointAt(mu), q = Ln<S>(b).pointAt(mu);
      onQuadric = max(onQuadric, S(abs(S(p.x() * p.x() + p.y() * p.y() - p.z() * p.z() - S(1))) +
                                   abs(S(q.x() * q.x() + q.y() * q.y() - q.z() * q.z() - S(1)))));
    }
    for (const int t2k : {7, 22}) {
      const S t2 = tenths<S>(t2k);
      crossMeet = max(crossMeet, S(abs(reciprocalProduct(a, bookRegulusLine(2, t2)))));
      minSame = min(minSame, S(abs(reciprocalProduct(a, bookRegulusLine(1, S(th + t2))))));
    }
    // Reflection in z = 0 sends family 1 to family 2.
    const Vec3<S> flip(S(1), S(1), S(-1));
    const Ln<S> ra = Ln<S>::pointDirection(Vec3<S>(Ln<S>(a).pointAt(S(0)).cwiseProduct(flip)), Vec3<S>(Ln<S>(a).direction().cwiseProduct(flip)));
    const Vec6<S> r = ra.normalized().coords();
    reflect = max(reflect, S(abs(S(r(0) + r(3))) + abs(S(r(1) + r(4))) + abs(S(r(2) - r(5)))));
  }
  c.checkResidual("printed Plücker coordinates = p_ij of the printed points (θ = 0.3, 1.9, −2.4, 3.0)", printed, tolId<S>());
  c.checkResidual("Klein quadric", klein, tolId<S>());
  c.checkResidual("2-plane equations (family 1: p01 = p23, p02 = p31, p03 = −p12; family 2 opposite)", planes, tolId<S>());
  c.checkResidual("points of the lines lie on x² + y² − z² = 1 (r = 1: the book's r is silently 1)", onQuadric, tolId<S>(256));
  c.checkResidual("a family-1 and a family-2 line always meet", crossMeet, tolId<S>());
  c.recordIn("two family-1 lines are skew (smallest |⟨a, a'⟩|)", "> 0.01", io::numberText(minSame), minSame, S(1) / S(100),
             minSame > S(1) / S(100));
  c.checkResidual("reflection in z = 0 maps family 1 into family 2's 2-plane", reflect, tolId<S>(64));
  c.note("E6.9: the text's \"see Section 6.4\" for the two families of planes should be Section 6.3.");
}

// GF §6.5.1, GF-6.5.1-conic-to-quadric
template <class S> void conicToQuadric(Context& c) {
  auto g = rng(81);
  const Mat3<S> A = Mat3<S>::Identity(), B = Vec3<S>(S(-1), S(-1), S(1)).asDiagonal();
  S worst(0);
  for (int k = 0; k < 100; ++k) {
    const Vec3<S> t = rv<S>(g, -3, 3);
    worst = max(worst, S(abs(S(twoPlaneQuadric(A, B, t) + (t.x() * t.x() + t.y() * t.y() - t.z() * t.z() - S(1))))));
  }
  c.checkResidual("family 1: det(A + B T(t)) = −(x² + y² − z² − 1), T x = t × x (100 random t)", worst, tolId<S>(256));
  // Rotating a line about a skew line: every point of every generator on the quadric.
  const Ln<S> axis = Ln<S>::pointDirection(v10<S>(3, -2, 1), v10<S>(2, 1, 10));
  const Ln<S> l0 = Ln<S>::pointDirection(v10<S>(12, 5, -3), v10<S>(3, 10, 8));
  const Regulus<S> r(axis, l0);
  S on(0);
  for (int k = 0; k < 24; ++k)
    for (const S& mu : {S(-2), S(0), S(3) / S(2)}) on = max(on, S(abs(r.implicit(r.generator(S(26 * k) / S(100)).pointAt(mu)))));
  c.checkResidual("rotating a line about a skew axis: points on cos²α(ρ² − d²) = z² sin²α", on, tolId<S>(1024));
  c.checkNear("… d = distance(axis, l₀)", distance(axis, l0), r.distance(), tolId<S>());
  // Book-style check on the swept regulus: its lines satisfy a 2-plane Aω + Bv = 0 in the axis frame.
  const Regulus<S> z(Ln<S>::pointDirection(Vec3<S>::Zero(), Vec3<S>::UnitZ()),
                     Ln<S>::pointDirection(Vec3<S>(S(1), S(0), S(0)), Vec3<S>(S(0), S(1), S(1))));
  S plane(0);
  for (int k = 0; k < 12; ++k) {
    const Vec6<S> s = z.generator(S(k) / S(2)).normalized().coords() * sqrt(S(2));
    plane = max(plane, S(abs(S(s(0) + s(3))) + abs(S(s(1) + s(4))) + abs(S(s(2) - s(5)))));
  }
  c.checkResidual("the sweep of (1,0,0) + μ(0,1,1) about z is the book's family 2 (its 2-plane p01 = −p23, …)", plane, tolId<S>(256));
}

// GF §6.5.2, GF-6.5.2-cylindroid-two-lines (E6.3)
template <class S> void cylindroidTwoLines(Context& c) {
  const S l(1), phi = pi<S>() / S(3);
  const Vec6<S> s1 = six(Vec3<S>(S(1), S(0), S(0)), Vec3<S>(Vec3<S>::Zero()));
  const Vec6<S> s2 = six(Vec3<S>(cos(phi), sin(phi), S(0)), Vec3<S>(-l * sin(phi), l * cos(phi), S(0)));
  auto g = rng(82);
  S worstPitch(0), worstZ(0), worstCubic(0), printedCubic(0), worstOn(0);
  const Cylindroid<S> cy(s1, s2);
  for (int k = 0; k < 100; ++k) {
    const S mu = uni<S>(g), la = uni<S>(g);
    const Vec6<S> s = mu * s1 + la * s2;
    const S dd = mu * mu + la * la + S(2) * mu * la * cos(phi);
    worstPitch = max(worstPitch, S(abs(S(screwPitch(s) - (-mu * la * l * sin(phi) / dd)))));
    const Ln<S> ax = screwAxis(s).axis;
    const Vec3<S> f = ax.foot();
    worstZ = max(worstZ, S(abs(S(f.z() - l * (la * la + la * mu * cos(phi)) / dd))));  // corrected sign
    for (const S& t : {S(-1), tenths<S>(7)}) {
      const Vec3<S> p = ax.pointAt(t);
      const S lhs = p.z() * (p.x() * p.x() + p.y() * p.y()), cot = cos(phi) / sin(phi);
      worstCubic = max(worstCubic, S(abs(S(lhs - l * (p.y() * p.y() + p.x() * p.y() * cot)))));
      printedCubic = max(printedCubic, S(abs(S(lhs + l * (p.y() * p.y() + p.x() * p.y() * cot)))));
      worstOn = max(worstOn, S(abs(cy.implicit(p))));
    }
  }
  c.checkResidual("pitch of μs₁ + λs₂ = −μλ l sin φ/(μ² + λ² + 2μλ cos φ) (100 random, l = 1, φ = π/3)", worstPitch, tolId<S>(256));
  c.checkResidual("axis height z = +l(λ² + λμ cos φ)/D (corrected sign)", worstZ, tolId<S>(256));
  c.checkResidual("axes on z(x² + y²) = +l(y² + xy cot φ) (corrected cubic)", worstCubic, tolId<S>(1024));
  c.checkPrintedFails("printed z(x² + y²) = −l(y² + xy cot φ)", "E6.3", printedCubic, tolId<S>(1024));
  c.checkResidual("axes on the canonical cubic of Cylindroid (principal frame)", worstOn, tolId<S>(1024));
  c.checkNear("μ = 0 is the second line, at height +l", l, screwAxis(s2).axis.foot().z(), tolId<S>());
  c.checkNear("principal pitch max = l(cos φ + 1)/(2 sin φ)", S(l * (cos(phi) + S(1)) / (S(2) * sin(phi))), cy.pitchMax(), tolId<S>());
  c.checkNear("principal pitch min = l(cos φ − 1)/(2 sin φ)", S(l * (cos(phi) - S(1)) / (S(2) * sin(phi))), cy.pitchMin(), tolId<S>());
  // Extremes.
  const Cylindroid<S> ortho(s1, six(Vec3<S>(S(0), S(1), S(0)), Vec3<S>(-l, S(0), S(0))));
  c.checkNear("φ = π/2: pitches ±l/2", S(l / S(2)), ortho.pitchMax(), tolId<S>());
  const Cylindroid<S> flat(s1, six(Vec3<S>(cos(phi), sin(phi), S(0)), Vec3<S>(Vec3<S>::Zero())));
  c.checkNear("l = 0: a flat pencil, all pitches 0", S(0), S(abs(flat.pitchMax()) + abs(flat.pitchMin())), tolId<S>());
  const S se = Tolerance<S>::sqrtEpsilon();
  for (const S& ph : {S(se / S(4)), S(S(4) * se)}) {
    bool threw = false;
    try {
      Cylindroid<S>(s1, six(Vec3<S>(cos(ph), sin(ph), S(0)), Vec3<S>(-l * sin(ph), l * cos(ph), S(0))));
    } catch (const InvalidInput&) { threw = true; }
    c.checkEqual("φ = " + num(S(ph / se)) + "·√ε: " + (ph < se ? "rejected (contains an infinite-pitch screw to working precision)" : "accepted"),
                 ph < se ? 1 : 0, threw ? 1 : 0);
  }
}

// GF §6.5.2, GF-6.5.2-cylindroid-principal-form (E6.4)
template <class S> void cylindroidPrincipal(Context& c) {
  const S rx = tenths<S>(7), ry = tenths<S>(-4);
  S printedIn(0), corrected(0), pitchRes(0), gen(0);
  for (const int thk : {2, 9, 13, 25}) {
    const S th = tenths<S>(thk);
    const S la = cos(th), mu = sin(th);
    // Printed inputs (1,0,0; 0,r_x,0) and (0,1,0; r_y,0,0).
    const Vec6<S> a = six(Vec3<S>(S(1), S(0), S(0)), Vec3<S>(S(0), rx, S(0)));
    const Vec6<S> bPrinted = six(Vec3<S>(S(0), S(1), S(0)), Vec3<S>(ry, S(0), S(0)));
    const Vec6<S> bFixed = six(Vec3<S>(S(0), S(1), S(0)), Vec3<S>(-ry, S(0), S(0)));
    const S n2 = la * la + mu * mu;
    const Vec6<S> sp = la * n2 * a + mu * n2 * bPrinted;
    // The book's general line, as printed.
    const S m = la * la * rx - mu * mu * ry;
    const Vec6<S> book = six(Vec3<S>(la * n2, mu * n2, S(0)), Vec3<S>(-mu * m, la * m, S(0)));
    gen = max(gen, S((screwAxis(sp).axis.coords() - screwAxis(book).axis.coords()).norm()));
    printedIn = max(printedIn, S(abs(S(screwAxis(sp).axis.foot().z() - (rx * la * la - ry * mu * mu)))));
    const Vec6<S> sf = la * a + mu * bFixed;
    corrected = max(corrected, S(abs(S(screwAxis(sf).axis.foot().z() - (rx * la * la + ry * mu * mu)))));
    pitchRes = max(pitchRes, S(abs(S(screwPitch(sf) - la * mu * (rx - ry) / (la * la + mu * mu)))));
  }
  c.checkResidual("the printed general line is the pencil of the printed inputs (axes agree)", gen, tolId<S>(64));
  c.checkResidual("printed inputs: axis height r_x cos²θ − r_y sin²θ (not + : E6.4)", printedIn, tolId<S>(64));
  c.checkResidual("with the second line (0,1,0; −r_y,0,0) the height is r_x cos²θ + r_y sin²θ", corrected, tolId<S>(64));
  c.checkResidual("pitch λμ(r_x − r_y)/(λ² + μ²) (corrected input)", pitchRes, tolId<S>(64));
  // r_x = r_y: all lines through one point (degenerate).
  const S half = S(1) / S(2);
  const Vec6<S> ex = six(Vec3<S>(S(1), S(0), S(0)), Vec3<S>(S(0), half, S(0)));
  const Cylindroid<S> deg(ex, six(Vec3<S>(S(0), S(1), S(0)), Vec3<S>(-half, S(0), S(0))));
  c.checkNear("r_x = r_y = 0.5: principal pitches equal (0)", S(0), S(abs(deg.pitchMax()) + abs(deg.pitchMin())), tolId<S>());
  c.checkNear("… every axis through (0, 0, 0.5)", S(0), deg.axis(tenths<S>(8)).distanceTo(Vec3<S>(S(0), S(0), half)), tolId<S>(64));
  const Vec6<S> ey = six(Vec3<S>(S(0), S(1), S(0)), Vec3<S>(half, S(0), S(0)));
  c.checkNear("r_x = −r_y = 0.5: height at θ is 0.5 cos 2θ (cf. GF-9.4-cylindroid-invariants)", S(half * cos(tenths<S>(14))),
              screwAxis(Vec6<S>(cos(tenths<S>(7)) * ex + sin(tenths<S>(7)) * ey)).axis.foot().z(), tolId<S>(64));
}

// GF §6.5.2, GF-6.5.2-fixed-axode (proposal: the book gives no example)
template <class S> void fixedAxode(Context& c) {
  const Vec6<S> A = six(Vec3<S>(S(0), S(0), S(1)), Vec3<S>(S(0), S(0), tenths<S>(2)));
  const Vec6<S> B = six(Vec3<S>(S(1), S(0), S(0)), Vec3<S>(S(0), S(1) / S(2), tenths<S>(1)));
  // Central differences at h = ε^(1/3) (6e-6 in double, was 1e-5): truncation h²|g‴|/6 plus rounding
  // ε|g|/h, both ~ε^(2/3); the bound 64ε^(2/3) (2.3e-9 in double, was 1e-8) covers |g‴|, |g| ≲ 10 here.
  const S h = Tolerance<S>::precision(2), fdTol = S(64) * h * h;
  auto gOf = [&](const S& t) { return SE3Tangent<S>(Vec6<S>(t * A)).exp() * SE3Tangent<S>(Vec6<S>(t * B)).exp(); };
  S fd(0);
  for (const int tk : {2, 9, 17}) {
    const S t = tenths<S>(tk);
    const Vec6<S> an = A + SE3Tangent<S>(Vec6<S>(t * A)).exp().adjoint() * B;
    const Mat4<S> dg = (gOf(S(t + h)).matrix() - gOf(S(t - h)).matrix()) / (S(2) * h);
    const Vec6<S> nd = SE3Tangent<S>::vee(Mat4<S>(dg * gOf(t).inverse().matrix())).coeffs();
    fd = max(fd, S((nd - an).norm()));
  }
  c.checkResidual("ġg⁻¹ = A + Ad(e^{tA})B (central differences, h = ε^(1/3) = " + num(h) + "; bound 64ε^(2/3))", fd, fdTol);
  // One-parameter subgroup: all axes coincide.
  S same(0);
  for (const int tk : {3, 11, 20}) {
    const S t = tenths<S>(tk);
    auto e = [&](const S& u) { return SE3Tangent<S>(Vec6<S>(u * A)).exp(); };
    const Mat4<S> dg = (e(S(t + h)).matrix() - e(S(t - h)).matrix()) / (S(2) * h);
    const Vec6<S> nd = SE3Tangent<S>::vee(Mat4<S>(dg * e(t).inverse().matrix())).coeffs();
    same = max(same, S((screwAxis(nd).axis.coords() - screwAxis(A).axis.coords()).norm()));
  }
  c.checkResidual("one-parameter subgroup e^{tA}: the instantaneous axis (finite differences) is A's axis at t = 0.3, 1.1, 2 (bound 64ε^(2/3))",
                  same, fdTol);
  // The fixed axode of the composite motion is a ruled surface: axes move, are lines, striction exists.
  auto axisAt = [&](const S& u) { return Vec6<S>(screwAxis(Vec6<S>(A + SE3Tangent<S>(Vec6<S>(u * A)).exp().adjoint() * B)).axis.coords()); };
  const RuledSurface<S> ax([&](const S& t) { return axisAt(t); },
                           [&](const S& t) { return Vec6<S>((axisAt(S(t + h)) - axisAt(S(t - h))) / (S(2) * h)); });
  S klein(0);
  for (const S& t : {S(0), S(1) / S(2), S(1)}) klein = max(klein, S(abs(kleinValue(ax.coords(t)))));
  c.checkResidual("axode generators are lines", klein, tolId<S>(64));
  const S half = S(1) / S(2);
  c.record("the axode is not a cylinder at t = 0.5 (|u'| > 0)", "non-cylindrical", ax.isCylindrical(half) ? "cylindrical" : "non-cylindrical", 0, 0,
           !ax.isCylindrical(half));
  const Vec3<S> sp = ax.strictionPoint(half);
  c.note("Finite differences for the axode's derivative; the striction point of the axode at t = 0.5 is " + num(sp.x()) + ", " +
         num(sp.y()) + ", " + num(sp.z()) + ".");
}

// GF §6.5.3, GF-6.5.3-curvature-axes (E6.1)
template <class S> void curvatureAxes(Context& c) {
  S onPoint(0), printedMoment(0), surface(0), rational(0);
  const S half = S(1) / S(2), quarter = S(1) / S(4);
  for (const auto& [kx, ky] : {std::pair{S(1), S(3)}, std::pair{S(2), S(-1)}, std::pair{half, quarter}}) {
    for (const int phk : {1, 7, 13, 29}) {
      const S phi = tenths<S>(phk);
      const S k = kx * cos(phi) * cos(phi) + ky * sin(phi) * sin(phi);
      const Vec3<S> w(-sin(phi), cos(phi), S(0)), q(S(0), S(0), S(1) / k);
      const Vec3<S> bookMoment = Vec3<S>(cos(phi), sin(phi), S(0)) / k;
      const Ln<S> ax(curvatureAxis(kx, ky, S(cos(phi)), S(sin(phi))));
      onPoint = max(onPoint, ax.distanceTo(q));
      printedMoment = max(printedMoment, S((bookMoment - q.cross(w)).norm()));
      for (const S& t : {S(-1), half, S(2)}) {
        const Vec3<S> p = ax.pointAt(t);
        surface = max(surface, S(abs(curvatureAxesImplicit(kx, ky, p)) / (S(1) + p.squaredNorm() * (S(1) + abs(p.z())))));
      }
      // The rational cubic s(λ, μ) and s(φ) = (−i sin φ + j cos φ, …) are the same line.
      const Ln<S> fromPhi = Ln<S>::pointDirection(q, w);
      rational = max(rational, fromPhi.sameAs(ax) ? S(0) : S(1));
    }
  }
  c.checkResidual("axis s(φ) passes through (0, 0, 1/k_φ) (Euler k_φ = k_x cos²φ + k_y sin²φ)", onPoint, tolId<S>(64));
  c.checkResidual("the rational cubic s(λ, μ) is the line s(φ) (convention A)", rational, S(0));
  c.checkResidual("axes on z(k_x y² + k_y x²) = x² + y²", surface, tolId<S>(256));
  c.checkPrintedFails("printed moment (i cos φ + j sin φ)/k_φ equals q × ω (it is ω × q: convention B)", "E6.1", printedMoment, tolId<S>(64));
  const Vec3<S> pHalf(S(0), S(0), half);
  c.checkResidual("umbilic k_x = k_y = 2: every axis through (0, 0, ½)",
                  S(Ln<S>(curvatureAxis(S(2), S(2), tenths<S>(3), tenths<S>(8))).distanceTo(pHalf) +
                    Ln<S>(curvatureAxis(S(2), S(2), tenths<S>(-6), tenths<S>(1))).distanceTo(pHalf)),
                  tolId<S>(64));
  c.checkEqual("saddle k_x = 1, k_y = −1, asymptotic direction λ = μ: the axis is the line at infinity", 1,
               Ln<S>(curvatureAxis(S(1), S(-1), S(1), S(1))).isAtInfinity() ? 1 : 0);
  // μ = 1 + d with d = 1e-9 (√ε in float, where 1 + 1e-9 = 1); d read back as μ − 1 (exact). K = λ² − μ²
  // ≈ −2d is computed with rounding ~2ε, i.e. ε/d relative: bound 4ε/d relative to the height.
  const S mu = S(1) + max(tenTo<S>(-9), Tolerance<S>::sqrtEpsilon()), d = mu - S(1);
  const S height = -(S(2) + S(2) * d + d * d) / (S(2) * d + d * d);
  c.checkNear("… near it (λ = 1, μ = 1 + " + num(d) + "): axis at height (λ² + μ²)/K ≈ −1/d (K rounded: bound 4ε/d relative)", height,
              Ln<S>(curvatureAxis(S(1), S(-1), S(1), mu)).foot().z(), S(abs(height) * S(4) * Tolerance<S>::epsilon() / d));
  c.checkEqual("parabolic point k_x = 0: the axis for φ = 0 is at infinity too", 1,
               Ln<S>(curvatureAxis(S(0), S(1), S(1), S(0))).isAtInfinity() ? 1 : 0);
}

SOMA_STUDY_SCALAR("GF-6.5.1-regulus", "The two reguli of the hyperboloid x² + y² − z² = 1 in Plücker coordinates", "GF §6.5.1", regulus);
SOMA_STUDY_SCALAR("GF-6.5.1-conic-to-quadric", "A conic in the Klein quadric fills a quadric det(A + BT) = 0", "GF §6.5.1", conicToQuadric);
SOMA_STUDY_SCALAR("GF-6.5.2-cylindroid-two-lines", "The cylindroid of two lines: pitch, axes, cubic surface (E6.3)", "GF §6.5.2", cylindroidTwoLines);
SOMA_STUDY_SCALAR("GF-6.5.2-cylindroid-principal-form", "Cylindroid from two perpendicular lines (E6.4)", "GF §6.5.2", cylindroidPrincipal);
SOMA_STUDY_SCALAR("GF-6.5.2-fixed-axode", "The fixed axode of a one-parameter motion", "GF §6.5.2", fixedAxode);
SOMA_STUDY_SCALAR("GF-6.5.3-curvature-axes", "Axes of curvature of a surface point form a cubic ruled surface (E6.1)", "GF §6.5.3", curvatureAxes);

}  // namespace
}  // namespace soma::studies::gf06::SOMA_UNITY_ID
