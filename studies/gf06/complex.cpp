// Studies of GF §6.6–6.8: linear complexes (equation, 4×4 form, null polarity, symmetries), the
// reciprocal-screw inverse Jacobian of a 6R arm, Grassmannians (double).
#include "gf06/common.hpp"

namespace soma::studies::gf06::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// GF §6.6, GF-6.6-linear-complex
void linearComplex(Context& c) {
  auto g = rng(91);
  double singular = 0, pitchErr = 0, perp = 0;
  for (int k = 0; k < 100; ++k) {
    const L m = L::pointDirection(rv(g, -2, 2), rv(g));
    const LinearComplex<double> cs = LinearComplex<double>::singular(m);
    singular = std::max(singular, cs.relativeResidual(L::pointDirection(m.pointAt(uni(g)), rv(g))));
    const V6 s = six(rv(g), rv(g));
    const LinearComplex<double> cc(s);
    pitchErr = std::max(pitchErr, std::abs(cc.pitch() - s.head<3>().dot(s.tail<3>()) / s.head<3>().squaredNorm()));
    // Lines of the complex through random points: b·ω + α·v = 0.
    perp = std::max(perp, cc.relativeResidual(cc.lineThrough(rv(g, -3, 3), uni(g, 0, 3))));
  }
  c.checkResidual("singular complex (α·b = 0): every line meeting the line is in it (100)", singular, tolId(256));
  c.checkResidual("pitch = α·b/α·α", pitchErr, tolId(64));
  c.checkResidual("lines through a point in its null plane satisfy b·ω + α·v = 0", perp, tolId(1024));
  const LinearComplex<double> inf(six(V3::Zero(), V3(0, 0, 1)));
  c.checkEqual("α = 0: infinite pitch", "inf", std::isinf(inf.pitch()) ? "inf" : "finite");
  c.checkEqual("… its lines are those ⟂ b: (1,2,0) through (3,4,5) in, (1,2,1) out", "in/out",
               std::string(inf.contains(L::pointDirection(V3(3, 4, 5), V3(1, 2, 0))) ? "in" : "?") + "/" +
                   (inf.contains(L::pointDirection(V3(3, 4, 5), V3(1, 2, 1))) ? "in" : "out"));
  const L m = L::pointDirection(V3(1, 0, 0), V3(0, 1, 1));
  c.checkEqual("α·b → 0: pitch 1e-20 is singular, 1e-3 is not (threshold Tolerance::identity)", "singular/regular",
               std::string(LinearComplex<double>::fromAxisPitch(m, 1e-20).isSingular() ? "singular" : "regular") + "/" +
                   (LinearComplex<double>::fromAxisPitch(m, 1e-3).isSingular() ? "singular" : "regular"));
  complexFigure(c);
}

// GF §6.6, GF-6.6-complex-4x4 (E6.5, E6.6)
void complex4x4(Context& c) {
  auto g = rng(92);
  double ident = 0, det = 0, nullPlane = 0, printedC = 0, correctedC = 0, polarity = 0;
  for (int k = 0; k < 100; ++k) {
    const V3 al = rv(g), b = rv(g);
    const LinearComplex<double> cc(six(al, b));
    const Mat4<double> X = cc.matrix4();
    const Vec4<double> xp(uni(g), uni(g), uni(g), uni(g)), yp(uni(g), uni(g), uni(g), uni(g));  // (x1,x2,x3,x0)
    const V3 xv = xp.head<3>(), yv = yp.head<3>();
    const V6 l = six(V3(xp(3) * yv - yp(3) * xv), V3(xv.cross(yv)));
    ident = std::max(ident, std::abs(double(yp.dot(X * xp)) - reciprocalProduct(six(al, b), l)));
    det = std::max(det, std::abs(X.determinant() - std::pow(al.dot(b), 2)));
    // Null plane C_i of y: printed (E6.6) vs corrected coefficients; test a point x of each plane.
    const double y0 = yp(3), y1 = yp(0), y2 = yp(1), y3 = yp(2);
    const double a1 = al(0), a2 = al(1), a3 = al(2), b1 = b(0), b2 = b(1), b3 = b(2);
    const Vec4<double> Cp(-b1 * y0 + a3 * y2 + a2 * y3, -b2 * y0 - a3 * y1 + a1 * y3, -b3 * y0 - a2 * y1 - a1 * y2, b1 * y1 + b2 * y2 + b3 * y3);
    const Vec4<double> Cc(-b1 * y0 + a3 * y2 - a2 * y3, -b2 * y0 - a3 * y1 + a1 * y3, -b3 * y0 + a2 * y1 - a1 * y2, b1 * y1 + b2 * y2 + b3 * y3);
    auto pointOn = [&](const Vec4<double>& C) {  // x with C·x = 0: x = r − (C·r/|C|²)C
      const Vec4<double> r(uni(g), uni(g), uni(g), uni(g));
      return Vec4<double>(r - C.dot(r) / C.squaredNorm() * C);
    };
    auto residual = [&](const Vec4<double>& x) { return std::abs(double(yp.dot(X * x))) / (x.norm() * yp.norm()); };
    printedC = std::max(printedC, residual(pointOn(Cp)));
    correctedC = std::max(correctedC, residual(pointOn(Cc)));
    // soma's null plane of a finite point, and the null point of that plane.
    const V3 y = rv(g, -2, 2);
    const pga::Plane<double> pl = cc.nullPlane(y);
    nullPlane = std::max(nullPlane, std::abs(pl.normal().dot(y) - pl.distance()) + cc.relativeResidual(cc.lineThrough(y, 1.0)));
    const Vec4<double> yh = cc.nullPoint(pl);
    polarity = std::max(polarity, (yh.tail<3>() / yh(0) - y).norm());
  }
  c.checkResidual("yᵀX x = b·ω + α·v with p_ij = x_i y_j − x_j y_i (100 random)", ident, tolId(256));
  c.checkResidual("det X = (α·b)²", det, tolId(256));
  c.checkResidual("corrected C₁ = −b₁y₀ + α₃y₂ − α₂y₃, C₃ = −b₃y₀ + α₂y₁ − α₁y₂: points of the null plane give complex lines", correctedC, tolId(256));
  c.checkPrintedFails("printed C₁, C₃ (sign of α₂)", "E6.5/E6.6", printedC, 1e-6);
  c.checkResidual("nullPlane(y) contains y and the complex lines through y", nullPlane, tolId(1024));
  c.checkResidual("null polarity is invertible: nullPoint(nullPlane(y)) = y", polarity, 1e-10);
  const LinearComplex<double> sing = LinearComplex<double>::singular(L::pointDirection(V3::Zero(), V3::UnitX()));
  c.checkNear("singular complex: det X = 0", 0.0, sing.matrix4().determinant(), 0.0);
  const LinearComplex<double> cz = LinearComplex<double>::fromAxisPitch(L::pointDirection(V3::Zero(), V3::UnitZ()), 0.5);
  c.checkNear("plane x = 1 (parallel to the axis): null point at infinity (x₀ = 0)", 0.0, cz.nullPoint(pga::Plane<double>(V3(1, 0, 0), 1)).x(), tolId());
}

// GF §6.6, GF-6.6-complex-symmetries (E6.1)
void complexSymmetries(Context& c) {
  auto g = rng(93);
  double fixes = 0, keeps = 0, axisKlein = 0;
  for (int k = 0; k < 100; ++k) {
    const V6 s = six(rv(g), rv(g));
    const LinearComplex<double> cc(s);
    const SE3d x = cc.symmetry(uni(g, -3.1, 3.1), uni(g, -3, 3));
    fixes = std::max(fixes, (lineAction(x) * s - s).norm());
    keeps = std::max(keeps, cc.relativeResidual(cc.lineThrough(rv(g, -2, 2), uni(g, 0, 3)).transformed(x)));
    axisKlein = std::max(axisKlein, kleinDefect(V6(six(s.head<3>(), V3(s.tail<3>() - s.head<3>() * s.head<3>().dot(s.tail<3>()) / s.head<3>().squaredNorm())))));
  }
  c.checkResidual("R = e^{θα}, t = α×(I − R)b/|α|² − λα fixes (α, b) (100 random θ, λ)", fixes, tolId(1024));
  c.checkResidual("… and maps complex lines to complex lines", keeps, tolId(1024));
  c.checkResidual("axis (α, b − α(α·b)/|α|²) is a line", axisKlein, tolId(64));
  const LinearComplex<double> cc(six(V3(1, 2, 0), V3(3, -1, 2)));
  c.checkResidual("θ = π", (lineAction(cc.symmetry(pi<double>(), 0.5)) * cc.screw() - cc.screw()).norm(), tolId(64));
  const LinearComplex<double> huge(six(V3(1e-6, 0, 0), V3(1, 0.5, 0.2)));
  c.checkResidual("|α| = 1e-6 ≪ |b| (pitch 1e6): relative defect", (lineAction(huge.symmetry(1.0, 0.0)) * huge.screw() - huge.screw()).norm() / huge.screw().norm(), 1e-9);
  c.note("Sp(4,ℝ) ∩ SE(3) = SO(2) × ℝ: the two parameters θ (rotation about the axis) and λ (translation along it).");
}

// GF §6.7, GF-6.7-inverse-jacobian-6R
PumaLikeArm<double> puma(std::mt19937_64& g, double elbowOffset) {
  PumaLikeArm<double> a;
  a.w1 = V3::UnitZ();
  const double t = uni(g, -3, 3);
  a.w2 = V3(std::cos(t), std::sin(t), 0);
  const V3 e = a.w1.cross(a.w2);
  a.xe = 0.6 * e + 0.3 * a.w1;
  a.xc = a.xe + 0.8 * (std::cos(elbowOffset) * e.normalized() + std::sin(elbowOffset) * a.w1) ;
  // Elbow singular when o, x_e, x_c are collinear: direction of x_e is atan2(0.3, 0.6).
  a.w4 = (a.xc - a.xe).normalized();
  a.w5 = ru(g);
  a.w6 = ru(g);
  return a;
}
void inverseJacobian(Context& c) {
  auto g = rng(94);
  double recip = 0, wj = 0, vsNum = 0;
  for (int k = 0; k < 50; ++k) {
    const PumaLikeArm<double> a = puma(g, uni(g, 1.0, 2.5));
    const Mat6<double> j = a.jacobian();
    const auto z = pumaLikeReciprocalLines(a);
    for (int i = 0; i < 6; ++i)
      for (int m = 0; m < 6; ++m)
        if (i != m) recip = std::max(recip, std::abs(reciprocalProduct(z[i], V6(j.col(m)))));
    const Mat6<double> w = inverseJacobianFromReciprocals(j, z);
    wj = std::max(wj, (w * j - Mat6<double>::Identity()).norm());
    vsNum = std::max(vsNum, (w - j.inverse()).norm() / j.inverse().norm());
  }
  c.checkResidual("z_iᵀQ₀s_j = 0 for i ≠ j (50 random configurations)", recip, tolId(256));
  c.checkResidual("W J = I₆", wj, 1e-12);
  c.checkResidual("W = J⁻¹ by LU (relative)", vsNum, 1e-12);
  // Sweep towards the elbow singularity: o, x_e, x_c collinear at offset angle atan2(0.3, 0.6).
  const double sing = std::atan2(0.3, 0.6);
  std::string sweep;
  double prev = 1e300;
  bool monotone = true;
  for (const double d : {1e-1, 1e-3, 1e-5, 1e-7}) {
    auto g2 = rng(95);
    const PumaLikeArm<double> a = puma(g2, sing + d);
    const auto z = pumaLikeReciprocalLines(a);
    double smallest = 1e300;
    for (int i = 0; i < 6; ++i) smallest = std::min(smallest, std::abs(reciprocalProduct(z[i], V6(a.jacobian().col(i)))) / (z[i].norm() * a.jacobian().col(i).norm()));
    sweep += num(d) + ": " + num(smallest) + "; ";
    monotone = monotone && smallest < prev;
    prev = smallest;
  }
  c.record("elbow singularity: min |z_iᵀQ₀s_i| (relative) falls with the offset δ", "decreasing to 0", sweep, 0, 0, monotone && prev < 1e-6);
  auto g3 = rng(95);
  const PumaLikeArm<double> atSing = puma(g3, sing);
  bool threw = false;
  try {
    inverseJacobianFromReciprocals(atSing.jacobian(), pumaLikeReciprocalLines(atSing));
  } catch (const InvalidInput&) { threw = true; }
  c.checkEqual("at the elbow singularity: InvalidInput", 1, threw ? 1 : 0);
}

// GF §6.8, GF-6.8-grassmannian-embedding
void grassmannEmbedding(Context& c) {
  auto g = rng(96);
  double rel = 0, minRandom = 1e300, klein = 0;
  for (int k = 0; k < 100; ++k) {
    for (const int m : {4, 5, 6}) {
      Eigen::MatrixXd b(m, 2);
      for (int i = 0; i < m; ++i) b.row(i) << uni(g), uni(g);
      const Eigen::VectorXd p = pluckerEmbedding<double>(b);
      rel = std::max(rel, pluckerRelationsG2<double>(p, m).cwiseAbs().maxCoeff());
      Eigen::VectorXd q(p.size());
      for (int i = 0; i < q.size(); ++i) q(i) = uni(g);
      minRandom = std::min(minRandom, pluckerRelationsG2<double>(q, m).cwiseAbs().maxCoeff());
      if (m == 4) {
        // Klein relation = Pfaffian p01p23 − p02p13 + p03p12 = ω·v in 6-vector form.
        const V6 s = six(V3(p(0), p(1), p(2)), V3(p(5), -p(4), p(3)));
        klein = std::max(klein, std::abs(kleinValue(s) - pluckerRelationsG2<double>(p, 4)(0)));
      }
    }
  }
  c.checkResidual("G(2,4), G(2,5), G(2,6): relations vanish on x ∧ y (100 each)", rel, tolId(64));
  c.record("a random vector violates them (smallest max-violation of 300)", "> 1e-6", num(minRandom), 0, 0, minRandom > 1e-6);
  c.checkResidual("the G(2,4) relation is the Klein quadric ω·v (p31 = −p13)", klein, tolId(64));
  c.checkEqual("number of relations for G(2,5)", 5, pluckerRelationsG2<double>(Eigen::VectorXd::Zero(10), 5).size());
  c.checkEqual("number of relations for G(2,6) (used in ch. 8)", 15, pluckerRelationsG2<double>(Eigen::VectorXd::Zero(15), 6).size());
  c.checkEqual("coordinates of G(3,6): C(6,3)", 20, static_cast<long long>(pluckerIndexSets(3, 6).size()));
  // x ∧ y of the book's (x0..x3): same as PluckerLine::throughHomogeneousPoints.
  Vec4<double> x(1, 0.2, -0.4, 0.7), y(0.5, 1.1, 0.3, -0.2);
  Eigen::MatrixXd b(4, 2);
  b.col(0) = x;
  b.col(1) = y;
  const Eigen::VectorXd p = pluckerEmbedding<double>(b);
  const V6 s = six(V3(p(0), p(1), p(2)), V3(p(5), -p(4), p(3)));
  c.checkResidual("x ∧ y = (x₀y₁ − x₁y₀, …; x₂y₃ − x₃y₂, …) = PluckerLine::throughHomogeneousPoints", (s - L::throughHomogeneousPoints(x, y).coords()).norm(), tolId());
}

// GF §6.8, GF-6.8-grassmannian-homogeneous (E6.7)
void grassmannHomogeneous(Context& c) {
  bool all = true;
  for (int m = 1; m <= 12; ++m)
    for (int n = 0; n <= m; ++n) all = all && grassmannianDimension(n, m) == n * (m - n);
  c.checkEqual("½m(m−1) − ½n(n−1) − ½(m−n)(m−n−1) = n(m − n) for all 0 ≤ n ≤ m ≤ 12", 1, all ? 1 : 0);
  c.checkEqual("dim G(2,4) (lines in PR³)", 4, grassmannianDimension(2, 4));
  c.checkEqual("dim G(2,6)", 8, grassmannianDimension(2, 6));
  c.checkEqual("dim G(3,6)", 9, grassmannianDimension(3, 6));
  c.checkEqual("dim G(1,5) = dim PR⁴ (the book's G(1,m) = PR^m is off by one: E6.7)", 4, grassmannianDimension(1, 5));
  // G(2,4) embedded: 6 coordinates, 1 relation ⇒ projective dimension 5 − 1 = 4.
  c.checkEqual("Plücker: C(4,2) − 1 − 1 relation = 4", 4, static_cast<long long>(pluckerIndexSets(2, 4).size()) - 1 - 1);
}

SOMA_STUDY_DOUBLE("GF-6.6-linear-complex", "Linear line complexes: b·ω + α·v = 0, pitch, singular and infinite-pitch complexes", "GF §6.6", linearComplex);
SOMA_STUDY_DOUBLE("GF-6.6-complex-4x4", "The complex as a 4×4 antisymmetric form and its null polarity (E6.5, E6.6)", "GF §6.6", complex4x4);
SOMA_STUDY_DOUBLE("GF-6.6-complex-symmetries", "Rigid symmetries and axis of a linear complex (E6.1)", "GF §6.6", complexSymmetries);
SOMA_STUDY_DOUBLE("GF-6.7-inverse-jacobian-6R", "Inverse Jacobian of a PUMA-like arm by reciprocal lines", "GF §6.7", inverseJacobian);
SOMA_STUDY_DOUBLE("GF-6.8-grassmannian-embedding", "Plücker embedding of Grassmannians and the Plücker relations", "GF §6.8", grassmannEmbedding);
SOMA_STUDY_DOUBLE("GF-6.8-grassmannian-homogeneous", "Grassmannians as homogeneous spaces: dimension n(m − n) (E6.7)", "GF §6.8", grassmannHomogeneous);

}  // namespace
}  // namespace soma::studies::gf06::SOMA_UNITY_ID
