// Studies of GF §6.5: reguli, the conic-to-quadric construction, the cylindroid, the fixed axode
// and the curvature-axis surfaces (double). Figures are in gf06/figures.cpp.
#include "gf06/common.hpp"

namespace soma::studies::gf06::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// GF §6.5.1, GF-6.5.1-regulus
void regulus(Context& c) {
  double klein = 0, planes = 0, onQuadric = 0, printed = 0, crossMeet = 0, minSame = 1e300, reflect = 0;
  for (const double th : {0.3, 1.9, -2.4, 3.0}) {
    const V6 a = bookRegulusLine(1, th), b = bookRegulusLine(2, th);
    // Recompute from the book's points with p_ij = x_i y_j − x_j y_i, order (w, x, y, z).
    Vec4<double> x, y1, y2;
    x << 0, std::cos(th), std::sin(th), 1;
    y1 << 1, -std::sin(th), std::cos(th), 0;
    y2 << 1, std::sin(th), -std::cos(th), 0;
    auto pl = [](const Vec4<double>& p, const Vec4<double>& q) {
      auto P = [&](int i, int j) { return p(i) * q(j) - p(j) * q(i); };
      return six(V3(P(0, 1), P(0, 2), P(0, 3)), V3(P(2, 3), P(3, 1), P(1, 2)));
    };
    printed = std::max(printed, (pl(x, y1) - a).norm() + (pl(x, y2) - b).norm());
    klein = std::max(klein, std::abs(kleinValue(a)) + std::abs(kleinValue(b)));
    planes = std::max(planes, std::abs(a(0) - a(3)) + std::abs(a(1) - a(4)) + std::abs(a(2) + a(5)) +
                                  std::abs(b(0) + b(3)) + std::abs(b(1) + b(4)) + std::abs(b(2) - b(5)));
    for (const double mu : {-2.0, 0.5, 3.0}) {
      const V3 p = L(a).pointAt(mu), q = L(b).pointAt(mu);
      onQuadric = std::max(onQuadric, std::abs(p.x() * p.x() + p.y() * p.y() - p.z() * p.z() - 1) +
                                          std::abs(q.x() * q.x() + q.y() * q.y() - q.z() * q.z() - 1));
    }
    for (const double t2 : {0.7, 2.2}) {
      crossMeet = std::max(crossMeet, std::abs(reciprocalProduct(a, bookRegulusLine(2, t2))));
      minSame = std::min(minSame, std::abs(reciprocalProduct(a, bookRegulusLine(1, th + t2))));
    }
    // Reflection in z = 0 sends family 1 to family 2.
    const L ra = L::pointDirection(V3(L(a).pointAt(0).cwiseProduct(V3(1, 1, -1))), V3(L(a).direction().cwiseProduct(V3(1, 1, -1))));
    const V6 r = ra.normalized().coords();
    reflect = std::max(reflect, std::abs(r(0) + r(3)) + std::abs(r(1) + r(4)) + std::abs(r(2) - r(5)));
  }
  c.checkResidual("printed Plücker coordinates = p_ij of the printed points (θ = 0.3, 1.9, −2.4, 3.0)", printed, tolId());
  c.checkResidual("Klein quadric", klein, tolId());
  c.checkResidual("2-plane equations (family 1: p01 = p23, p02 = p31, p03 = −p12; family 2 opposite)", planes, tolId());
  c.checkResidual("points of the lines lie on x² + y² − z² = 1 (r = 1: the book's r is silently 1)", onQuadric, tolId(256));
  c.checkResidual("a family-1 and a family-2 line always meet", crossMeet, tolId());
  c.record("two family-1 lines are skew (smallest |⟨a, a'⟩|)", "> 0.01", num(minSame), 0, 0, minSame > 0.01);
  c.checkResidual("reflection in z = 0 maps family 1 into family 2's 2-plane", reflect, tolId(64));
  c.note("E6.9: the text's \"see Section 6.4\" for the two families of planes should be Section 6.3.");
}

// GF §6.5.1, GF-6.5.1-conic-to-quadric
void conicToQuadric(Context& c) {
  auto g = rng(81);
  const Mat3<double> A = Mat3<double>::Identity(), B = V3(-1, -1, 1).asDiagonal();
  double worst = 0;
  for (int k = 0; k < 100; ++k) {
    const V3 t = rv(g, -3, 3);
    worst = std::max(worst, std::abs(twoPlaneQuadric(A, B, t) + (t.x() * t.x() + t.y() * t.y() - t.z() * t.z() - 1)));
  }
  c.checkResidual("family 1: det(A + B T(t)) = −(x² + y² − z² − 1), T x = t × x (100 random t)", worst, tolId(256));
  // Rotating a line about a skew line: every point of every generator on the quadric.
  const L axis = L::pointDirection(V3(0.3, -0.2, 0.1), V3(0.2, 0.1, 1));
  const L l0 = L::pointDirection(V3(1.2, 0.5, -0.3), V3(0.3, 1, 0.8));
  const Regulus<double> r(axis, l0);
  double on = 0;
  for (int k = 0; k < 24; ++k)
    for (const double mu : {-2.0, 0.0, 1.5}) on = std::max(on, std::abs(r.implicit(r.generator(0.26 * k).pointAt(mu))));
  c.checkResidual("rotating a line about a skew axis: points on cos²α(ρ² − d²) = z² sin²α", on, tolId(1024));
  c.checkNear("… d = distance(axis, l₀)", distance(axis, l0), r.distance(), tolId());
  // Book-style check on the swept regulus: its lines satisfy a 2-plane Aω + Bv = 0 in the axis frame.
  const Regulus<double> z(L::pointDirection(V3::Zero(), V3::UnitZ()), L::pointDirection(V3(1, 0, 0), V3(0, 1, 1)));
  double plane = 0;
  for (int k = 0; k < 12; ++k) {
    const V6 s = z.generator(0.5 * k).normalized().coords() * std::sqrt(2.0);
    plane = std::max(plane, std::abs(s(0) + s(3)) + std::abs(s(1) + s(4)) + std::abs(s(2) - s(5)));
  }
  c.checkResidual("the sweep of (1,0,0) + μ(0,1,1) about z is the book's family 2 (its 2-plane p01 = −p23, …)", plane, tolId(256));
}

// GF §6.5.2, GF-6.5.2-cylindroid-two-lines (E6.3)
void cylindroidTwoLines(Context& c) {
  const double l = 1.0, phi = pi<double>() / 3;
  const V6 s1 = six(V3(1, 0, 0), V3::Zero());
  const V6 s2 = six(V3(std::cos(phi), std::sin(phi), 0), V3(-l * std::sin(phi), l * std::cos(phi), 0));
  auto g = rng(82);
  double worstPitch = 0, worstZ = 0, worstCubic = 0, printedCubic = 0, worstOn = 0;
  const Cylindroid<double> cy(s1, s2);
  for (int k = 0; k < 100; ++k) {
    const double mu = uni(g), la = uni(g);
    const V6 s = mu * s1 + la * s2;
    const double dd = mu * mu + la * la + 2 * mu * la * std::cos(phi);
    worstPitch = std::max(worstPitch, std::abs(screwPitch(s) - (-mu * la * l * std::sin(phi) / dd)));
    const L ax = screwAxis(s).axis;
    const V3 f = ax.foot();
    worstZ = std::max(worstZ, std::abs(f.z() - l * (la * la + la * mu * std::cos(phi)) / dd));  // corrected sign
    for (const double t : {-1.0, 0.7}) {
      const V3 p = ax.pointAt(t);
      const double lhs = p.z() * (p.x() * p.x() + p.y() * p.y()), cot = std::cos(phi) / std::sin(phi);
      worstCubic = std::max(worstCubic, std::abs(lhs - l * (p.y() * p.y() + p.x() * p.y() * cot)));
      printedCubic = std::max(printedCubic, std::abs(lhs + l * (p.y() * p.y() + p.x() * p.y() * cot)));
      worstOn = std::max(worstOn, std::abs(cy.implicit(p)));
    }
  }
  c.checkResidual("pitch of μs₁ + λs₂ = −μλ l sin φ/(μ² + λ² + 2μλ cos φ) (100 random, l = 1, φ = π/3)", worstPitch, tolId(256));
  c.checkResidual("axis height z = +l(λ² + λμ cos φ)/D (corrected sign)", worstZ, tolId(256));
  c.checkResidual("axes on z(x² + y²) = +l(y² + xy cot φ) (corrected cubic)", worstCubic, tolId(1024));
  c.checkPrintedFails("printed z(x² + y²) = −l(y² + xy cot φ)", "E6.3", printedCubic, 1e-3);
  c.checkResidual("axes on the canonical cubic of Cylindroid (principal frame)", worstOn, tolId(1024));
  c.checkNear("μ = 0 is the second line, at height +l", l, screwAxis(s2).axis.foot().z(), tolId());
  c.checkNear("principal pitch max = l(cos φ + 1)/(2 sin φ)", l * (std::cos(phi) + 1) / (2 * std::sin(phi)), cy.pitchMax(), tolId());
  c.checkNear("principal pitch min = l(cos φ − 1)/(2 sin φ)", l * (std::cos(phi) - 1) / (2 * std::sin(phi)), cy.pitchMin(), tolId());
  // Extremes.
  const Cylindroid<double> ortho(s1, six(V3(0, 1, 0), V3(-l, 0, 0)));
  c.checkNear("φ = π/2: pitches ±l/2", l / 2, ortho.pitchMax(), tolId());
  const Cylindroid<double> flat(s1, six(V3(std::cos(phi), std::sin(phi), 0), V3::Zero()));
  c.checkNear("l = 0: a flat pencil, all pitches 0", 0.0, std::abs(flat.pitchMax()) + std::abs(flat.pitchMin()), tolId());
  const double se = Tolerance<double>::sqrtEpsilon();
  for (const double ph : {se / 4, 4 * se}) {
    bool threw = false;
    try {
      Cylindroid<double>(s1, six(V3(std::cos(ph), std::sin(ph), 0), V3(-l * std::sin(ph), l * std::cos(ph), 0)));
    } catch (const InvalidInput&) { threw = true; }
    c.checkEqual("φ = " + num(ph / se) + "·√ε: " + (ph < se ? "rejected (contains an infinite-pitch screw to working precision)" : "accepted"),
                 ph < se ? 1 : 0, threw ? 1 : 0);
  }
}

// GF §6.5.2, GF-6.5.2-cylindroid-principal-form (E6.4)
void cylindroidPrincipal(Context& c) {
  const double rx = 0.7, ry = -0.4;
  double printedIn = 0, corrected = 0, pitchRes = 0, gen = 0;
  for (const double th : {0.2, 0.9, 1.3, 2.5}) {
    const double la = std::cos(th), mu = std::sin(th);
    // Printed inputs (1,0,0; 0,r_x,0) and (0,1,0; r_y,0,0).
    const V6 a = six(V3(1, 0, 0), V3(0, rx, 0)), bPrinted = six(V3(0, 1, 0), V3(ry, 0, 0)), bFixed = six(V3(0, 1, 0), V3(-ry, 0, 0));
    const V6 sp = la * (la * la + mu * mu) * a + mu * (la * la + mu * mu) * bPrinted;
    // The book's general line, as printed.
    const V6 book = six(V3(la * (la * la + mu * mu), mu * (la * la + mu * mu), 0), V3(-mu * (la * la * rx - mu * mu * ry), la * (la * la * rx - mu * mu * ry), 0));
    gen = std::max(gen, (screwAxis(sp).axis.coords() - screwAxis(book).axis.coords()).norm());
    printedIn = std::max(printedIn, std::abs(screwAxis(sp).axis.foot().z() - (rx * la * la - ry * mu * mu)));
    const V6 sf = la * a + mu * bFixed;
    corrected = std::max(corrected, std::abs(screwAxis(sf).axis.foot().z() - (rx * la * la + ry * mu * mu)));
    pitchRes = std::max(pitchRes, std::abs(screwPitch(sf) - la * mu * (rx - ry) / (la * la + mu * mu)));
  }
  c.checkResidual("the printed general line is the pencil of the printed inputs (axes agree)", gen, tolId(64));
  c.checkResidual("printed inputs: axis height r_x cos²θ − r_y sin²θ (not + : E6.4)", printedIn, tolId(64));
  c.checkResidual("with the second line (0,1,0; −r_y,0,0) the height is r_x cos²θ + r_y sin²θ", corrected, tolId(64));
  c.checkResidual("pitch λμ(r_x − r_y)/(λ² + μ²) (corrected input)", pitchRes, tolId(64));
  // r_x = r_y: all lines through one point (degenerate).
  const Cylindroid<double> deg(six(V3(1, 0, 0), V3(0, 0.5, 0)), six(V3(0, 1, 0), V3(-0.5, 0, 0)));
  c.checkNear("r_x = r_y = 0.5: principal pitches equal (0)", 0.0, std::abs(deg.pitchMax()) + std::abs(deg.pitchMin()), tolId());
  c.checkNear("… every axis through (0, 0, 0.5)", 0.0, deg.axis(0.8).distanceTo(V3(0, 0, 0.5)), tolId(64));
  const Cylindroid<double> sym(six(V3(1, 0, 0), V3(0, 0.5, 0)), six(V3(0, 1, 0), V3(0.5, 0, 0)));
  c.checkNear("r_x = −r_y = 0.5: height at θ is 0.5 cos 2θ (cf. GF-9.4-cylindroid-invariants)", 0.5 * std::cos(1.4),
              screwAxis(V6(std::cos(0.7) * six(V3(1, 0, 0), V3(0, 0.5, 0)) + std::sin(0.7) * six(V3(0, 1, 0), V3(0.5, 0, 0)))).axis.foot().z(), tolId(64));
  (void)sym;
}

// GF §6.5.2, GF-6.5.2-fixed-axode (proposal: the book gives no example)
void fixedAxode(Context& c) {
  const V6 A = six(V3(0, 0, 1), V3(0, 0, 0.2)), B = six(V3(1, 0, 0), V3(0, 0.5, 0.1));
  // g(t) = exp(tA) exp(tB): ġg⁻¹ = A + Ad(exp(tA))B.
  auto gOf = [&](double t) { return SE3Tangent<double>(V6(t * A)).exp() * SE3Tangent<double>(V6(t * B)).exp(); };
  double fd = 0;
  for (const double t : {0.2, 0.9, 1.7}) {
    const V6 an = A + SE3Tangent<double>(V6(t * A)).exp().adjoint() * B;
    const double h = 1e-5;
    const Mat4<double> dg = (gOf(t + h).matrix() - gOf(t - h).matrix()) / (2 * h);
    const V6 num = SE3Tangent<double>::vee(Mat4<double>(dg * gOf(t).inverse().matrix())).coeffs();
    fd = std::max(fd, (num - an).norm());
  }
  c.checkResidual("ġg⁻¹ = A + Ad(e^{tA})B (central differences, h = 1e-5)", fd, 1e-8);
  // One-parameter subgroup: all axes coincide.
  double same = 0;
  for (const double t : {0.3, 1.1, 2.0}) {
    const double h = 1e-5;
    auto e = [&](double u) { return SE3Tangent<double>(V6(u * A)).exp(); };
    const Mat4<double> dg = (e(t + h).matrix() - e(t - h).matrix()) / (2 * h);
    const V6 num = SE3Tangent<double>::vee(Mat4<double>(dg * e(t).inverse().matrix())).coeffs();
    same = std::max(same, (screwAxis(num).axis.coords() - screwAxis(A).axis.coords()).norm());
  }
  c.checkResidual("one-parameter subgroup e^{tA}: the instantaneous axis (finite differences) is A's axis at t = 0.3, 1.1, 2", same, 1e-8);
  // The fixed axode of the composite motion is a ruled surface: axes move, are lines, striction exists.
  const RuledSurface<double> ax(
      [&](const double& t) { return screwAxis(V6(A + SE3Tangent<double>(V6(t * A)).exp().adjoint() * B)).axis.coords(); },
      [&](const double& t) {
        const double h = 1e-5;
        auto f = [&](double u) { return screwAxis(V6(A + SE3Tangent<double>(V6(u * A)).exp().adjoint() * B)).axis.coords(); };
        return V6((f(t + h) - f(t - h)) / (2 * h));
      });
  double klein = 0;
  for (const double t : {0.0, 0.5, 1.0}) klein = std::max(klein, std::abs(kleinValue(ax.coords(t))));
  c.checkResidual("axode generators are lines", klein, tolId(64));
  c.record("the axode is not a cylinder at t = 0.5 (|u'| > 0)", "non-cylindrical", ax.isCylindrical(0.5) ? "cylindrical" : "non-cylindrical", 0, 0,
           !ax.isCylindrical(0.5));
  c.note("Finite differences for the axode's derivative; the striction point of the axode at t = 0.5 is " +
         num(ax.strictionPoint(0.5).x()) + ", " + num(ax.strictionPoint(0.5).y()) + ", " + num(ax.strictionPoint(0.5).z()) + ".");
}

// GF §6.5.3, GF-6.5.3-curvature-axes (E6.1)
void curvatureAxes(Context& c) {
  double onPoint = 0, printedMoment = 0, surface = 0, rational = 0;
  for (const auto& [kx, ky] : {std::pair{1.0, 3.0}, std::pair{2.0, -1.0}, std::pair{0.5, 0.25}}) {
    for (const double phi : {0.1, 0.7, 1.3, 2.9}) {
      const double k = kx * std::cos(phi) * std::cos(phi) + ky * std::sin(phi) * std::sin(phi);
      const V3 w(-std::sin(phi), std::cos(phi), 0), q(0, 0, 1 / k);
      const V3 bookMoment = V3(std::cos(phi), std::sin(phi), 0) / k;
      const L ax(curvatureAxis(kx, ky, std::cos(phi), std::sin(phi)));
      onPoint = std::max(onPoint, ax.distanceTo(q));
      printedMoment = std::max(printedMoment, (bookMoment - q.cross(w)).norm());
      for (const double t : {-1.0, 0.5, 2.0}) {
        const V3 p = ax.pointAt(t);
        surface = std::max(surface, std::abs(curvatureAxesImplicit(kx, ky, p)) / (1 + p.squaredNorm() * (1 + std::abs(p.z()))));
      }
      // The rational cubic s(λ, μ) and s(φ) = (−i sin φ + j cos φ, …) are the same line.
      const L fromPhi = L::pointDirection(q, w);
      rational = std::max(rational, fromPhi.sameAs(ax) ? 0.0 : 1.0);
    }
  }
  c.checkResidual("axis s(φ) passes through (0, 0, 1/k_φ) (Euler k_φ = k_x cos²φ + k_y sin²φ)", onPoint, tolId(64));
  c.checkResidual("the rational cubic s(λ, μ) is the line s(φ) (convention A)", rational, 0.0);
  c.checkResidual("axes on z(k_x y² + k_y x²) = x² + y²", surface, tolId(256));
  c.checkPrintedFails("printed moment (i cos φ + j sin φ)/k_φ equals q × ω (it is ω × q: convention B)", "E6.1", printedMoment, 1e-6);
  c.checkResidual("umbilic k_x = k_y = 2: every axis through (0, 0, ½)",
                  L(curvatureAxis(2.0, 2.0, 0.3, 0.8)).distanceTo(V3(0, 0, 0.5)) + L(curvatureAxis(2.0, 2.0, -0.6, 0.1)).distanceTo(V3(0, 0, 0.5)), tolId(64));
  c.checkEqual("saddle k_x = 1, k_y = −1, asymptotic direction λ = μ: the axis is the line at infinity", 1,
               L(curvatureAxis(1.0, -1.0, 1.0, 1.0)).isAtInfinity() ? 1 : 0);
  const double d = 1e-9;
  c.checkNear("… near it (λ = 1, μ = 1 + 1e-9): axis at height (λ² + μ²)/K ≈ −1e9 (K computed with rounding 1e-16/2e-9)",
              -(2 + 2 * d + d * d) / (2 * d + d * d),
              L(curvatureAxis(1.0, -1.0, 1.0, 1.0 + d)).foot().z(), 1e-6 * 1e9);
  c.checkNear("parabolic point k_x = 0: the axis for φ = 0 is at infinity too", 1.0, L(curvatureAxis(0.0, 1.0, 1.0, 0.0)).isAtInfinity() ? 1.0 : 0.0, 0.0);
}

SOMA_STUDY_DOUBLE("GF-6.5.1-regulus", "The two reguli of the hyperboloid x² + y² − z² = 1 in Plücker coordinates", "GF §6.5.1", regulus);
SOMA_STUDY_DOUBLE("GF-6.5.1-conic-to-quadric", "A conic in the Klein quadric fills a quadric det(A + BT) = 0", "GF §6.5.1", conicToQuadric);
SOMA_STUDY_DOUBLE("GF-6.5.2-cylindroid-two-lines", "The cylindroid of two lines: pitch, axes, cubic surface (E6.3)", "GF §6.5.2", cylindroidTwoLines);
SOMA_STUDY_DOUBLE("GF-6.5.2-cylindroid-principal-form", "Cylindroid from two perpendicular lines (E6.4)", "GF §6.5.2", cylindroidPrincipal);
SOMA_STUDY_DOUBLE("GF-6.5.2-fixed-axode", "The fixed axode of a one-parameter motion", "GF §6.5.2", fixedAxode);
SOMA_STUDY_DOUBLE("GF-6.5.3-curvature-axes", "Axes of curvature of a surface point form a cubic ruled surface (E6.1)", "GF §6.5.3", curvatureAxes);

}  // namespace
}  // namespace soma::studies::gf06::SOMA_UNITY_ID
