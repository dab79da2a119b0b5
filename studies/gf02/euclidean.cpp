// Studies of GF chapter 2 — Lie groups, §2.4 (actions and products) and §2.5 (the proper
// Euclidean group: isometries, homogeneous matrices, Chasles, coordinate frames).
#include "soma/algebra/se2.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/screw.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/studies/study.hpp"

#include "soma/studies/gf02_gf03_support.hpp"

#include <string>
#include <vector>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using namespace gf23;
const char* const kChapter = "GF 2 — Lie groups";

/// Plücker coordinates (ω, v = q × ω) of the line through q with direction ω, moved by g:
/// (Rω, Rv + t × Rω) — the adjoint action on lines (GF ch. 6).
template <class S> Vec6<S> moveLine(const SE3<S>& g, const Vec6<S>& l) { return g.adjoint() * l; }

// ---- GF-2.4-direct-product-and-actions --------------------------------------------------------
// GF §2.4, GF-2.4-direct-product-and-actions: (g1,h1)(g2,h2) = (g1g2, h1h2); actions satisfy
// (A1) a(e, x) = x, (A2) a(g1, a(g2, x)) = a(g1g2, x); representations also (A3).
template <class S> void actions(Context& c) {
  using std::abs;
  using std::sqrt;
  auto g = rng(2401);
  const S tol = Tolerance<S>::identity(64);
  const int n = std::is_same_v<S, mpreal> ? 20 : 100;
  // Direct product SO(2) × R realised as cylindric motions about x: the pair product equals
  // the product of the 4×4 matrices (the factors commute).
  S eDirect(0);
  for (int t = 0; t < n; ++t) {
    const S a1 = uni<S>(g, -3, 3), a2 = uni<S>(g, -3, 3), x1 = uni<S>(g), x2 = uni<S>(g);
    const auto cyl = [](const S& a, const S& x) { return hom<S>(rotX<S>(a), Vec3<S>(x, S(0), S(0))); };
    eDirect = std::max(eDirect, maxAbs(Mat4<S>(cyl(a1, x1) * cyl(a2, x2) - cyl(a1 + a2, x1 + x2))));
  }
  c.checkResidual("direct product SO(2) × R: (θ1,x1)(θ2,x2) = (θ1+θ2, x1+x2) as cylindric 4×4 motions", eDirect, tol);

  S a1Rot(0), a2Rot(0), a3Rot(0), a1Pt(0), a2Pt(0), a2Far(0), a2Line(0), lineConsist(0), a3Ad(0), a2Ad(0);
  S a2Left(0), a2Right(0), a2RightNoInv(S(1e30));
  for (int t = 0; t < n; ++t) {
    const SO3<S> r1 = SO3<S>::Random(g), r2 = SO3<S>::Random(g);
    const Vec3<S> p = uniVec3<S>(g), q = uniVec3<S>(g);
    a1Rot = std::max(a1Rot, maxAbs(Vec3<S>(SO3<S>().act(p) - p)));
    a2Rot = std::max(a2Rot, maxAbs(Vec3<S>(r1.act(r2.act(p)) - (r1 * r2).act(p))));
    a3Rot = std::max(a3Rot, maxAbs(Vec3<S>(r1.act(Vec3<S>(p + q)) - r1.act(p) - r1.act(q))));
    const SE3<S> g1 = SE3<S>::Random(g), g2 = SE3<S>::Random(g), x = SE3<S>::Random(g);
    a1Pt = std::max(a1Pt, maxAbs(Vec3<S>(SE3<S>().act(p) - p)));
    a2Pt = std::max(a2Pt, maxAbs(Vec3<S>(g1.act(g2.act(p)) - (g1 * g2).act(p))));
    const Vec3<S> far = p * S(1000000);
    a2Far = std::max(a2Far, maxAbs(Vec3<S>(g1.act(g2.act(far)) - (g1 * g2).act(far))) / S(1000000));
    // lines through q with direction ω
    Vec3<S> w = uniVec3<S>(g);
    w /= sqrt(w.squaredNorm());
    Vec6<S> line;
    line << w, q.cross(w);
    a2Line = std::max(a2Line, maxAbs(Vec6<S>(moveLine(g1, moveLine(g2, line)) - moveLine(SE3<S>(g1 * g2), line))));
    const Vec6<S> moved = moveLine(g1, line);
    const Vec3<S> wq = g1.so3().act(w);
    lineConsist = std::max(lineConsist, maxAbs(Vec6<S>(moved - (Vec6<S>() << wq, g1.act(q).cross(wq)).finished())));
    // Ad on se(3): a representation (A2, A3)
    const Vec6<S> s1 = (Vec6<S>() << uniVec3<S>(g), uniVec3<S>(g)).finished();
    const Vec6<S> s2 = (Vec6<S>() << uniVec3<S>(g), uniVec3<S>(g)).finished();
    a2Ad = std::max(a2Ad, maxAbs(Mat6<S>(g1.adjoint() * g2.adjoint() - (g1 * g2).adjoint())));
    a3Ad = std::max(a3Ad, maxAbs(Vec6<S>(g1.adjoint() * Vec6<S>(s1 + s2) - g1.adjoint() * s1 - g1.adjoint() * s2)));
    // the group acting on itself
    const auto d = [](const SE3<S>& a, const SE3<S>& b) { return maxAbs(Mat4<S>(a.matrix() - b.matrix())); };
    a2Left = std::max(a2Left, d(g1 * (g2 * x), (g1 * g2) * x));
    a2Right = std::max(a2Right, d((x * g2.inverse()) * g1.inverse(), x * (g1 * g2).inverse()));
    a2RightNoInv = std::min(a2RightNoInv, d((x * g2) * g1, x * (g1 * g2)));
  }
  c.checkResidual("SO(3) on R³: (A1) e(p) = p", a1Rot, S(0));
  c.checkResidual("SO(3) on R³: (A2) R1(R2 p) = (R1R2) p", a2Rot, tol);
  c.checkResidual("SO(3) on R³: (A3) R(p + q) = Rp + Rq (a representation)", a3Rot, tol);
  c.checkResidual("SE(3) on points: (A1)", a1Pt, S(0));
  c.checkResidual("SE(3) on points: (A2)", a2Pt, tol);
  c.checkResidual("SE(3) on points 1e6 from the origin: (A2), relative to 1e6", a2Far, tol);
  c.checkResidual("SE(3) on lines (Plücker, v = q × ω): (A2)", a2Line, tol);
  c.checkResidual("the moved line is the line through g(q) with direction Rω", lineConsist, tol);
  c.checkResidual("Ad on se(3): (A2) Ad(g1)Ad(g2) = Ad(g1g2)", a2Ad, tol);
  c.checkResidual("Ad on se(3): (A3) linear (a representation)", a3Ad, tol);
  c.checkResidual("left action l(g1, g) = g1 g: (A2)", a2Left, tol);
  c.checkResidual("right action r(g1, g) = g g1⁻¹: (A2)", a2Right, tol);
  c.recordIn("r(g1, g) = g g1 without the inverse: (A2), smallest violation over the sample (> 1e-3)",
             "fails (the book: the inverse is needed for (A2))", io::numberText(a2RightNoInv), a2RightNoInv,
             S(1) / S(1000), a2RightNoInv > S(1) / S(1000));
}

SOMA_STUDY({.id = "GF-2.4-direct-product-and-actions",
            .title = "Direct products; action axioms (A1)–(A3) on points, lines, se(3), the group",
            .source = "GF §2.4",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { actions<S>(c); }); }});

// ---- GF-2.4-semidirect-product ----------------------------------------------------------------
/// The book's semi-direct product G ⋉ H of a group G acting linearly on a commutative H.
// GF §2.4, GF-2.4-semidirect-product
template <class G, class H, class Act> struct Semidirect {
  G g;
  H h;
  Semidirect operator*(const Semidirect& o) const { return {g * o.g, H(h + Act()(g, o.h))}; }
  Semidirect inverse() const {
    const G gi = g.inverse();
    return {gi, H(-Act()(gi, h))};
  }
};
template <class S> struct RotAct {
  Vec3<S> operator()(const SO3<S>& r, const Vec3<S>& v) const { return r.act(v); }
};
template <class S> struct U1Act {  // U(1) acting on R² = C by multiplication
  Vec2<S> operator()(const Cx<S>& z, const Vec2<S>& v) const {
    return Vec2<S>(z.re * v(0) - z.im * v(1), z.im * v(0) + z.re * v(1));
  }
};
template <class S> struct U1 {
  Cx<S> z;
  U1 operator*(const U1& o) const { return {z * o.z}; }
  U1 inverse() const { return {z.conj()}; }
};
template <class S> struct U1ActW {
  Vec2<S> operator()(const U1<S>& u, const Vec2<S>& v) const { return U1Act<S>()(u.z, v); }
};

// GF §2.4, GF-2.4-semidirect-product: (g1,h1)(g2,h2) = (g1g2, h1 + g1(h2)), identity (e, 0),
// (g,h)⁻¹ = (g⁻¹, −g⁻¹(h)); SO(3) ⋉ R³ is SE(3) and U(1) ⋉ R² is SE(2).
template <class S> void semidirect(Context& c) {
  auto g = rng(2402);
  const S tol = Tolerance<S>::identity(64);
  using SE = Semidirect<SO3<S>, Vec3<S>, RotAct<S>>;
  using SE2s = Semidirect<U1<S>, Vec2<S>, U1ActW<S>>;
  const auto mat = [](const SE& x) { return hom<S>(x.g.matrix(), x.h); };
  const int n = std::is_same_v<S, mpreal> ? 20 : 100;
  S eAss(0), eId(0), eInv(0), eHom(0), eLib(0), eSE2(0);
  const SE e{SO3<S>(), Vec3<S>::Zero()};
  for (int t = 0; t < n; ++t) {
    const SE a{SO3<S>::Random(g), uniVec3<S>(g)}, b{SO3<S>::Random(g), uniVec3<S>(g)},
        d{SO3<S>::Random(g), uniVec3<S>(g)};
    eAss = std::max(eAss, maxAbs(Mat4<S>(mat(a * (b * d)) - mat((a * b) * d))));
    eId = std::max(eId, std::max(maxAbs(Mat4<S>(mat(e * a) - mat(a))), maxAbs(Mat4<S>(mat(a * e) - mat(a)))));
    eInv = std::max(eInv, std::max(maxAbs(Mat4<S>(mat(a * a.inverse()) - Mat4<S>::Identity())),
                                   maxAbs(Mat4<S>(mat(a.inverse() * a) - Mat4<S>::Identity()))));
    eHom = std::max(eHom, maxAbs(Mat4<S>(mat(a * b) - mat(a) * mat(b))));
    eLib = std::max(eLib, maxAbs(Mat4<S>(mat(a * b) - (SE3<S>(a.g, a.h) * SE3<S>(b.g, b.h)).matrix())));
    const S th1 = uni<S>(g, -3, 3), th2 = uni<S>(g, -3, 3);
    const Vec2<S> t1(uni<S>(g), uni<S>(g)), t2(uni<S>(g), uni<S>(g));
    const SE2s p = SE2s{U1<S>{cexpi<S>(th1)}, t1} * SE2s{U1<S>{cexpi<S>(th2)}, t2};
    const SE2<S> q = SE2<S>(th1, t1) * SE2<S>(th2, t2);
    eSE2 = std::max(eSE2, maxAbs(Vec4<S>(Vec4<S>(p.g.z.re, p.g.z.im, p.h(0), p.h(1)) -
                                        Vec4<S>(q.real(), q.imag(), q.translation()(0), q.translation()(1)))));
  }
  c.checkResidual("SO(3) ⋉ R³: associativity", eAss, tol);
  c.checkResidual("SO(3) ⋉ R³: identity (e, 0)", eId, tol);
  c.checkResidual("SO(3) ⋉ R³: (g,h)⁻¹ = (g⁻¹, −g⁻¹(h))", eInv, tol);
  c.checkResidual("SO(3) ⋉ R³ product = product of 4×4 homogeneous matrices", eHom, tol);
  c.checkResidual("SO(3) ⋉ R³ product = library SE3::compose", eLib, tol);
  c.checkResidual("U(1) ⋉ R² product = library SE2 product", eSE2, tol);
  // Extremes: huge h with g near the identity; long products (drift of the G part).
  const SE big{SO3<S>::fromAxisAngle(Vec3<S>(S(0), S(0), S(1)), Tolerance<S>::sqrtEpsilon()),
               Vec3<S>(S(1000000), S(-2000000), S(500000))};
  const SE prod = big * big.inverse();
  c.checkResidual("(g, h)(g, h)⁻¹ = e for |h| ~ 2e6, g near e (relative to |h|)",
                  maxAbs(Mat4<S>(mat(prod) - Mat4<S>::Identity())) / S(2000000), tol);
  const int N = std::is_same_v<S, mpreal> ? 2000 : 100000;
  const SE step{SO3<S>::Random(g), uniVec3<S>(g)};
  SE acc = e;
  for (int t = 0; t < N; ++t) acc = acc * step;
  const Mat3<S> r = acc.g.matrix();
  const S drift = maxAbs(Mat3<S>(r.transpose() * r - Mat3<S>::Identity()));
  c.checkResidual("orthogonality of the G part after " + std::to_string(N) + " products (SO3 renormalises)",
                  drift, tol);
  // and the H part against the closed form: the product of N copies of (R, t) is
  // (R^N, (I + R + … + R^{N−1}) t); compare the sum evaluated by repeated squaring.
  Mat3<S> powR = step.g.matrix(), accR = Mat3<S>::Identity();
  Vec3<S> sumT = Vec3<S>::Zero();
  Mat3<S> geomR = Mat3<S>::Identity();  // I + R + … + R^{2^k − 1}
  for (int bits = N, k = 0; bits; bits >>= 1, ++k) {
    if (bits & 1) {
      sumT += accR * geomR * step.h;
      accR = accR * powR;
    }
    geomR = geomR + powR * geomR;
    powR = powR * powR;
  }
  // each step rounds at the scale of the running |h|, which grows linearly along the axis
  const S hScale = S(1) + maxAbs(acc.h);
  c.checkResidual("H part after " + std::to_string(N) + " products = (I + R + … + R^{N−1}) t (binary powering), ≤ 16Nε·|h|",
                  maxAbs(Vec3<S>(acc.h - sumT)), S(16) * S(N) * Tolerance<S>::epsilon() * hScale);
  c.note("After " + std::to_string(N) + " products |h| = " + toString(maxAbs(acc.h), 3) +
         " and the H part differs from the closed form by " + toString(maxAbs(Vec3<S>(acc.h - sumT)), 3) + ".");
}

SOMA_STUDY({.id = "GF-2.4-semidirect-product",
            .title = "Semi-direct product G ⋉ H: axioms, SO(3) ⋉ R³ = SE(3), U(1) ⋉ R² = SE(2)",
            .source = "GF §2.4",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { semidirect<S>(c); }); }});

// ---- GF-2.4-similarity-congruence -------------------------------------------------------------
// GF §2.4, GF-2.4-similarity-congruence: S(g, M) = gMg⁻¹ and C(g, M) = gMgᵀ are
// representations of GL(n); C preserves symmetry; dim M^S(n) = n(n+1)/2; O(n) is the
// stabiliser of I under congruence.
template <class S> void similarityCongruence(Context& c) {
  using std::abs;
  using std::pow;
  auto g = rng(2403);
  const S tol = Tolerance<S>::identity(256);
  const int n = 4;
  const auto randGL = [&]() { return MatX<S>(uniMat<S>(g, n, n) + MatX<S>::Identity(n, n) * S(2)); };
  S eS1(0), eS2(0), eS3(0), eC1(0), eC2(0), eC3(0), eSym(0);
  const MatX<S> I = MatX<S>::Identity(n, n);
  for (int t = 0; t < 30; ++t) {
    const MatX<S> g1 = randGL(), g2 = randGL(), m1 = uniMat<S>(g, n, n), m2 = uniMat<S>(g, n, n);
    const auto Sim = [](const MatX<S>& a, const MatX<S>& m) { return MatX<S>(a * m * a.inverse()); };
    const auto Con = [](const MatX<S>& a, const MatX<S>& m) { return MatX<S>(a * m * a.transpose()); };
    const S sc = S(1) + maxAbs(MatX<S>(Sim(g1 * g2, m1)));
    eS1 = std::max(eS1, maxAbs(MatX<S>(Sim(I, m1) - m1)));
    eS2 = std::max(eS2, maxAbs(MatX<S>(Sim(g1, Sim(g2, m1)) - Sim(g1 * g2, m1))) / sc);
    eS3 = std::max(eS3, maxAbs(MatX<S>(Sim(g1, MatX<S>(m1 + m2)) - Sim(g1, m1) - Sim(g1, m2))) / sc);
    const MatX<S> s1 = (m1 + m1.transpose()) / S(2), s2 = (m2 + m2.transpose()) / S(2);
    const S cc = S(1) + maxAbs(MatX<S>(Con(g1 * g2, s1)));
    eC1 = std::max(eC1, maxAbs(MatX<S>(Con(I, s1) - s1)));
    eC2 = std::max(eC2, maxAbs(MatX<S>(Con(g1, Con(g2, s1)) - Con(g1 * g2, s1))) / cc);
    eC3 = std::max(eC3, maxAbs(MatX<S>(Con(g1, MatX<S>(s1 + s2)) - Con(g1, s1) - Con(g1, s2))) / cc);
    const MatX<S> cs = Con(g1, s1);
    eSym = std::max(eSym, maxAbs(MatX<S>(cs - cs.transpose())) / cc);
  }
  c.checkResidual("similarity (A1) S(e, M) = M", eS1, S(0));
  c.checkResidual("similarity (A2) S(g1, S(g2, M)) = S(g1g2, M) (relative)", eS2, tol);
  c.checkResidual("similarity (A3) linear in M (relative)", eS3, tol);
  c.checkResidual("congruence (A1) on symmetric M", eC1, S(0));
  c.checkResidual("congruence (A2) (relative)", eC2, tol);
  c.checkResidual("congruence (A3) (relative)", eC3, tol);
  c.checkResidual("congruence keeps M symmetric (relative)", eSym, tol);
  for (int m = 2; m <= 5; ++m) {
    // dim M(n) = n², dim M^S(n) = rank of the symmetriser M ↦ (M + Mᵀ)/2 on the basis M_ij
    MatX<S> sym(m * m, m * m);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        MatX<S> e = MatX<S>::Zero(m, m);
        e(i, j) = S(1);
        const MatX<S> se = (e + e.transpose()) / S(2);
        sym.col(i * m + j) = Eigen::Map<const VecX<S>>(se.data(), m * m);
      }
    c.checkEqual("dim M^S(" + std::to_string(m) + ") = n(n+1)/2", m * (m + 1) / 2, numericalRank<S>(sym));
    // stabiliser of I: kernel of X ↦ X + Xᵀ, dimension n(n−1)/2 = dim O(n)
    c.checkEqual("dim stabiliser of I under congruence (X + Xᵀ = 0) = n(n−1)/2 = dim O(" + std::to_string(m) + ")",
                 m * (m - 1) / 2, m * m - numericalRank<S>(MatX<S>(S(2) * sym)));
  }
  S eStab(0);
  for (int t = 0; t < 20; ++t) {
    const Mat3<S> o = SO3<S>::Random(g).matrix();
    eStab = std::max(eStab, std::max(maxAbs(Mat3<S>(o * o.transpose() - Mat3<S>::Identity())),
                                     maxAbs(Mat3<S>(o.transpose() * o - Mat3<S>::Identity()))));
  }
  c.checkResidual("O(3): g I gᵀ = I and gᵀ I g = I (either definition)", eStab, Tolerance<S>::identity(64));
  const MatX<S> gl = randGL();
  const S glMiss = maxAbs(MatX<S>(gl * gl.transpose() - I));
  c.recordIn("a random GL(4) element does not stabilise I: |g gᵀ − I|", "> 0.1", io::numberText(glMiss), glMiss,
             S(1) / S(10), glMiss > S(1) / S(10));
  // Ill-conditioned g: the similarity (A2) error grows with cond(g)².
  const S kappa = pow(Tolerance<S>::epsilon(), S(-1) / S(4));
  MatX<S> d = MatX<S>::Identity(n, n);
  d(1, 1) = pow(kappa, S(1) / S(2));
  d(3, 3) = kappa;
  MatX<S> u = MatX<S>::Identity(n, n), v = u;
  u.block(0, 0, 3, 3) = SO3<S>::Random(g).matrix();
  v.block(1, 1, 3, 3) = SO3<S>::Random(g).matrix();
  const MatX<S> gi = u * d * v, g2 = randGL(), m = uniMat<S>(g, n, n);
  const MatX<S> ref = gi * g2 * m * MatX<S>(gi * g2).inverse();
  const S err = maxAbs(MatX<S>(gi * MatX<S>(g2 * m * g2.inverse()) * gi.inverse() - ref)) / maxAbs(ref);
  c.checkResidual("similarity (A2) with cond(g) = ε^{-1/4}: relative error ≤ 256ε·cond²", err, tol * kappa * kappa);
  c.note("Ill-conditioned g (cond " + toString(kappa, 3) + "): similarity (A2) relative error " + toString(err, 3) + ".");
}

SOMA_STUDY({.id = "GF-2.4-similarity-congruence",
            .title = "Similarity gMg⁻¹ and congruence gMgᵀ as representations; dim M^S(n)",
            .source = "GF §2.4",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { similarityCongruence<S>(c); }); }});

// ---- GF-2.5.1-euclidean-pairs -----------------------------------------------------------------
// GF §2.5.1, GF-2.5.1-euclidean-pairs: v' = Mv + t preserves |u − v|²;
// (M2, t2)(M1, t1) = (M2M1, M2t1 + t2); SE(n) excludes reflections.
template <class S> void euclideanPairs(Context& c) {
  using std::abs;
  auto g = rng(2501);
  const S tol = Tolerance<S>::identity(64);
  S eDist(0), eRefl(0), eProd(0), eLib(0), eFar(0);
  for (int t = 0; t < 100; ++t) {
    const SE3<S> a = SE3<S>::Random(g), b = SE3<S>::Random(g);
    const Vec3<S> u = uniVec3<S>(g), v = uniVec3<S>(g);
    eDist = std::max(eDist, abs((a.act(u) - a.act(v)).squaredNorm() - (u - v).squaredNorm()));
    // a reflection pair (det M = −1) of E(3) preserves distances too
    Mat3<S> m = a.rotation();
    m.col(0) = -m.col(0);
    const Vec3<S> mu = m * u + a.translation(), mv = m * v + a.translation();
    eRefl = std::max(eRefl, abs((mu - mv).squaredNorm() - (u - v).squaredNorm()));
    // the product formula equals the composition of the point maps
    const Mat3<S> m1 = a.rotation(), m2 = b.rotation();
    const Vec3<S> t1 = a.translation(), t2 = b.translation();
    const Vec3<S> viaPair = (m2 * m1) * u + (m2 * t1 + t2);
    eProd = std::max(eProd, maxAbs(Vec3<S>(viaPair - b.act(a.act(u)))));
    eLib = std::max(eLib, maxAbs(Vec3<S>((b * a).translation() - (m2 * t1 + t2))));
    // 1e8-scale points: relative error of the squared distance
    const Vec3<S> U = u * S(100000000), V = v * S(100000000);
    eFar = std::max(eFar, abs((a.act(U) - a.act(V)).squaredNorm() - (U - V).squaredNorm()) / (U - V).squaredNorm());
  }
  c.checkResidual("|u' − v'|² = |u − v|² (SE(3))", eDist, tol);
  c.checkResidual("|u' − v'|² = |u − v|² for a reflection pair (E(3))", eRefl, tol);
  c.checkResidual("(M2,t2)(M1,t1) = (M2M1, M2t1 + t2) reproduces v ↦ M2(M1v + t1) + t2", eProd, tol);
  c.checkResidual("library compose translation = M2t1 + t2", eLib, tol);
  c.checkResidual("points at 1e8: relative error of |u' − v'|²", eFar, tol);
  // SE(3) rejects a reflection.
  Mat4<S> refl = Mat4<S>::Identity();
  refl(0, 0) = S(-1);
  bool rejected = false;
  try {
    (void)SE3<S>::fromMatrix(refl);
  } catch (const InvalidInput&) {
    rejected = true;
  }
  c.checkEqual("SE3::fromMatrix rejects det M = −1 (reflections are not proper motions)", 1, rejected ? 1 : 0);
}

SOMA_STUDY({.id = "GF-2.5.1-euclidean-pairs",
            .title = "Isometries as pairs (M, t): distance, product formula, E(n) vs SE(n)",
            .source = "GF §2.5.1",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { euclideanPairs<S>(c); }); }});

// ---- GF-2.5.1-homogeneous ---------------------------------------------------------------------
// GF §2.5.1, GF-2.5.1-homogeneous: (R, t) ↦ [[R, t], [0, 1]] is a homomorphism; the inverse is
// [[Rᵀ, −Rᵀt], [0, 1]]; the action on (v, 1) is Rv + t; the plane z = 1 is invariant (SE(2)).
template <class S> void homogeneous(Context& c) {
  using std::abs;
  auto g = rng(2502);
  const S tol = Tolerance<S>::identity(64);
  S eHom(0), eInv(0), eEig(0), eAct(0), ePlane(0), eMetric(0), eRound(0);
  for (int t = 0; t < 100; ++t) {
    const SE3<S> a = SE3<S>::Random(g), b = SE3<S>::Random(g);
    eHom = std::max(eHom, maxAbs(Mat4<S>(a.matrix() * b.matrix() - (a * b).matrix())));
    const Mat3<S> r = a.rotation();
    const Mat4<S> closed = hom<S>(r.transpose(), Vec3<S>(-r.transpose() * a.translation()));
    eInv = std::max(eInv, maxAbs(Mat4<S>(closed - a.inverse().matrix())));
    eEig = std::max(eEig, maxAbs(Mat4<S>(closed - a.matrix().inverse())));  // Eigen's 4×4 inverse
    const Vec3<S> v = uniVec3<S>(g);
    const Vec4<S> vh = (a.matrix() * Vec4<S>(v(0), v(1), v(2), S(1)));
    eAct = std::max(eAct, maxAbs(Vec3<S>(vh.template head<3>() - (r * v + a.translation()))) + abs(vh(3) - S(1)));
    eRound = std::max(eRound, maxAbs(Mat4<S>(SE3<S>::fromMatrix(a.matrix()).matrix() - a.matrix())));
    // SE(2) on the plane z = 1 of R³
    const SE2<S> p = SE2<S>::Random(g);
    const Vec3<S> x(uni<S>(g), uni<S>(g), S(1)), y(uni<S>(g), uni<S>(g), S(1));
    const Vec3<S> px = p.matrix() * x, py = p.matrix() * y;
    ePlane = std::max(ePlane, std::max(abs(px(2) - S(1)), abs(py(2) - S(1))));
    eMetric = std::max(eMetric, abs((px - py).squaredNorm() - (x - y).squaredNorm()));
  }
  c.checkResidual("[[R2,t2],[0,1]][[R1,t1],[0,1]] = [[R2R1, R2t1 + t2],[0,1]] (library compose)", eHom, tol);
  c.checkResidual("closed-form inverse [[Rᵀ, −Rᵀt],[0,1]] = library inverse", eInv, tol);
  c.checkResidual("closed-form inverse = Eigen's numerical 4×4 inverse", eEig, tol);
  c.checkResidual("action on (v, 1) gives (Rv + t, 1)", eAct, tol);
  c.checkResidual("SE3::fromMatrix(X.matrix()) round trip", eRound, tol);
  c.checkResidual("SE(2) 3×3 matrices keep the plane z = 1 (exact)", ePlane, S(0));
  c.checkResidual("and preserve the Euclidean metric on it", eMetric, tol);
  // Extremes: |t| = 1e8 with a rotation near the identity; non-orthonormal R rejected.
  const S big(100000000);
  const SE3<S> x(SO3<S>::fromAxisAngle(Vec3<S>(S(1), S(0), S(0)), Tolerance<S>::sqrtEpsilon()),
                 Vec3<S>(big, -big / S(3), big / S(7)));
  c.checkResidual("|t| = 1e8, R near I: X·X⁻¹ = I (relative to |t|)",
                  maxAbs(Mat4<S>(x.matrix() * x.inverse().matrix() - Mat4<S>::Identity())) / big, tol);
  Mat4<S> drifted = SE3<S>::Random(g).matrix();
  drifted.template topLeftCorner<3, 3>() *= S(1) + S(1000) * Tolerance<S>::input();
  bool rejected = false;
  try {
    (void)SE3<S>::fromMatrix(drifted);
  } catch (const InvalidInput&) {
    rejected = true;
  }
  c.checkEqual("a rotation block scaled by 1 + 1000·input tolerance is rejected", 1, rejected ? 1 : 0);
}

SOMA_STUDY({.id = "GF-2.5.1-homogeneous",
            .title = "Homogeneous 4×4 representation of SE(3): product, inverse, action, z = 1 plane",
            .source = "GF §2.5.1",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { homogeneous<S>(c); }); }});

// ---- GF-2.5.2-screw-motion-matrix -------------------------------------------------------------
/// The book's screw motion about an axis through the origin, pitch p per TURN.
// GF §2.5.2, GF-2.5.2-screw-motion-matrix
template <class S> Mat4<S> screwAtOrigin(const Vec3<S>& v, const S& p, const S& th) {
  return hom<S>(SO3<S>::fromAxisAngle(v, th).matrix(), Vec3<S>(th / (S(2) * pi<S>()) * p * v));
}

// GF §2.5.2, GF-2.5.2-screw-motion-matrix: conjugating by the translation u gives
// [[R, θp/2π v + (I − R)u], [0, 1]]; points on the axis advance by θp/2π along it.
template <class S> void screwMotionMatrix(Context& c) {
  using std::abs;
  using std::sqrt;
  auto g = rng(2503);
  const S tol = Tolerance<S>::identity(64);
  S eConj(0), eLib(0), eAxis(0), ePitch(0);
  for (int t = 0; t < 100; ++t) {
    Vec3<S> v = uniVec3<S>(g);
    v /= sqrt(v.squaredNorm());
    const Vec3<S> u = uniVec3<S>(g);
    const S p = uni<S>(g, -2, 2), th = uni<S>(g, -3, 3);
    const Mat4<S> at0 = screwAtOrigin(v, p, th);
    const Mat4<S> conj = translation4<S>(u) * at0 * translation4<S>(Vec3<S>(-u));
    const Mat3<S> r = at0.template topLeftCorner<3, 3>();
    const Mat4<S> closed = hom<S>(r, Vec3<S>(th / (S(2) * pi<S>()) * p * v + (Mat3<S>::Identity() - r) * u));
    eConj = std::max(eConj, maxAbs(Mat4<S>(conj - closed)));
    // the library's screwMotion takes the pitch per radian h = p/2π
    eLib = std::max(eLib, maxAbs(Mat4<S>(screwMotion<S>(v, u, p / (S(2) * pi<S>()), th).matrix() - closed)));
    // a point on the axis, u + λv, moves by θp/2π along v
    const S lam = uni<S>(g, -5, 5);
    const Vec4<S> pt(u(0) + lam * v(0), u(1) + lam * v(1), u(2) + lam * v(2), S(1));
    const Vec4<S> moved = closed * pt;
    eAxis = std::max(eAxis, maxAbs(Vec3<S>(moved.template head<3>() - pt.template head<3>() - th / (S(2) * pi<S>()) * p * v)));
    // screwOf recovers the per-radian pitch h = p/2π (θ ∈ (0, π) keeps the axis sign)
    if (th > S(1) / S(10) && th < S(3)) {
      const Screw<S> sc = screwOf(SE3<S>::fromMatrix(closed));
      ePitch = std::max(ePitch, abs(S(2) * pi<S>() * sc.pitch - p));
    }
  }
  c.checkResidual("T(u) X(θ, p) T(−u) = [[R, θp/2π v + (I − R)u],[0, 1]]", eConj, tol);
  c.checkResidual("= library screwMotion(v, u, h = p/2π, θ)", eLib, tol);
  c.checkResidual("points on the axis advance by θp/2π along v", eAxis, tol);
  c.checkResidual("book pitch per turn p = 2π × library pitch per radian (screwOf)", ePitch, tol);
  c.note("Convention: the book's §2.5.2 pitch p is per full turn; soma (and GF ch. 4 on) use h = p/2π per radian.");
}

SOMA_STUDY({.id = "GF-2.5.2-screw-motion-matrix",
            .title = "Screw motion matrix about an axis through u (pitch per turn)",
            .source = "GF §2.5.2",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { screwMotionMatrix<S>(c); }); }});

// ---- GF-2.5.2-chasles-decomposition -----------------------------------------------------------
/// The book's constructive proof as an algorithm: θ, v̂ from R (via the logarithm, §4.4),
/// p = (2π/θ) v̂·t, then (I − R)u = t − (θ/2π) p v̂ solved with u ⟂ v̂ through the normal
/// equations (AᵀA + v̂v̂ᵀ)u = Aᵀb.
// GF §2.5.2, GF-2.5.2-chasles-decomposition
template <class S> struct BookScrew {
  S theta, p;
  Vec3<S> v, u;
};
template <class S> BookScrew<S> bookChasles(const SE3<S>& x) {
  using std::sqrt;
  const Vec3<S> w = x.so3().log().coeffs();
  BookScrew<S> s;
  s.theta = sqrt(w.squaredNorm());
  s.v = w / s.theta;
  const Vec3<S> t = x.translation();
  s.p = S(2) * pi<S>() / s.theta * s.v.dot(t);
  const Mat3<S> a = Mat3<S>::Identity() - x.rotation();
  const Vec3<S> b = t - s.theta / (S(2) * pi<S>()) * s.p * s.v;
  s.u = Mat3<S>(a.transpose() * a + s.v * s.v.transpose()).partialPivLu().solve(Vec3<S>(a.transpose() * b));
  return s;
}

// GF §2.5.2, GF-2.5.2-chasles-decomposition: every proper rigid motion except a pure
// translation is a screw motion; the book's construction agrees with the se(3) logarithm.
template <class S> void chasles(Context& c) {
  using std::abs;
  using std::pow;
  using std::sqrt;
  auto g = rng(2504);
  const S tol = Tolerance<S>::identity(256);
  S eRec(0), ePitch(0), ePoint(0), eAxis(0);
  for (int t = 0; t < 100; ++t) {
    const SE3<S> x = SE3<S>::Random(g);
    const BookScrew<S> b = bookChasles(x);
    const Mat4<S> rec = translation4<S>(b.u) * hom<S>(x.rotation(), Vec3<S>(b.theta / (S(2) * pi<S>()) * b.p * b.v)) *
                        translation4<S>(Vec3<S>(-b.u));
    eRec = std::max(eRec, maxAbs(Mat4<S>(rec - x.matrix())));
    const Screw<S> s = screwOf(x);
    ePitch = std::max(ePitch, abs(b.p / (S(2) * pi<S>()) - s.pitch));
    ePoint = std::max(ePoint, maxAbs(Vec3<S>(b.u - s.point)));
    eAxis = std::max(eAxis, maxAbs(Vec3<S>(b.v - s.axis)));
  }
  c.checkResidual("book construction reconstructs [[R, t],[0,1]] (100 random motions)", eRec, tol);
  c.checkResidual("book p/2π = pitch from the se(3) log, ω·v/|ω|²", ePitch, tol);
  c.checkResidual("book axis point u (chosen ⟂ v̂) = ω × v/|ω|²", ePoint, tol);
  c.checkResidual("book axis v̂ = ω/|ω|", eAxis, tol);

  // (I − R) has rank 2 for R ≠ I and rank 0 for R = I (where the construction fails).
  const SE3<S> x = SE3<S>::Random(g);
  c.checkEqual("rank(I − R) = 2 for a random R", 2,
               numericalRank<S>(MatX<S>(Mat3<S>::Identity() - x.rotation())));
  const SE3<S> pureT(SO3<S>(), Vec3<S>(S(1), S(2), S(3)));
  c.checkEqual("rank(I − R) = 0 for R = I: the book's method fails (pure translation)", 0,
               numericalRank<S>(MatX<S>(Mat3<S>::Identity() - pureT.rotation())));
  c.checkEqual("screwOf reports a pure translation for R = I", 1, screwOf(pureT).pureTranslation ? 1 : 0);

  // Extremes.
  Vec3<S> v = uniVec3<S>(g);
  v /= sqrt(v.squaredNorm());
  Vec3<S> perp = v.cross(uniVec3<S>(g));
  perp /= sqrt(perp.squaredNorm());
  {  // t ∥ v̂ through the origin: u = 0
    const SE3<S> y = screwMotion<S>(v, Vec3<S>::Zero(), S(3) / S(10), S(12) / S(10));
    c.checkResidual("t ∥ v̂ (axis through the origin): u = 0", maxAbs(bookChasles(y).u), tol);
  }
  {  // t ⟂ v̂: pitch 0
    const SE3<S> y(SO3<S>::fromAxisAngle(v, S(7) / S(10)), perp);
    c.checkResidual("t ⟂ v̂: pitch 0", abs(bookChasles(y).p), tol);
  }
  {  // θ = π: the axis sign is ambiguous, both signs describe the same motion
    const Vec3<S> u = uniVec3<S>(g);
    const SE3<S> y = screwMotion<S>(v, u, S(1) / S(5), pi<S>());
    const BookScrew<S> b = bookChasles(y);
    const Mat4<S> rec = translation4<S>(b.u) * hom<S>(y.rotation(), Vec3<S>(b.theta / (S(2) * pi<S>()) * b.p * b.v)) *
                        translation4<S>(Vec3<S>(-b.u));
    c.checkResidual("θ = π: reconstruction (either axis sign)", maxAbs(Mat4<S>(rec - y.matrix())), tol);
  }
  {  // θ → 0 with a fixed translation: p = 2π v̂·t/θ → ∞, the axis solve degrades like 1/θ²
    const S th = Tolerance<S>::precision(3);
    const Vec3<S> u = uniVec3<S>(g);
    const SE3<S> y = screwMotion<S>(v, u, S(1) / (S(5) * th), th);  // translation along v̂ ≈ 0.2
    const BookScrew<S> b = bookChasles(y);
    const Mat4<S> rec = translation4<S>(b.u) * hom<S>(y.rotation(), Vec3<S>(b.theta / (S(2) * pi<S>()) * b.p * b.v)) *
                        translation4<S>(Vec3<S>(-b.u));
    c.checkResidual("θ = ε^{1/4}, pitch 0.2/θ: reconstruction (tolerance × 1/θ²)",
                    maxAbs(Mat4<S>(rec - y.matrix())), tol / (th * th));
    c.checkNear("θ = ε^{1/4}: p/2π = 0.2/θ (large pitch)", S(1) / (S(5) * th), b.p / (S(2) * pi<S>()),
                tol / (th * th * th));
  }
}

SOMA_STUDY({.id = "GF-2.5.2-chasles-decomposition",
            .title = "Chasles: the book's screw construction vs the se(3) logarithm",
            .source = "GF §2.5.2",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { chasles<S>(c); }); }});

// ---- GF-2.5.3-active-passive ------------------------------------------------------------------
// GF §2.5.3, GF-2.5.3-active-passive: coordinates in a frame (R, t) are p' = Rᵀp − Rᵀt, i.e.
// the inverse of the active motion; a motion X' in the dashed frame is X = F X' F⁻¹.
template <class S> void activePassive(Context& c) {
  auto g = rng(2505);
  const S tol = Tolerance<S>::identity(64);
  S eCoord(0), eDot(0), eConj(0), eLib(0), eWrongMin(S(1e30));
  for (int t = 0; t < 100; ++t) {
    const SE3<S> f = SE3<S>::Random(g), xd = SE3<S>::Random(g);
    const Vec3<S> p = uniVec3<S>(g);
    const Mat3<S> r = f.rotation();
    const Vec3<S> pd = r.transpose() * p - r.transpose() * f.translation();
    eCoord = std::max(eCoord, maxAbs(Vec3<S>(pd - f.inverse().act(p))));
    // x' = (p − t)·i' with i' = R i, etc.
    const Vec3<S> viaDots((p - f.translation()).dot(r.col(0)), (p - f.translation()).dot(r.col(1)),
                          (p - f.translation()).dot(r.col(2)));
    eDot = std::max(eDot, maxAbs(Vec3<S>(viaDots - pd)));
    // X' moves p1' to p2' in the dashed frame; the same physical move in the undashed frame
    const Vec3<S> p1d = uniVec3<S>(g);
    const Vec3<S> p2d = xd.act(p1d);
    const Vec3<S> p1 = f.act(p1d), p2 = f.act(p2d);
    const Mat4<S> X = f.matrix() * xd.matrix() * f.inverse().matrix();
    eConj = std::max(eConj, maxAbs(Vec3<S>((X * Vec4<S>(p1(0), p1(1), p1(2), S(1))).template head<3>() - p2)));
    eLib = std::max(eLib, maxAbs(Mat4<S>(changeOfFrame(f, xd).matrix() - X)));
    const Mat4<S> wrong = f.inverse().matrix() * xd.matrix() * f.matrix();
    eWrongMin = std::min(eWrongMin, maxAbs(Vec3<S>((wrong * Vec4<S>(p1(0), p1(1), p1(2), S(1))).template head<3>() - p2)));
  }
  c.checkResidual("p' = Rᵀp − Rᵀt = [[R, t],[0,1]]⁻¹ p", eCoord, tol);
  c.checkResidual("x' = (p − t)·Ri etc.", eDot, tol);
  c.checkResidual("X = F X' F⁻¹ maps p1 to p2 (world coordinates)", eConj, tol);
  c.checkResidual("library changeOfFrame(F, X') = F X' F⁻¹", eLib, tol);
  c.recordIn("the opposite conjugation F⁻¹ X' F (the frequent sign bug): smallest miss (> 1e-3)", "fails",
             io::numberText(eWrongMin), eWrongMin, S(1) / S(1000), eWrongMin > S(1) / S(1000));
  c.note("Erratum E2.5 (OCR) garbles X'(p1', 1)ᵀ = (p2', 1)ᵀ in the seed; the content is reproduced above.");
}

SOMA_STUDY({.id = "GF-2.5.3-active-passive",
            .title = "Active vs passive: frame coordinates and change of frame X = F X' F⁻¹",
            .source = "GF §2.5.3",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { activePassive<S>(c); }); }});

}  // namespace
}  // namespace soma::studies::SOMA_UNITY_ID
