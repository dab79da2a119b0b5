// Studies of GF chapter 3 — Subgroups, §3.5 (subgroups of SE(3), Table 3.1) and §3.6
// (Reuleaux's lower pairs).
#include "soma/algebra/lie_algebra.hpp"
#include "soma/algebra/screw.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/studies/study.hpp"

#include "soma/studies/gf02_gf03_support.hpp"

#include <Eigen/QR>

#include <functional>
#include <string>
#include <vector>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using namespace gf23;
const char* const kChapter = "GF 3 — Subgroups";

template <class S> Vec6<S> tw(const Vec3<S>& w, const Vec3<S>& v) { return (Vec6<S>() << w, v).finished(); }
template <class S> Vec3<S> e3(int i) { return Vec3<S>::Unit(i); }

/// Closure defect of span(B) ⊂ se(3) under the bracket: max over basis pairs of the component
/// of [b_i, b_j] orthogonal to the span (basis orthonormalised first). 0 ⇔ a subalgebra.
template <class S> S closureDefect(const std::vector<Vec6<S>>& basis) {
  const int k = int(basis.size());
  MatX<S> b(6, k);
  for (int i = 0; i < k; ++i) b.col(i) = basis[std::size_t(i)];
  Eigen::HouseholderQR<MatX<S>> qr(b);
  const MatX<S> q = qr.householderQ() * MatX<S>::Identity(6, k);
  const MatX<S> proj = MatX<S>::Identity(6, 6) - q * q.transpose();
  S d(0);
  for (int i = 0; i < k; ++i)
    for (int j = i + 1; j < k; ++j) {
      const Vec6<S> br = bracket(SE3Tangent<S>(Vec6<S>(q.col(i))), SE3Tangent<S>(Vec6<S>(q.col(j)))).coeffs();
      d = std::max(d, maxAbs(VecX<S>(proj * br)));
    }
  return d;
}
template <class S> int spanDim(const std::vector<Vec6<S>>& basis) {
  MatX<S> b(6, int(basis.size()));
  for (std::size_t i = 0; i < basis.size(); ++i) b.col(int(i)) = basis[i];
  return numericalRank<S>(b);
}

// ---- GF-3.5-translations-normal ---------------------------------------------------------------
// GF §3.5, GF-3.5-translations-normal: (R, u)(I, t)(R, u)⁻¹ = (I, Rt), so R³ ◁ SE(3) and
// SE(3)/R³ = SO(3).
template <class S> void translationsNormal(Context& c) {
  auto g = rng(3501);
  const S tol = Tolerance<S>::identity(64);
  S eConj(0), eQuot(0), eFar(0);
  for (int t = 0; t < 100; ++t) {
    const SE3<S> x = SE3<S>::Random(g), y = SE3<S>::Random(g);
    const Vec3<S> tt = uniVec3<S>(g);
    const Mat4<S> conj = x.matrix() * translation4<S>(tt) * x.inverse().matrix();
    eConj = std::max(eConj, maxAbs(Mat4<S>(conj - translation4<S>(Vec3<S>(x.rotation() * tt)))));
    // the projection (R, t) ↦ R is a homomorphism with kernel the translations
    eQuot = std::max(eQuot, maxAbs(Mat3<S>((x * y).rotation() - x.rotation() * y.rotation())));
  }
  c.checkResidual("(R,u)(I,t)(R,u)⁻¹ = (I, Rt) (100 random)", eConj, tol);
  c.checkResidual("(R1,t1)(R2,t2) ↦ R1R2: SE(3) → SO(3) is a homomorphism (quotient by R³)", eQuot, tol);
  // |t|, |u| ~ 1e6 with R near a half-turn: relative to 1e6
  for (int t = 0; t < 20; ++t) {
    Vec3<S> ax = uniVec3<S>(g);
    using std::sqrt;
    ax /= sqrt(ax.squaredNorm());
    const SE3<S> x(SO3<S>::fromAxisAngle(ax, pi<S>() - Tolerance<S>::sqrtEpsilon()), Vec3<S>(uniVec3<S>(g) * S(1000000)));
    const Vec3<S> tt = uniVec3<S>(g) * S(1000000);
    const Mat4<S> conj = x.matrix() * translation4<S>(tt) * x.inverse().matrix();
    eFar = std::max(eFar, maxAbs(Mat4<S>(conj - translation4<S>(Vec3<S>(x.rotation() * tt)))) / S(1000000));
  }
  c.checkResidual("|t|, |u| ~ 1e6, R near a half-turn: relative error", eFar, tol);
}

SOMA_STUDY({.id = "GF-3.5-translations-normal",
            .title = "The translations R³ form a normal subgroup of SE(3); SE(3)/R³ = SO(3)",
            .source = "GF §3.5",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { translationsNormal<S>(c); }); }});

// ---- GF-3.5-subgroups-of-R3-and-SO3 -----------------------------------------------------------
// GF §3.5, GF-3.5-subgroups-of-R3-and-SO3: the closed subgroups of R³ are Z^k × R^m (k + m ≤ 3,
// the book's ten); the connected subgroups of SO(3) are 0, SO(2), SO(3); O(2) is disconnected.
template <class S> void subgroupsR3SO3(Context& c) {
  using std::abs;
  using std::floor;
  using std::sqrt;
  auto g = rng(3502);
  const S tol = Tolerance<S>::identity(64);
  // The book's list written as (k lattice directions, m continuous directions).
  const std::vector<std::pair<int, int>> book = {{0, 3}, {0, 2}, {0, 1}, {1, 0}, {1, 1},
                                                 {1, 2}, {2, 0}, {2, 1}, {3, 0}, {0, 0}};
  int enumerated = 0, inBook = 0;
  for (int k = 0; k <= 3; ++k)
    for (int m = 0; k + m <= 3; ++m) {
      ++enumerated;
      for (const auto& p : book) inBook += (p == std::make_pair(k, m));
    }
  c.checkEqual("closed subgroups Z^k × R^m of R³ (k + m ≤ 3): count", 10, enumerated);
  c.checkEqual("each of them is in the book's list (pZ, pZ × R, …, 0)", enumerated, inBook);
  // a lattice pZ × qZ × R is closed under sums and negatives (membership up to rounding)
  const S p = S(3) / S(7), q = S(5) / S(3);
  S eLat(0);
  for (int t = 0; t < 100; ++t) {
    const int a1 = int(uni<double>(g, -50, 50)), a2 = int(uni<double>(g, -50, 50)), b1 = int(uni<double>(g, -50, 50)),
              b2 = int(uni<double>(g, -50, 50));
    const Vec3<S> x(S(a1) * p, S(b1) * q, uni<S>(g)), y(S(a2) * p, S(b2) * q, uni<S>(g));
    const Vec3<S> s = x - y;
    const S f0 = s(0) / p, f1 = s(1) / q;
    eLat = std::max(eLat, abs(f0 - floor(f0 + S(1) / S(2))) + abs(f1 - floor(f1 + S(1) / S(2))));
  }
  // fl(a₁p) − fl(a₂p), then / p: the coordinate's error is ≤ (ε/2)(|a₁| + |a₂| + 2|a₁ − a₂|) ≤ 150ε for
  // |aᵢ| < 50, for each of the two lattice coordinates
  c.checkResidual("pZ × qZ × R: x − y stays in the subgroup (integer coordinates / p, q; 300ε)", eLat,
                  S(300) * Tolerance<S>::epsilon());
  // so(3): every 2-plane fails to close (the bracket of an orthonormal basis is the unit
  // normal), so the connected subgroups of SO(3) have dimensions 0, 1, 3 only.
  S minDefect(S(10)), maxDefect(0);
  for (int t = 0; t < 200; ++t) {
    Vec3<S> a = uniVec3<S>(g), b = uniVec3<S>(g);
    a /= sqrt(a.squaredNorm());
    b -= b.dot(a) * a;
    b /= sqrt(b.squaredNorm());
    const Vec3<S> br = a.cross(b);  // [a, b] in so(3)
    const S defect = sqrt((br - br.dot(a) * a - br.dot(b) * b).squaredNorm());
    minDefect = std::min(minDefect, defect), maxDefect = std::max(maxDefect, defect);
  }
  c.checkNear("2-planes of so(3): closure defect = 1 (min over 200 random planes)", S(1), minDefect, tol);
  c.checkNear("… and max", S(1), maxDefect, tol);
  // The dimensions that occur, computed: 0 and 3 always; 1 when a line closes ([a, a] = a × a = 0 for
  // the 200 sampled a); 2 only if some sampled plane closed (defect ≤ tol, which the min above rules out).
  S lineBracket(0);
  for (int t = 0; t < 200; ++t) {
    const Vec3<S> a = uniVec3<S>(g);
    lineBracket = std::max(lineBracket, S(sqrt(a.cross(a).squaredNorm())));
  }
  std::string dims = "0";
  if (lineBracket <= tol) dims += ",1";
  if (minDefect <= tol) dims += ",2";
  dims += ",3";
  c.checkEqual("dimensions of the subalgebras of so(3) (1: a line closes; 2: a sampled plane closes)", "0,1,3", dims);
  // O(2) ⊂ SO(3): rotations about z together with a half-turn about x; closed, two components.
  S eClose(0);
  int comps[2] = {0, 0};
  for (int t = 0; t < 100; ++t) {
    const auto elem = [&](bool flip) {
      const Mat3<S> rz = rotZ<S>(uni<S>(g, -3.14, 3.14));
      return flip ? Mat3<S>(rotX<S>(pi<S>()) * rz) : rz;
    };
    const Mat3<S> m = elem(t % 2) * elem((t / 2) % 2);
    // membership: M e_z = ±e_z
    const Vec3<S> mz = m * e3<S>(2);
    eClose = std::max(eClose, std::min(maxAbs(Vec3<S>(mz - e3<S>(2))), maxAbs(Vec3<S>(mz + e3<S>(2)))));
    comps[m(2, 2) > S(0) ? 0 : 1]++;
  }
  c.checkResidual("O(2) = {R_z(θ)} ∪ {R_x(π)R_z(θ)} is closed under products", eClose, tol);
  c.checkEqual("products land in both components (m33 = +1 and −1): both seen", 1, (comps[0] > 0 && comps[1] > 0) ? 1 : 0);
  c.note("The subgroups of R³ are enumerated as Z^k × R^m; the classification theorem itself is "
         "not re-proved. In so(3) the bracket of an orthonormal pair is their cross product, a "
         "unit vector normal to the plane: no 2-dimensional subalgebra exists.");
}

SOMA_STUDY({.id = "GF-3.5-subgroups-of-R3-and-SO3",
            .title = "Subgroups of R³ and connected subgroups of SO(3); O(2)",
            .source = "GF §3.5",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { subgroupsR3SO3<S>(c); }); }});

// ---- GF-3.5-table-3.1-connected-subgroups -----------------------------------------------------
// GF §3.5, GF-3.5-table-3.1-connected-subgroups: the Lie algebras of the subgroups in Table 3.1
// are closed under the bracket and have the listed dimensions; nearby non-examples are not.
template <class S> void table31(Context& c) {
  auto g = rng(3503);
  const S tol = Tolerance<S>::identity(64);
  const S h = S(3) / S(7);  // pitch per radian of H_p (p = 2πh per turn)
  const Vec3<S> z0 = Vec3<S>::Zero();
  struct Row {
    std::string name;
    int dim;
    std::vector<Vec6<S>> basis;
  };
  const std::vector<Row> rows = {
      {"SE(3)", 6, {tw<S>(e3<S>(0), z0), tw<S>(e3<S>(1), z0), tw<S>(e3<S>(2), z0), tw<S>(z0, e3<S>(0)), tw<S>(z0, e3<S>(1)), tw<S>(z0, e3<S>(2))}},
      {"SE(2) × R (Schoenflies)", 4, {tw<S>(e3<S>(2), z0), tw<S>(z0, e3<S>(0)), tw<S>(z0, e3<S>(1)), tw<S>(z0, e3<S>(2))}},
      {"SE(2)", 3, {tw<S>(e3<S>(2), z0), tw<S>(z0, e3<S>(0)), tw<S>(z0, e3<S>(1))}},
      {"SO(3)", 3, {tw<S>(e3<S>(0), z0), tw<S>(e3<S>(1), z0), tw<S>(e3<S>(2), z0)}},
      {"R³", 3, {tw<S>(z0, e3<S>(0)), tw<S>(z0, e3<S>(1)), tw<S>(z0, e3<S>(2))}},
      {"H_p ⋉ R²", 3, {tw<S>(e3<S>(0), Vec3<S>(h * e3<S>(0))), tw<S>(z0, e3<S>(1)), tw<S>(z0, e3<S>(2))}},
      {"SO(2) × R (cylindric)", 2, {tw<S>(e3<S>(0), z0), tw<S>(z0, e3<S>(0))}},
      {"R²", 2, {tw<S>(z0, e3<S>(0)), tw<S>(z0, e3<S>(1))}},
      {"SO(2)", 1, {tw<S>(e3<S>(0), z0)}},
      {"R", 1, {tw<S>(z0, e3<S>(0))}},
      {"H_p", 1, {tw<S>(e3<S>(0), Vec3<S>(h * e3<S>(0)))}}};
  for (const auto& r : rows) {
    c.checkEqual(r.name + ": dimension", r.dim, spanDim<S>(r.basis));
    c.checkResidual(r.name + ": closed under the bracket", closureDefect<S>(r.basis), tol);
    // and so is every conjugate (Ad(g) is a Lie-algebra automorphism)
    const SE3<S> x = SE3<S>::Random(g);
    std::vector<Vec6<S>> conj;
    for (const auto& b : r.basis) conj.push_back(x.adjoint() * b);
    // Ad(x)b rounds by ε‖Ad‖ a vector: the subspace moves by ≤ κ(Ad) times that (first order)
    const S kappaAd = x.adjoint().norm() * x.inverse().adjoint().norm();
    c.checkResidual(r.name + ": a random conjugate is closed too (tol·κ(Ad))", closureDefect<S>(conj), tol * kappaAd);
  }
  // non-examples from the derivation
  const std::vector<Row> bad = {
      {"SO(3) + R² (book: SO(3) rotates any plane away)", 5, {tw<S>(e3<S>(0), z0), tw<S>(e3<S>(1), z0), tw<S>(e3<S>(2), z0), tw<S>(z0, e3<S>(0)), tw<S>(z0, e3<S>(1))}},
      {"SO(2) ⋉ R² with the plane not the rotation plane", 3, {tw<S>(e3<S>(2), z0), tw<S>(z0, e3<S>(0)), tw<S>(z0, e3<S>(2))}},
      {"SO(2) × R with R not along the axis", 2, {tw<S>(e3<S>(2), z0), tw<S>(z0, e3<S>(0))}}};
  for (const auto& r : bad) {
    const S d = closureDefect<S>(r.basis);
    c.recordIn(r.name + ": closure defect (> 0.1)", "fails (not a subalgebra)", io::numberText(d), d, S(1) / S(10),
               d > S(1) / S(10));
  }
  // dim 5: none. A 5-dimensional subspace is the kernel of a functional φ; search 3000 random φ
  // plus the coordinate functionals for a closed one (evidence, not a proof).
  S minDefect(S(10));
  for (int t = 0; t < 3006; ++t) {
    Vec6<S> phi;
    if (t < 6) phi = Vec6<S>::Unit(t);
    else
      for (int i = 0; i < 6; ++i) phi(i) = gauss<S>(g);
    // basis of ker φ: orthogonal complement of φ via QR
    const MatX<S> phiM = phi;
    Eigen::HouseholderQR<MatX<S>> qr(phiM);
    const MatX<S> q = qr.householderQ() * MatX<S>::Identity(6, 6);
    std::vector<Vec6<S>> basis;
    for (int i = 1; i < 6; ++i) basis.push_back(Vec6<S>(q.col(i)));
    minDefect = std::min(minDefect, closureDefect<S>(basis));
  }
  c.recordIn("dim 5: smallest closure defect over 3006 hyperplanes of se(3)", "> 0.01 (no 5-dim subgroup)",
             io::numberText(minDefect), minDefect, S(1) / S(100), minDefect > S(1) / S(100));
  // H_p for different p are not conjugate: the pitch ω·v/ω·ω is invariant under Ad.
  // a = Ad(x)s: a_ω = Rω, a_v = t × Rω + Rv round by ε(|t||ω| + |v|); a_ω·a_v cancels terms of that
  // size times |ω|, so the pitch's error is tol·(1 + |t| + |v|/|ω|) in units of (1 + |t|)(1 + |v|/|ω|)
  S ePitch(0);
  for (int t = 0; t < 50; ++t) {
    const Vec6<S> s = tw<S>(uniVec3<S>(g), uniVec3<S>(g));
    const SE3<S> x = SE3<S>::Random(g);
    const Vec6<S> a = x.adjoint() * s;
    const auto pitch = [](const Vec6<S>& y) { return y.template head<3>().dot(y.template tail<3>()) / y.template head<3>().squaredNorm(); };
    using std::abs;
    const S scale = (S(1) + x.translation().norm()) * (S(1) + s.template tail<3>().norm() / s.template head<3>().norm());
    ePitch = std::max(ePitch, abs(pitch(a) - pitch(s)) / scale);
  }
  c.checkResidual("pitch ω·v/|ω|² is Ad-invariant: H_p, H_p' (p ≠ p') are not conjugate (relative to (1 + |t|)(1 + |v|/|ω|))",
                  ePitch, tol);
  c.note("The table's lost dimension-4 label and alignment (E3.4, OCR) are restored as in the catalogue. "
         "The dim-5 row is supported by a random search only.");
}

SOMA_STUDY({.id = "GF-3.5-table-3.1-connected-subgroups",
            .title = "Table 3.1: the connected subgroups of SE(3) via closed subalgebras",
            .source = "GF §3.5",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { table31<S>(c); }); }});

// ---- GF-3.5-subgroup-intersection -------------------------------------------------------------
// GF §3.5, GF-3.5-subgroup-intersection: rotations about p ∩ rotations about q = rotations about
// the line pq (p ≠ q), or the whole SO(3) about p (p = q).
template <class S> void subgroupIntersection(Context& c) {
  using std::abs;
  using std::sqrt;
  auto g = rng(3504);
  const S tol = Tolerance<S>::identity(64);
  // Lie algebras {(ω, p × ω)} and {(ω, q × ω)}: the intersection is the null space of [Bp, −Bq].
  const auto basisAbout = [](const Vec3<S>& p) {
    MatX<S> b(6, 3);
    for (int i = 0; i < 3; ++i) b.col(i) = tw<S>(e3<S>(i), Vec3<S>(p.cross(e3<S>(i))));
    return b;
  };
  const auto interDim = [&](const Vec3<S>& p, const Vec3<S>& q) {
    MatX<S> m(6, 6);
    m << basisAbout(p), -basisAbout(q);
    return 6 - numericalRank<S>(m);
  };
  S eDir(0), eFix(0), dirBound(0);
  int bad = 0;
  for (int t = 0; t < 100; ++t) {
    const Vec3<S> p = uniVec3<S>(g), q = uniVec3<S>(g);
    bad += interDim(p, q) != 1;
    // the intersection direction: ω with (p − q) × ω = 0, i.e. ω ∥ p − q
    MatX<S> m(6, 6);
    m << basisAbout(p), -basisAbout(q);
    Eigen::FullPivLU<MatX<S>> lu(m);
    lu.setThreshold(Tolerance<S>::rank());
    const VecX<S> nv = lu.kernel().col(0);
    Vec3<S> w = nv.head(3);
    w /= sqrt(w.squaredNorm());
    Vec3<S> d = p - q;
    d /= sqrt(d.squaredNorm());
    eDir = std::max(eDir, sqrt(w.cross(d).squaredNorm()));
    // the LU's kernel vector is the exact one of m + F, ‖F‖ ≤ tol‖m‖, so it turns by ≤ ‖F‖/σ₅(m), σ₅
    // estimated by the smallest nonzero pivot |u₅₅| of the complete-pivoting LU (rank-revealing);
    // d = p − q carries ε(|p| + |q|)/|p − q|
    dirBound = std::max(dirBound, tol * (m.norm() / abs(lu.matrixLU()(4, 4)) +
                                         (sqrt(p.squaredNorm()) + sqrt(q.squaredNorm())) / sqrt(Vec3<S>(p - q).squaredNorm())));
    // group level: a rotation about the line pq fixes both p and q
    const SE3<S> r = screwMotion<S>(d, p, S(0), uni<S>(g, -3, 3));
    eFix = std::max(eFix, maxAbs(Vec3<S>(r.act(p) - p)) + maxAbs(Vec3<S>(r.act(q) - q)));
  }
  c.checkEqual("p ≠ q (100 random pairs): pairs whose intersection is not 1-dimensional (SO(2) about pq)", 0, bad);
  c.checkResidual("the common rotation axis is parallel to p − q (tol(‖m‖/|u₅₅| + (|p| + |q|)/|p − q|))", eDir, dirBound);
  c.checkResidual("rotations about the line pq fix p and q", eFix, tol);
  const Vec3<S> p = uniVec3<S>(g);
  c.checkEqual("p = q: the intersection is the SO(3) about p (dim 3)", 3, interDim(p, p));
  // near coincidence: the rank decision flips at a distance set by the tolerance
  const S far = Tolerance<S>::precision(2);
  c.checkEqual("|p − q| = ε^{1/3}: still dim 1", 1, interDim(p, Vec3<S>(p + far * e3<S>(0))));
  const S near = Tolerance<S>::epsilon();
  c.checkEqual("|p − q| = ε: numerically dim 3 (rank decision with tolerance)", 3, interDim(p, Vec3<S>(p + near * e3<S>(0))));
}

SOMA_STUDY({.id = "GF-3.5-subgroup-intersection",
            .title = "Intersection of the rotation groups about two points",
            .source = "GF §3.5",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { subgroupIntersection<S>(c); }); }});

// ---- GF-3.6-reuleaux-lower-pairs --------------------------------------------------------------
template <class S> struct LowerPair {
  std::string name;
  std::function<S(const Vec3<S>&)> f;                       // implicit equation F = 0
  std::function<Vec3<S>(std::mt19937_64&)> sample;          // a random point on the surface
  std::function<SE3<S>(std::mt19937_64&)> symmetry;         // a random element of its subgroup
};

// GF §3.6, GF-3.6-reuleaux-lower-pairs: the six lower pairs are the surfaces invariant under
// SO(2), R, H_p, SO(2) × R, SO(3), SE(2); the larger subgroups have 3-dimensional orbits.
template <class S> void reuleaux(Context& c) {
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::floor;
  using std::sin;
  using std::sqrt;
  auto g = rng(3601);
  const S tol = Tolerance<S>::identity(256);
  const S h = S(3) / S(10);  // helicoid pitch per radian
  const Vec3<S> c0(S(3) / S(10), S(-2) / S(10), S(5) / S(10));
  const auto rotAbout = [](const Vec3<S>& axis, const Vec3<S>& pt, const S& th) { return screwMotion<S>(axis, pt, S(0), th); };
  std::vector<LowerPair<S>> pairs;
  pairs.push_back({"sphere (SO(3) about its centre)",
                   [c0](const Vec3<S>& x) { return (x - c0).squaredNorm() - S(169) / S(100); },
                   [c0](std::mt19937_64& gg) {
                     Vec3<S> u(gauss<S>(gg), gauss<S>(gg), gauss<S>(gg));
                     return Vec3<S>(c0 + u * (S(13) / S(10) / sqrt(u.squaredNorm())));
                   },
                   [c0](std::mt19937_64& gg) {
                     return SE3<S>(SE3<S>(SO3<S>(), c0) * SE3<S>(SO3<S>::Random(gg), Vec3<S>::Zero()) *
                                   SE3<S>(SO3<S>(), Vec3<S>(-c0)));
                   }});
  pairs.push_back({"plane z = 0.4 (SE(2))", [](const Vec3<S>& x) { return x(2) - S(4) / S(10); },
                   [](std::mt19937_64& gg) { return Vec3<S>(uni<S>(gg, -2, 2), uni<S>(gg, -2, 2), S(4) / S(10)); },
                   [rotAbout](std::mt19937_64& gg) {
                     const SE3<S> r = rotAbout(e3<S>(2), Vec3<S>(uni<S>(gg), uni<S>(gg), S(0)), uni<S>(gg, -3, 3));
                     return SE3<S>(SE3<S>(SO3<S>(), Vec3<S>(uni<S>(gg), uni<S>(gg), S(0))) * r);
                   }});
  pairs.push_back({"cylinder about the x-parallel line through (0, 0.5, −0.2) (SO(2) × R, any H_p)",
                   [](const Vec3<S>& x) {
                     return (x(1) - S(1) / S(2)) * (x(1) - S(1) / S(2)) + (x(2) + S(1) / S(5)) * (x(2) + S(1) / S(5)) - S(49) / S(100);
                   },
                   [](std::mt19937_64& gg) {
                     const S t = uni<S>(gg, -3.14, 3.14);
                     return Vec3<S>(uni<S>(gg, -2, 2), S(1) / S(2) + S(7) / S(10) * cos(t), -S(1) / S(5) + S(7) / S(10) * sin(t));
                   },
                   [](std::mt19937_64& gg) {  // a screw of random pitch about the axis
                     return screwMotion<S>(e3<S>(0), Vec3<S>(S(0), S(1) / S(2), -S(1) / S(5)), uni<S>(gg, -2, 2), uni<S>(gg, -3, 3));
                   }});
  pairs.push_back({"surface of revolution ρ = 1 + sin(z)/2 about z (SO(2))",
                   [](const Vec3<S>& x) { return sqrt(x(0) * x(0) + x(1) * x(1)) - (S(1) + sin(x(2)) / S(2)); },
                   [](std::mt19937_64& gg) {
                     const S z = uni<S>(gg, -2, 2), t = uni<S>(gg, -3.14, 3.14);
                     const S r = S(1) + sin(z) / S(2);
                     return Vec3<S>(r * cos(t), r * sin(t), z);
                   },
                   [rotAbout](std::mt19937_64& gg) { return rotAbout(e3<S>(2), Vec3<S>::Zero(), uni<S>(gg, -3, 3)); }});
  pairs.push_back({"surface of translation y = sin x + x²/4 along z (R)",
                   [](const Vec3<S>& x) { return x(1) - sin(x(0)) - x(0) * x(0) / S(4); },
                   [](std::mt19937_64& gg) {
                     const S u = uni<S>(gg, -2, 2);
                     return Vec3<S>(u, sin(u) + u * u / S(4), uni<S>(gg, -2, 2));
                   },
                   [](std::mt19937_64& gg) { return SE3<S>(SO3<S>(), Vec3<S>(S(0), S(0), uni<S>(gg, -3, 3))); }});
  pairs.push_back({"helicoidal surface z = ρ²/5 + hφ about z (H_p, h = 0.3)",
                   [h](const Vec3<S>& x) {
                     const S rho = sqrt(x(0) * x(0) + x(1) * x(1)), phi = atan2(x(1), x(0));
                     const S period = S(2) * pi<S>() * h;
                     const S r = (x(2) - rho * rho / S(5) - h * phi) / period;
                     return (r - floor(r + S(1) / S(2))) * period;  // distance to the nearest sheet
                   },
                   [h](std::mt19937_64& gg) {
                     const S rho = uni<S>(gg, 0.2, 2), phi = uni<S>(gg, -3.14, 3.14);
                     return Vec3<S>(rho * cos(phi), rho * sin(phi), rho * rho / S(5) + h * phi);
                   },
                   [h](std::mt19937_64& gg) { return screwMotion<S>(e3<S>(2), Vec3<S>::Zero(), h, uni<S>(gg, -6, 6)); }});
  for (auto& lp : pairs) {
    S onSurface(0), inv(0), moved(S(1e30));
    for (int t = 0; t < 50; ++t) {
      const Vec3<S> x = lp.sample(g);
      onSurface = std::max(onSurface, abs(lp.f(x)));
      const SE3<S> s = lp.symmetry(g);
      inv = std::max(inv, abs(lp.f(s.act(x))));
    }
    // teeth: a generic rigid motion moves the surface off itself
    for (int k = 0; k < 5; ++k) {
      const SE3<S> gen = SE3<S>::Random(g);
      S worst(0);
      for (int t = 0; t < 50; ++t) worst = std::max(worst, abs(lp.f(gen.act(lp.sample(g)))));
      moved = std::min(moved, worst);
    }
    c.checkResidual(lp.name + ": sample points satisfy F = 0", onSurface, tol);
    c.checkResidual(lp.name + ": F(g·x) = 0 for 50 random g in its subgroup", inv, tol);
    c.recordIn(lp.name + ": a generic rigid motion moves it off itself (min over 5 of max |F|)", "> 0.01",
               io::numberText(moved), moved, S(1) / S(100), moved > S(1) / S(100));
  }
  // Orbit dimensions at a generic point: rank of the velocities ω × x + v over a basis.
  const Vec3<S> x(S(7) / S(10), S(-4) / S(10), S(11) / S(10));
  const Vec3<S> z0 = Vec3<S>::Zero();
  const auto orbitDim = [&](const std::vector<Vec6<S>>& basis, const Vec3<S>& at) {
    MatX<S> m(3, int(basis.size()));
    for (std::size_t i = 0; i < basis.size(); ++i)
      m.col(int(i)) = Vec3<S>(basis[i].template head<3>().cross(at) + basis[i].template tail<3>());
    return numericalRank<S>(m);
  };
  const std::vector<std::tuple<std::string, std::vector<Vec6<S>>, int>> orbits = {
      {"SO(2)", {tw<S>(e3<S>(2), z0)}, 1},
      {"R", {tw<S>(z0, e3<S>(2))}, 1},
      {"H_p", {tw<S>(e3<S>(2), Vec3<S>(h * e3<S>(2)))}, 1},
      {"SO(2) × R", {tw<S>(e3<S>(2), z0), tw<S>(z0, e3<S>(2))}, 2},
      {"SO(3)", {tw<S>(e3<S>(0), z0), tw<S>(e3<S>(1), z0), tw<S>(e3<S>(2), z0)}, 2},
      {"SE(2)", {tw<S>(e3<S>(2), z0), tw<S>(z0, e3<S>(0)), tw<S>(z0, e3<S>(1))}, 2},
      {"R³", {tw<S>(z0, e3<S>(0)), tw<S>(z0, e3<S>(1)), tw<S>(z0, e3<S>(2))}, 3},
      {"H_p ⋉ R²", {tw<S>(e3<S>(0), Vec3<S>(h * e3<S>(0))), tw<S>(z0, e3<S>(1)), tw<S>(z0, e3<S>(2))}, 3},
      {"SE(2) × R", {tw<S>(e3<S>(2), z0), tw<S>(z0, e3<S>(0)), tw<S>(z0, e3<S>(1)), tw<S>(z0, e3<S>(2))}, 3},
      {"SE(3)", {tw<S>(e3<S>(0), z0), tw<S>(e3<S>(1), z0), tw<S>(e3<S>(2), z0), tw<S>(z0, e3<S>(0)), tw<S>(z0, e3<S>(1)), tw<S>(z0, e3<S>(2))}, 3}};
  std::string got, want;
  for (const auto& [name, basis, dim] : orbits) {
    got += name + ":" + std::to_string(orbitDim(basis, x)) + " ";
    want += name + ":" + std::to_string(dim) + " ";
  }
  c.checkEqual("orbit dimensions at a generic point (2 ⇒ a lower pair surface, 3 ⇒ none)", want, got);
  c.checkEqual("SO(2) orbit of a point on its axis is a fixed point (dim 0)", 0,
               orbitDim({tw<S>(e3<S>(2), z0)}, Vec3<S>(S(0), S(0), S(2))));
}

SOMA_STUDY({.id = "GF-3.6-reuleaux-lower-pairs",
            .title = "Reuleaux's six lower pairs as surfaces invariant under subgroups of SE(3)",
            .source = "GF §3.6",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { reuleaux<S>(c); }); }});

}  // namespace
}  // namespace soma::studies::SOMA_UNITY_ID
