// Studies of GF chapter 11: the Study quadric, its 3-planes and their intersections (§11.2),
// quadric sections of linkages (§11.4, §11.5.3–11.5.4) and the intersection ring (§11.5).
// Double precision; the geometry is instantiated and tested for all five scalars in tests/geometry/study.
#include "soma/geometry/study/constraint_quadrics.hpp"
#include "soma/geometry/study/intersection_ring.hpp"
#include "soma/geometry/study/quaternion_matrices.hpp"
#include "soma/geometry/study/study_plane.hpp"
#include "soma/studies/study.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <random>

namespace soma::studies::gf11::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using S = double;
constexpr const char* kChapter = "GF 11 — The Study quadric";

std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }
double uni(std::mt19937_64& g, double lo = -1, double hi = 1) { return std::uniform_real_distribution<double>(lo, hi)(g); }
Vec3<S> vec3(std::mt19937_64& g) { return Vec3<S>(uni(g), uni(g), uni(g)); }
Vec3<S> unit3(std::mt19937_64& g) { return vec3(g).normalized(); }
Mat4<S> orthogonal(std::mt19937_64& g, int det) {
  Mat4<S> A;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) A(i, j) = uni(g);
  Mat4<S> Q = Eigen::HouseholderQR<Mat4<S>>(A).householderQ();
  if ((Q.determinant() > 0) != (det > 0)) Q.col(0) = -Q.col(0);
  return Q;
}
SE3<S> rotationAbout(const Vec3<S>& axis, double angle, const Vec3<S>& point) {
  const SO3<S> R = SO3<S>::fromAxisAngle(axis, angle);
  return SE3<S>(R, Vec3<S>(point - R.act(point)));
}
Vec8<S> study(const SE3<S>& m) { return StudyParameters<S>::fromSE3(m).coeffs(); }
double tol(int ulps = 256) { return Tolerance<S>::identity(ulps); }
/// Numerical rank of a set of points of PR⁷ (columns), relative to the largest singular value.
template <int N> int rankOf(const Eigen::Matrix<S, 8, N>& m) {
  const auto sv = Eigen::JacobiSVD<Eigen::Matrix<S, 8, N>>(m).singularValues();
  int r = 0;
  for (int k = 0; k < sv.size(); ++k) r += sv(k) > Tolerance<S>::rank() * sv(0);
  return r;
}

// ---- GF §11.2.1 ----------------------------------------------------------------------------
void linesThroughIdentity(Context& c) {
  auto g = rng(1101);
  // A point of the quadric with c0 ≠ 0: the motion of a rotation with a translation along its axis.
  const Vec8<S> x = study(SE3<S>(SO3<S>::fromAxisAngle(Vec3<S>(0, 0, 1), 0.8), Vec3<S>(0.3, -0.2, 1.1)));
  const Vec8<S> one = StudyParameters<S>().coeffs();
  c.record("the chosen point (a screw with pitch) has |c₀|", "> 0.1", toString(std::abs(x(4)), 4), std::abs(x(4)), 0.1,
           std::abs(x(4)) > 0.1);
  double worstOut = 0, worstIn = 0;
  for (double t : {0.3, -1.7, 5.0}) {
    const Vec8<S> p = one + t * x;
    worstOut = std::max(worstOut, std::abs(p.head<4>().dot(p.tail<4>())) / p.squaredNorm());
  }
  c.record("the line 1 + t x through a point with c₀ ≠ 0 leaves the quadric (min over 3 t of |a·c|/|x|²)", "> 1e-3",
           toString(worstOut, 4), worstOut, 1e-3, worstOut > 1e-3);
  // Normal form c0 = 0: any point with c0 = 0 on the quadric spans a line inside it.
  for (int k = 0; k < 20; ++k) {
    Vec3<S> a = vec3(g), cv = vec3(g);
    cv -= cv.dot(a) / a.squaredNorm() * a;  // a⃗·c⃗ = 0
    Vec8<S> y;
    y << 0, a, 0, cv;
    for (double t : {0.3, -1.7, 5.0}) {
      const Vec8<S> p = one + t * y;
      worstIn = std::max(worstIn, std::abs(p.head<4>().dot(p.tail<4>())) / p.squaredNorm());
    }
  }
  c.checkResidual("c₀ = 0, a⃗·c⃗ = 0: α + β(a⃗ + εc⃗) stays in the quadric (20 lines × 3 points)", worstIn, tol());
}

void rotationTranslationLines(Context& c) {
  auto g = rng(1102);
  // Pitch-zero exponentials and translations are lines (rank 2 for three points); a screw of
  // non-zero pitch traces a conic (rank 3).
  const Vec3<S> axis = unit3(g), q = vec3(g);
  auto screw = [&](double pitch, double theta) {
    const SE3<S> r = rotationAbout(axis, theta, q);
    return study(SE3<S>(r.so3(), Vec3<S>(r.translation() + pitch * theta * axis)));
  };
  Eigen::Matrix<S, 8, 3> rot, tr, sc;
  const Vec3<S> t = vec3(g);
  for (int k = 0; k < 3; ++k) {
    const double th = 0.4 + 0.9 * k;
    rot.col(k) = screw(0, th);
    tr.col(k) = study(SE3<S>(SO3<S>(), Vec3<S>(th * t)));
    sc.col(k) = screw(0.3, th);
  }
  c.checkEqual("three rotations about one line span a line of P⁷ (rank)", 2, rankOf<3>(rot));
  c.checkEqual("three translations along one direction span a line (rank)", 2, rankOf<3>(tr));
  c.checkEqual("a screw motion of pitch 0.3 is not a line: three points have rank", 3, rankOf<3>(sc));
  // The direction part (a⃗, c⃗) of the rotation line is the Plücker line of the axis (a⃗·c⃗ = 0).
  const Vec8<S> d = rot.col(1) - rot.col(0) * (rot.col(1)(0) / rot.col(0)(0));
  c.checkResidual("rotation line: its direction (a⃗, c⃗) has a⃗·c⃗ = 0 (a line of space)",
                  std::abs(d.segment<3>(1).dot(d.segment<3>(5))) / d.squaredNorm(), tol());
}

// ---- GF §11.2.2 ----------------------------------------------------------------------------
void threePlanes(Context& c) {
  auto g = rng(1103);
  double worst = 0;
  int a = 0, b = 0;
  for (int k = 0; k < 200; ++k) {
    const int det = k % 2 ? 1 : -1;
    const auto P = StudyPlane<S>::fromOrthogonal(orthogonal(g, det));
    (P.kind() == StudyPlaneKind::A ? a : b)++;
    Vec4<S> y(uni(g), uni(g), uni(g), uni(g));
    const Vec8<S> x = P.point(y);
    worst = std::max({worst, std::abs(x.head<4>().dot(x.tail<4>())) / x.squaredNorm(), P.residual(x)});
  }
  c.checkResidual("a = (M+I)y, c = (M−I)y satisfies a·c = 0 and (I−M)a + (I+M)c = 0 (200 random M ∈ O(4))", worst, tol());
  c.checkEqual("det M = +1 planes classified A", 100, a);
  c.checkEqual("det M = −1 planes classified B", 100, b);
}

void planesThroughIdentity(Context& c) {
  auto g = rng(1104);
  const Vec3<S> p = vec3(g);
  const auto P = StudyPlane<S>::rotationsAbout(p);  // the book's Cayley form
  double worst = 0, worstC = 0;
  for (int k = 0; k < 20; ++k) {
    const Vec8<S> x = study(rotationAbout(unit3(g), uni(g, -3, 3), p));
    worst = std::max(worst, P.residual(x));
    worstC = std::max({worstC, std::abs(x(4)), (x.segment<3>(5) - p.cross(Vec3<S>(x.segment<3>(1)))).cwiseAbs().maxCoeff()});
  }
  c.checkResidual("M = diag(1, Cay(p)), Cay(p) = (I+[p]×)(I−[p]×)⁻¹: contains 20 random rotations about p", worst, tol());
  c.checkResidual("… and on it c₀ = 0, c⃗ = p × a⃗", worstC, tol());
  c.checkEqual("SO(3)_p is an A-plane", "A", P.kind() == StudyPlaneKind::A ? "A" : "B");
  const auto E = StudyPlane<S>::planarMotions(Vec3<S>(0, 0, 1));
  double worstE = 0;
  for (int k = 0; k < 20; ++k) {
    const SE3<S> m = SE3<S>(SO3<S>(), Vec3<S>(uni(g), uni(g), 0)) * rotationAbout(Vec3<S>(0, 0, 1), uni(g, -3, 3), vec3(g));
    const Vec8<S> x = study(m);
    worstE = std::max({worstE, E.residual(x), std::abs(x(1)), std::abs(x(2)), std::abs(x(4)), std::abs(x(7))});
  }
  c.checkResidual("R = half-turn about z: the SE(2) A-plane, a₁ = a₂ = c₀ = c₃ = 0 on 20 planar motions", worstE, tol());
  const auto T = StudyPlane<S>::translations();
  c.checkResidual("R = −I₃: the translations (a B-plane)", T.residual(study(SE3<S>(SO3<S>(), vec3(g)))), tol());
  c.checkEqual("R³ is a B-plane", "B", T.kind() == StudyPlaneKind::A ? "A" : "B");
  c.checkEqual("M = −I₄ is the A-plane at infinity a = 0", "A",
               StudyPlane<S>::atInfinity().kind() == StudyPlaneKind::A ? "A" : "B");
  // Near the extreme: Cay(p) → a half-turn as |p| → ∞ (SO(3)_p degenerates to SE(2)).
  const Vec3<S> far = 1e8 * Vec3<S>(0, 0, 1);
  const Mat3<S> half = 2 * Vec3<S>(0, 0, 1) * Vec3<S>(0, 0, 1).transpose() - Mat3<S>::Identity();
  c.checkResidual("|p| = 1e8 along z: Cay(p) is the half-turn about z to O(1/|p|)",
                  (cayleyRotation<S>(far) - half).cwiseAbs().maxCoeff(), 4e-8);
}

void planeCosets(Context& c) {
  auto g = rng(1105);
  double worst = 0;
  int kept = 0;
  for (int k = 0; k < 20; ++k) {
    const SE3<S> m = SE3<S>::Random(g);
    const Vec3<S> p = vec3(g);
    const auto P = StudyPlane<S>::rotationsAbout(p).leftTranslated(DualQuaternion<S>::fromSE3(m));
    kept += P.kind() == StudyPlaneKind::A;
    worst = std::max(worst, P.residual(study(SE3<S>(m * rotationAbout(unit3(g), uni(g, -3, 3), p)))));
  }
  c.checkEqual("g·SO(3)_p recovered from four points is an A-plane (det M = +1), 20 random g", 20, kept);
  c.checkResidual("… and contains g·(rotations about p)", worst, tol());
}

// ---- GF §11.2.3 ----------------------------------------------------------------------------
void intersectionCorank(Context& c) {
  auto g = rng(1106);
  int agree = 0;
  for (int k = 0; k < 100; ++k) {
    const auto P = StudyPlane<S>::fromOrthogonal(orthogonal(g, k % 2 ? 1 : -1));
    const auto Q = StudyPlane<S>::fromOrthogonal(orthogonal(g, k % 3 ? 1 : -1));
    agree += intersectionDimension(P, Q) == intersectionDimensionByEigenvalues(P, Q);
  }
  c.checkEqual("corank of the stacked 8×8 system − 1 = multiplicity of eigenvalue 1 of M₁M₂ᵀ − 1 (100 random pairs)", 100,
               agree);
}

void intersectionCases(Context& c) {
  auto g = rng(1107);
  int aa = 0, bb = 0, ab = 0;
  for (int k = 0; k < 50; ++k) {
    const auto A1 = StudyPlane<S>::fromOrthogonal(orthogonal(g, 1)), A2 = StudyPlane<S>::fromOrthogonal(orthogonal(g, 1));
    const auto B1 = StudyPlane<S>::fromOrthogonal(orthogonal(g, -1)), B2 = StudyPlane<S>::fromOrthogonal(orthogonal(g, -1));
    aa += intersectionDimension(A1, A2) == -1;
    bb += intersectionDimension(B1, B2) == -1;
    ab += intersectionDimension(A1, B1) == 0;
  }
  c.checkEqual("A∩A empty (50 random pairs)", 50, aa);
  c.checkEqual("B∩B empty", 50, bb);
  c.checkEqual("A∩B one point", 50, ab);
  // Special positions from the normal form diag(rot θ, rot φ): θ = 0 → a line.
  const Mat4<S> M1 = orthogonal(g, 1);
  Mat4<S> R = Mat4<S>::Identity();
  R.bottomRightCorner<2, 2>() << std::cos(1.0), -std::sin(1.0), std::sin(1.0), std::cos(1.0);
  c.checkEqual("A∩A with θ = 0: a line", 1,
               intersectionDimension(StudyPlane<S>::fromOrthogonal(M1), StudyPlane<S>::fromOrthogonal(Mat4<S>(R * M1))));
  Mat4<S> Rb = R;
  Rb(0, 0) = -1;  // det −1 with three unit eigenvalues? no: diag(−1, 1, rot φ) has one; use φ = 0
  Rb.bottomRightCorner<2, 2>().setIdentity();
  c.checkEqual("A∩B with φ = 0 (three unit eigenvalues): a 2-plane", 2,
               intersectionDimension(StudyPlane<S>::fromOrthogonal(M1), StudyPlane<S>::fromOrthogonal(Mat4<S>(Rb * M1))));
}

void meetInfinite(Context& c) {
  const auto inf = StudyPlane<S>::atInfinity();
  c.checkEqual("SO(3)_p meets the A-plane at infinity: no (dimension)", -1,
               intersectionDimension(inf, StudyPlane<S>::rotationsAbout(Vec3<S>(0.3, -1, 2))));
  c.checkEqual("SE(2) meets it in a line", 1, intersectionDimension(inf, StudyPlane<S>::planarMotions(Vec3<S>(0, 0, 1))));
  Mat4<S> M = Mat4<S>::Identity();
  M.bottomRightCorner<3, 3>() = -cayleyRotation<S>(Vec3<S>(0.2, 0.5, -0.7));
  c.checkEqual("a generic B-plane through 1 (det R = −1) meets it in a point", 0,
               intersectionDimension(inf, StudyPlane<S>::fromOrthogonal(M)));
  c.checkEqual("R³ meets it in a 2-plane", 2, intersectionDimension(inf, StudyPlane<S>::translations()));
}

void kleinAnalogue(Context& c) {
  // The same argument for the Klein quadric ω·v = 0 of P⁵ and its planes (I−M)ω + (I+M)v = 0, M ∈ O(3).
  auto g = rng(1108);
  auto o3 = [&](int det) {
    Mat3<S> A;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) A(i, j) = uni(g);
    Mat3<S> Q = Eigen::HouseholderQR<Mat3<S>>(A).householderQ();
    if ((Q.determinant() > 0) != (det > 0)) Q.col(0) = -Q.col(0);
    return Q;
  };
  auto dim = [](const Mat3<S>& M1, const Mat3<S>& M2) {
    Eigen::Matrix<S, 6, 6> m;
    m << Mat3<S>::Identity() - M1, Mat3<S>::Identity() + M1, Mat3<S>::Identity() - M2, Mat3<S>::Identity() + M2;
    const auto sv = Eigen::JacobiSVD<Eigen::Matrix<S, 6, 6>>(m).singularValues();
    int r = 0;
    for (int k = 0; k < 6; ++k) r += sv(k) > Tolerance<S>::rank() * sv(0);
    return 6 - r - 1;
  };
  int same = 0, opposite = 0;
  for (int k = 0; k < 50; ++k) {
    const int d = k % 2 ? 1 : -1;
    same += dim(o3(d), o3(d)) == 0;
    opposite += dim(o3(d), o3(-d)) == -1;
  }
  c.checkEqual("Klein quadric: two planes of the same family meet in a point (a common line of space), 50 pairs", 50, same);
  c.checkEqual("… planes of opposite families generically do not meet (GF-11.5 Halphen: α·β = 0)", 50, opposite);
}

// ---- GF §11.4 ------------------------------------------------------------------------------
void lineIsotropy(Context& c) {
  auto g = rng(1109);
  double worst = 0;
  for (int k = 0; k < 20; ++k) {
    const SE3<S> m = SE3<S>(SO3<S>(), Vec3<S>(0, 0, uni(g, -3, 3))) * rotationAbout(Vec3<S>(0, 0, 1), uni(g, -3, 3), Vec3<S>::Zero().eval());
    const Vec8<S> x = study(m);
    worst = std::max({worst, std::abs(x(1)), std::abs(x(2)), std::abs(x(5)), std::abs(x(6)), std::abs(x(0) * x(4) + x(3) * x(7))});
  }
  c.checkResidual("isotropy of the z-axis (rotations and slides along z) lies in a₁ = a₂ = c₁ = c₂ = 0 and a₀c₀ + a₃c₃ = 0",
                  worst, tol());
  // The non-subgroup points: the printed "a₂ = a₃ = 0" contains (1,0,0,0 : 0,0,0,1), the
  // translation by 2 along z (c = ½ t a), a subgroup element; a₀ = a₃ = 0 is the line at infinity.
  Vec8<S> x = Vec8<S>::Zero();
  x(0) = 1, x(7) = 1;
  const SE3<S> m = StudyParameters<S>(x).toSE3();
  const double slide = (m.translation() - Vec3<S>(0, 0, 2)).norm() + (m.rotation() - Mat3<S>::Identity()).norm();
  c.checkResidual("(1,0,0,0 : 0,0,0,1) with a₂ = a₃ = 0 is the translation by 2 along z", slide, tol());
  c.checkPrintedFails("\"the line at infinity a₂ = a₃ = 0\" has no motions: distance of that point from a = 0", "GF11-1",
              x.head<4>().norm(), tol());
  c.checkEqual("a₀ = a₃ = 0 on the isotropy 3-plane is the line at infinity (a = 0)", "yes",
               StudyParameters<S>(Vec8<S>((Vec8<S>() << 0, 0, 0, 0, 0.3, 0, 0, -1.2).finished())).inExceptionalPlane() ? "yes" : "no");
}

void twoRThreePlane(Context& c) {
  auto g = rng(1110);
  double worst = 0;
  for (int k = 0; k < 30; ++k) {
    const double l = uni(g, 0.1, 3), alpha = uni(g, 0.1, 3);
    const SE3<S> m = rotationAbout(Vec3<S>(0, 0, 1), uni(g, -3, 3), Vec3<S>::Zero().eval()) *
                     rotationAbout(Vec3<S>(0, -std::sin(alpha), std::cos(alpha)), uni(g, -3, 3), Vec3<S>(l, 0, 0));
    worst = std::max(worst, (twoRevoluteEquations<S>(l, alpha) * study(m)).cwiseAbs().maxCoeff());
  }
  c.checkResidual("l a₂ − c₃ = l a₁ − c₀ = l a₁ cos α − c₁ sin α = l a₂ cos α − c₂ sin α = 0 on 30 random 2R postures",
                  worst, tol());
  // Erratum GF11-7: "3-plane ∩ Study quadric is a 2-dimensional quadric" fails for l = 0 (and
  // α = 0): there the 3-plane (c = 0, the SO(3) A-plane) lies wholly in the quadric. Measure the
  // Study form a·c on random points of the 3-plane: identically 0 for l = 0, not for l = 0.5.
  auto formOnPlane = [&](double l, double alpha) {
    const Eigen::Matrix<S, 8, 4> K = Eigen::FullPivLU<Eigen::Matrix<S, 4, 8>>(twoRevoluteEquations<S>(l, alpha)).kernel();
    double m = 0;
    for (int k = 0; k < 20; ++k) {
      const Vec8<S> x = K * Vec4<S>(uni(g), uni(g), uni(g), uni(g));
      m = std::max(m, std::abs(x.head<4>().dot(x.tail<4>())) / x.squaredNorm());
    }
    return m;
  };
  const double zeroL = formOnPlane(0.0, 0.7), someL = formOnPlane(0.5, 0.7), zeroAlpha = formOnPlane(0.5, 0.0);
  c.record("l = 0: max |a·c| on 20 points of the 2R 3-plane (the plane lies in the quadric; erratum GF11-7)", "0",
           toString(zeroL, 3), zeroL, tol(), zeroL <= tol());
  c.record("α = 0: the same (the SE(2) A-plane; erratum GF11-7)", "0", toString(zeroAlpha, 3), zeroAlpha, tol(),
           zeroAlpha <= tol());
  c.record("l = 0.5, α = 0.7: the form is not zero on the plane (a genuine quadric surface)", "> 1e-3", toString(someL, 3),
           someL, 1e-3, someL > 1e-3);
}

// ---- GF §11.5 ------------------------------------------------------------------------------
void tableRing(Context& c) {
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

void ringCounts(Context& c) {
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
S sphericalSphericalFormAsPrinted(const Vec8<S>& x, S l) {
  const S a0 = x(0), a1 = x(1), a2 = x(2), a3 = x(3), c0 = x(4), c1 = x(5), c2 = x(6), c3 = x(7);
  return (c0 - l * a3) * c0 + (c1 + l * a2) * c1 + (c2 - l * a1) * c2 + (c3 + l * a0) * c3;
}

/// The book's homogenised leg equation evaluated literally with quaternions h₀ = a, h₁ = c:
/// (|p|² + |q|² − L²) h₀h₀* + h₀ q h₀* p + p h₀ q h₀* + 2 h₀ q h₁* − 2 h₁ q h₀* + 2 p h₁ h₀* − 2 h₀ h₁* p + 4 h₁ h₁*.
// GF §11.5.4 lines 7263–7278 as printed (correct)
Vec4<S> stewartLegExpressionAsPrinted(const Vec8<S>& x, const Vec3<S>& p, const Vec3<S>& q, S L) {
  const Vec4<S> h0 = x.head<4>(), h1 = x.tail<4>();
  const Vec4<S> qq(0, q.x(), q.y(), q.z()), pp(0, p.x(), p.y(), p.z());
  auto mul = [](const Vec4<S>& u, const Vec4<S>& v) { return Vec4<S>(quaternionLeftMatrix<S>(u) * v); };
  auto conj = [](const Vec4<S>& u) { return Vec4<S>(u(0), -u(1), -u(2), -u(3)); };
  const Vec4<S> h0s = conj(h0), h1s = conj(h1);
  const S k = p.squaredNorm() + q.squaredNorm() - L * L;
  return k * mul(h0, h0s) + mul(mul(mul(h0, qq), h0s), pp) + mul(pp, mul(mul(h0, qq), h0s)) + 2 * mul(mul(h0, qq), h1s) -
         2 * mul(mul(h1, qq), h0s) + 2 * mul(mul(pp, h1), h0s) - 2 * mul(mul(h0, h1s), pp) + 4 * mul(h1, h1s);
}

void ssLinkVariety(Context& c) {
  auto g = rng(1111);
  double worst = 0, worstQ = 0, worstOff = 1e300;
  for (int k = 0; k < 30; ++k) {
    const double l = uni(g, 0.2, 3);
    const SE3<S> m = rotationAbout(unit3(g), uni(g, -3, 3), Vec3<S>::Zero().eval()) * rotationAbout(unit3(g), uni(g, -3, 3), Vec3<S>(0, 0, l));
    const Vec8<S> x = study(m);
    worst = std::max(worst, std::abs(sphericalSphericalFormAsPrinted(x, l)) / (1 + l * l));
    worstQ = std::max(worstQ, std::abs(quadricResidual<S>(sphereConstraintQuadric<S>(Vec3<S>::Zero(), Vec3<S>(0, 0, l), l), x)));
    const Vec8<S> y = study(SE3<S>(m.so3(), Vec3<S>(m.translation() + Vec3<S>(0.5, 0, 0))));
    worstOff = std::min(worstOff, std::abs(sphericalSphericalFormAsPrinted(y, l)));
  }
  c.checkResidual("book's S–S quadric (c₀ − l a₃)c₀ + (c₁ + l a₂)c₁ + (c₂ − l a₁)c₂ + (c₃ + l a₀)c₃ on 30 S–S postures", worst,
                  tol(512));
  c.checkResidual("soma's sphere quadric |a q + 2c − p a|² − L²|a|² (p = 0, q = (0,0,l), L = l) on the same postures", worstQ,
                  tol(512));
  c.record("the book's form is not identically zero: min over motions displaced by 0.5 off the variety", "> 1e-3",
           toString(worstOff, 4), worstOff, 1e-3, worstOff > 1e-3);
}

void ssAtInfinity(Context& c) {
  auto g = rng(1112);
  double worst = 0;
  for (int k = 0; k < 20; ++k) {
    const Mat8<S> Q = sphereConstraintQuadric<S>(vec3(g), vec3(g), uni(g, 0.1, 3));
    Vec8<S> x = Vec8<S>::Zero();
    x.tail<4>() << uni(g), uni(g), uni(g), uni(g);
    worst = std::max(worst, std::abs(x.dot(Q * x) - 4 * x.tail<4>().squaredNorm()) / x.squaredNorm());
  }
  c.checkResidual("every leg quadric restricted to a = 0 is 4(c₀² + c₁² + c₂² + c₃²): the conic at infinity it contains", worst,
                  tol());
}

void stewartLegQuadric(Context& c) {
  auto g = rng(1113);
  double worst = 0, worstBook = 0, worstVec = 0;
  for (int k = 0; k < 50; ++k) {
    const Vec3<S> p = 2 * vec3(g), q = vec3(g);
    const SE3<S> m = SE3<S>::Random(g);
    const double L = (m.act(q) - p).norm();
    const Vec8<S> x = study(m) * uni(g, 0.5, 3);
    worst = std::max(worst, std::abs(quadricResidual<S>(sphereConstraintQuadric<S>(p, q, L), x)) / (1 + L * L));
    const Vec4<S> book = stewartLegExpressionAsPrinted(x, p, q, L);
    worstBook = std::max(worstBook, std::abs(book(0)) / x.squaredNorm() / (1 + L * L));
    worstVec = std::max(worstVec, book.tail<3>().cwiseAbs().maxCoeff() / x.squaredNorm() / (1 + L * L));
  }
  c.checkResidual("soma's leg quadric vanishes at 50 random poses with L = |g(q) − p| (any projective scale)", worst, tol(512));
  c.checkResidual("the book's homogenised leg equation (scalar part) vanishes at the same poses", worstBook, tol(512));
  c.checkResidual("… and its vector part vanishes identically", worstVec, tol(512));
  const Mat8<S> Q1 = sphereConstraintQuadric<S>(vec3(g), vec3(g), 1.3), Q2 = sphereConstraintQuadric<S>(vec3(g), vec3(g), 0.8);
  c.checkResidual("Wampler: the difference of two leg quadrics has no c–c (4h₁h₁*) block",
                  (Q1 - Q2).bottomRightCorner<4, 4>().cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-11.2.1-lines-through-identity", "Lines through the identity in the quadric have c₀ = 0", "GF §11.2.1",
           linesThroughIdentity);
SOMA_STUDY_DOUBLE("GF-11.2.1-rotation-translation-lines", "Rotations about a line and translations are lines; screws are conics",
           "GF §11.2.1", rotationTranslationLines);
SOMA_STUDY_DOUBLE("GF-11.2.2-three-planes-A-B", "3-planes (I−M)a + (I+M)c = 0, M ∈ O(4): A-planes and B-planes", "GF §11.2.2",
           threePlanes);
SOMA_STUDY_DOUBLE("GF-11.2.2-planes-through-identity", "SO(3)_p (Cayley), SE(2), R³ and the plane at infinity", "GF §11.2.2",
           planesThroughIdentity);
SOMA_STUDY_DOUBLE("GF-11.2.2-A-plane-cosets", "Cosets g·SO(3)_p are A-planes", "GF §11.2.2", planeCosets);
SOMA_STUDY_DOUBLE("GF-11.2.3-intersection-corank", "Intersection of 3-planes: corank = multiplicity of eigenvalue 1 of M₁M₂ᵀ",
           "GF §11.2.3", intersectionCorank);
SOMA_STUDY_DOUBLE("GF-11.2.3-intersection-cases", "A∩A and B∩B empty, A∩B a point; special positions", "GF §11.2.3",
           intersectionCases);
SOMA_STUDY_DOUBLE("GF-11.2.3-meet-infinite-A-plane", "Meeting the A-plane at infinity: none, line, point, 2-plane", "GF §11.2.3",
           meetInfinite);
SOMA_STUDY_DOUBLE("GF-11.2.3-klein-analogue", "The Klein-quadric analogue: α∩α and β∩β a point, α∩β empty", "GF §11.2.3",
           kleinAnalogue);
SOMA_STUDY_DOUBLE("GF-11.4-line-isotropy-quadric", "Isotropy of a line: the quadric a₀c₀ + a₃c₃ = 0 (erratum: a₀ = a₃ = 0)",
           "GF §11.4", lineIsotropy);
SOMA_STUDY_DOUBLE("GF-11.4-2R-three-plane", "The 2R dyad lies in a 3-plane (degenerate l = 0 shown)", "GF §11.4", twoRThreePlane);
SOMA_STUDY_DOUBLE("GF-11.5-table-11.2", "The intersection ring of the Study quadric (Table 11.2)", "GF §11.5", tableRing);
SOMA_STUDY_DOUBLE("GF-11.5-2R-class", "Counts from the ring: 2R, 6R (16), 6-3 Stewart (16), tripod wrist (8), guard 128",
           "GF §11.5", ringCounts);
SOMA_STUDY_DOUBLE("GF-11.5.3-SS-link-variety", "The S–S link variety is a quadric (book's form and soma's agree)", "GF §11.5.3",
           ssLinkVariety);
SOMA_STUDY_DOUBLE("GF-11.5.3-SS-quadric-at-infinity", "Every S–S variety contains the conic c·c = 0, a = 0", "GF §11.5.3",
           ssAtInfinity);
SOMA_STUDY_DOUBLE("GF-11.5.4-stewart-leg-quadric", "The Stewart leg equation as a quadric in Study parameters", "GF §11.5.4",
           stewartLegQuadric);

}  // namespace soma::studies::gf11::SOMA_UNITY_ID
