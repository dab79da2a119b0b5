// Studies of GF chapter 2 — Lie groups, §2.1 (definitions and first examples).
// Other sections: gf02/matrix_groups.cpp (§2.2–2.3), gf02/euclidean.cpp (§2.4–2.5).
#include "soma/algebra/quaternion.hpp"
#include "soma/algebra/se2.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/studies/study.hpp"

#include "soma/studies/gf02_gf03_support.hpp"

#include <functional>
#include <string>
#include <vector>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using namespace gf23;
const char* const kChapter = "GF 2 — Lie groups";

// ---- GF-2.1-group-axioms ----------------------------------------------------------------------
/// Records three checks (identity, inverses, associativity) for a group given by its product,
/// inverse, identity and a distance, over consecutive triples of the sample `xs`.
template <class S, class G>
void checkAxioms(Context& c, const std::string& group, const std::vector<G>& xs, const G& e,
                 const std::function<G(const G&, const G&)>& mul,
                 const std::function<G(const G&)>& inv,
                 const std::function<S(const G&, const G&)>& dist, const S& tol) {
  S eId(0), eInv(0), eAss(0);
  for (std::size_t i = 0; i + 2 < xs.size(); ++i) {
    const G &a = xs[i], &b = xs[i + 1], &d = xs[i + 2];
    for (const S err : {dist(mul(e, a), a), dist(mul(a, e), a)})
      if (err > eId) eId = err;
    for (const S err : {dist(mul(inv(a), a), e), dist(mul(a, inv(a)), e)})
      if (err > eInv) eInv = err;
    const S err = dist(mul(a, mul(b, d)), mul(mul(a, b), d));
    if (err > eAss) eAss = err;
  }
  const std::string n = " (" + std::to_string(xs.size()) + " random elements)";
  c.checkResidual(group + ": eg = ge = g" + n, eId, tol);
  c.checkResidual(group + ": g⁻¹g = gg⁻¹ = e" + n, eInv, tol);
  c.checkResidual(group + ": g1(g2g3) = (g1g2)g3" + n, eAss, tol);
}

// GF §2.1, GF-2.1-group-axioms: eg = ge = g, g⁻¹g = gg⁻¹ = e, g1(g2g3) = (g1g2)g3 for every
// group type of chapter 2, on random elements, near the cut locus and at mixed scales.
template <class S> void groupAxioms(Context& c) {
  using std::abs;
  auto g = rng(2101);
  const int n = std::is_same_v<S, mpreal> ? 12 : 40;
  const S tol = Tolerance<S>::identity(64);

  {  // R³ under addition
    std::vector<Vec3<S>> xs;
    for (int i = 0; i < n; ++i) xs.push_back(uniVec3<S>(g));
    checkAxioms<S, Vec3<S>>(
        c, "R³", xs, Vec3<S>::Zero(), [](const Vec3<S>& a, const Vec3<S>& b) { return Vec3<S>(a + b); },
        [](const Vec3<S>& a) { return Vec3<S>(-a); },
        [](const Vec3<S>& a, const Vec3<S>& b) { return maxAbs(a - b); }, tol);
  }
  {  // U(1), unit complex numbers
    std::vector<Cx<S>> xs;
    for (int i = 0; i < n; ++i) xs.push_back(cexpi<S>(uni<S>(g, 0, 2 * std::numbers::pi)));
    checkAxioms<S, Cx<S>>(
        c, "U(1)", xs, Cx<S>(S(1)), [](const Cx<S>& a, const Cx<S>& b) { return a * b; },
        [](const Cx<S>& a) { return a.conj(); },
        [](const Cx<S>& a, const Cx<S>& b) { return cabs(a - b); }, tol);
  }
  {  // unit quaternions (book's product formula), S³
    std::vector<Quat<S>> xs;
    for (int i = 0; i < n; ++i) xs.push_back(SO3<S>::Random(g).quaternion());
    checkAxioms<S, Quat<S>>(
        c, "unit quaternions", xs, Quat<S>(S(1), S(0), S(0), S(0)),
        [](const Quat<S>& a, const Quat<S>& b) { return quaternionProduct(a, b); },
        [](const Quat<S>& a) { return a.conjugate(); },
        [](const Quat<S>& a, const Quat<S>& b) { return maxAbs(a.coeffs() - b.coeffs()); }, tol);
  }
  const auto so3dist = [](const SO3<S>& a, const SO3<S>& b) { return maxAbs(a.matrix() - b.matrix()); };
  {  // SO(3) random, then near the cut locus (angle π − δ)
    std::vector<SO3<S>> xs;
    for (int i = 0; i < n; ++i) xs.push_back(SO3<S>::Random(g));
    checkAxioms<S, SO3<S>>(c, "SO(3)", xs, SO3<S>(),
                           [](const SO3<S>& a, const SO3<S>& b) { return a * b; },
                           [](const SO3<S>& a) { return a.inverse(); }, so3dist, tol);
    xs.clear();
    const S delta = Tolerance<S>::sqrtEpsilon();
    for (int i = 0; i < n; ++i) {
      Vec3<S> ax = uniVec3<S>(g);
      using std::sqrt;
      ax /= sqrt(ax.squaredNorm());
      xs.push_back(SO3<S>::fromAxisAngle(ax, pi<S>() - delta));
    }
    checkAxioms<S, SO3<S>>(c, "SO(3) near the cut locus, angle π − √ε", xs, SO3<S>(),
                           [](const SO3<S>& a, const SO3<S>& b) { return a * b; },
                           [](const SO3<S>& a) { return a.inverse(); }, so3dist, tol);
  }
  {  // SE(3): unit-scale, then translations 1e6 mixed with 1e-9 (error relative to 1e6)
    std::vector<SE3<S>> xs;
    for (int i = 0; i < n; ++i) xs.push_back(SE3<S>::Random(g));
    const auto se3dist = [](const SE3<S>& a, const SE3<S>& b) { return maxAbs(a.matrix() - b.matrix()); };
    checkAxioms<S, SE3<S>>(c, "SE(3)", xs, SE3<S>(),
                           [](const SE3<S>& a, const SE3<S>& b) { return a * b; },
                           [](const SE3<S>& a) { return a.inverse(); }, se3dist, tol);
    xs.clear();
    const S big(1000000), tiny = S(1) / S(1000000000);
    for (int i = 0; i < n; ++i) {
      const SE3<S> x = SE3<S>::Random(g);
      xs.emplace_back(x.so3(), Vec3<S>(x.translation() * (i % 2 ? big : tiny)));
    }
    checkAxioms<S, SE3<S>>(c, "SE(3), |t| ~ 1e6 mixed with 1e-9 (tolerance × 1e6)", xs, SE3<S>(),
                           [](const SE3<S>& a, const SE3<S>& b) { return a * b; },
                           [](const SE3<S>& a) { return a.inverse(); }, se3dist, tol * big);
  }
  {  // SE(2)
    std::vector<SE2<S>> xs;
    for (int i = 0; i < n; ++i) xs.push_back(SE2<S>::Random(g));
    checkAxioms<S, SE2<S>>(
        c, "SE(2)", xs, SE2<S>(), [](const SE2<S>& a, const SE2<S>& b) { return a * b; },
        [](const SE2<S>& a) { return a.inverse(); },
        [](const SE2<S>& a, const SE2<S>& b) { return maxAbs(a.matrix() - b.matrix()); }, tol);
  }
  {  // SU(2) as complex 2×2 matrices
    std::vector<CMat<S>> xs;
    for (int i = 0; i < n; ++i) {
      const Quat<S> q = SO3<S>::Random(g).quaternion();
      xs.push_back(su2<S>(q.w(), q.x(), q.y(), q.z()));
    }
    checkAxioms<S, CMat<S>>(
        c, "SU(2)", xs, CMat<S>::identity(2), [](const CMat<S>& a, const CMat<S>& b) { return a * b; },
        [](const CMat<S>& a) { return a.adjoint(); },
        [](const CMat<S>& a, const CMat<S>& b) { return (a - b).maxAbs(); }, tol);
  }
  c.note("Distances: max-abs difference of the matrix representations (quaternion components "
         "for S³). Differentiability of mult and inv is the subject of the ch. 4 Jacobian studies.");
}

SOMA_STUDY({.id = "GF-2.1-group-axioms",
            .title = "Group axioms for R³, U(1), S³, SO(3), SE(3), SE(2), SU(2)",
            .source = "GF §2.1",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { groupAxioms<S>(c); }); }});

// ---- GF-2.1-Rn-additive -----------------------------------------------------------------------
// GF §2.1, GF-2.1-Rn-additive: e = 0, mult(u, v) = u + v, inv(u) = −u, commutative.
template <class S> void rnAdditive(Context& c) {
  using std::abs;
  auto g = rng(2102);
  constexpr int n = 6;
  using V = Eigen::Matrix<S, n, 1>;
  S eId(0), eInv(0), eCom(0), eAssRel(0);
  for (int k = 0; k < 200; ++k) {
    V u, v, w;
    for (int i = 0; i < n; ++i) {
      // mixed magnitudes 1e±12: addition is then not exactly associative
      const S su = (k + i) % 3 == 0 ? S(1000000000000.0) : (k + i) % 3 == 1 ? S(1) : S(1) / S(1000000000000.0);
      u(i) = uni<S>(g) * su;
      v(i) = uni<S>(g) / su;
      w(i) = uni<S>(g);
    }
    eId = std::max(eId, maxAbs(V(u + V::Zero()) - u));
    eInv = std::max(eInv, maxAbs(V(u + V(-u))));
    eCom = std::max(eCom, maxAbs(V(u + v) - V(v + u)));
    for (int i = 0; i < n; ++i) {
      const S d = abs((u(i) + v(i)) + w(i) - (u(i) + (v(i) + w(i))));
      const S scale = abs(u(i)) + abs(v(i)) + abs(w(i));
      eAssRel = std::max(eAssRel, d / scale);
    }
  }
  c.checkResidual("u + 0 = u (exact)", eId, S(0));
  c.checkResidual("u + (−u) = 0 (exact)", eInv, S(0));
  c.checkResidual("u + v = v + u (exact: IEEE addition commutes)", eCom, S(0));
  c.checkResidual("(u+v)+w = u+(v+w) relative to |u|+|v|+|w|, 1e±12 mixed (≤ 2ε)", eAssRel,
                  S(2) * Tolerance<S>::epsilon());
  // The classic witness that floating-point addition is not associative.
  const S a = S(1) / S(10), b = S(2) / S(10), d = S(3) / S(10);
  const S defect = abs((a + b) + d - (a + (b + d)));
  c.checkResidual("(0.1+0.2)+0.3 − (0.1+(0.2+0.3)) ≤ 2ε·0.6", defect,
                  S(2) * Tolerance<S>::epsilon() * (a + b + d));
  c.note("In " + std::string(scalarName<S>()) + " (0.1+0.2)+0.3 − (0.1+(0.2+0.3)) = " + toString(defect, 3) +
         ": the group law holds exactly in R but only to rounding in floating point.");
}

SOMA_STUDY({.id = "GF-2.1-Rn-additive",
            .title = "Rⁿ as an additive group: identity, inverse, commutativity, associativity",
            .source = "GF §2.1",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { rnAdditive<S>(c); }); }});

// ---- GF-2.1-U1-unit-complex -------------------------------------------------------------------
// GF §2.1, GF-2.1-U1-unit-complex: z1 z2 = cos(θ1+θ2) + i sin(θ1+θ2); z̄ is the inverse.
template <class S> void u1UnitComplex(Context& c) {
  using std::cos;
  using std::sin;
  using std::abs;
  const S t1 = S(7) / S(10), t2 = S(23) / S(10);  // θ1 + θ2 = 3 < π
  const S re = cos(t1) * cos(t2) - sin(t1) * sin(t2);
  const S im = cos(t1) * sin(t2) + sin(t1) * cos(t2);
  const S tol = Tolerance<S>::identity(8);
  c.checkNear("Re(z1 z2) = cos(θ1+θ2), θ1 = 0.7, θ2 = 2.3", cos(t1 + t2), re, tol);
  c.checkNear("Im(z1 z2) = sin(θ1+θ2)", sin(t1 + t2), im, tol);
  // Wrap-around: θ and θ + 2π are the same element.
  const S t3 = S(1) / S(1000);
  c.checkNear("cos(θ + 2π) = cos θ at θ = 1e-3", cos(t3), cos(t3 + 2 * pi<S>()), S(16) * Tolerance<S>::epsilon() * 2 * pi<S>());
  // Inverse is the conjugate: z z̄ = 1.
  c.checkNear("z z̄ = 1", S(1), cos(t1) * cos(t1) + sin(t1) * sin(t1), tol);
  // Near 2π from below times a small angle lands just above 0: z(2π − 1e-3) z(2e-3) = z(1e-3).
  const Cx<S> w = cexpi<S>(2 * pi<S>() - t3) * cexpi<S>(2 * t3);
  c.checkResidual("z(2π − 1e-3)·z(2e-3) = z(1e-3)", cabs(w - cexpi<S>(t3)), S(16) * Tolerance<S>::epsilon() * 2 * pi<S>());
  // Renormalisation drift of repeated products: |z^N| − 1 and the angle of z^N against Nθ.
  const int N = std::is_same_v<S, mpreal> ? 20000 : 1000000;
  const S th = S(1) / S(7);
  const Cx<S> z1 = cexpi<S>(th);
  Cx<S> zn(S(1));
  for (int k = 0; k < N; ++k) zn = zn * z1;
  using std::sqrt;
  const S drift = abs(sqrt(zn.abs2()) - S(1));
  c.checkResidual("||z^N| − 1| after N = " + std::to_string(N) + " products ≤ 2Nε", drift,
                  S(2) * S(N) * Tolerance<S>::epsilon());
  const S angErr = cabs(zn - cexpi<S>(S(N) * th));
  c.checkResidual("|z^N − e^{iNθ}| ≤ 4Nε (error grows linearly, no renormalisation)", angErr,
                  S(4) * S(N) * Tolerance<S>::epsilon());
  c.note("After " + std::to_string(N) + " products the modulus drifted by " + toString(drift, 3) +
         " and the element by " + toString(angErr, 3) + " (no renormalisation).");
}

SOMA_STUDY({.id = "GF-2.1-U1-unit-complex",
            .title = "Unit complex numbers U(1): angle addition, inverse, wrap-around, drift",
            .source = "GF §2.1",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { u1UnitComplex<S>(c); }); }});

// ---- GF-2.1-quaternion-product ----------------------------------------------------------------
// GF §2.1, GF-2.1-quaternion-product: the book's product formula, i² = j² = k² = ijk = −1,
// q*q = a² + b² + c² + d², |q1 q2| = |q1||q2|; unit quaternions form a group with inverse q*.
template <class S> void quaternionProductStudy(Context& c) {
  using std::abs;
  const Quat<S> one(S(1), S(0), S(0), S(0)), i(S(0), S(1), S(0), S(0)), j(S(0), S(0), S(1), S(0)),
      k(S(0), S(0), S(0), S(1));
  const auto P = [](const Quat<S>& a, const Quat<S>& b) { return quaternionProduct(a, b); };
  const auto d = [](const Quat<S>& a, const Quat<S>& b) { return maxAbs(a.coeffs() - b.coeffs()); };
  const Quat<S> mone(S(-1), S(0), S(0), S(0));
  S unitErr(0);
  for (const S e : {d(P(i, i), mone), d(P(j, j), mone), d(P(k, k), mone), d(P(P(i, j), k), mone),
                    d(P(i, j), k), d(P(j, k), i), d(P(k, i), j), d(P(j, i), Quat<S>(-k.coeffs()))})
    unitErr = std::max(unitErr, e);
  c.checkResidual("i² = j² = k² = ijk = −1, ij = k, jk = i, ki = j, ji = −k (exact)", unitErr, S(0));

  auto g = rng(2103);
  const int n = std::is_same_v<S, mpreal> ? 50 : 500;
  S eEigen(0), eConj(0), eNorm(0), eSign(0), eInv(0);
  for (int t = 0; t < n; ++t) {
    // non-unit quaternions with norms between 0.1 and 10
    Quat<S> a(uni<S>(g), uni<S>(g), uni<S>(g), uni<S>(g)), b(uni<S>(g), uni<S>(g), uni<S>(g), uni<S>(g));
    a.coeffs() *= uni<S>(g, 0.1, 10);
    const S na2 = a.coeffs().squaredNorm(), nb2 = b.coeffs().squaredNorm();
    const S scale = S(1) + na2 + nb2;
    // independent implementation: Eigen's Quaternion::operator*
    eEigen = std::max(eEigen, d(P(a, b), Quat<S>(a * b)) / scale);
    const Quat<S> qq = P(a.conjugate(), a);
    eConj = std::max(eConj, (abs(qq.w() - na2) + maxAbs(qq.vec())) / (S(1) + na2));
    eNorm = std::max(eNorm, abs(P(a, b).coeffs().squaredNorm() - na2 * nb2) / (S(1) + na2 * nb2));
    eSign = std::max(eSign, d(P(Quat<S>(-a.coeffs()), b), Quat<S>(-P(a, b).coeffs())));
    const Quat<S> u = SO3<S>::Random(g).quaternion();
    eInv = std::max(eInv, std::max(d(P(u, u.conjugate()), one), d(P(u.conjugate(), u), one)));
  }
  const S tol = Tolerance<S>::identity(64);
  c.checkResidual("book product = Eigen's Quaternion product (relative)", eEigen, tol);
  c.checkResidual("q*q = a² + b² + c² + d² (vector part 0)", eConj, tol);
  c.checkResidual("|q1 q2|² = |q1|²|q2|² (relative)", eNorm, tol);
  c.checkResidual("(−q1) q2 = −(q1 q2) (exact)", eSign, S(0));
  c.checkResidual("unit q: q q* = q* q = 1", eInv, tol);
  // non-commutativity measured
  const Quat<S> a(S(1), S(2), S(3), S(4)), b(S(-2), S(1), S(5), S(-3));
  const S nonComm = d(P(a, b), P(b, a));  // = 2·max|a⃗ × b⃗| = 58 exactly for these integers
  c.recordIn("q1 q2 ≠ q2 q1 (non-commutative): |q1q2 − q2q1| > 1", "> 1", io::numberText(nonComm), nonComm, S(1),
             nonComm > S(1));
  // Renormalisation drift over many products of unit quaternions.
  const int N = std::is_same_v<S, mpreal> ? 5000 : 100000;
  Quat<S> acc = one;
  const Quat<S> step = SO3<S>::Random(g).quaternion();
  for (int t = 0; t < N; ++t) acc = P(acc, step);
  using std::sqrt;
  const S drift = abs(sqrt(acc.coeffs().squaredNorm()) - S(1));
  c.checkResidual("||q^N| − 1| after N = " + std::to_string(N) + " products ≤ 4Nε", drift,
                  S(4) * S(N) * Tolerance<S>::epsilon());
  c.note("Norm drift after " + std::to_string(N) + " unit-quaternion products: " + toString(drift, 3) + ".");
}

SOMA_STUDY({.id = "GF-2.1-quaternion-product",
            .title = "Quaternion product formula, conjugate, norm; unit quaternions as a group",
            .source = "GF §2.1",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { quaternionProductStudy<S>(c); }); }});

// ---- GF-2.1-GL-SL-dimensions ------------------------------------------------------------------
/// Dimension of a matrix group at I: n² minus the rank of the linearised constraint map,
/// built column by column from F(I + E_ij) − F(I − E_ij) (exact for quadratic F).
template <class S>
int groupDimension(int n, const std::function<MatX<S>(const MatX<S>&)>& constraint) {
  const MatX<S> I = MatX<S>::Identity(n, n);
  const MatX<S> f0 = constraint(I);
  MatX<S> jac(f0.size(), n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      MatX<S> e = MatX<S>::Zero(n, n);
      e(i, j) = S(1);
      const MatX<S> df = (constraint(I + e) - constraint(I - e)) / S(2);
      jac.col(i * n + j) = Eigen::Map<const VecX<S>>(df.data(), df.size());
    }
  return n * n - numericalRank<S>(jac);
}

// GF §2.1, GF-2.1-GL-SL-dimensions: det(AB) = det A det B; dim GL(n) = n², dim SL(n) = n² − 1;
// SL(2) is the quadric a11a22 − a12a21 = 1.
template <class S> void glSlDimensions(Context& c) {
  using std::abs;
  using std::pow;
  auto g = rng(2104);
  S eDet(0);
  for (int n = 2; n <= 5; ++n)
    for (int t = 0; t < 20; ++t) {
      const MatX<S> a = uniMat<S>(g, n, n), b = uniMat<S>(g, n, n);
      const S da = a.determinant(), db = b.determinant();
      eDet = std::max(eDet, abs((a * b).determinant() - da * db) / (S(1) + abs(da * db)));
    }
  c.checkResidual("det(AB) = det A det B, random n = 2..5 (relative)", eDet, Tolerance<S>::identity(256));

  // Gradient of det at a random A ∈ SL(n): det is affine in each entry, so
  // det(A + E_ij) − det(A) is the exact cofactor; compare with Jacobi's det(A)·A^{-T}.
  S eGrad(0);
  for (int n = 2; n <= 4; ++n) {
    MatX<S> a = uniMat<S>(g, n, n) + MatX<S>::Identity(n, n) * S(2);
    const S da = a.determinant();
    a.row(0) /= da;  // now det A = 1: a point of SL(n)
    MatX<S> grad(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        MatX<S> ae = a;
        ae(i, j) += S(1);
        grad(i, j) = ae.determinant() - a.determinant();
      }
    const MatX<S> jacobi = a.determinant() * MatX<S>(a.inverse().transpose());
    eGrad = std::max(eGrad, maxAbs(MatX<S>(grad - jacobi)) / (S(1) + maxAbs(jacobi)));
    const MatX<S> row = Eigen::Map<const MatX<S>>(grad.data(), 1, n * n);
    c.checkEqual("dim SL(" + std::to_string(n) + ") = n² − rank d(det) at a random A ∈ SL(n) = " +
                     std::to_string(n * n - 1),
                 n * n - 1, n * n - numericalRank<S>(row));
  }
  c.checkResidual("d(det) at A ∈ SL(n): finite cofactor = det(A)·A^{-T} (Jacobi)", eGrad,
                  Tolerance<S>::identity(1024));

  // Dimensions from the linearised defining equations at I.
  for (int n = 2; n <= 4; ++n) {
    c.checkEqual("dim GL(" + std::to_string(n) + ") = n² (open set, no constraint)", n * n,
                 groupDimension<S>(n, [](const MatX<S>&) { return MatX<S>(MatX<S>::Zero(1, 1)); }));
    c.checkEqual("dim SL(" + std::to_string(n) + ") = n² − 1 (det A = 1)", n * n - 1,
                 groupDimension<S>(n, [](const MatX<S>& m) {
                   MatX<S> r(1, 1);
                   r(0, 0) = m.determinant() - S(1);
                   return r;
                 }));
    c.checkEqual("dim O(" + std::to_string(n) + ") = n(n−1)/2 (MᵀM = I; cf. GF-4.1)", n * (n - 1) / 2,
                 groupDimension<S>(n, [](const MatX<S>& m) {
                   return MatX<S>(m.transpose() * m - MatX<S>::Identity(m.rows(), m.cols()));
                 }));
  }
  // SL(2) is the quadric a11 a22 − a12 a21 = 1.
  S eQuad(0);
  for (int t = 0; t < 50; ++t) {
    Mat2<S> a;
    a << uni<S>(g), uni<S>(g), uni<S>(g), uni<S>(g);
    S da = a.determinant();
    if (da < S(0)) a.row(0) = -a.row(0), da = -da;
    a /= pow(da, S(1) / S(2));
    eQuad = std::max(eQuad, abs(a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0) - S(1)));
  }
  c.checkResidual("A/√det A ∈ SL(2) lies on a11a22 − a12a21 = 1", eQuad, Tolerance<S>::identity(64));
  // Extreme: the projection A/det(A)^{1/n} cannot reach SL(n) for det A < 0 and n even:
  // det(λA) = λⁿ det A < 0 for every real λ.
  Mat2<S> r;
  r << S(1), S(0), S(0), S(-2);
  const Mat2<S> rs = r / pow(abs(r.determinant()), S(1) / S(2));
  c.checkNear("det A < 0, n = 2: det(A/|det A|^{1/2}) = −1 (no real scaling reaches SL(2))", S(-1),
              rs.determinant(), Tolerance<S>::identity(8));
}

SOMA_STUDY({.id = "GF-2.1-GL-SL-dimensions",
            .title = "GL(n), SL(n): determinant multiplicative, dimensions n² and n² − 1",
            .source = "GF §2.1",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { glSlDimensions<S>(c); }); }});

}  // namespace
}  // namespace soma::studies::SOMA_UNITY_ID
