// Studies of GF chapter 11: the Study quadric, its 3-planes and their intersections (§11.2),
// quadric sections of linkages (§11.4, §11.5.3–11.5.4) and the intersection ring (§11.5).
// Every study runs in the asked scalar (--scalar): draws in double cast to S (gf11/common.hpp),
// book values as exact fractions, ranks by soma's one-sided Jacobi SVD (small_linalg.hpp).
#include "gf11/common.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/geometry/study/constraint_quadrics.hpp"
#include "soma/geometry/study/intersection_ring.hpp"
#include "soma/geometry/study/quaternion_matrices.hpp"
#include "soma/geometry/study/study_plane.hpp"
#include "soma/studies/study.hpp"

#include <random>

namespace soma::studies::gf11::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using std::abs;
using std::cos;
using std::sin;

/// A random element of O(4) with the given determinant sign: a matrix drawn in double, cast to S,
/// its columns made orthonormal in S (Gram–Schmidt twice), the first negated if the sign is wrong.
template <class S, int N> Eigen::Matrix<S, N, N> orthogonal(std::mt19937_64& g, int det) {
  Eigen::Matrix<S, N, N> A;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) A(i, j) = uni<S>(g);
  Eigen::Matrix<S, N, N> Q = orthonormalColumns(A);
  if ((Q.determinant() > S(0)) != (det > 0)) Q.col(0) = -Q.col(0);
  return Q;
}
template <class S> SE3<S> rotationAbout(const Vec3<S>& axis, const S& angle, const Vec3<S>& point) {
  const SO3<S> R = SO3<S>::fromAxisAngle(axis, angle);
  return SE3<S>(R, Vec3<S>(point - R.act(point)));
}
template <class S> Vec8<S> study(const SE3<S>& m) { return StudyParameters<S>::fromSE3(m).coeffs(); }
/// |a·c| / |x|²: the Study form of x relative to its scale.
template <class S> S studyForm(const Vec8<S>& x) {
  return S(abs(S(x.template head<4>().dot(x.template tail<4>()))) / x.squaredNorm());
}
/// Numerical rank of a set of points of PR⁷ (columns), relative to the largest singular value
/// (soma's one-sided Jacobi SVD, threshold 1024 ε).
template <class S, int R, int C> int rankOf(const Eigen::Matrix<S, R, C>& m) {
  return detail::smallNumericalRank<S>(detail::SmallMat<S>(m));
}

// Thresholds: tol<S>() = 256 ε bounds the rounding of the short sums these checks evaluate (a·c of
// eight products of unit-scale coordinates, a 3-plane's eight equations, a composition of two
// motions: each a few ε, 256 ε = 5.7e-14 in double as before); 512 ε where the leg quadrics of
// scale 1 + L² enter, 1024 ε after a Gram–Schmidt or two reflections.

// ---- GF §11.2.1 ----------------------------------------------------------------------------
template <class S> void linesThroughIdentity(Context& c) {
  auto g = rng(1101);
  // A point of the quadric with c0 ≠ 0: the motion of a rotation with a translation along its axis.
  const Vec8<S> x = study(SE3<S>(SO3<S>::fromAxisAngle(Vec3<S>(0, 0, 1), frac<S>(4, 5)),
                                 Vec3<S>(frac<S>(3, 10), frac<S>(-1, 5), frac<S>(11, 10))));
  const Vec8<S> one = StudyParameters<S>().coeffs();
  const S c0 = abs(x(4));
  c.recordIn<S>("the chosen point (a screw with pitch) has |c₀|", "> 0.1", toString(c0, 4), c0, frac<S>(1, 10),
                c0 > frac<S>(1, 10));
  S worstOut = S(0), worstIn = S(0);
  const std::array<S, 3> ts{frac<S>(3, 10), frac<S>(-17, 10), S(5)};
  for (const S& t : ts) worstOut = std::max<S>(worstOut, studyForm<S>(Vec8<S>(one + t * x)));
  c.recordIn<S>("the line 1 + t x through a point with c₀ ≠ 0 leaves the quadric (min over 3 t of |a·c|/|x|²)", "> 1e-3",
                toString(worstOut, 4), worstOut, frac<S>(1, 1000), worstOut > frac<S>(1, 1000));
  // Normal form c0 = 0: any point with c0 = 0 on the quadric spans a line inside it.
  for (int k = 0; k < 20; ++k) {
    const Vec3<S> a = rv3<S>(g);
    Vec3<S> cv = rv3<S>(g);
    cv -= S(cv.dot(a) / a.squaredNorm()) * a;  // a⃗·c⃗ = 0
    Vec8<S> y;
    y << S(0), a, S(0), cv;
    for (const S& t : ts) worstIn = std::max<S>(worstIn, studyForm<S>(Vec8<S>(one + t * y)));
  }
  c.checkResidual("c₀ = 0, a⃗·c⃗ = 0: α + β(a⃗ + εc⃗) stays in the quadric (20 lines × 3 points; 256 ε)", worstIn, tol<S>());
}

template <class S> void rotationTranslationLines(Context& c) {
  auto g = rng(1102);
  // Pitch-zero exponentials and translations are lines (rank 2 for three points); a screw of
  // non-zero pitch traces a conic (rank 3).
  const Vec3<S> axis = unit3<S>(g), q = rv3<S>(g);
  auto screw = [&](const S& pitch, const S& theta) {
    const SE3<S> r = rotationAbout<S>(axis, theta, q);
    return study(SE3<S>(r.so3(), Vec3<S>(r.translation() + S(pitch * theta) * axis)));
  };
  Eigen::Matrix<S, 8, 3> rot, tr, sc;
  const Vec3<S> t = rv3<S>(g);
  for (int k = 0; k < 3; ++k) {
    const S th = frac<S>(4 + 9 * k, 10);
    rot.col(k) = screw(S(0), th);
    tr.col(k) = study(SE3<S>(SO3<S>(), Vec3<S>(th * t)));
    sc.col(k) = screw(frac<S>(3, 10), th);
  }
  c.checkEqual("three rotations about one line span a line of P⁷ (rank)", 2, rankOf(rot));
  c.checkEqual("three translations along one direction span a line (rank)", 2, rankOf(tr));
  c.checkEqual("a screw motion of pitch 0.3 is not a line: three points have rank", 3, rankOf(sc));
  // The direction part (a⃗, c⃗) of the rotation line is the Plücker line of the axis (a⃗·c⃗ = 0).
  const Vec8<S> d = rot.col(1) - rot.col(0) * S(rot.col(1)(0) / rot.col(0)(0));
  c.checkResidual("rotation line: its direction (a⃗, c⃗) has a⃗·c⃗ = 0 (a line of space; 256 ε)",
                  S(abs(S(d.template segment<3>(1).dot(d.template segment<3>(5)))) / d.squaredNorm()), tol<S>());
}

// ---- GF §11.2.2 ----------------------------------------------------------------------------
template <class S> void threePlanes(Context& c) {
  auto g = rng(1103);
  S worst = S(0);
  int a = 0, b = 0;
  for (int k = 0; k < 200; ++k) {
    const int det = k % 2 ? 1 : -1;
    const auto P = StudyPlane<S>::fromOrthogonal(orthogonal<S, 4>(g, det));
    (P.kind() == StudyPlaneKind::A ? a : b)++;
    const Vec8<S> x = P.point(rv4<S>(g));
    worst = std::max<S>({worst, studyForm<S>(x), P.residual(x)});
  }
  c.checkResidual("a = (M+I)y, c = (M−I)y satisfies a·c = 0 and (I−M)a + (I+M)c = 0 (200 random M ∈ O(4); 256 ε)", worst,
                  tol<S>());
  c.checkEqual("det M = +1 planes classified A", 100, a);
  c.checkEqual("det M = −1 planes classified B", 100, b);
}

template <class S> void planesThroughIdentity(Context& c) {
  auto g = rng(1104);
  const Vec3<S> p = rv3<S>(g);
  const auto P = StudyPlane<S>::rotationsAbout(p);  // the book's Cayley form
  S worst = S(0), worstC = S(0);
  for (int k = 0; k < 20; ++k) {
    const Vec3<S> axis = unit3<S>(g);
    const Vec8<S> x = study(rotationAbout<S>(axis, uni<S>(g, -3, 3), p));
    worst = std::max<S>(worst, P.residual(x));
    worstC = std::max<S>({worstC, S(abs(x(4))),
                          S((x.template segment<3>(5) - p.cross(Vec3<S>(x.template segment<3>(1)))).cwiseAbs().maxCoeff())});
  }
  c.checkResidual("M = diag(1, Cay(p)), Cay(p) = (I+[p]×)(I−[p]×)⁻¹: contains 20 random rotations about p (256 ε)", worst,
                  tol<S>());
  c.checkResidual("… and on it c₀ = 0, c⃗ = p × a⃗", worstC, tol<S>());
  c.checkEqual("SO(3)_p is an A-plane", "A", P.kind() == StudyPlaneKind::A ? "A" : "B");
  const auto E = StudyPlane<S>::planarMotions(Vec3<S>(0, 0, 1));
  S worstE = S(0);
  for (int k = 0; k < 20; ++k) {
    const S tx = uni<S>(g), ty = uni<S>(g), th = uni<S>(g, -3, 3);
    const Vec3<S> centre = rv3<S>(g);
    const SE3<S> m = SE3<S>(SO3<S>(), Vec3<S>(tx, ty, S(0))) * rotationAbout<S>(Vec3<S>(0, 0, 1), th, centre);
    const Vec8<S> x = study(m);
    worstE = std::max<S>({worstE, E.residual(x), S(abs(x(1))), S(abs(x(2))), S(abs(x(4))), S(abs(x(7)))});
  }
  c.checkResidual("R = half-turn about z: the SE(2) A-plane, a₁ = a₂ = c₀ = c₃ = 0 on 20 planar motions (256 ε)", worstE,
                  tol<S>());
  const auto T = StudyPlane<S>::translations();
  c.checkResidual("R = −I₃: the translations (a B-plane; 256 ε)", T.residual(study(SE3<S>(SO3<S>(), rv3<S>(g)))), tol<S>());
  c.checkEqual("R³ is a B-plane", "B", T.kind() == StudyPlaneKind::A ? "A" : "B");
  c.checkEqual("M = −I₄ is the A-plane at infinity a = 0", "A",
               StudyPlane<S>::atInfinity().kind() == StudyPlaneKind::A ? "A" : "B");
  // Near the extreme: Cay(p) → a half-turn as |p| → ∞ (SO(3)_p degenerates to SE(2)). The off-diagonal
  // entries are 2p/(1 + p²) ≈ 2/|p|: bound 4/|p| for the truncation plus 64 ε for the rounding of the
  // 3 × 3 inverse's entries (≈ ±1 after the cancellation 1 − p² over 1 + p²).
  const S big = S(100000000);
  const Vec3<S> far = big * Vec3<S>(0, 0, 1);
  const Mat3<S> half = S(2) * Vec3<S>(0, 0, 1) * Vec3<S>(0, 0, 1).transpose() - Mat3<S>::Identity();
  c.checkResidual("|p| = 1e8 along z: Cay(p) is the half-turn about z to O(1/|p|) (4/|p| + 64 ε)",
                  S((cayleyRotation<S>(far) - half).cwiseAbs().maxCoeff()), S(S(4) / big + tol<S>(64)));
}

template <class S> void planeCosets(Context& c) {
  auto g = rng(1105);
  S worst = S(0);
  int kept = 0;
  for (int k = 0; k < 20; ++k) {
    const SE3<S> m = SE3<S>::Random(g);
    const Vec3<S> p = rv3<S>(g);
    const auto P = StudyPlane<S>::rotationsAbout(p).leftTranslated(DualQuaternion<S>::fromSE3(m));
    kept += P.kind() == StudyPlaneKind::A;
    const Vec3<S> axis = unit3<S>(g);
    const S angle = uni<S>(g, -3, 3);
    worst = std::max<S>(worst, P.residual(study(SE3<S>(m * rotationAbout<S>(axis, angle, p)))));
  }
  c.checkEqual("g·SO(3)_p recovered from four points is an A-plane (det M = +1), 20 random g", 20, kept);
  c.checkResidual("… and contains g·(rotations about p) (256 ε)", worst, tol<S>());
}

// ---- GF §11.2.3 ----------------------------------------------------------------------------
template <class S> void intersectionCorank(Context& c) {
  auto g = rng(1106);
  int agree = 0;
  for (int k = 0; k < 100; ++k) {
    const auto P = StudyPlane<S>::fromOrthogonal(orthogonal<S, 4>(g, k % 2 ? 1 : -1));
    const auto Q = StudyPlane<S>::fromOrthogonal(orthogonal<S, 4>(g, k % 3 ? 1 : -1));
    agree += intersectionDimension(P, Q) == intersectionDimensionByEigenvalues(P, Q);
  }
  c.checkEqual("corank of the stacked 8×8 system − 1 = multiplicity of eigenvalue 1 of M₁M₂ᵀ − 1 (100 random pairs)", 100,
               agree);
}

template <class S> void intersectionCases(Context& c) {
  auto g = rng(1107);
  int aa = 0, bb = 0, ab = 0;
  for (int k = 0; k < 50; ++k) {
    const auto A1 = StudyPlane<S>::fromOrthogonal(orthogonal<S, 4>(g, 1));
    const auto A2 = StudyPlane<S>::fromOrthogonal(orthogonal<S, 4>(g, 1));
    const auto B1 = StudyPlane<S>::fromOrthogonal(orthogonal<S, 4>(g, -1));
    const auto B2 = StudyPlane<S>::fromOrthogonal(orthogonal<S, 4>(g, -1));
    aa += intersectionDimension(A1, A2) == -1;
    bb += intersectionDimension(B1, B2) == -1;
    ab += intersectionDimension(A1, B1) == 0;
  }
  c.checkEqual("A∩A empty (50 random pairs)", 50, aa);
  c.checkEqual("B∩B empty", 50, bb);
  c.checkEqual("A∩B one point", 50, ab);
  // Special positions from the normal form diag(rot θ, rot φ): θ = 0 → a line.
  const Mat4<S> M1 = orthogonal<S, 4>(g, 1);
  Mat4<S> R = Mat4<S>::Identity();
  const S c1 = cos(S(1)), s1 = sin(S(1));
  R.template bottomRightCorner<2, 2>() << c1, -s1, s1, c1;
  c.checkEqual("A∩A with θ = 0: a line", 1,
               intersectionDimension(StudyPlane<S>::fromOrthogonal(M1), StudyPlane<S>::fromOrthogonal(Mat4<S>(R * M1))));
  Mat4<S> Rb = R;
  Rb(0, 0) = S(-1);  // diag(−1, 1, rot φ) with φ = 0: det −1 and three unit eigenvalues
  Rb.template bottomRightCorner<2, 2>().setIdentity();
  c.checkEqual("A∩B with φ = 0 (three unit eigenvalues): a 2-plane", 2,
               intersectionDimension(StudyPlane<S>::fromOrthogonal(M1), StudyPlane<S>::fromOrthogonal(Mat4<S>(Rb * M1))));
}

template <class S> void meetInfinite(Context& c) {
  const auto inf = StudyPlane<S>::atInfinity();
  c.checkEqual("SO(3)_p meets the A-plane at infinity: no (dimension)", -1,
               intersectionDimension(inf, StudyPlane<S>::rotationsAbout(Vec3<S>(frac<S>(3, 10), S(-1), S(2)))));
  c.checkEqual("SE(2) meets it in a line", 1, intersectionDimension(inf, StudyPlane<S>::planarMotions(Vec3<S>(0, 0, 1))));
  Mat4<S> M = Mat4<S>::Identity();
  M.template bottomRightCorner<3, 3>() = -cayleyRotation<S>(Vec3<S>(frac<S>(1, 5), frac<S>(1, 2), frac<S>(-7, 10)));
  c.checkEqual("a generic B-plane through 1 (det R = −1) meets it in a point", 0,
               intersectionDimension(inf, StudyPlane<S>::fromOrthogonal(M)));
  c.checkEqual("R³ meets it in a 2-plane", 2, intersectionDimension(inf, StudyPlane<S>::translations()));
}

template <class S> void kleinAnalogue(Context& c) {
  // The same argument for the Klein quadric ω·v = 0 of P⁵ and its planes (I−M)ω + (I+M)v = 0, M ∈ O(3).
  auto g = rng(1108);
  auto dim = [](const Mat3<S>& M1, const Mat3<S>& M2) {
    Eigen::Matrix<S, 6, 6> m;
    m << Mat3<S>::Identity() - M1, Mat3<S>::Identity() + M1, Mat3<S>::Identity() - M2, Mat3<S>::Identity() + M2;
    return 6 - rankOf(m) - 1;
  };
  int same = 0, opposite = 0;
  for (int k = 0; k < 50; ++k) {
    const int d = k % 2 ? 1 : -1;
    const Mat3<S> P1 = orthogonal<S, 3>(g, d), P2 = orthogonal<S, 3>(g, d);
    same += dim(P1, P2) == 0;
    const Mat3<S> Q1 = orthogonal<S, 3>(g, d), Q2 = orthogonal<S, 3>(g, -d);
    opposite += dim(Q1, Q2) == -1;
  }
  c.checkEqual("Klein quadric: two planes of the same family meet in a point (a common line of space), 50 pairs", 50, same);
  c.checkEqual("… planes of opposite families generically do not meet (GF-11.5 Halphen: α·β = 0)", 50, opposite);
}

// ---- GF §11.4 ------------------------------------------------------------------------------
template <class S> void lineIsotropy(Context& c) {
  auto g = rng(1109);
  S worst = S(0);
  for (int k = 0; k < 20; ++k) {
    const S slide = uni<S>(g, -3, 3), angle = uni<S>(g, -3, 3);
    const SE3<S> m = SE3<S>(SO3<S>(), Vec3<S>(S(0), S(0), slide)) * rotationAbout<S>(Vec3<S>(0, 0, 1), angle, Vec3<S>::Zero().eval());
    const Vec8<S> x = study(m);
    worst = std::max<S>({worst, S(abs(x(1))), S(abs(x(2))), S(abs(x(5))), S(abs(x(6))), S(abs(S(x(0) * x(4) + x(3) * x(7))))});
  }
  c.checkResidual("isotropy of the z-axis (rotations and slides along z) lies in a₁ = a₂ = c₁ = c₂ = 0 and a₀c₀ + a₃c₃ = 0 (256 ε)",
                  worst, tol<S>());
  // The non-subgroup points: the printed "a₂ = a₃ = 0" contains (1,0,0,0 : 0,0,0,1), the
  // translation by 2 along z (c = ½ t a), a subgroup element; a₀ = a₃ = 0 is the line at infinity.
  Vec8<S> x = Vec8<S>::Zero();
  x(0) = S(1), x(7) = S(1);
  const SE3<S> m = StudyParameters<S>(x).toSE3();
  const S slide = S((m.translation() - Vec3<S>(0, 0, 2)).norm() + (m.rotation() - Mat3<S>::Identity()).norm());
  c.checkResidual("(1,0,0,0 : 0,0,0,1) with a₂ = a₃ = 0 is the translation by 2 along z (256 ε)", slide, tol<S>());
  c.checkPrintedFails("\"the line at infinity a₂ = a₃ = 0\" has no motions: distance of that point from a = 0", "GF11-1",
                      S(x.template head<4>().norm()), tol<S>());
  Vec8<S> inf = Vec8<S>::Zero();
  inf(4) = frac<S>(3, 10), inf(7) = frac<S>(-6, 5);
  c.checkEqual("a₀ = a₃ = 0 on the isotropy 3-plane is the line at infinity (a = 0)", "yes",
               StudyParameters<S>(inf).inExceptionalPlane() ? "yes" : "no");
}

template <class S> void twoRThreePlane(Context& c) {
  auto g = rng(1110);
  S worst = S(0);
  for (int k = 0; k < 30; ++k) {
    const S l = uni<S>(g, 0.1, 3), alpha = uni<S>(g, 0.1, 3);
    const S th1 = uni<S>(g, -3, 3), th2 = uni<S>(g, -3, 3);
    const SE3<S> m = rotationAbout<S>(Vec3<S>(0, 0, 1), th1, Vec3<S>::Zero().eval()) *
                     rotationAbout<S>(Vec3<S>(S(0), S(-sin(alpha)), S(cos(alpha))), th2, Vec3<S>(l, S(0), S(0)));
    worst = std::max<S>(worst, S((twoRevoluteEquations<S>(l, alpha) * study(m)).cwiseAbs().maxCoeff()));
  }
  c.checkResidual("l a₂ − c₃ = l a₁ − c₀ = l a₁ cos α − c₁ sin α = l a₂ cos α − c₂ sin α = 0 on 30 random 2R postures (256 ε)",
                  worst, tol<S>());
  // Erratum GF11-7: "3-plane ∩ Study quadric is a 2-dimensional quadric" fails for l = 0 (and
  // α = 0): there the 3-plane (c = 0, the SO(3) A-plane) lies wholly in the quadric. Measure the
  // Study form a·c on random points of the 3-plane (its basis: the orthonormal complement of the
  // four equations' rows): identically 0 for l = 0, not for l = 0.5.
  auto formOnPlane = [&](const S& l, const S& alpha) {
    const Eigen::Matrix<S, 8, 4> rows = twoRevoluteEquations<S>(l, alpha).transpose();
    const detail::SmallMat<S> K = detail::smallComplement<S>(detail::SmallMat<S>(orthonormalColumns(rows)));
    S m = S(0);
    for (int k = 0; k < 20; ++k) m = std::max<S>(m, studyForm<S>(Vec8<S>(K * rv4<S>(g))));
    return m;
  };
  const S zeroL = formOnPlane(S(0), frac<S>(7, 10)), someL = formOnPlane(frac<S>(1, 2), frac<S>(7, 10)),
          zeroAlpha = formOnPlane(frac<S>(1, 2), S(0));
  c.recordIn<S>("l = 0: max |a·c| on 20 points of the 2R 3-plane (the plane lies in the quadric; erratum GF11-7; 256 ε)", "0",
                toString(zeroL, 3), zeroL, tol<S>(), zeroL <= tol<S>());
  c.recordIn<S>("α = 0: the same (the SE(2) A-plane; erratum GF11-7)", "0", toString(zeroAlpha, 3), zeroAlpha, tol<S>(),
                zeroAlpha <= tol<S>());
  c.recordIn<S>("l = 0.5, α = 0.7: the form is not zero on the plane (a genuine quadric surface)", "> 1e-3", toString(someL, 3),
                someL, frac<S>(1, 1000), someL > frac<S>(1, 1000));
}

// ---- GF §11.5 ------------------------------------------------------------------------------
// The intersection ring is exact integer arithmetic: the two studies below compute the same in
// every scalar (they take --scalar for uniformity and have nothing to round).
template <class S> void tableRing(Context& c) {
  using C = StudyClass;
  int assoc = 0, total = 0;
  for (int a = 0; a < C::kCells; ++a)
    for (int b = 0; b < C::kCells; ++b)
      for (int d = 0; d < C::kCells; ++d, ++total)
        assoc += (C::cell(C::Cell(a)) * C::cell(C::Cell(b))) * C::cell(C::Cell(d)) ==
                 C::cell(C::Cell(a)) * (C::cell(C::Cell(b)) * C::cell(C::Cell(d)));
  c.checkEqual("Table 11.2 is associative on all 512 triples of cells", total, assoc);
  c.checkEqual("σ₅⁶ = 2, the degree of the quadric", 2, C::sigma5().pow(6).degree());
  c.checkEqual("σ₅·σ₅·σ₂ = 1", 1, (C::sigma5() * C::sigma5() * C::sigma2()).degree());
  c.checkEqual("σ₅·σ₄·σ_A = 1", 1, (C::sigma5() * C::sigma4() * C::sigmaA()).degree());
  c.checkEqual("σ₄·σ₅ =", "σ_A + σ_B", (C::sigma4() * C::sigma5()).toString());
}

template <class S> void ringCounts(Context& c) {
  using C = StudyClass;
  c.checkEqual("2R class 2σ₂ meets a general σ₄ in", 2, (2 * C::sigma2() * C::sigma4()).degree());
  c.checkEqual("6R: (2σ_A + 4σ_B)² = ", 16, ((2 * C::sigmaA() + 4 * C::sigmaB()).pow(2)).degree());
  c.checkEqual("6-3 Stewart: (2σ₄)³ = ", 16, (2 * C::sigma4()).pow(3).degree());
  c.checkEqual("tripod wrist: (2σ₅)³ =", "8σ_A + 8σ_B", (2 * C::sigma5()).pow(3).toString());
  c.checkEqual("… ∩ σ_A (rotations about the ball joint) =", 8, ((2 * C::sigma5()).pow(3) * C::sigmaA()).degree());
  c.checkEqual("guard: the naive general 6-6 Stewart count (2σ₅)⁶ is 128, not the true 40", 128,
               (2 * C::sigma5()).pow(6).degree());
  c.checkEqual("cells of Q⁶ (even real dimensions 0…12) = χ(Q⁶) = 2m + 2 with m = 3", 8, C::kCells);
}

/// The book's extra quadric of the S–S link, second joint at distance l on the z-axis:
/// (c₀ − l a₃)c₀ + (c₁ + l a₂)c₁ + (c₂ − l a₁)c₂ + (c₃ + l a₀)c₃.
// GF §11.5.3 line 7242 as printed (correct)
template <class S> S sphericalSphericalFormAsPrinted(const Vec8<S>& x, const S& l) {
  const S a0 = x(0), a1 = x(1), a2 = x(2), a3 = x(3), c0 = x(4), c1 = x(5), c2 = x(6), c3 = x(7);
  return (c0 - l * a3) * c0 + (c1 + l * a2) * c1 + (c2 - l * a1) * c2 + (c3 + l * a0) * c3;
}

/// The book's homogenised leg equation evaluated literally with quaternions h₀ = a, h₁ = c:
/// (|p|² + |q|² − L²) h₀h₀* + h₀ q h₀* p + p h₀ q h₀* + 2 h₀ q h₁* − 2 h₁ q h₀* + 2 p h₁ h₀* − 2 h₀ h₁* p + 4 h₁ h₁*.
// GF §11.5.4 lines 7263–7278 as printed (correct)
template <class S> Vec4<S> stewartLegExpressionAsPrinted(const Vec8<S>& x, const Vec3<S>& p, const Vec3<S>& q, const S& L) {
  const Vec4<S> h0 = x.template head<4>(), h1 = x.template tail<4>();
  const Vec4<S> qq(S(0), q.x(), q.y(), q.z()), pp(S(0), p.x(), p.y(), p.z());
  auto mul = [](const Vec4<S>& u, const Vec4<S>& v) { return Vec4<S>(quaternionLeftMatrix<S>(u) * v); };
  auto conj = [](const Vec4<S>& u) { return Vec4<S>(u(0), -u(1), -u(2), -u(3)); };
  const Vec4<S> h0s = conj(h0), h1s = conj(h1);
  const S k = p.squaredNorm() + q.squaredNorm() - L * L;
  return k * mul(h0, h0s) + mul(mul(mul(h0, qq), h0s), pp) + mul(pp, mul(mul(h0, qq), h0s)) + S(2) * mul(mul(h0, qq), h1s) -
         S(2) * mul(mul(h1, qq), h0s) + S(2) * mul(mul(pp, h1), h0s) - S(2) * mul(mul(h0, h1s), pp) + S(4) * mul(h1, h1s);
}

template <class S> void ssLinkVariety(Context& c) {
  auto g = rng(1111);
  S worst = S(0), worstQ = S(0), worstOff = S(0);
  for (int k = 0; k < 30; ++k) {
    const S l = uni<S>(g, 0.2, 3);
    const Vec3<S> ax1 = unit3<S>(g);
    const S th1 = uni<S>(g, -3, 3);
    const Vec3<S> ax2 = unit3<S>(g);
    const S th2 = uni<S>(g, -3, 3);
    const SE3<S> m = rotationAbout<S>(ax1, th1, Vec3<S>::Zero().eval()) * rotationAbout<S>(ax2, th2, Vec3<S>(S(0), S(0), l));
    const Vec8<S> x = study(m);
    worst = std::max<S>(worst, S(abs(sphericalSphericalFormAsPrinted<S>(x, l)) / (S(1) + l * l)));
    worstQ = std::max<S>(
        worstQ, S(abs(quadricResidual<S>(sphereConstraintQuadric<S>(Vec3<S>::Zero(), Vec3<S>(S(0), S(0), l), l), x))));
    const Vec8<S> y = study(SE3<S>(m.so3(), Vec3<S>(m.translation() + Vec3<S>(frac<S>(1, 2), S(0), S(0)))));
    const S off = abs(sphericalSphericalFormAsPrinted<S>(y, l));
    worstOff = k == 0 ? off : std::min<S>(worstOff, off);
  }
  c.checkResidual("book's S–S quadric (c₀ − l a₃)c₀ + (c₁ + l a₂)c₁ + (c₂ − l a₁)c₂ + (c₃ + l a₀)c₃ on 30 S–S postures (512 ε)",
                  worst, tol<S>(512));
  c.checkResidual("soma's sphere quadric |a q + 2c − p a|² − L²|a|² (p = 0, q = (0,0,l), L = l) on the same postures (512 ε)",
                  worstQ, tol<S>(512));
  c.recordIn<S>("the book's form is not identically zero: min over motions displaced by 0.5 off the variety", "> 1e-3",
                toString(worstOff, 4), worstOff, frac<S>(1, 1000), worstOff > frac<S>(1, 1000));
}

template <class S> void ssAtInfinity(Context& c) {
  auto g = rng(1112);
  S worst = S(0);
  for (int k = 0; k < 20; ++k) {
    const Vec3<S> p = rv3<S>(g), q = rv3<S>(g);
    const Mat8<S> Q = sphereConstraintQuadric<S>(p, q, uni<S>(g, 0.1, 3));
    Vec8<S> x = Vec8<S>::Zero();
    x.template tail<4>() = rv4<S>(g);
    worst = std::max<S>(worst, S(abs(S(x.dot(Q * x) - S(4) * x.template tail<4>().squaredNorm())) / x.squaredNorm()));
  }
  c.checkResidual("every leg quadric restricted to a = 0 is 4(c₀² + c₁² + c₂² + c₃²): the conic at infinity it contains (256 ε)",
                  worst, tol<S>());
}

template <class S> void stewartLegQuadric(Context& c) {
  auto g = rng(1113);
  S worst = S(0), worstBook = S(0), worstVec = S(0);
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> p = S(2) * rv3<S>(g), q = rv3<S>(g);
    const SE3<S> m = SE3<S>::Random(g);
    const S L = (m.act(q) - p).norm();
    const Vec8<S> x = study(m) * uni<S>(g, 0.5, 3);
    worst = std::max<S>(worst, S(abs(quadricResidual<S>(sphereConstraintQuadric<S>(p, q, L), x)) / (S(1) + L * L)));
    const Vec4<S> book = stewartLegExpressionAsPrinted<S>(x, p, q, L);
    worstBook = std::max<S>(worstBook, S(abs(book(0)) / x.squaredNorm() / (S(1) + L * L)));
    worstVec = std::max<S>(worstVec, S(book.template tail<3>().cwiseAbs().maxCoeff() / x.squaredNorm() / (S(1) + L * L)));
  }
  c.checkResidual("soma's leg quadric vanishes at 50 random poses with L = |g(q) − p| (any projective scale; 512 ε)", worst,
                  tol<S>(512));
  c.checkResidual("the book's homogenised leg equation (scalar part) vanishes at the same poses (512 ε)", worstBook, tol<S>(512));
  c.checkResidual("… and its vector part vanishes identically (512 ε)", worstVec, tol<S>(512));
  const Vec3<S> p1 = rv3<S>(g), q1 = rv3<S>(g);
  const Mat8<S> Q1 = sphereConstraintQuadric<S>(p1, q1, frac<S>(13, 10));
  const Vec3<S> p2 = rv3<S>(g), q2 = rv3<S>(g);
  const Mat8<S> Q2 = sphereConstraintQuadric<S>(p2, q2, frac<S>(4, 5));
  c.checkResidual("Wampler: the difference of two leg quadrics has no c–c (4h₁h₁*) block (exact)",
                  S((Q1 - Q2).template bottomRightCorner<4, 4>().cwiseAbs().maxCoeff()), S(0));
}

}  // namespace

SOMA_STUDY_SCALAR("GF-11.2.1-lines-through-identity", "Lines through the identity in the quadric have c₀ = 0", "GF §11.2.1",
                  linesThroughIdentity);
SOMA_STUDY_SCALAR("GF-11.2.1-rotation-translation-lines", "Rotations about a line and translations are lines; screws are conics",
                  "GF §11.2.1", rotationTranslationLines);
SOMA_STUDY_SCALAR("GF-11.2.2-three-planes-A-B", "3-planes (I−M)a + (I+M)c = 0, M ∈ O(4): A-planes and B-planes", "GF §11.2.2",
                  threePlanes);
SOMA_STUDY_SCALAR("GF-11.2.2-planes-through-identity", "SO(3)_p (Cayley), SE(2), R³ and the plane at infinity", "GF §11.2.2",
                  planesThroughIdentity);
SOMA_STUDY_SCALAR("GF-11.2.2-A-plane-cosets", "Cosets g·SO(3)_p are A-planes", "GF §11.2.2", planeCosets);
SOMA_STUDY_SCALAR("GF-11.2.3-intersection-corank", "Intersection of 3-planes: corank = multiplicity of eigenvalue 1 of M₁M₂ᵀ",
                  "GF §11.2.3", intersectionCorank);
SOMA_STUDY_SCALAR("GF-11.2.3-intersection-cases", "A∩A and B∩B empty, A∩B a point; special positions", "GF §11.2.3",
                  intersectionCases);
SOMA_STUDY_SCALAR("GF-11.2.3-meet-infinite-A-plane", "Meeting the A-plane at infinity: none, line, point, 2-plane", "GF §11.2.3",
                  meetInfinite);
SOMA_STUDY_SCALAR("GF-11.2.3-klein-analogue", "The Klein-quadric analogue: α∩α and β∩β a point, α∩β empty", "GF §11.2.3",
                  kleinAnalogue);
SOMA_STUDY_SCALAR("GF-11.4-line-isotropy-quadric", "Isotropy of a line: the quadric a₀c₀ + a₃c₃ = 0 (erratum: a₀ = a₃ = 0)",
                  "GF §11.4", lineIsotropy);
SOMA_STUDY_SCALAR("GF-11.4-2R-three-plane", "The 2R dyad lies in a 3-plane (degenerate l = 0 shown)", "GF §11.4", twoRThreePlane);
SOMA_STUDY_SCALAR("GF-11.5-table-11.2", "The intersection ring of the Study quadric (Table 11.2)", "GF §11.5", tableRing);
SOMA_STUDY_SCALAR("GF-11.5-2R-class", "Counts from the ring: 2R, 6R (16), 6-3 Stewart (16), tripod wrist (8), guard 128",
                  "GF §11.5", ringCounts);
SOMA_STUDY_SCALAR("GF-11.5.3-SS-link-variety", "The S–S link variety is a quadric (book's form and soma's agree)", "GF §11.5.3",
                  ssLinkVariety);
SOMA_STUDY_SCALAR("GF-11.5.3-SS-quadric-at-infinity", "Every S–S variety contains the conic c·c = 0, a = 0", "GF §11.5.3",
                  ssAtInfinity);
SOMA_STUDY_SCALAR("GF-11.5.4-stewart-leg-quadric", "The Stewart leg equation as a quadric in Study parameters", "GF §11.5.4",
                  stewartLegQuadric);

}  // namespace soma::studies::gf11::SOMA_UNITY_ID
