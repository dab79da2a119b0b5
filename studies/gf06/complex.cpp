// Studies of GF §6.6–6.8: linear complexes (equation, 4×4 form, null polarity, symmetries), the
// reciprocal-screw inverse Jacobian of a 6R arm, Grassmannians. Every study runs in the asked scalar
// (--scalar); the figure of GF-6.6-linear-complex is drawn in double (soma::render).
#include "gf06/common.hpp"
#include "soma/algebra/small_linalg.hpp"

namespace soma::studies::gf06::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using std::abs;
using std::max;
using std::min;

template <class S> Vec4<S> rv4(std::mt19937_64& g) {
  const S a = uni<S>(g), b = uni<S>(g), cc = uni<S>(g), d = uni<S>(g);
  return Vec4<S>(a, b, cc, d);
}

// GF §6.6, GF-6.6-linear-complex
template <class S> void linearComplex(Context& c) {
  using std::isinf;
  auto g = rng(91);
  S singular(0), pitchErr(0), perp(0);
  for (int k = 0; k < 100; ++k) {
    const Vec3<S> p0 = rv<S>(g, -2, 2), d0 = rv<S>(g);
    const Ln<S> m = Ln<S>::pointDirection(p0, d0);
    const LinearComplex<S> cs = LinearComplex<S>::singular(m);
    const Vec3<S> q = m.pointAt(uni<S>(g));
    singular = max(singular, cs.relativeResidual(Ln<S>::pointDirection(q, rv<S>(g))));
    const Vec3<S> sa = rv<S>(g), sb = rv<S>(g);
    const Vec6<S> s = six(sa, sb);
    const LinearComplex<S> cc(s);
    pitchErr = max(pitchErr, S(abs(S(cc.pitch() - s.template head<3>().dot(s.template tail<3>()) / s.template head<3>().squaredNorm()))));
    // Lines of the complex through random points: b·ω + α·v = 0.
    const Vec3<S> y = rv<S>(g, -3, 3);
    perp = max(perp, cc.relativeResidual(cc.lineThrough(y, uni<S>(g, 0, 3))));
  }
  c.checkResidual("singular complex (α·b = 0): every line meeting the line is in it (100)", singular, tolId<S>(256));
  c.checkResidual("pitch = α·b/α·α", pitchErr, tolId<S>(64));
  c.checkResidual("lines through a point in its null plane satisfy b·ω + α·v = 0", perp, tolId<S>(1024));
  const LinearComplex<S> inf(six(Vec3<S>(Vec3<S>::Zero()), Vec3<S>(S(0), S(0), S(1))));
  c.checkEqual("α = 0: infinite pitch", "inf", isinf(inf.pitch()) ? "inf" : "finite");
  const Vec3<S> p345(S(3), S(4), S(5));
  c.checkEqual("… its lines are those ⟂ b: (1,2,0) through (3,4,5) in, (1,2,1) out", "in/out",
               std::string(inf.contains(Ln<S>::pointDirection(p345, Vec3<S>(S(1), S(2), S(0)))) ? "in" : "?") + "/" +
                   (inf.contains(Ln<S>::pointDirection(p345, Vec3<S>(S(1), S(2), S(1)))) ? "in" : "out"));
  const Ln<S> m = Ln<S>::pointDirection(Vec3<S>(S(1), S(0), S(0)), Vec3<S>(S(0), S(1), S(1)));
  // the tiny pitch: ε·1e-4 (1e-20 in double), below the threshold 64ε on every rung
  const S tinyPitch = Tolerance<S>::epsilon() * tenTo<S>(-4);
  c.checkEqual("α·b → 0: pitch " + num(tinyPitch) + " is singular, 1e-3 is not (threshold Tolerance::identity)", "singular/regular",
               std::string(LinearComplex<S>::fromAxisPitch(m, tinyPitch).isSingular() ? "singular" : "regular") + "/" +
                   (LinearComplex<S>::fromAxisPitch(m, tenTo<S>(-3)).isSingular() ? "singular" : "regular"));
  complexFigure(c);  // drawn in double by soma::render (gf06/figures.cpp)
}

// GF §6.6, GF-6.6-complex-4x4 (E6.5, E6.6)
template <class S> void complex4x4(Context& c) {
  auto g = rng(92);
  S ident(0), det(0), nullPlane(0), printedC(0), correctedC(0), polarity(0);
  for (int k = 0; k < 100; ++k) {
    const Vec3<S> al = rv<S>(g), b = rv<S>(g);
    const LinearComplex<S> cc(six(al, b));
    const Mat4<S> X = cc.matrix4();
    const Vec4<S> xp = rv4<S>(g), yp = rv4<S>(g);  // (x1,x2,x3,x0)
    const Vec3<S> xv = xp.template head<3>(), yv = yp.template head<3>();
    const Vec6<S> l = six(Vec3<S>(xp(3) * yv - yp(3) * xv), Vec3<S>(xv.cross(yv)));
    ident = max(ident, S(abs(S(S(yp.dot(X * xp)) - reciprocalProduct(six(al, b), l)))));
    const S ab = al.dot(b);
    det = max(det, S(abs(S(X.determinant() - ab * ab))));
    // Null plane C_i of y: printed (E6.6) vs corrected coefficients; test a point x of each plane.
    const S y0 = yp(3), y1 = yp(0), y2 = yp(1), y3 = yp(2);
    const S a1 = al(0), a2 = al(1), a3 = al(2), b1 = b(0), b2 = b(1), b3 = b(2);
    const Vec4<S> Cp(-b1 * y0 + a3 * y2 + a2 * y3, -b2 * y0 - a3 * y1 + a1 * y3, -b3 * y0 - a2 * y1 - a1 * y2, b1 * y1 + b2 * y2 + b3 * y3);
    const Vec4<S> Cc(-b1 * y0 + a3 * y2 - a2 * y3, -b2 * y0 - a3 * y1 + a1 * y3, -b3 * y0 + a2 * y1 - a1 * y2, b1 * y1 + b2 * y2 + b3 * y3);
    auto pointOn = [&](const Vec4<S>& C) {  // x with C·x = 0: x = r − (C·r/|C|²)C
      const Vec4<S> r = rv4<S>(g);
      return Vec4<S>(r - C.dot(r) / C.squaredNorm() * C);
    };
    auto residual = [&](const Vec4<S>& x) { return S(abs(S(yp.dot(X * x))) / (x.norm() * yp.norm())); };
    printedC = max(printedC, residual(pointOn(Cp)));
    correctedC = max(correctedC, residual(pointOn(Cc)));
    // soma's null plane of a finite point, and the null point of that plane.
    const Vec3<S> y = rv<S>(g, -2, 2);
    const pga::Plane<S> pl = cc.nullPlane(y);
    nullPlane = max(nullPlane, S(abs(S(pl.normal().dot(y) - pl.distance())) + cc.relativeResidual(cc.lineThrough(y, S(1)))));
    const Vec4<S> yh = cc.nullPoint(pl);
    // The polarity solves X; the antisymmetric X has singular values σ₁ ≥ σ₂ with σ₁σ₂ = |α·b| and
    // σ₁² + σ₂² = |α|² + |b|², so κ(X) ≤ (|α|² + |b|²)/|α·b|: the error is read relative to κ(X)(1 + |y|).
    const S kappa = (al.squaredNorm() + b.squaredNorm()) / abs(ab);
    polarity = max(polarity, S((yh.template tail<3>() / yh(0) - y).norm() / (kappa * (S(1) + y.norm()))));
  }
  c.checkResidual("yᵀX x = b·ω + α·v with p_ij = x_i y_j − x_j y_i (100 random)", ident, tolId<S>(256));
  c.checkResidual("det X = (α·b)²", det, tolId<S>(256));
  c.checkResidual("corrected C₁ = −b₁y₀ + α₃y₂ − α₂y₃, C₃ = −b₃y₀ + α₂y₁ − α₁y₂: points of the null plane give complex lines", correctedC, tolId<S>(256));
  c.checkPrintedFails("printed C₁, C₃ (sign of α₂)", "E6.5/E6.6", printedC, tolId<S>(256));
  c.checkResidual("nullPlane(y) contains y and the complex lines through y", nullPlane, tolId<S>(1024));
  c.checkResidual("null polarity is invertible: nullPoint(nullPlane(y)) = y (relative to κ(X)(1 + |y|))", polarity, tolId<S>(64));
  const LinearComplex<S> sing = LinearComplex<S>::singular(Ln<S>::pointDirection(Vec3<S>::Zero(), Vec3<S>::UnitX()));
  c.checkNear("singular complex: det X = 0", S(0), S(sing.matrix4().determinant()), S(0));
  const LinearComplex<S> cz = LinearComplex<S>::fromAxisPitch(Ln<S>::pointDirection(Vec3<S>::Zero(), Vec3<S>::UnitZ()), S(1) / S(2));
  c.checkNear("plane x = 1 (parallel to the axis): null point at infinity (x₀ = 0)", S(0),
              S(cz.nullPoint(pga::Plane<S>(Vec3<S>(S(1), S(0), S(0)), S(1))).x()), tolId<S>());
}

// GF §6.6, GF-6.6-complex-symmetries (E6.1)
template <class S> void complexSymmetries(Context& c) {
  auto g = rng(93);
  S fixes(0), keeps(0), axisKlein(0);
  for (int k = 0; k < 100; ++k) {
    const Vec3<S> sa = rv<S>(g), sb = rv<S>(g);
    const Vec6<S> s = six(sa, sb);
    const LinearComplex<S> cc(s);
    const S th = uni<S>(g, -3.1, 3.1), lam = uni<S>(g, -3, 3);
    const SE3<S> x = cc.symmetry(th, lam);
    fixes = max(fixes, S((lineAction(x) * s - s).norm()));
    const Vec3<S> y = rv<S>(g, -2, 2);
    keeps = max(keeps, cc.relativeResidual(cc.lineThrough(y, uni<S>(g, 0, 3)).transformed(x)));
    axisKlein = max(axisKlein, kleinDefect(Vec6<S>(six(sa, Vec3<S>(sb - sa * sa.dot(sb) / sa.squaredNorm())))));
  }
  c.checkResidual("R = e^{θα}, t = α×(I − R)b/|α|² − λα fixes (α, b) (100 random θ, λ)", fixes, tolId<S>(1024));
  c.checkResidual("… and maps complex lines to complex lines", keeps, tolId<S>(1024));
  c.checkResidual("axis (α, b − α(α·b)/|α|²) is a line", axisKlein, tolId<S>(64));
  const LinearComplex<S> cc(six(Vec3<S>(S(1), S(2), S(0)), Vec3<S>(S(3), S(-1), S(2))));
  c.checkResidual("θ = π", S((lineAction(cc.symmetry(pi<S>(), S(1) / S(2))) * cc.screw() - cc.screw()).norm()), tolId<S>(64));
  const LinearComplex<S> huge(six(Vec3<S>(tenTo<S>(-6), S(0), S(0)), Vec3<S>(S(1), S(1) / S(2), S(2) / S(10))));
  // t = α × (I − R)b/|α|² carries b's rounding times 1/|α| = 1e6: the bound is pitch·4ε.
  c.checkResidual("|α| = 1e-6 ≪ |b| (pitch 1e6): relative defect (bound 1e6·4ε)",
                  S((lineAction(huge.symmetry(S(1), S(0))) * huge.screw() - huge.screw()).norm() / huge.screw().norm()),
                  S(tenTo<S>(6) * tolId<S>(4)));
  c.note("Sp(4,ℝ) ∩ SE(3) = SO(2) × ℝ: the two parameters θ (rotation about the axis) and λ (translation along it).");
}

// GF §6.7, GF-6.7-inverse-jacobian-6R
template <class S> PumaLikeArm<S> puma(std::mt19937_64& g, const S& elbowOffset) {
  using std::cos;
  using std::sin;
  PumaLikeArm<S> a;
  a.w1 = Vec3<S>::UnitZ();
  const S t = uni<S>(g, -3, 3);
  a.w2 = Vec3<S>(cos(t), sin(t), S(0));
  const Vec3<S> e = a.w1.cross(a.w2);
  a.xe = S(6) / S(10) * e + S(3) / S(10) * a.w1;
  a.xc = a.xe + S(8) / S(10) * (cos(elbowOffset) * e.normalized() + sin(elbowOffset) * a.w1);
  // Elbow singular when o, x_e, x_c are collinear: direction of x_e is atan2(0.3, 0.6).
  a.w4 = (a.xc - a.xe).normalized();
  a.w5 = ru<S>(g);
  a.w6 = ru<S>(g);
  return a;
}
template <class S> void inverseJacobian(Context& c) {
  using std::atan2;
  auto g = rng(94);
  S recip(0), wj(0), vsNum(0), kappa(0);
  for (int k = 0; k < 50; ++k) {
    const PumaLikeArm<S> a = puma<S>(g, uni<S>(g, 1.0, 2.5));
    const Mat6<S> j = a.jacobian();
    const auto z = pumaLikeReciprocalLines(a);
    for (int i = 0; i < 6; ++i)
      for (int m = 0; m < 6; ++m)
        if (i != m) recip = max(recip, S(abs(reciprocalProduct(z[i], Vec6<S>(j.col(m)))) / (z[i].norm() * j.col(m).norm())));
    const Mat6<S> w = inverseJacobianFromReciprocals(j, z);
    Mat6<S> jinv;  // J⁻¹ column by column by soma's elimination (small_linalg.hpp), the LU reference
    for (int col = 0; col < 6; ++col) {
      Vec6<S> e = Vec6<S>::Unit(col);
      detail::smallSolveInPlace<S, 6>(j, e);
      jinv.col(col) = e;
    }
    wj = max(wj, S((w * j - Mat6<S>::Identity()).norm()));
    vsNum = max(vsNum, S((w - jinv).norm() / jinv.norm()));
    kappa = max(kappa, S(j.norm() * jinv.norm()));
  }
  c.checkResidual("z_iᵀQ₀s_j = 0 for i ≠ j, relative to |z_i||s_j| (50 random configurations)", recip, tolId<S>(256));
  // The condition bound of an inverse: a relative perturbation ε of J moves J⁻¹ by ≲ ε·κ(J) relative
  // (Frobenius κ, the largest of the 50 configurations, ~1.3e4). Measured: ~0.1 ε·κ on every rung.
  c.checkResidual("W J = I₆ (bound ε·κ(J), κ ≤ " + num(kappa) + ")", wj, S(Tolerance<S>::epsilon() * kappa));
  c.checkResidual("W = J⁻¹ by LU (relative; bound ε·κ(J))", vsNum, S(Tolerance<S>::epsilon() * kappa));
  // Sweep towards the elbow singularity: o, x_e, x_c collinear at offset angle atan2(0.3, 0.6).
  // Offsets 1e-1 … 1e-7, down to 1000ε (below, the angle itself is not resolved: float stops at 1e-3).
  const S sing = atan2(S(3) / S(10), S(6) / S(10));
  std::string sweep;
  S prev(1000), last(1);  // relative products are ≤ 1
  bool monotone = true;
  for (const int e : {1, 3, 5, 7}) {
    const S d = tenTo<S>(-e);
    if (d < S(1000) * Tolerance<S>::epsilon()) break;
    auto g2 = rng(95);
    const PumaLikeArm<S> a = puma<S>(g2, S(sing + d));
    const auto z = pumaLikeReciprocalLines(a);
    S smallest(1000);
    for (int i = 0; i < 6; ++i)
      smallest = min(smallest, S(abs(reciprocalProduct(z[i], Vec6<S>(a.jacobian().col(i)))) / (z[i].norm() * a.jacobian().col(i).norm())));
    sweep += num(d) + ": " + num(smallest) + "; ";
    monotone = monotone && smallest < prev;
    prev = smallest;
    last = d;
  }
  c.record("elbow singularity: min |z_iᵀQ₀s_i| (relative) falls with the offset δ, to < 10δ at the last", "decreasing to 0", sweep, 0, 0,
           monotone && prev < S(10) * last);
  auto g3 = rng(95);
  const PumaLikeArm<S> atSing = puma<S>(g3, sing);
  bool threw = false;
  try {
    inverseJacobianFromReciprocals(atSing.jacobian(), pumaLikeReciprocalLines(atSing));
  } catch (const InvalidInput&) { threw = true; }
  c.checkEqual("at the elbow singularity: InvalidInput", 1, threw ? 1 : 0);
}

// GF §6.8, GF-6.8-grassmannian-embedding
template <class S> void grassmannEmbedding(Context& c) {
  using MatXS = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
  using VecXS = Eigen::Matrix<S, Eigen::Dynamic, 1>;
  auto g = rng(96);
  S rel(0), minRandom(1000), klein(0);  // 1000: above any relation of entries in [−1, 1]
  for (int k = 0; k < 100; ++k) {
    for (const int m : {4, 5, 6}) {
      MatXS b(m, 2);
      for (int i = 0; i < m; ++i) {
        const S x0 = uni<S>(g), x1 = uni<S>(g);
        b.row(i) << x0, x1;
      }
      const VecXS p = pluckerEmbedding<S>(b);
      rel = max(rel, S(pluckerRelationsG2<S>(p, m).cwiseAbs().maxCoeff()));
      VecXS q(p.size());
      for (int i = 0; i < q.size(); ++i) q(i) = uni<S>(g);
      minRandom = min(minRandom, S(pluckerRelationsG2<S>(q, m).cwiseAbs().maxCoeff()));
      if (m == 4) {
        // Klein relation = Pfaffian p01p23 − p02p13 + p03p12 = ω·v in 6-vector form.
        const Vec6<S> s = six(Vec3<S>(p(0), p(1), p(2)), Vec3<S>(p(5), -p(4), p(3)));
        klein = max(klein, S(abs(S(kleinValue(s) - pluckerRelationsG2<S>(p, 4)(0)))));
      }
    }
  }
  c.checkResidual("G(2,4), G(2,5), G(2,6): relations vanish on x ∧ y (100 each)", rel, tolId<S>(64));
  c.recordIn("a random vector violates them (smallest max-violation of 300)", "> 1e-6", io::numberText(minRandom), minRandom,
             tenTo<S>(-6), minRandom > tenTo<S>(-6));
  c.checkResidual("the G(2,4) relation is the Klein quadric ω·v (p31 = −p13)", klein, tolId<S>(64));
  c.checkEqual("number of relations for G(2,5)", 5, pluckerRelationsG2<S>(VecXS::Zero(10), 5).size());
  c.checkEqual("number of relations for G(2,6) (used in ch. 8)", 15, pluckerRelationsG2<S>(VecXS::Zero(15), 6).size());
  c.checkEqual("coordinates of G(3,6): C(6,3)", 20, static_cast<long long>(pluckerIndexSets(3, 6).size()));
  // x ∧ y of the book's (x0..x3): same as PluckerLine::throughHomogeneousPoints.
  const S ten(10);
  const Vec4<S> x(S(1), S(2) / ten, S(-4) / ten, S(7) / ten), y(S(5) / ten, S(11) / ten, S(3) / ten, S(-2) / ten);
  MatXS b(4, 2);
  b.col(0) = x;
  b.col(1) = y;
  const VecXS p = pluckerEmbedding<S>(b);
  const Vec6<S> s = six(Vec3<S>(p(0), p(1), p(2)), Vec3<S>(p(5), -p(4), p(3)));
  c.checkResidual("x ∧ y = (x₀y₁ − x₁y₀, …; x₂y₃ − x₃y₂, …) = PluckerLine::throughHomogeneousPoints",
                  S((s - Ln<S>::throughHomogeneousPoints(x, y).coords()).norm()), tolId<S>());
}

// GF §6.8, GF-6.8-grassmannian-homogeneous (E6.7): integer dimension counts, no scalar arithmetic.
template <class S> void grassmannHomogeneous(Context& c) {
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

SOMA_STUDY_SCALAR("GF-6.6-linear-complex", "Linear line complexes: b·ω + α·v = 0, pitch, singular and infinite-pitch complexes", "GF §6.6", linearComplex);
SOMA_STUDY_SCALAR("GF-6.6-complex-4x4", "The complex as a 4×4 antisymmetric form and its null polarity (E6.5, E6.6)", "GF §6.6", complex4x4);
SOMA_STUDY_SCALAR("GF-6.6-complex-symmetries", "Rigid symmetries and axis of a linear complex (E6.1)", "GF §6.6", complexSymmetries);
SOMA_STUDY_SCALAR("GF-6.7-inverse-jacobian-6R", "Inverse Jacobian of a PUMA-like arm by reciprocal lines", "GF §6.7", inverseJacobian);
SOMA_STUDY_SCALAR("GF-6.8-grassmannian-embedding", "Plücker embedding of Grassmannians and the Plücker relations", "GF §6.8", grassmannEmbedding);
SOMA_STUDY_SCALAR("GF-6.8-grassmannian-homogeneous", "Grassmannians as homogeneous spaces: dimension n(m − n) (E6.7)", "GF §6.8", grassmannHomogeneous);

}  // namespace
}  // namespace soma::studies::gf06::SOMA_UNITY_ID
