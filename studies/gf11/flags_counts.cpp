// Studies of GF §11.2.4 (quadric Grassmannians), §11.3 (partial flags and the fibres of their
// projections, Table 11.1) and the structural parts of §11.5 (Bézout–Halphen, the P¹ × P¹ example,
// the cell decomposition of the Study quadric). Every study runs in the asked scalar (--scalar): draws in
// double cast to S (gf11/common.hpp), ranks and eigenvectors by soma's small Jacobi solvers (small_linalg.hpp).
#include "gf11/common.hpp"
#include "soma/algebra/polynomial.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/geometry/lines/line.hpp"
#include "soma/geometry/study/constraint_quadrics.hpp"
#include "soma/geometry/study/quaternion_matrices.hpp"
#include "soma/geometry/study/study_plane.hpp"
#include "soma/studies/study.hpp"

#include <complex>
#include <random>

namespace soma::studies::gf11::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using std::abs;
using std::cos;
using std::sin;
using std::sqrt;
template <class S> using MatX = detail::SmallMat<S>;
template <class S> using VecX = Eigen::Matrix<S, Eigen::Dynamic, 1>;
template <class S> using RowX = Eigen::Matrix<S, 1, Eigen::Dynamic>;

/// A random rotation of R⁴: q ↦ g₁ q g₂* (left and right quaternion matrices, GF §9.3).
template <class S> Mat4<S> randomSO4(std::mt19937_64& g) {
  const Vec4<S> g1 = unit4<S>(g), g2 = unit4<S>(g);
  return quaternionLeftMatrix<S>(g1) * quaternionRightMatrix<S>(Vec4<S>(g2(0), -g2(1), -g2(2), -g2(3)));
}
template <class S> int rankOf(const MatX<S>& m) { return detail::smallNumericalRank<S>(m); }
/// a·b by Eigen's coefficient-based (lazy) product: these matrices are at most 8 × 12, and the
/// blocked GEMM kernels of `*` on dynamic matrices, instantiated for five scalars, made this file's
/// compile several times longer.
template <class A, class B> auto mul(const A& a, const B& b) { return a.lazyProduct(b).eval(); }
template <class S> MatX<S> projector(const MatX<S>& a) {
  const MatX<S> q = orthonormalColumns(a);
  return mul(q, q.transpose());
}
template <class S> Vec8<S> study(const SE3<S>& m) { return StudyParameters<S>::fromSE3(m).coeffs(); }
template <class S> SE3<S> motionOf(const Vec8<S>& x) { return StudyParameters<S>(x).toSE3(); }
template <class S> SE3<S> translation(const Vec3<S>& t) { return SE3<S>(SO3<S>(), t); }
/// The Study quadric a·c = 0 as a symmetric 8 × 8 matrix.
template <class S> MatX<S> quadricQ() { return studyQuadricMatrix<S>(); }
/// |z| of a complex number in S (the scalar's own sqrt).
template <class S> S cabs(const std::complex<S>& z) { return sqrt(S(z.real() * z.real() + z.imag() * z.imag())); }

// Thresholds: tol<S>() = 256 ε bounds the rounding of the short sums checked (quadratic forms of
// unit vectors, 8-term products: a few ε each; 5.7e-14 in double as before); 1024 ε after a
// Gram–Schmidt, two reflections or a composition of three motions (2.3e-13 in double as before).

// ---- GF-11.2.4-quadric-grassmannians ---------------------------------------------------------
// G^Hy(k, 8): isotropic k-planes of Hy' = diag(I₄, −I₄). Dimension twice: the tangent space cut out
// by the linearised isotropy conditions, and the orbit of O(4) × O(4) (rank of its Lie algebra's
// action); both against k(8 − k) − k(k + 1)/2 = 6, 9, 9, 6.
template <class S> void quadricGrassmannians(Context& c) {
  auto g = rng(11241);
  MatX<S> H = MatX<S>::Identity(8, 8);
  H.bottomRightCorner(4, 4) *= S(-1);
  // The 12 generators of o(4) ⊕ o(4).
  std::vector<MatX<S>> gens;
  for (int block = 0; block < 2; ++block)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        MatX<S> e = MatX<S>::Zero(8, 8);
        e(4 * block + i, 4 * block + j) = S(1);
        e(4 * block + j, 4 * block + i) = S(-1);
        gens.push_back(e);
      }
  for (int k = 1; k <= 4; ++k) {
    // A random isotropic k-plane: columns (u; R u), R ∈ SO(4).
    const Mat4<S> R = randomSO4<S>(g);
    MatX<S> V(8, k);
    for (int i = 0; i < k; ++i) {
      const Vec4<S> u = unit4<S>(g);
      V.col(i) << u, R * u;
    }
    V = orthonormalColumns(V);
    const S iso = mul(mul(V.transpose(), H), V).cwiseAbs().maxCoeff();
    const MatX<S> C = detail::smallComplement<S>(V);  // 8 × (8 − k)
    // Tangent: V + C X, X ∈ R^{(8−k)×k}; the isotropy conditions sym(Vᵀ H C X) = 0.
    const int n = (8 - k) * k, m = k * (k + 1) / 2;
    MatX<S> J(m, n);
    for (int col = 0; col < n; ++col) {
      MatX<S> X = MatX<S>::Zero(8 - k, k);
      X(col % (8 - k), col / (8 - k)) = S(1);
      const MatX<S> D = mul(mul(mul(V.transpose(), H), C), X);
      const MatX<S> Ssym = D + D.transpose();
      int row = 0;
      for (int i = 0; i < k; ++i)
        for (int j = i; j < k; ++j) J(row++, col) = Ssym(i, j);
    }
    const int tangentDim = n - rankOf<S>(J);
    // Orbit: the velocities Cᵀ E V of the 12 generators.
    MatX<S> A(n, 12);
    for (int e = 0; e < 12; ++e) {
      const MatX<S> v = mul(mul(C.transpose(), gens[std::size_t(e)]), V);
      A.col(e) = Eigen::Map<const VecX<S>>(v.data(), n);
    }
    const int orbitDim = rankOf<S>(A);
    const int expected = k * (8 - k) - k * (k + 1) / 2;
    c.checkResidual("k = " + std::to_string(k) + ": the random k-plane is isotropic (256 ε)", iso, tol<S>());
    c.checkEqual("dim G^Hy(" + std::to_string(k) + ", 8) from the tangent space = k(8 − k) − k(k + 1)/2", expected, tangentDim);
    c.checkEqual("… = the orbit dimension of O(4) × O(4) (12 − dim isotropy)", expected, orbitDim);
  }
  c.note("dim G^Hy(1,8) = 6 = dim SO(4) (the quadric), dim G^Hy(4,8) = 6 = dim O(4) (A- or B-planes: triality); "
         "G^Hy(2,8): 12 − 3 (O(2)³), G^Hy(3,8): 12 − 3 (O(3) × O(1)²) = 9, as the book's quotients say.");
}

// ---- GF-11.2.4-isotropic-2-plane-normal-form -------------------------------------------------
/// The Householder reflection of R^n taking the unit vector u to e₁ (the identity when u = e₁).
template <class S> MatX<S> reflectionTo(const VecX<S>& u) {
  VecX<S> w = u;
  w(0) -= S(1);
  const S nw = w.norm();
  if (nw <= tol<S>()) return MatX<S>::Identity(u.size(), u.size());
  w /= nw;
  return MatX<S>::Identity(u.size(), u.size()) - S(2) * mul(w, w.transpose());
}
template <class S> VecX<S> unitOf(const VecX<S>& v) { return VecX<S>(v / S(v.norm())); }
template <class S> void isotropicNormalForm(Context& c) {
  auto g = rng(11242);
  S worstFifth = S(0), worstStd = S(0), worstSpan = S(0), worstIso = S(0);
  MatX<S> Std = MatX<S>::Zero(8, 2);
  Std(0, 0) = Std(4, 0) = Std(1, 1) = Std(5, 1) = S(1);
  for (int n = 0; n < 50; ++n) {
    const Mat4<S> R = randomSO4<S>(g);
    const Vec4<S> w1u = unit4<S>(g);
    const S s1 = uni<S>(g, 0.5, 2);
    const Vec4<S> w2u = unit4<S>(g);
    const S s2 = uni<S>(g, 0.5, 2);
    const Vec4<S> u1 = w1u * s1, u2 = w2u * s2;
    VecX<S> v1(8), v2(8);
    v1 << u1, R * u1;
    v2 << u2, R * u2;
    // M₁, M₂ ∈ O(4) (reflections) taking x₁ and y₁ to |x₁| e₁ (|x₁| = |y₁| by isotropy).
    const MatX<S> M1 = reflectionTo<S>(unitOf<S>(v1.head(4))), M2 = reflectionTo<S>(unitOf<S>(v1.tail(4)));
    MatX<S> T1 = MatX<S>::Zero(8, 8);
    T1.topLeftCorner(4, 4) = M1;
    T1.bottomRightCorner(4, 4) = M2;
    VecX<S> w1 = mul(T1, v1), w2 = mul(T1, v2);
    w1 /= S(w1(0));
    w2 -= S(w2(0)) * w1;  // the first coordinate 0 forces the fifth to vanish (Hy'(v₁, v₂) = 0)
    worstFifth = std::max<S>(worstFifth, S(abs(w2(4)) / w2.norm()));
    // R₁, R₂ ∈ O(3) on coordinates 1–3 and 5–7 taking the remaining parts to e₁.
    const MatX<S> R1 = reflectionTo<S>(unitOf<S>(w2.segment(1, 3))), R2 = reflectionTo<S>(unitOf<S>(w2.segment(5, 3)));
    MatX<S> T2 = MatX<S>::Identity(8, 8);
    T2.block(1, 1, 3, 3) = R1;
    T2.block(5, 5, 3, 3) = R2;
    VecX<S> z2 = mul(T2, w2);
    z2 /= S(z2(1));
    const VecX<S> z1 = mul(T2, w1);
    worstStd = std::max<S>({worstStd, S((z1 - Std.col(0)).norm()), S((z2 - Std.col(1)).norm())});
    MatX<S> V(8, 2);
    V << v1, v2;
    worstSpan = std::max<S>(worstSpan, S((projector<S>(MatX<S>(mul(mul(T2, T1), V))) - projector<S>(Std)).cwiseAbs().maxCoeff()));
    // The isotropy group diag(A, B, A, C), A, B, C ∈ O(2), keeps the standard plane.
    auto o2 = [&](bool reflect) {
      const S t = uni<S>(g, -3, 3);
      MatX<S> m(2, 2);
      m << cos(t), -sin(t), sin(t), cos(t);
      if (reflect) m.col(1) *= S(-1);
      return m;
    };
    const MatX<S> A = o2(n % 2 == 0), B = o2(n % 3 == 0), Cm = o2(false);
    MatX<S> D = MatX<S>::Zero(8, 8);
    D.block(0, 0, 2, 2) = A;
    D.block(2, 2, 2, 2) = B;
    D.block(4, 4, 2, 2) = A;
    D.block(6, 6, 2, 2) = Cm;
    worstIso = std::max<S>(worstIso, S((projector<S>(MatX<S>(mul(D, Std))) - projector<S>(Std)).cwiseAbs().maxCoeff()));
  }
  c.checkResidual("after v₁ ↦ (1,0,0,0,1,0,0,0), clearing the first coordinate of v₂ clears the fifth (50 planes; 256 ε)",
                  worstFifth, tol<S>());
  c.checkResidual("O(4) × O(4) reduces every isotropic 2-plane to v₁ = e₀ + e₄, v₂ = e₁ + e₅ (1024 ε)", worstStd, tol<S>(1024));
  c.checkResidual("… the transformed span is the standard span (projectors; 1024 ε)", worstSpan, tol<S>(1024));
  c.checkResidual("diag(A, B, A, C), A, B, C ∈ O(2), preserves the standard 2-plane (256 ε)", worstIso, tol<S>());
}

// ---- GF-11.3-flag-projections-fibres ---------------------------------------------------------
template <class S> void flagFibres(Context& c) {
  auto g = rng(1131);
  // (1) Point to point: g₁ SO(3)_O g₂⁻¹ is an A-plane, and all its motions take s to t.
  S worstMaps = S(0), worstContains = S(0);
  int aPlanes = 0;
  const int N = 20;
  for (int n = 0; n < N; ++n) {
    const Vec3<S> s = rv3<S>(g), t = rv3<S>(g);
    const auto P = StudyPlane<S>::rotationsAbout(Vec3<S>::Zero())
                       .leftTranslated(DualQuaternion<S>::fromSE3(translation<S>(t)))
                       .rightTranslated(DualQuaternion<S>::fromSE3(translation<S>(Vec3<S>(-s))));
    aPlanes += P.kind() == StudyPlaneKind::A;
    for (int k = 0; k < 5; ++k) {
      const Vec8<S> x = P.point(unit4<S>(g));
      worstMaps = std::max<S>(worstMaps, S((motionOf<S>(x).act(s) - t).norm()));
      const SE3<S> m = translation<S>(t) * SE3<S>(SO3<S>::Random(g), Vec3<S>::Zero()) * translation<S>(Vec3<S>(-s));
      worstContains = std::max<S>(worstContains, P.residual(study<S>(m)));
    }
  }
  c.checkEqual("point → point: g₁ SO(3)_O g₂⁻¹ is an A-plane (20 random pairs)", N, aPlanes);
  c.checkResidual("… every motion in it takes s to t (1024 ε)", worstMaps, tol<S>(1024));
  c.checkResidual("… and every motion taking s to t lies in it (1024 ε)", worstContains, tol<S>(1024));
  // (2) Pointed directed line → pointed directed line: a line of the quadric (rank 2, isotropic).
  // (3) Lined plane → lined plane: a line through a point of the A-plane at infinity (a translation).
  // (4) Directed line → directed line: a quadric surface, the 3-plane ∩ the Study quadric.
  const Vec3<S> s = rv3<S>(g), t = rv3<S>(g);
  const SO3<S> R0 = SO3<S>::Random(g);
  const Vec3<S> d = unit3<S>(g), e = R0.act(d);
  MatX<S> pointed(8, 6), lined(8, 6), directed(8, 12);
  for (int k = 0; k < 6; ++k) {
    const S phi = uni<S>(g, -3, 3), lambda = uni<S>(g, -2, 2);
    const SO3<S> spin = SO3<S>::fromAxisAngle(e, phi);
    // the motions x ↦ t + spin R0 (x − s): s ↦ t, d ↦ e.
    const SE3<S> m = translation<S>(t) * SE3<S>(spin * R0, Vec3<S>::Zero()) * translation<S>(Vec3<S>(-s));
    pointed.col(k) = study<S>(m);
    // lined plane (plane ⟂ d through s, line through s along a ⟂ direction): fixed up to sliding
    // along the line: x ↦ t + λ f + R0 (x − s), f = R0 (line direction).
    const Vec3<S> lineDir = d.unitOrthogonal();
    lined.col(k) = study<S>(translation<S>(Vec3<S>(t + lambda * R0.act(lineDir))) * SE3<S>(R0, Vec3<S>::Zero()) *
                            translation<S>(Vec3<S>(-s)));
    // directed line through s along d → through t along e: spin about e and slide along it.
    directed.col(2 * k) = study<S>(translation<S>(Vec3<S>(t + lambda * e)) * SE3<S>(spin * R0, Vec3<S>::Zero()) *
                                   translation<S>(Vec3<S>(-s)));
    directed.col(2 * k + 1) = study<S>(translation<S>(Vec3<S>(t - S(frac<S>(7, 10) * lambda) * e)) *
                                       SE3<S>(SO3<S>::fromAxisAngle(e, S(-phi / S(2))) * R0, Vec3<S>::Zero()) *
                                       translation<S>(Vec3<S>(-s)));
  }
  const int lineRank = rankOf<S>(pointed), linedRank = rankOf<S>(lined), dirRank = rankOf<S>(directed);
  // isotropy of the pointed fibre: every combination stays on the quadric.
  const MatX<S> Q = quadricQ<S>();
  const MatX<S> Bp = orthonormalColumns(MatX<S>(pointed.leftCols(2)));
  const S lineIso = mul(mul(Bp.transpose(), Q), Bp).cwiseAbs().maxCoeff();
  // lined fibre: its span meets a = 0 (a combination of two translates with a = 0).
  const MatX<S> Bl = orthonormalColumns(MatX<S>(lined.leftCols(2)));
  const S linedInfinity = detail::smallSingularValues<S>(MatX<S>(Bl.topRows(4))).back();
  // directed fibre: the 3-plane is not in the quadric, but the motions are on it.
  const MatX<S> Bd = orthonormalColumns(MatX<S>(directed.leftCols(4)));
  S dirOn = S(0);
  for (int k = 0; k < 12; ++k) {
    const VecX<S> x = directed.col(k);
    dirOn = std::max<S>(dirOn, S(abs(S(x.dot(mul(Q, x)))) / x.squaredNorm()));
  }
  const S dirOff = mul(mul(Bd.transpose(), Q), Bd).cwiseAbs().maxCoeff();
  c.checkEqual("pointed directed line → another: the motions span a line (rank 2)", 2, lineRank);
  c.checkResidual("… which lies in the quadric (isotropic: max |BᵀQB|; 256 ε)", lineIso, tol<S>());
  c.checkEqual("lined plane → another: the motions span a line (rank 2)", 2, linedRank);
  c.checkResidual("… meeting the A-plane at infinity (smallest singular value of its a-part; 256 ε)", linedInfinity, tol<S>());
  c.checkEqual("directed line → another (SO(2) × R): the motions span a 3-plane (rank 4)", 4, dirRank);
  c.checkResidual("… every such motion is on the Study quadric (256 ε)", dirOn, tol<S>());
  c.recordIn<S>("… but the 3-plane is not in it: the fibre is a quadric surface (max |BᵀQB| > 0.01)", "> 0.01",
                toString(dirOff, 4), dirOff, frac<S>(1, 100), dirOff > frac<S>(1, 100));
}

// ---- GF-11.3-table-11.1 -----------------------------------------------------------------------
// Dimensions of the flag manifolds twice: in R⁴, 6 − dim of the stabiliser in so(4) of the standard
// oriented flag; in R³, 6 − dim of the stabiliser in se(3) of the figure (Saletan contraction).
// The constraint matrices have small integer entries: exact in every scalar.
template <class S> MatX<S> stacked(const std::vector<RowX<S>>& rows) {
  MatX<S> A(Eigen::Index(rows.size()), 6);
  for (std::size_t k = 0; k < rows.size(); ++k) A.row(Eigen::Index(k)) = rows[k];
  return A;
}
template <class S> int so4OrbitDim(const std::vector<int>& dims) {
  // X ∈ so(4) keeps V_k = span(e₀..e_{d−1}) iff X_{ab} = 0 for a ≥ d > b.
  std::vector<RowX<S>> rows;
  int idx = 0;
  std::array<std::array<int, 4>, 4> var{};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) var[i][j] = var[j][i] = idx++;
  for (int d : dims)
    for (int a = d; a < 4; ++a)
      for (int b = 0; b < d; ++b) {
        RowX<S> r = RowX<S>::Zero(6);
        r(var[a][b]) = S(1);
        rows.push_back(r);
      }
  if (rows.empty()) return 0;
  return rankOf<S>(stacked<S>(rows));  // the orbit dimension = 6 − dim stabiliser = rank of the constraints
}
enum Fig : unsigned { Pt = 1, Axis = 2, PlaneN = 4, LineInPlane = 8, Frame = 16 };
template <class S> int se3OrbitDim(unsigned fig) {
  // Constraints on a twist (ω, v), velocity field u(x) = v + ω × x; the figure at the origin:
  // point O; line = z-axis; plane z = 0 (normal z); line in the plane = x-axis.
  using Rows = std::vector<RowX<S>>;
  Rows rows;
  auto velocityRows = [&](const Vec3<S>& x) {  // the 3 rows of u(x)
    Rows r(3, RowX<S>::Zero(6));
    for (int i = 0; i < 3; ++i) {
      r[std::size_t(i)](3 + i) = S(1);
      const Vec3<S> ei = Vec3<S>::Unit(i);  // (ω × x)_i = ω · (x × e_i)
      const Vec3<S> coef = x.cross(ei);
      for (int k = 0; k < 3; ++k) r[std::size_t(i)](k) = coef(k);
    }
    return r;
  };
  auto omegaCross = [&](const Vec3<S>& dir) {  // rows of ω × dir
    Rows r(3, RowX<S>::Zero(6));
    for (int i = 0; i < 3; ++i) {
      const Vec3<S> coef = dir.cross(Vec3<S>::Unit(i));
      for (int k = 0; k < 3; ++k) r[std::size_t(i)](k) = coef(k);
    }
    return r;
  };
  auto add = [&](const Rows& r) { rows.insert(rows.end(), r.begin(), r.end()); };
  auto component = [&](const Rows& r, const Vec3<S>& n) {  // n · (3 rows)
    RowX<S> out = RowX<S>::Zero(6);
    for (int i = 0; i < 3; ++i) out += n(i) * r[std::size_t(i)];
    return out;
  };
  const Vec3<S> O = Vec3<S>::Zero(), X = Vec3<S>::UnitX(), Y = Vec3<S>::UnitY(), Z = Vec3<S>::UnitZ();
  if (fig & Frame) {
    add(velocityRows(O));
    add(omegaCross(X));
    add(omegaCross(Y));
  }
  if (fig & Pt) add(velocityRows(O));
  if (fig & Axis) {  // the z-axis kept as a directed line: ω × z = 0, u(O) and u(z) along z
    add(omegaCross(Z));
    rows.push_back(component(velocityRows(O), X));
    rows.push_back(component(velocityRows(O), Y));
    rows.push_back(component(velocityRows(Z), X));
    rows.push_back(component(velocityRows(Z), Y));
  }
  if (fig & PlaneN) {  // the oriented plane z = 0: ω × z = 0 and u · z = 0 on the plane
    add(omegaCross(Z));
    for (const Vec3<S>& p : {O, X, Y}) rows.push_back(component(velocityRows(p), Z));
  }
  if (fig & LineInPlane) {  // the x-axis in it: ω × x = 0, u(O), u(x) along x
    add(omegaCross(X));
    for (const Vec3<S>& p : {O, X}) {
      rows.push_back(component(velocityRows(p), Y));
      rows.push_back(component(velocityRows(p), Z));
    }
  }
  return rankOf<S>(stacked<S>(rows));
}
template <class S> void table111(Context& c) {
  struct Row {
    const char* flag;
    std::vector<int> dims;
    const char* figure;
    unsigned fig;
    int expected;
  };
  const std::vector<Row> rows = {{"F⁺(1,2,3;4)", {1, 2, 3}, "soma", Frame, 6},
                                 {"F⁺(1,2;4)", {1, 2}, "pointed line", Pt | Axis, 5},
                                 {"F⁺(2,3;4)", {2, 3}, "lined plane", PlaneN | LineInPlane, 5},
                                 {"F⁺(1,3;4)", {1, 3}, "pointed plane", Pt | PlaneN, 5},
                                 {"F⁺(1;4)", {1}, "point", Pt, 3},
                                 {"F⁺(2;4)", {2}, "directed line", Axis, 4},
                                 {"F⁺(3;4)", {3}, "oriented plane", PlaneN, 3}};
  for (const Row& r : rows) {
    c.checkEqual(std::string(r.flag) + ": dim = 6 − dim stabiliser in so(4)", r.expected, so4OrbitDim<S>(r.dims));
    c.checkEqual(std::string("… = the degrees of freedom of a ") + r.figure + " in R³ (6 − dim stabiliser in se(3))", r.expected,
                 se3OrbitDim<S>(r.fig));
  }
}

// ---- GF-11.5-P1xP1-five-points ----------------------------------------------------------------
template <class S> void p1xp1(Context& c) {
  using C = std::complex<S>;
  auto g = rng(1151);
  // x₀y₁² + x₁y₀² (class α₀β₁ + 2α₁β₀ in the book's notation: degree 1 in x, 2 in y) and a generic
  // curve of degree 2 in x, 1 in y: in the chart x₀ = y₀ = 1, x = −y² on the first, so the second
  // gives a(−y²) + b(−y²) y = 0 of degree 5 (a, b quadratics in x).
  std::array<S, 3> a, b;
  for (auto& v : a) v = uni<S>(g);
  for (auto& v : b) v = uni<S>(g);
  std::vector<S> poly(6, S(0));  // Σ poly_k y^k
  for (int i = 0; i < 3; ++i) {
    const S sgn = (i % 2 == 0) ? S(1) : S(-1);  // (−y²)^i
    poly[std::size_t(2 * i)] += a[std::size_t(i)] * sgn;
    poly[std::size_t(2 * i + 1)] += b[std::size_t(i)] * sgn;
  }
  const auto roots = polynomialRoots<S>(poly);
  S worst = S(0), minSep = S(0);
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const C y = roots[i], x = -y * y;
    const C f = x + y * y;
    const C h = C(a[0]) + C(a[1]) * x + C(a[2]) * x * x + (C(b[0]) + C(b[1]) * x + C(b[2]) * x * x) * y;
    const S ay = cabs<S>(y);
    worst = std::max<S>({worst, cabs<S>(f), S(cabs<S>(h) / (S(1) + ay * ay * ay * ay * ay))});
    for (std::size_t j = 0; j < i; ++j) {
      const S sep = cabs<S>(C(roots[i] - roots[j]));
      minSep = (i == 1 && j == 0) ? sep : std::min<S>(minSep, sep);
    }
  }
  c.checkEqual("the curves (1,2) and (2,1) meet in 5 points (roots of the degree-5 eliminant)", 5, int(roots.size()));
  // |h|/(1 + |y|⁵) at an Aberth root: the root's own backward error (a few ε·Σ|c_k||y|^k) plus the
  // rounding of evaluating h in its factored form (≈ 20 products): 1024 ε (2.3e-13 in double; 1e-12 before).
  c.checkResidual("… each on both curves (relative to 1 + |y|⁵; 1024 ε)", worst, tol<S>(1024));
  c.recordIn<S>("… and they are distinct (minimum separation)", "> 1e-3", toString(minSep, 4), minSep, frac<S>(1, 1000),
                minSep > frac<S>(1, 1000));
  // The ring: (a α₀β₁ + b α₁β₀)(c α₀β₁ + d α₁β₀) = (ad + bc) × point, with α₁² = β₁² = 0.
  const int ringCount = 1 * 1 + 2 * 2;
  c.checkEqual("ring: (α₀β₁ + 2α₁β₀)(2α₀β₁ + α₁β₀) = 1·1 + 2·2 = 5 points", 5, ringCount);
}

// ---- GF-11.5-bezout-halphen -------------------------------------------------------------------
// Halphen on the Klein quadric: congruences of bidegree (m, n) share m₁m₂ + n₁n₂ lines. α-planes
// (lines through a point) are (1, 0), β-planes (lines in a plane) (0, 1), the lines meeting two
// skew lines (1, 1).
template <class S> MatX<S> alphaPlane(const Vec3<S>& P, std::mt19937_64& g) {
  MatX<S> m(6, 3);
  for (int k = 0; k < 3; ++k) m.col(k) = PluckerLine<S>::throughPoints(P, Vec3<S>(P + rv3<S>(g))).coords();
  return m;
}
template <class S> MatX<S> betaPlane(const Vec3<S>& n, const S& dist, std::mt19937_64& g) {
  const Vec3<S> u = n.unitOrthogonal(), w = n.cross(u);
  auto pointIn = [&] {
    const S x = uni<S>(g), y = uni<S>(g);
    return Vec3<S>(dist * n + x * u + y * w);
  };
  MatX<S> m(6, 3);
  for (int k = 0; k < 3; ++k) {
    const Vec3<S> p1 = pointIn(), p2 = pointIn();
    m.col(k) = PluckerLine<S>::throughPoints(p1, p2).coords();
  }
  return m;
}
/// Projective dimension of the intersection of two linear subspaces of P⁵ (columns span them).
template <class S> int meetDim(const MatX<S>& A, const MatX<S>& B) {
  MatX<S> AB(6, A.cols() + B.cols());
  AB << A, B;
  return int(A.cols() + B.cols()) - rankOf<S>(AB) - 1;
}
template <class S> void bezoutHalphen(Context& c) {
  auto g = rng(1152);
  const Vec3<S> P = rv3<S>(g), Qp = rv3<S>(g), n1 = unit3<S>(g), n2 = unit3<S>(g);
  const MatX<S> aP = alphaPlane<S>(P, g), aQ = alphaPlane<S>(Qp, g);
  c.checkEqual("α ∩ α: two points share one line (1·1 + 0·0 = 1: a point of P⁵, dim 0)", 0, meetDim<S>(aP, aQ));
  const MatX<S> b1 = betaPlane<S>(n1, frac<S>(3, 10), g), b2 = betaPlane<S>(n2, frac<S>(-1, 5), g);
  c.checkEqual("β ∩ β: two planes share one line (0·0 + 1·1 = 1)", 0, meetDim<S>(b1, b2));
  const MatX<S> aFar = alphaPlane<S>(Vec3<S>(P + S(5) * n1), g), b3 = betaPlane<S>(n1, frac<S>(3, 10), g);
  c.checkEqual("α ∩ β: a point off a plane: no common line (1·0 + 0·1 = 0: empty, dim −1)", -1, meetDim<S>(aFar, b3));
  // (1,1)·(1,1) = 2: the lines meeting four random lines. The four linear conditions ⟨ℓ, Lᵢ⟩ = 0
  // leave a pencil ℓ = x + s y in P⁵; the Klein quadric on it is a quadratic in s: 2 solutions.
  MatX<S> L(4, 6);
  std::vector<PluckerLine<S>> lines;
  // The four lines all meet a chosen line ℓ₀, so that the instance has real transversals (ℓ₀ and
  // a second one: complex roots come in pairs).
  const Vec3<S> q0 = rv3<S>(g), q1 = rv3<S>(g);
  const PluckerLine<S> l0 = PluckerLine<S>::throughPoints(q0, q1);
  for (int i = 0; i < 4; ++i) {
    const S u = uni<S>(g, -2, 2);
    const Vec3<S> other = rv3<S>(g);
    lines.push_back(PluckerLine<S>::throughPoints(Vec3<S>(q0 + u * (q1 - q0)), other));
    const Vec6<S> s = lines.back().coords();
    L.row(i) << s.template tail<3>().transpose(), s.template head<3>().transpose();  // ⟨ℓ, s⟩ = ω·v_s + v·ω_s
  }
  const MatX<S> K = detail::smallComplement<S>(orthonormalColumns(MatX<S>(L.transpose())));  // 6 × 2: the pencil
  const Vec6<S> x = K.col(0), y = K.col(1);
  auto klein = [](const Vec6<S>& a, const Vec6<S>& b) {
    return S(a.template head<3>().dot(b.template tail<3>()) + a.template tail<3>().dot(b.template head<3>()));
  };
  // (x + s y)·(x + s y) = klein(x,x) + 2s klein(x,y) + s² klein(y,y) (Klein form ⟨a,a⟩ = 2 ω·v).
  const auto roots = polynomialRoots<S>({klein(x, x), S(2 * klein(x, y)), klein(y, y)});
  c.checkEqual("(1,1) ∩ (1,1): lines meeting four random lines (1·1 + 1·1 = 2)", 2, int(roots.size()));
  // A root is real when its imaginary part is below √ε relative (a real double root splits by at most that).
  auto isReal = [](const std::complex<S>& s) { return abs(s.imag()) <= Tolerance<S>::sqrtEpsilon() * (S(1) + cabs<S>(s)); };
  S worst = S(0);
  int real = 0;
  for (const auto& s : roots) {
    if (!isReal(s)) continue;
    ++real;
    const Vec6<S> l = x + s.real() * y;
    for (const auto& m : lines) worst = std::max<S>(worst, S(abs(klein(l, m.coords())) / (l.norm() * m.coords().norm())));
  }
  // ℓ₀ is one of them (as a point of P⁵: 1 − cos² of the angle to the nearer root).
  S toL0 = S(1);
  const Vec6<S> l0c = l0.coords() / S(l0.coords().norm());
  for (const auto& s : roots) {
    if (!isReal(s)) continue;
    const Vec6<S> lr = x + s.real() * y;
    const Vec6<S> l = lr / S(lr.norm());
    toL0 = std::min<S>(toL0, S(abs(S(S(1) - l.dot(l0c) * l.dot(l0c)))));  // |1 − cos²|: rounding can make it −ε
  }
  c.checkEqual("… both transversals are real for this instance (four lines meeting ℓ₀)", 2, real);
  c.checkResidual("… the real ones meet all four (reciprocal products; 1024 ε)", worst, tol<S>(1024));
  c.checkResidual("… and ℓ₀ is one of them (1 − cos² in P⁵; 1024 ε)", toL0, tol<S>(1024));
}

// ---- GF-11.5-cell-decomposition ---------------------------------------------------------------
/// A basis of {x : Aᵀ Q x = 0} (the polar of span A), 8 × (8 − rank).
template <class S> MatX<S> polar(const MatX<S>& A) {
  return detail::smallComplement<S>(orthonormalColumns(MatX<S>(mul(quadricQ<S>(), A))));
}
template <class S> int restrictedRank(const MatX<S>& W) { return rankOf<S>(MatX<S>(mul(mul(W.transpose(), quadricQ<S>()), W))); }
template <class S> void cellDecomposition(Context& c) {
  auto g = rng(1153);
  // P₀ ⊂ P₁ ⊂ P₂ in the quadric: the identity, the rotations about z, plus c₁ (pairwise a·c = 0),
  // moved by a random motion x ↦ g x (which keeps the quadric).
  const SO3<S> R = SO3<S>::Random(g);
  const Vec3<S> t = rv3<S>(g);
  const Eigen::Matrix<S, 8, 8> Lg = dualQuaternionLeftMatrix<S>(DualQuaternion<S>::fromSE3(SE3<S>(R, t)));
  MatX<S> P2(8, 3);
  P2 << Lg.col(0), Lg.col(3), Lg.col(5);
  const MatX<S> P0 = P2.leftCols(1), P1 = P2.leftCols(2);
  c.checkResidual("P₀ ⊂ P₁ ⊂ P₂ lie in the quadric (256 ε)", S(mul(mul(P2.transpose(), quadricQ<S>()), P2).cwiseAbs().maxCoeff()),
                  tol<S>());
  // Q₅ = P₆ ∩ Q_S with P₆ the tangent hyperplane at P₀: singular at P₀ (rank 6 on the 7-dim P₆).
  const MatX<S> P6 = polar<S>(P0);
  c.checkEqual("tangent hyperplane P₆ (dim 7 as a subspace of R⁸)", 7, int(P6.cols()));
  c.checkEqual("Q₅ = P₆ ∩ Q_S: rank 6 on P₆, singular exactly at P₀", 6, restrictedRank<S>(P6));
  const MatX<S> P5 = polar<S>(P1);
  c.checkEqual("polar 5-plane of P₁: Q₄ has rank 4 there (a double line: the kernel is P₁)", 4, restrictedRank<S>(P5));
  const MatX<S> P4 = polar<S>(P2);
  c.checkEqual("polar 4-plane of P₂: rank 2 (P₄ ∩ Q₄ is a pair of 3-planes)", 2, restrictedRank<S>(P4));
  // Factor the rank-2 form on P₄ into two hyperplanes of P₄: an A-plane and a B-plane through P₂.
  std::vector<S> vals;
  MatX<S> vecs;
  detail::smallSymEigen<S>(MatX<S>(mul(mul(P4.transpose(), quadricQ<S>()), P4)), vals, vecs);
  const VecX<S> up = vecs.col(0), um = vecs.col(Eigen::Index(vals.size()) - 1);
  int kinds[2] = {0, 0};
  S worstIn = S(0);
  for (int sgn : {1, -1}) {
    const VecX<S> form = S(sqrt(vals.front())) * up + S(S(sgn) * sqrt(S(-vals.back()))) * um;
    const MatX<S> sub = mul(P4, detail::smallComplement<S>(MatX<S>(form / S(form.norm()))));  // 8 × 4
    const Eigen::Matrix<S, 8, 4> pts = sub;
    const auto plane = StudyPlane<S>::fromSpan(pts);
    kinds[plane.kind() == StudyPlaneKind::A ? 0 : 1]++;
    for (int k = 0; k < 3; ++k) worstIn = std::max<S>(worstIn, plane.residual(Vec8<S>(P2.col(k))));
  }
  c.checkEqual("… the two 3-planes are one A-plane and one B-plane", "1 A, 1 B",
               std::to_string(kinds[0]) + " A, " + std::to_string(kinds[1]) + " B");
  c.checkResidual("… both contain P₂ (1024 ε)", worstIn, tol<S>(1024));
  // Cells of real dimension 0, 2, 4, 6, 6, 8, 10, 12: χ(Q⁶) = 8. Independent count: a generic C*
  // action a_i ↦ t^{w_i} a_i, c_i ↦ t^{−w_i} c_i keeps Σ a_i c_i; its fixed points in P⁷ are the 8
  // coordinate points (distinct weights ±w_i), all on the quadric: χ = 8.
  const std::array<int, 8> cellDims{0, 2, 4, 6, 6, 8, 10, 12};
  int onQuadric = 0;
  for (int k = 0; k < 8; ++k) {
    const VecX<S> e = VecX<S>::Unit(8, k);
    onQuadric += abs(S(e.dot(mul(quadricQ<S>(), e)))) == S(0);
  }
  c.checkEqual("cells of the decomposition (book): 8, all of even dimension", 8, int(cellDims.size()));
  c.checkEqual("fixed points of a generic torus action on Q⁶ (= χ(Q⁶) = 2m + 2, m = 3)", 8, onQuadric);
}

SOMA_STUDY_SCALAR("GF-11.2.4-quadric-grassmannians", "Isotropic k-planes of Hy: dimensions 6, 9, 9, 6 (two ways)", "GF §11.2.4",
                  quadricGrassmannians);
SOMA_STUDY_SCALAR("GF-11.2.4-isotropic-2-plane-normal-form", "O(4) × O(4) reduces every isotropic 2-plane to the standard one",
                  "GF §11.2.4", isotropicNormalForm);
SOMA_STUDY_SCALAR("GF-11.3-flag-projections-fibres", "Fibres of the flag projections: A-plane, lines, quadric surface",
                  "GF §11.3", flagFibres);
SOMA_STUDY_SCALAR("GF-11.3-table-11.1", "Table 11.1: flag manifolds, homogeneous spaces, figures in R³ (dimensions two ways)",
                  "GF §11.3", table111);
SOMA_STUDY_SCALAR("GF-11.5-P1xP1-five-points", "Curves of classes α₀β₁ + 2α₁β₀ and 2α₀β₁ + α₁β₀ meet in five points", "GF §11.5",
                  p1xp1);
SOMA_STUDY_SCALAR("GF-11.5-bezout-halphen", "Halphen: congruences (m₁,n₁), (m₂,n₂) share m₁m₂ + n₁n₂ lines", "GF §11.5",
                  bezoutHalphen);
SOMA_STUDY_SCALAR("GF-11.5-cell-decomposition", "The cell decomposition of the Study quadric: Q₅, Q₄, P_A ∪ P_B; χ = 8",
                  "GF §11.5", cellDecomposition);

}  // namespace
}  // namespace soma::studies::gf11::SOMA_UNITY_ID
