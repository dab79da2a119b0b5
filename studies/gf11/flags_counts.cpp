// Studies of GF §11.2.4 (quadric Grassmannians), §11.3 (partial flags and the fibres of their
// projections, Table 11.1) and the structural parts of §11.5 (Bézout–Halphen, the P¹ × P¹ example,
// the cell decomposition of the Study quadric). Double precision: linear algebra on 8-vectors.
#include "soma/algebra/polynomial.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/geometry/lines/line.hpp"
#include "soma/geometry/study/constraint_quadrics.hpp"
#include "soma/geometry/study/quaternion_matrices.hpp"
#include "soma/geometry/study/study_plane.hpp"
#include "soma/studies/study.hpp"

#include <random>

namespace soma::studies::gf11flags::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using S = double;
using MatX = Eigen::MatrixXd;
using VecX = Eigen::VectorXd;
constexpr const char* kChapter = "GF 11 — The Study quadric";

std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }
double uni(std::mt19937_64& g, double lo = -1, double hi = 1) { return std::uniform_real_distribution<double>(lo, hi)(g); }
Vec3<S> vec3(std::mt19937_64& g) { return Vec3<S>(uni(g), uni(g), uni(g)); }
Vec4<S> unit4(std::mt19937_64& g) { return Vec4<S>(uni(g), uni(g), uni(g), uni(g)).normalized(); }
/// A random rotation of R⁴: q ↦ g₁ q g₂* (left and right quaternion matrices, GF §9.3).
Mat4<S> randomSO4(std::mt19937_64& g) {
  const Vec4<S> g1 = unit4(g), g2 = unit4(g);
  return quaternionLeftMatrix<S>(g1) * quaternionRightMatrix<S>(Vec4<S>(g2(0), -g2(1), -g2(2), -g2(3)));
}
int rankOf(const MatX& m) { return detail::smallNumericalRank<S>(m); }
/// Orthonormal basis of the column span (Gram–Schmidt twice).
MatX orthonormal(const MatX& a) {
  MatX q = a;
  for (Eigen::Index j = 0; j < q.cols(); ++j) {
    for (int pass = 0; pass < 2; ++pass)
      for (Eigen::Index i = 0; i < j; ++i) q.col(j) -= q.col(i) * q.col(i).dot(q.col(j));
    q.col(j).normalize();
  }
  return q;
}
MatX projector(const MatX& a) {
  const MatX q = orthonormal(a);
  return q * q.transpose();
}
Vec8<S> study(const SE3<S>& m) { return StudyParameters<S>::fromSE3(m).coeffs(); }
SE3<S> motionOf(const Vec8<S>& x) { return StudyParameters<S>(x).toSE3(); }
SE3<S> translation(const Vec3<S>& t) { return SE3<S>(SO3<S>(), t); }
double tol(int ulps = 256) { return Tolerance<S>::identity(ulps); }
/// The Study quadric a·c = 0 as a symmetric 8 × 8 matrix.
MatX quadricQ() { return studyQuadricMatrix<S>(); }

// ---- GF-11.2.4-quadric-grassmannians ---------------------------------------------------------
// G^Hy(k, 8): isotropic k-planes of Hy' = diag(I₄, −I₄). Dimension twice: the tangent space cut out
// by the linearised isotropy conditions, and the orbit of O(4) × O(4) (rank of its Lie algebra's
// action); both against k(8 − k) − k(k + 1)/2 = 6, 9, 9, 6.
void quadricGrassmannians(Context& c) {
  auto g = rng(11241);
  MatX H = MatX::Identity(8, 8);
  H.bottomRightCorner(4, 4) *= -1;
  // The 12 generators of o(4) ⊕ o(4).
  std::vector<MatX> gens;
  for (int block = 0; block < 2; ++block)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        MatX e = MatX::Zero(8, 8);
        e(4 * block + i, 4 * block + j) = 1;
        e(4 * block + j, 4 * block + i) = -1;
        gens.push_back(e);
      }
  for (int k = 1; k <= 4; ++k) {
    // A random isotropic k-plane: columns (u; R u), R ∈ SO(4).
    const Mat4<S> R = randomSO4(g);
    MatX V(8, k);
    for (int i = 0; i < k; ++i) {
      const Vec4<S> u = unit4(g);
      V.col(i) << u, R * u;
    }
    V = orthonormal(V);
    const double iso = (V.transpose() * H * V).cwiseAbs().maxCoeff();
    const MatX C = detail::smallComplement<S>(V);  // 8 × (8 − k)
    // Tangent: V + C X, X ∈ R^{(8−k)×k}; the isotropy conditions sym(Vᵀ H C X) = 0.
    const int n = (8 - k) * k, m = k * (k + 1) / 2;
    MatX J(m, n);
    for (int col = 0; col < n; ++col) {
      MatX X = MatX::Zero(8 - k, k);
      X(col % (8 - k), col / (8 - k)) = 1;
      const MatX D = V.transpose() * H * C * X;
      const MatX Ssym = D + D.transpose();
      int row = 0;
      for (int i = 0; i < k; ++i)
        for (int j = i; j < k; ++j) J(row++, col) = Ssym(i, j);
    }
    const int tangentDim = n - rankOf(J);
    // Orbit: the velocities Cᵀ E V of the 12 generators.
    MatX A(n, 12);
    for (int e = 0; e < 12; ++e) {
      const MatX v = C.transpose() * gens[std::size_t(e)] * V;
      A.col(e) = Eigen::Map<const VecX>(v.data(), n);
    }
    const int orbitDim = rankOf(A);
    const int expected = k * (8 - k) - k * (k + 1) / 2;
    c.checkResidual("k = " + std::to_string(k) + ": the random k-plane is isotropic", iso, tol());
    c.checkEqual("dim G^Hy(" + std::to_string(k) + ", 8) from the tangent space = k(8 − k) − k(k + 1)/2", expected, tangentDim);
    c.checkEqual("… = the orbit dimension of O(4) × O(4) (12 − dim isotropy)", expected, orbitDim);
  }
  c.note("dim G^Hy(1,8) = 6 = dim SO(4) (the quadric), dim G^Hy(4,8) = 6 = dim O(4) (A- or B-planes: triality); "
         "G^Hy(2,8): 12 − 3 (O(2)³), G^Hy(3,8): 12 − 3 (O(3) × O(1)²) = 9, as the book's quotients say.");
}

// ---- GF-11.2.4-isotropic-2-plane-normal-form -------------------------------------------------
/// The Householder reflection of R^n taking the unit vector u to e₁ (the identity when u = e₁).
MatX reflectionTo(const VecX& u) {
  VecX w = u;
  w(0) -= 1;
  if (w.norm() <= tol()) return MatX::Identity(u.size(), u.size());
  w.normalize();
  return MatX::Identity(u.size(), u.size()) - 2 * w * w.transpose();
}
void isotropicNormalForm(Context& c) {
  auto g = rng(11242);
  double worstFifth = 0, worstStd = 0, worstSpan = 0, worstIso = 0;
  MatX Std = MatX::Zero(8, 2);
  Std(0, 0) = Std(4, 0) = Std(1, 1) = Std(5, 1) = 1;
  for (int n = 0; n < 50; ++n) {
    const Mat4<S> R = randomSO4(g);
    const Vec4<S> u1 = unit4(g) * uni(g, 0.5, 2), u2 = unit4(g) * uni(g, 0.5, 2);
    VecX v1(8), v2(8);
    v1 << u1, R * u1;
    v2 << u2, R * u2;
    // M₁, M₂ ∈ O(4) (reflections) taking x₁ and y₁ to |x₁| e₁ (|x₁| = |y₁| by isotropy).
    const MatX M1 = reflectionTo(v1.head(4).normalized()), M2 = reflectionTo(v1.tail(4).normalized());
    MatX T1 = MatX::Zero(8, 8);
    T1.topLeftCorner(4, 4) = M1;
    T1.bottomRightCorner(4, 4) = M2;
    VecX w1 = T1 * v1, w2 = T1 * v2;
    w1 /= w1(0);
    w2 -= w2(0) * w1;  // the first coordinate 0 forces the fifth to vanish (Hy'(v₁, v₂) = 0)
    worstFifth = std::max(worstFifth, std::abs(w2(4)) / w2.norm());
    // R₁, R₂ ∈ O(3) on coordinates 1–3 and 5–7 taking the remaining parts to e₁.
    const MatX R1 = reflectionTo(w2.segment(1, 3).normalized()), R2 = reflectionTo(w2.segment(5, 3).normalized());
    MatX T2 = MatX::Identity(8, 8);
    T2.block(1, 1, 3, 3) = R1;
    T2.block(5, 5, 3, 3) = R2;
    VecX z2 = T2 * w2;
    z2 /= z2(1);
    const VecX z1 = T2 * w1;
    worstStd = std::max({worstStd, (z1 - Std.col(0)).norm(), (z2 - Std.col(1)).norm()});
    MatX V(8, 2);
    V << v1, v2;
    worstSpan = std::max(worstSpan, (projector(T2 * T1 * V) - projector(Std)).cwiseAbs().maxCoeff());
    // The isotropy group diag(A, B, A, C), A, B, C ∈ O(2), keeps the standard plane.
    auto o2 = [&](bool reflect) {
      const double t = uni(g, -3, 3);
      MatX m(2, 2);
      m << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
      if (reflect) m.col(1) *= -1;
      return m;
    };
    const MatX A = o2(n % 2 == 0), B = o2(n % 3 == 0), Cm = o2(false);
    MatX D = MatX::Zero(8, 8);
    D.block(0, 0, 2, 2) = A;
    D.block(2, 2, 2, 2) = B;
    D.block(4, 4, 2, 2) = A;
    D.block(6, 6, 2, 2) = Cm;
    worstIso = std::max(worstIso, (projector(D * Std) - projector(Std)).cwiseAbs().maxCoeff());
  }
  c.checkResidual("after v₁ ↦ (1,0,0,0,1,0,0,0), clearing the first coordinate of v₂ clears the fifth (50 planes)",
                  worstFifth, tol());
  c.checkResidual("O(4) × O(4) reduces every isotropic 2-plane to v₁ = e₀ + e₄, v₂ = e₁ + e₅", worstStd, tol(1024));
  c.checkResidual("… the transformed span is the standard span (projectors)", worstSpan, tol(1024));
  c.checkResidual("diag(A, B, A, C), A, B, C ∈ O(2), preserves the standard 2-plane", worstIso, tol());
}

// ---- GF-11.3-flag-projections-fibres ---------------------------------------------------------
void flagFibres(Context& c) {
  auto g = rng(1131);
  // (1) Point to point: g₁ SO(3)_O g₂⁻¹ is an A-plane, and all its motions take s to t.
  double worstMaps = 0, worstContains = 0;
  int aPlanes = 0;
  const int N = 20;
  for (int n = 0; n < N; ++n) {
    const Vec3<S> s = vec3(g), t = vec3(g);
    const auto P = StudyPlane<S>::rotationsAbout(Vec3<S>::Zero())
                       .leftTranslated(DualQuaternion<S>::fromSE3(translation(t)))
                       .rightTranslated(DualQuaternion<S>::fromSE3(translation(-s)));
    aPlanes += P.kind() == StudyPlaneKind::A;
    for (int k = 0; k < 5; ++k) {
      const Vec8<S> x = P.point(unit4(g));
      worstMaps = std::max(worstMaps, (motionOf(x).act(s) - t).norm());
      const SE3<S> m = translation(t) * SE3<S>(SO3<S>::Random(g), Vec3<S>::Zero()) * translation(-s);
      worstContains = std::max(worstContains, P.residual(study(m)));
    }
  }
  c.checkEqual("point → point: g₁ SO(3)_O g₂⁻¹ is an A-plane (20 random pairs)", N, aPlanes);
  c.checkResidual("… every motion in it takes s to t", worstMaps, tol(1024));
  c.checkResidual("… and every motion taking s to t lies in it", worstContains, tol(1024));
  // (2) Pointed directed line → pointed directed line: a line of the quadric (rank 2, isotropic).
  // (3) Lined plane → lined plane: a line through a point of the A-plane at infinity (a translation).
  // (4) Directed line → directed line: a quadric surface, the 3-plane ∩ the Study quadric.
  int lineRank = 0, linedRank = 0, dirRank = 0;
  double lineIso = 0, linedInfinity = 1, dirOff = 0, dirOn = 0;
  const Vec3<S> s = vec3(g), t = vec3(g);
  const SO3<S> R0 = SO3<S>::Random(g);
  const Vec3<S> d = vec3(g).normalized(), e = R0.act(d);
  MatX pointed(8, 6), lined(8, 6), directed(8, 12);
  for (int k = 0; k < 6; ++k) {
    const double phi = uni(g, -3, 3), lambda = uni(g, -2, 2);
    const SO3<S> spin = SO3<S>::fromAxisAngle(e, phi);
    // the motions x ↦ t + spin R0 (x − s): s ↦ t, d ↦ e.
    const SE3<S> m = translation(t) * SE3<S>(spin * R0, Vec3<S>::Zero()) * translation(-s);
    pointed.col(k) = study(m);
    // lined plane (plane ⟂ d through s, line through s along a ⟂ direction): fixed up to sliding
    // along the line: x ↦ t + λ f + R0 (x − s), f = R0 (line direction).
    const Vec3<S> lineDir = d.unitOrthogonal();
    lined.col(k) = study(translation(Vec3<S>(t + lambda * R0.act(lineDir))) * SE3<S>(R0, Vec3<S>::Zero()) * translation(-s));
    // directed line through s along d → through t along e: spin about e and slide along it.
    directed.col(2 * k) = study(translation(Vec3<S>(t + lambda * e)) * SE3<S>(spin * R0, Vec3<S>::Zero()) * translation(-s));
    directed.col(2 * k + 1) =
        study(translation(Vec3<S>(t - 0.7 * lambda * e)) * SE3<S>(SO3<S>::fromAxisAngle(e, -0.5 * phi) * R0, Vec3<S>::Zero()) *
              translation(-s));
  }
  lineRank = rankOf(pointed);
  linedRank = rankOf(lined);
  dirRank = rankOf(directed);
  // isotropy of the pointed fibre: every combination stays on the quadric.
  const MatX Q = quadricQ();
  const MatX Bp = orthonormal(pointed.leftCols(2));
  lineIso = (Bp.transpose() * Q * Bp).cwiseAbs().maxCoeff();
  // lined fibre: its span meets a = 0 (a combination of two translates with a = 0).
  const MatX Bl = orthonormal(lined.leftCols(2));
  linedInfinity = detail::smallSingularValues<S>(MatX(Bl.topRows(4))).back();
  // directed fibre: the 3-plane is not in the quadric, but the motions are on it.
  const MatX Bd = orthonormal(directed.leftCols(4));
  for (int k = 0; k < 12; ++k) {
    const VecX x = directed.col(k);
    dirOn = std::max(dirOn, std::abs(x.dot(Q * x)) / x.squaredNorm());
  }
  dirOff = (Bd.transpose() * Q * Bd).cwiseAbs().maxCoeff();
  c.checkEqual("pointed directed line → another: the motions span a line (rank 2)", 2, lineRank);
  c.checkResidual("… which lies in the quadric (isotropic: max |BᵀQB|)", lineIso, tol());
  c.checkEqual("lined plane → another: the motions span a line (rank 2)", 2, linedRank);
  c.checkResidual("… meeting the A-plane at infinity (smallest singular value of its a-part)", linedInfinity, tol());
  c.checkEqual("directed line → another (SO(2) × R): the motions span a 3-plane (rank 4)", 4, dirRank);
  c.checkResidual("… every such motion is on the Study quadric", dirOn, tol());
  c.record("… but the 3-plane is not in it: the fibre is a quadric surface (max |BᵀQB| > 0.01)", "> 0.01", toString(dirOff, 4),
           dirOff, 0.01, dirOff > 0.01);
}

// ---- GF-11.3-table-11.1 -----------------------------------------------------------------------
// Dimensions of the flag manifolds twice: in R⁴, 6 − dim of the stabiliser in so(4) of the standard
// oriented flag; in R³, 6 − dim of the stabiliser in se(3) of the figure (Saletan contraction).
int so4OrbitDim(const std::vector<int>& dims) {
  // X ∈ so(4) keeps V_k = span(e₀..e_{d−1}) iff X_{ab} = 0 for a ≥ d > b.
  std::vector<Eigen::RowVectorXd> rows;
  int idx = 0;
  std::array<std::array<int, 4>, 4> var{};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) var[i][j] = var[j][i] = idx++;
  for (int d : dims)
    for (int a = d; a < 4; ++a)
      for (int b = 0; b < d; ++b) {
        Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(6);
        r(var[a][b]) = 1;
        rows.push_back(r);
      }
  if (rows.empty()) return 0;
  MatX A(rows.size(), 6);
  for (std::size_t k = 0; k < rows.size(); ++k) A.row(Eigen::Index(k)) = rows[k];
  return rankOf(A);  // the orbit dimension = 6 − dim stabiliser = rank of the constraints
}
enum Fig : unsigned { Pt = 1, Axis = 2, PlaneN = 4, LineInPlane = 8, Frame = 16 };
int se3OrbitDim(unsigned fig) {
  // Constraints on a twist (ω, v), velocity field u(x) = v + ω × x; the figure at the origin:
  // point O; line = z-axis; plane z = 0 (normal z); line in the plane = x-axis.
  std::vector<Eigen::RowVectorXd> rows;
  auto velocityRows = [&](const Vec3<S>& x) {  // the 3 rows of u(x)
    std::vector<Eigen::RowVectorXd> r(3, Eigen::RowVectorXd::Zero(6));
    for (int i = 0; i < 3; ++i) {
      r[std::size_t(i)](3 + i) = 1;
      const Vec3<S> ei = Vec3<S>::Unit(i);  // (ω × x)_i = ω · (x × e_i)
      const Vec3<S> coef = x.cross(ei);
      for (int k = 0; k < 3; ++k) r[std::size_t(i)](k) = coef(k);
    }
    return r;
  };
  auto omegaCross = [&](const Vec3<S>& dir) {  // rows of ω × dir
    std::vector<Eigen::RowVectorXd> r(3, Eigen::RowVectorXd::Zero(6));
    for (int i = 0; i < 3; ++i) {
      const Vec3<S> coef = dir.cross(Vec3<S>::Unit(i));
      for (int k = 0; k < 3; ++k) r[std::size_t(i)](k) = coef(k);
    }
    return r;
  };
  auto add = [&](const std::vector<Eigen::RowVectorXd>& r) { rows.insert(rows.end(), r.begin(), r.end()); };
  auto component = [&](const std::vector<Eigen::RowVectorXd>& r, const Vec3<S>& n) {  // n · (3 rows)
    Eigen::RowVectorXd out = Eigen::RowVectorXd::Zero(6);
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
  MatX A(rows.size(), 6);
  for (std::size_t k = 0; k < rows.size(); ++k) A.row(Eigen::Index(k)) = rows[k];
  return rankOf(A);
}
void table111(Context& c) {
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
    c.checkEqual(std::string(r.flag) + ": dim = 6 − dim stabiliser in so(4)", r.expected, so4OrbitDim(r.dims));
    c.checkEqual(std::string("… = the degrees of freedom of a ") + r.figure + " in R³ (6 − dim stabiliser in se(3))", r.expected,
                 se3OrbitDim(r.fig));
  }
}

// ---- GF-11.5-P1xP1-five-points ----------------------------------------------------------------
void p1xp1(Context& c) {
  auto g = rng(1151);
  // x₀y₁² + x₁y₀² (class α₀β₁ + 2α₁β₀ in the book's notation: degree 1 in x, 2 in y) and a generic
  // curve of degree 2 in x, 1 in y: in the chart x₀ = y₀ = 1, x = −y² on the first, so the second
  // gives a(−y²) + b(−y²) y = 0 of degree 5 (a, b quadratics in x).
  std::array<double, 3> a{uni(g), uni(g), uni(g)}, b{uni(g), uni(g), uni(g)};
  std::vector<double> poly(6, 0.0);  // Σ poly_k y^k
  for (int i = 0; i < 3; ++i) {
    const double sgn = (i % 2 == 0) ? 1.0 : -1.0;  // (−y²)^i
    poly[std::size_t(2 * i)] += a[std::size_t(i)] * sgn;
    poly[std::size_t(2 * i + 1)] += b[std::size_t(i)] * sgn;
  }
  const auto roots = polynomialRoots<double>(poly);
  double worst = 0, minSep = 1e300;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const std::complex<double> y = roots[i], x = -y * y;
    const std::complex<double> f = x + y * y;
    const std::complex<double> h = a[0] + a[1] * x + a[2] * x * x + (b[0] + b[1] * x + b[2] * x * x) * y;
    worst = std::max({worst, std::abs(f), std::abs(h) / (1 + std::abs(y) * std::abs(y) * std::abs(y) * std::abs(y) * std::abs(y))});
    for (std::size_t j = 0; j < i; ++j) minSep = std::min(minSep, std::abs(roots[i] - roots[j]));
  }
  c.checkEqual("the curves (1,2) and (2,1) meet in 5 points (roots of the degree-5 eliminant)", 5, int(roots.size()));
  c.checkResidual("… each on both curves", worst, 1e-12);
  c.record("… and they are distinct (minimum separation)", "> 1e-3", toString(minSep, 4), minSep, 1e-3, minSep > 1e-3);
  // The ring: (a α₀β₁ + b α₁β₀)(c α₀β₁ + d α₁β₀) = (ad + bc) × point, with α₁² = β₁² = 0.
  const int ringCount = 1 * 1 + 2 * 2;
  c.checkEqual("ring: (α₀β₁ + 2α₁β₀)(2α₀β₁ + α₁β₀) = 1·1 + 2·2 = 5 points", 5, ringCount);
}

// ---- GF-11.5-bezout-halphen -------------------------------------------------------------------
// Halphen on the Klein quadric: congruences of bidegree (m, n) share m₁m₂ + n₁n₂ lines. α-planes
// (lines through a point) are (1, 0), β-planes (lines in a plane) (0, 1), the lines meeting two
// skew lines (1, 1).
MatX alphaPlane(const Vec3<S>& P, std::mt19937_64& g) {
  MatX m(6, 3);
  for (int k = 0; k < 3; ++k) m.col(k) = PluckerLine<S>::throughPoints(P, Vec3<S>(P + vec3(g))).coords();
  return m;
}
MatX betaPlane(const Vec3<S>& n, double dist, std::mt19937_64& g) {
  const Vec3<S> u = n.unitOrthogonal(), w = n.cross(u);
  auto pointIn = [&] { return Vec3<S>(dist * n + uni(g) * u + uni(g) * w); };
  MatX m(6, 3);
  for (int k = 0; k < 3; ++k) m.col(k) = PluckerLine<S>::throughPoints(pointIn(), pointIn()).coords();
  return m;
}
/// Projective dimension of the intersection of two linear subspaces of P⁵ (columns span them).
int meetDim(const MatX& A, const MatX& B) {
  MatX AB(6, A.cols() + B.cols());
  AB << A, B;
  return int(A.cols() + B.cols()) - rankOf(AB) - 1;
}
void bezoutHalphen(Context& c) {
  auto g = rng(1152);
  const Vec3<S> P = vec3(g), Qp = vec3(g), n1 = vec3(g).normalized(), n2 = vec3(g).normalized();
  c.checkEqual("α ∩ α: two points share one line (1·1 + 0·0 = 1: a point of P⁵, dim 0)", 0,
               meetDim(alphaPlane(P, g), alphaPlane(Qp, g)));
  c.checkEqual("β ∩ β: two planes share one line (0·0 + 1·1 = 1)", 0, meetDim(betaPlane(n1, 0.3, g), betaPlane(n2, -0.2, g)));
  c.checkEqual("α ∩ β: a point off a plane: no common line (1·0 + 0·1 = 0: empty, dim −1)", -1,
               meetDim(alphaPlane(Vec3<S>(P + 5.0 * n1), g), betaPlane(n1, 0.3, g)));
  // (1,1)·(1,1) = 2: the lines meeting four random lines. The four linear conditions ⟨ℓ, Lᵢ⟩ = 0
  // leave a pencil ℓ = x + s y in P⁵; the Klein quadric on it is a quadratic in s: 2 solutions.
  MatX L(4, 6);
  std::vector<PluckerLine<S>> lines;
  // The four lines all meet a chosen line ℓ₀, so that the instance has real transversals (ℓ₀ and
  // a second one: complex roots come in pairs).
  const Vec3<S> q0 = vec3(g), q1 = vec3(g);
  const PluckerLine<S> l0 = PluckerLine<S>::throughPoints(q0, q1);
  for (int i = 0; i < 4; ++i) {
    const double u = uni(g, -2, 2);
    lines.push_back(PluckerLine<S>::throughPoints(Vec3<S>(q0 + u * (q1 - q0)), vec3(g)));
    const Vec6<S> s = lines.back().coords();
    L.row(i) << s.tail<3>().transpose(), s.head<3>().transpose();  // ⟨ℓ, s⟩ = ω·v_s + v·ω_s
  }
  const MatX K = detail::smallComplement<S>(orthonormal(L.transpose()));  // 6 × 2: the pencil
  const Vec6<S> x = K.col(0), y = K.col(1);
  auto klein = [](const Vec6<S>& a, const Vec6<S>& b) { return a.head<3>().dot(b.tail<3>()) + a.tail<3>().dot(b.head<3>()); };
  // (x + s y)·(x + s y) = klein(x,x) + 2s klein(x,y) + s² klein(y,y) (Klein form ⟨a,a⟩ = 2 ω·v).
  const auto roots = polynomialRoots<double>({klein(x, x), 2 * klein(x, y), klein(y, y)});
  c.checkEqual("(1,1) ∩ (1,1): lines meeting four random lines (1·1 + 1·1 = 2)", 2, int(roots.size()));
  double worst = 0;
  int real = 0;
  for (const auto& s : roots) {
    if (std::abs(s.imag()) > 1e-9 * (1 + std::abs(s))) continue;
    ++real;
    const Vec6<S> l = x + s.real() * y;
    for (const auto& m : lines) worst = std::max(worst, std::abs(klein(l, m.coords())) / (l.norm() * m.coords().norm()));
  }
  // ℓ₀ is one of them (as a point of P⁵: 1 − cos² of the angle to the nearer root).
  double toL0 = 1;
  const Vec6<S> l0c = l0.coords().normalized();
  for (const auto& s : roots) {
    if (std::abs(s.imag()) > 1e-9 * (1 + std::abs(s))) continue;
    const Vec6<S> l = (x + s.real() * y).normalized();
    toL0 = std::min(toL0, 1 - l.dot(l0c) * l.dot(l0c));
  }
  c.checkEqual("… both transversals are real for this instance (four lines meeting ℓ₀)", 2, real);
  c.checkResidual("… the real ones meet all four (reciprocal products)", worst, tol(1024));
  c.checkResidual("… and ℓ₀ is one of them (1 − cos² in P⁵)", toL0, tol(1024));
}

// ---- GF-11.5-cell-decomposition ---------------------------------------------------------------
/// A basis of {x : Aᵀ Q x = 0} (the polar of span A), 8 × (8 − rank).
MatX polar(const MatX& A) { return detail::smallComplement<S>(orthonormal(MatX(quadricQ() * A))); }
int restrictedRank(const MatX& W) { return rankOf(MatX(W.transpose() * quadricQ() * W)); }
void cellDecomposition(Context& c) {
  auto g = rng(1153);
  // P₀ ⊂ P₁ ⊂ P₂ in the quadric: the identity, the rotations about z, plus c₁ (pairwise a·c = 0),
  // moved by a random motion x ↦ g x (which keeps the quadric).
  const Eigen::Matrix<S, 8, 8> Lg = dualQuaternionLeftMatrix<S>(DualQuaternion<S>::fromSE3(SE3<S>(SO3<S>::Random(g), vec3(g))));
  MatX P2(8, 3);
  P2 << Lg.col(0), Lg.col(3), Lg.col(5);
  const MatX P0 = P2.leftCols(1), P1 = P2.leftCols(2);
  c.checkResidual("P₀ ⊂ P₁ ⊂ P₂ lie in the quadric", (P2.transpose() * quadricQ() * P2).cwiseAbs().maxCoeff(),
                  tol());
  // Q₅ = P₆ ∩ Q_S with P₆ the tangent hyperplane at P₀: singular at P₀ (rank 6 on the 7-dim P₆).
  const MatX P6 = polar(P0);
  c.checkEqual("tangent hyperplane P₆ (dim 7 as a subspace of R⁸)", 7, int(P6.cols()));
  c.checkEqual("Q₅ = P₆ ∩ Q_S: rank 6 on P₆, singular exactly at P₀", 6, restrictedRank(P6));
  const MatX P5 = polar(P1);
  c.checkEqual("polar 5-plane of P₁: Q₄ has rank 4 there (a double line: the kernel is P₁)", 4, restrictedRank(P5));
  const MatX P4 = polar(P2);
  c.checkEqual("polar 4-plane of P₂: rank 2 (P₄ ∩ Q₄ is a pair of 3-planes)", 2, restrictedRank(P4));
  // Factor the rank-2 form on P₄ into two hyperplanes of P₄: an A-plane and a B-plane through P₂.
  std::vector<S> vals;
  MatX vecs;
  detail::smallSymEigen<S>(MatX(P4.transpose() * quadricQ() * P4), vals, vecs);
  const VecX up = vecs.col(0), um = vecs.col(Eigen::Index(vals.size()) - 1);
  int kinds[2] = {0, 0};
  double worstIn = 0;
  for (int sgn : {1, -1}) {
    const VecX form = std::sqrt(vals.front()) * up + sgn * std::sqrt(-vals.back()) * um;
    const MatX sub = P4 * detail::smallComplement<S>(MatX(form.normalized()));  // 8 × 4
    Eigen::Matrix<S, 8, 4> pts = sub;
    const auto plane = StudyPlane<S>::fromSpan(pts);
    kinds[plane.kind() == StudyPlaneKind::A ? 0 : 1]++;
    for (int k = 0; k < 3; ++k) worstIn = std::max(worstIn, plane.residual(Vec8<S>(P2.col(k))));
  }
  c.checkEqual("… the two 3-planes are one A-plane and one B-plane", "1 A, 1 B",
               std::to_string(kinds[0]) + " A, " + std::to_string(kinds[1]) + " B");
  c.checkResidual("… both contain P₂", worstIn, tol(1024));
  // Cells of real dimension 0, 2, 4, 6, 6, 8, 10, 12: χ(Q⁶) = 8. Independent count: a generic C*
  // action a_i ↦ t^{w_i} a_i, c_i ↦ t^{−w_i} c_i keeps Σ a_i c_i; its fixed points in P⁷ are the 8
  // coordinate points (distinct weights ±w_i), all on the quadric: χ = 8.
  const std::array<int, 8> cellDims{0, 2, 4, 6, 6, 8, 10, 12};
  int onQuadric = 0;
  for (int k = 0; k < 8; ++k) {
    const VecX e = VecX::Unit(8, k);
    onQuadric += std::abs(e.dot(quadricQ() * e)) == 0;
  }
  c.checkEqual("cells of the decomposition (book): 8, all of even dimension", 8, int(cellDims.size()));
  c.checkEqual("fixed points of a generic torus action on Q⁶ (= χ(Q⁶) = 2m + 2, m = 3)", 8, onQuadric);
}

SOMA_STUDY_DOUBLE("GF-11.2.4-quadric-grassmannians", "Isotropic k-planes of Hy: dimensions 6, 9, 9, 6 (two ways)", "GF §11.2.4",
            quadricGrassmannians);
SOMA_STUDY_DOUBLE("GF-11.2.4-isotropic-2-plane-normal-form", "O(4) × O(4) reduces every isotropic 2-plane to the standard one",
            "GF §11.2.4", isotropicNormalForm);
SOMA_STUDY_DOUBLE("GF-11.3-flag-projections-fibres", "Fibres of the flag projections: A-plane, lines, quadric surface",
            "GF §11.3", flagFibres);
SOMA_STUDY_DOUBLE("GF-11.3-table-11.1", "Table 11.1: flag manifolds, homogeneous spaces, figures in R³ (dimensions two ways)",
            "GF §11.3", table111);
SOMA_STUDY_DOUBLE("GF-11.5-P1xP1-five-points", "Curves of classes α₀β₁ + 2α₁β₀ and 2α₀β₁ + α₁β₀ meet in five points", "GF §11.5",
            p1xp1);
SOMA_STUDY_DOUBLE("GF-11.5-bezout-halphen", "Halphen: congruences (m₁,n₁), (m₂,n₂) share m₁m₂ + n₁n₂ lines", "GF §11.5",
            bezoutHalphen);
SOMA_STUDY_DOUBLE("GF-11.5-cell-decomposition", "The cell decomposition of the Study quadric: Q₅, Q₄, P_A ∪ P_B; χ = 8",
            "GF §11.5", cellDecomposition);

}  // namespace
}  // namespace soma::studies::gf11flags::SOMA_UNITY_ID
