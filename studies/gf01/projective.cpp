// Studies of GF §1.3 (projective space and quadrics): equality of homogeneous coordinates up to a
// non-zero (real or complex) scale, the polar hyperplane of a point with respect to a quadric, the
// rank of a singular quadric and its singular locus, and the linear projection from a centre onto
// a hyperplane. Every study honours --scalar: the linear algebra is soma's one-sided Jacobi SVD
// (algebra/small_linalg.hpp), complex numbers are kept as pairs of reals.
#include "gf01/common.hpp"

#include <fmt/format.h>

#include <limits>
#include <stdexcept>

namespace soma::studies::gf01::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF-1.3-projective-equality ---------------------------------------------------------------
/// A vector of C^{n+1} as its real and imaginary parts.
template <class S> struct CVec {
  VecX<S> re, im;
};
/// Largest |Re| or |Im| of an entry: a scale that neither overflows nor underflows (no squares).
template <class S> S cscale(const CVec<S>& u) { return maxOf(maxAbs(u.re), maxAbs(u.im)); }
/// λu for complex λ = (lr, li).
template <class S> CVec<S> cmul(const S& lr, const S& li, const CVec<S>& u) {
  return {VecX<S>(lr * u.re - li * u.im), VecX<S>(lr * u.im + li * u.re)};
}
/// The largest 2 × 2 minor |u_i v_j − u_j v_i| of u/‖u‖∞ and v/‖v‖∞: zero iff u, v are the same
/// point of PC^n (GF §1.3). Scale-free, and no coordinate is singled out (a zero x₀ is fine).
/// Throws for the zero vector, which is not a point.
template <class S> S minorsResidual(const CVec<S>& u0, const CVec<S>& v0) {
  const S su = cscale(u0), sv = cscale(v0);
  if (!(su > S(0)) || !(sv > S(0))) throw std::invalid_argument("the zero vector is not a point of projective space");
  const CVec<S> u{VecX<S>(u0.re / su), VecX<S>(u0.im / su)}, v{VecX<S>(v0.re / sv), VecX<S>(v0.im / sv)};
  S worst(0);
  for (Eigen::Index i = 0; i < u.re.size(); ++i)
    for (Eigen::Index j = i + 1; j < u.re.size(); ++j) {
      const S re = (u.re(i) * v.re(j) - u.im(i) * v.im(j)) - (u.re(j) * v.re(i) - u.im(j) * v.im(i));
      const S im = (u.re(i) * v.im(j) + u.im(i) * v.re(j)) - (u.re(j) * v.im(i) + u.im(j) * v.re(i));
      worst = maxOf(worst, maxOf(abs(re), abs(im)));
    }
  return worst;
}
/// Complex rank of the columns (as vectors of C^{n+1}): half the real rank of [[Re, −Im], [Im, Re]].
template <class S> int complexRank(const std::vector<CVec<S>>& cols) {
  const Eigen::Index n = cols.front().re.size(), k = Eigen::Index(cols.size());
  MatX<S> m(2 * n, 2 * k);
  for (Eigen::Index j = 0; j < k; ++j) {
    const CVec<S> u{VecX<S>(cols[std::size_t(j)].re / cscale(cols[std::size_t(j)])),
                    VecX<S>(cols[std::size_t(j)].im / cscale(cols[std::size_t(j)]))};
    m.col(j) << u.re, u.im;
    m.col(k + j) << VecX<S>(-u.im), u.re;
  }
  return detail::smallNumericalRank<S>(m) / 2;
}

template <class S> void projectiveEquality(Context& c) {
  std::mt19937_64 g(1301);
  const Eigen::Index n = 5;  // PC⁴
  const S tol = Tolerance<S>::identity(16);  // a minor of unit-scale entries: a few roundings
  auto randomC = [&](bool real) {
    CVec<S> u{randomVec<S>(g, n), real ? VecX<S>(VecX<S>::Zero(n)) : randomVec<S>(g, n)};
    return u;
  };
  // λ: real of both signs, complex, and at the ends of the scalar's range.
  const S tiny = std::numeric_limits<S>::min() / Tolerance<S>::epsilon();
  const S huge = std::numeric_limits<S>::max() * Tolerance<S>::epsilon();
  S worstSame(0), leastDiff(std::numeric_limits<S>::max());
  int agreeSame = 0, agreeDiff = 0;
  const int draws = 100;
  for (int k = 0; k < draws; ++k) {
    const CVec<S> u = randomC(k % 2 == 0);
    S lr = uniform<S>(g, -3, 3), li = k % 3 == 0 ? S(0) : uniform<S>(g, -3, 3);
    if (k == 0) lr = tiny, li = S(0);
    if (k == 1) lr = huge, li = S(0);
    if (k == 2) lr = -tiny, li = tiny;
    if (k == 3) lr = S(0), li = -huge;
    CVec<S> w = u;
    if (k == 4) w.re(0) = w.im(0) = S(0);  // a point with x₀ = 0: nothing may divide by it
    const CVec<S> lu = cmul(lr, li, w);
    const S same = minorsResidual(w, lu);
    worstSame = maxOf(worstSame, same);
    agreeSame += complexRank<S>({w, lu}) == 1;
    const CVec<S> v = randomC(k % 2 == 1);
    const S diff = minorsResidual(u, v);
    leastDiff = diff < leastDiff ? diff : leastDiff;
    agreeDiff += complexRank<S>({u, v}) == 2;
  }
  c.checkResidual(fmt::format("(x₀:…:x₄) = (λx₀:…:λx₄): largest 2×2 minor over {} draws (λ real ±, complex, "
                              "min/ε, max·ε; one point with x₀ = 0), tolerance 16ε",
                              draws),
                  worstSame, tol);
  c.checkEqual("… and the SVD rank of [u, λu] over C is 1 for every draw (second method)", draws, agreeSame);
  c.recordIn("independent random points: the smallest largest-minor stays far above 16ε", "> 16ε",
             io::numberText(leastDiff), leastDiff, tol, leastDiff > S(1000) * tol);
  c.checkEqual("… and their SVD rank over C is 2 for every draw", draws, agreeDiff);
  bool threw = false;
  try {
    (void)minorsResidual(CVec<S>{VecX<S>::Zero(n), VecX<S>::Zero(n)}, randomC(true));
  } catch (const std::invalid_argument&) {
    threw = true;
  }
  c.checkEqual("the zero vector is rejected (not a point)", 1, threw ? 1 : 0);
  // A k-dimensional subspace of PC^n is a (k+1)-plane of C^{n+1}: the projective line through a, b
  // holds exactly the points αa + βb (rank 2), and a random point is off it (rank 3).
  int onLine = 0, offLine = 0;
  for (int k = 0; k < 20; ++k) {
    const CVec<S> a = randomC(false), b = randomC(false), x = randomC(false);
    const CVec<S> al = cmul(uniform<S>(g), uniform<S>(g), a), be = cmul(uniform<S>(g), uniform<S>(g), b);
    const CVec<S> y{VecX<S>(al.re + be.re), VecX<S>(al.im + be.im)};
    onLine += complexRank<S>({a, b, y}) == 2;
    offLine += complexRank<S>({a, b, x}) == 3;
  }
  c.checkEqual("the line through a, b of PC⁴ is the 2-plane span(a, b) of C⁵: αa + βb on it (20 draws)", 20, onLine);
  c.checkEqual("… a random point is not (rank 3, 20 draws)", 20, offLine);
}

// ---- GF-1.3-quadric-polar ---------------------------------------------------------------------
/// A random symmetric (n+1) × (n+1) matrix A + Aᵀ (indefinite: its quadric has real points).
template <class S> MatX<S> randomSymmetric(std::mt19937_64& g, Eigen::Index n1) {
  const MatX<S> a = randomMat<S>(g, n1, n1);
  return a + a.transpose();
}
template <class S> S form(const MatX<S>& M, const VecX<S>& x, const VecX<S>& y) { return x.dot(M * y); }
/// The two roots of a t² + 2b t + c = 0 (real; b² ≥ ac), by the stable formula.
template <class S> std::pair<S, S> quadraticRoots(const S& a, const S& b, const S& c) {
  const S d = sqrt(b * b - a * c);
  const S q = -(b + (b < S(0) ? -d : d));
  return {q / a, c / q};
}
/// A point of the quadric xᵀMx = 0 on a random real line (drawn until it meets the quadric).
template <class S> VecX<S> pointOnQuadric(std::mt19937_64& g, const MatX<S>& M) {
  for (;;) {
    const VecX<S> x = randomVec<S>(g, M.rows()), y = randomVec<S>(g, M.rows());
    const S a = form(M, y, y), b = form(M, x, y), cc = form(M, x, x);
    if (b * b - a * cc > S(0)) return VecX<S>(x + quadraticRoots(a, b, cc).first * y);
  }
}
/// |xᵀMy| / (‖x‖ ‖M‖ ‖y‖): the scale-free size of a bilinear value (max-norms).
template <class S> S relForm(const MatX<S>& M, const VecX<S>& x, const VecX<S>& y) {
  return abs(form(M, x, y)) / (maxAbs(x) * maxAbs(M) * maxAbs(y) * S(M.rows()));
}

template <class S> void quadricPolar(Context& c) {
  std::mt19937_64 g(1302);
  const Eigen::Index n1 = 5;  // a quadric of PR⁴
  const MatX<S> M = randomSymmetric<S>(g, n1);
  // (i) At a point p of the quadric the tangent hyperplane is pᵀMx = 0: the velocity of any curve
  // of the quadric through p lies in it. Curves γ(s) = p + s w + α(s) z with α solved from the
  // quadric, velocity by central differences.
  const S h = fdStep<S>();
  S worstTangent(0), worstOn(0);
  using V1 = Eigen::Matrix<S, 1, 1>;
  for (int k = 0; k < 30; ++k) {
    const VecX<S> p = pointOnQuadric(g, M), w = randomVec<S>(g, n1);
    VecX<S> z = randomVec<S>(g, n1);
    // a transversal z (zᵀMp not small), so that α(s) stays real over the steps ±h
    while (abs(form(M, z, p)) < maxAbs(z) * maxAbs(VecX<S>(M * p)) / S(4)) z = randomVec<S>(g, n1);
    worstOn = maxOf(worstOn, relForm(M, p, p));
    auto gamma = [&](const S& s) {
      const VecX<S> P = p + s * w;
      const S a = form(M, z, z), b = form(M, z, P), cc = form(M, P, P);
      const auto [t1, t2] = quadraticRoots(a, b, cc);
      return VecX<S>(P + (abs(t1) < abs(t2) ? t1 : t2) * z);  // the branch through p (α(0) = 0)
    };
    // pᵀMγ(s) has derivative pᵀMγ'(0) at 0: zero iff the velocity lies in pᵀMx = 0
    const S scale = maxAbs(VecX<S>(M * p));
    worstTangent = maxOf(worstTangent, fdRatio<S>([&](const S& s) { return V1(form(M, p, gamma(s)) / scale); }, V1(S(0)), h));
  }
  c.checkResidual("the points drawn lie on the quadric (|pᵀMp| / ‖p‖²‖M‖, 30 points)", worstOn, Tolerance<S>::identity(64));
  c.checkResidual("velocity of a curve in the quadric through p lies in the tangent hyperplane pᵀMx = 0: d/ds pᵀMγ(s) "
                  "by central differences (h = ε^{1/3}, h/2) over its bound (2× Richardson's estimate + rounding), 30 curves",
                  worstTangent, S(1));
  // (ii) For any p the polar pᵀMx = 0 is the locus of the harmonic conjugates of p with respect to
  // the two points where a line through p meets the quadric (cross-ratio −1, from the roots).
  S worstHarmonic(0);
  int lines = 0;
  const VecX<S> p = randomVec<S>(g, n1);
  while (lines < 30) {
    const VecX<S> y = randomVec<S>(g, n1);
    const S a = form(M, y, y), b = form(M, p, y), cc = form(M, p, p);
    if (!(b * b - a * cc > S(0))) continue;
    const auto [t1, t2] = quadraticRoots(a, b, cc);
    if (abs(t1 + t2) < (abs(t1) + abs(t2)) / S(4)) continue;  // keep the conjugate's amplification ≤ 4
    ++lines;
    const S th = S(2) * t1 * t2 / (t1 + t2);  // (0, t_h; t1, t2) = −1
    const VecX<S> q = p + th * y;
    worstHarmonic = maxOf(worstHarmonic, relForm(M, p, q));
  }
  c.checkResidual("harmonic conjugate of p w.r.t. the two intersections of 30 lines through p lies on the polar pᵀMx = 0",
                  worstHarmonic, Tolerance<S>::identity(256));
  // The tangent lines from p touch the quadric along polar ∩ quadric: for q there, the line pq meets
  // the quadric in a double point (discriminant (pᵀMq)² − (pᵀMp)(qᵀMq) = 0).
  S worstTouch(0);
  const S pp = form(M, p, p);
  for (int k = 0; k < 30;) {
    VecX<S> x = randomVec<S>(g, n1), y = randomVec<S>(g, n1);
    x -= (form(M, p, x) / pp) * p;  // into the polar of p
    y -= (form(M, p, y) / pp) * p;
    const S a = form(M, y, y), b = form(M, x, y), cc = form(M, x, x);
    if (!(b * b - a * cc > S(0))) continue;
    ++k;
    const VecX<S> q = x + quadraticRoots(a, b, cc).first * y;
    const S disc = form(M, p, q) * form(M, p, q) - pp * form(M, q, q);
    worstTouch = maxOf(worstTouch, abs(disc) / (abs(pp) * maxAbs(q) * maxAbs(q) * maxAbs(M) * S(n1)));
  }
  c.checkResidual("… and q ∈ polar ∩ quadric: the line pq is tangent there (relative discriminant, 30 points)",
                  worstTouch, Tolerance<S>::identity(1024));
  // (iii) The polar of a k-dimensional subspace has dimension n − k − 1 (non-singular M).
  for (int k = 0; k <= 3; ++k) {
    const MatX<S> P = randomMat<S>(g, n1, k + 1);
    const MatX<S> rows = P.transpose() * M;  // the polar = {x : Pᵀ M x = 0}
    const int nullity = int(n1) - detail::smallNumericalRank<S>(rows);
    c.checkEqual(fmt::format("polar of a random {}-plane of PR⁴ has projective dimension 4 − {} − 1 = {}", k, k, 3 - k),
                 3 - k, nullity - 1);
  }
  // Extreme: a singular point (Mk = 0, M of rank 4) has no polar: kᵀM = 0, every x satisfies it.
  {
    const VecX<S> kvec = randomVec<S>(g, n1);
    const MatX<S> Pr = MatX<S>::Identity(n1, n1) - kvec * kvec.transpose() / kvec.squaredNorm();
    const MatX<S> Ms = Pr * M * Pr;  // a rank-4 quadric with vertex k
    c.checkEqual("rank-4 quadric: rank 4 (SVD)", 4, detail::smallNumericalRank<S>(Ms));
    c.checkResidual("… the polar of its vertex k is undefined: kᵀM = 0 (relative)",
                    maxAbs(VecX<S>(Ms * kvec)) / (maxAbs(Ms) * maxAbs(kvec) * S(n1)), Tolerance<S>::identity(64));
  }
}

// ---- GF-1.3-quadric-singularity-rank ----------------------------------------------------------
template <class S> void quadricSingularityRank(Context& c) {
  std::mt19937_64 g(1303);
  const Eigen::Index n1 = 5;
  const VecX<S> a = randomVec<S>(g, n1), b = randomVec<S>(g, n1);
  const MatX<S> M1 = a * a.transpose(), M2 = a * b.transpose() + b * a.transpose();
  // Rank 1: xᵀMx = (a·x)², a repeated hyperplane, every point of it singular.
  S worst1(0), worst2(0), worstSing1(0);
  for (int k = 0; k < 50; ++k) {
    const VecX<S> x = randomVec<S>(g, n1);
    worst1 = maxOf(worst1, abs(form(M1, x, x) - a.dot(x) * a.dot(x)) / (maxAbs(a) * maxAbs(a) * maxAbs(x) * maxAbs(x)));
    worst2 = maxOf(worst2, abs(form(M2, x, x) - S(2) * a.dot(x) * b.dot(x)) / (maxAbs(a) * maxAbs(b) * maxAbs(x) * maxAbs(x)));
    const VecX<S> xh = x - (a.dot(x) / a.squaredNorm()) * a;  // on the hyperplane a·x = 0
    worstSing1 = maxOf(worstSing1, maxAbs(VecX<S>(M1 * xh)) / (maxAbs(M1) * maxAbs(xh)));
  }
  c.checkEqual("M = aaᵀ has rank 1 (SVD)", 1, detail::smallNumericalRank<S>(M1));
  c.checkResidual("… xᵀMx = (a·x)²: the hyperplane a·x = 0 counted twice (50 random x)", worst1, Tolerance<S>::identity(64));
  c.checkResidual("… every point of that hyperplane is singular: Mx = 0 (50 points)", worstSing1, Tolerance<S>::identity(64));
  c.checkEqual("M = abᵀ + baᵀ has rank 2 (SVD)", 2, detail::smallNumericalRank<S>(M2));
  c.checkResidual("… xᵀMx = 2(a·x)(b·x): a pair of hyperplanes (50 random x)", worst2, Tolerance<S>::identity(64));
  // Its singular locus, the null space of M (SVD), is the intersection a·x = b·x = 0.
  {
    MatX<S> u, v;
    std::vector<S> sig;
    detail::smallSvd<S>(M2, u, sig, v);
    S worstNull(0);
    for (Eigen::Index j = 2; j < n1; ++j) {
      const VecX<S> z = v.col(j);
      worstNull = maxOf(worstNull, maxOf(abs(a.dot(z)) / sqrt(a.squaredNorm()), abs(b.dot(z)) / sqrt(b.squaredNorm())));
    }
    c.checkResidual("… its null space (3 singular vectors, SVD) lies in a·x = 0 and b·x = 0: singular along the "
                    "intersection of the two hyperplanes",
                    worstNull, Tolerance<S>::identity(256));
    // A point of one hyperplane off the other is a smooth point: gradient 2Mx ≠ 0.
    const VecX<S> x0 = randomVec<S>(g, n1), xa = x0 - (a.dot(x0) / a.squaredNorm()) * a;
    const S grad = maxAbs(VecX<S>(M2 * xa)) / (maxAbs(M2) * maxAbs(xa));
    c.recordIn("a point of a·x = 0 with b·x ≠ 0 is on the quadric but not singular (relative |Mx|)", "> 1e-3",
               io::numberText(grad), grad, S(1) / S(1000), grad > S(1) / S(1000) && relForm(M2, xa, xa) < Tolerance<S>::identity(64));
  }
  // A non-singular quadric: det M ≠ 0, no singular point (rank n + 1).
  {
    const MatX<S> M = randomSymmetric<S>(g, n1);
    c.checkEqual("random symmetric M: rank 5 — no singular point (pᵀM = 0 has only p = 0)", 5, detail::smallNumericalRank<S>(M));
    const S det = detail::smallDeterminant<S>(M);
    c.recordIn("… and det M ≠ 0 (relative to ‖M‖⁵)", "> 1e-3", io::numberText(det), abs(det), S(1) / S(1000),
               abs(det) / pow(maxAbs(M), S(5)) > S(1) / S(1000));
  }
  // Rank r = 3 (a cone with vertex a line): nullity 2, and the vertex points are on the quadric
  // with zero gradient.
  {
    const VecX<S> c1 = randomVec<S>(g, n1), c2 = randomVec<S>(g, n1), c3 = randomVec<S>(g, n1);
    const MatX<S> M = c1 * c1.transpose() - c2 * c2.transpose() + c3 * c3.transpose();
    c.checkEqual("M = c₁c₁ᵀ − c₂c₂ᵀ + c₃c₃ᵀ: rank 3, singular along a line (nullity 2)", 2,
                 int(n1) - detail::smallNumericalRank<S>(M));
  }
  // Extreme: the rank decision on both sides of its threshold (Tolerance::rank = 1024ε).
  {
    const MatX<S> Mab = a * a.transpose() / a.squaredNorm();
    const VecX<S> bo = b - (a.dot(b) / a.squaredNorm()) * a;
    const MatX<S> Mbb = bo * bo.transpose() / bo.squaredNorm();
    const S thr = Tolerance<S>::rank();
    c.checkEqual("aaᵀ + σ bbᵀ with σ = 10 × the rank threshold: rank 2", 2,
                 detail::smallNumericalRank<S>(MatX<S>(Mab + S(10) * thr * Mbb)));
    c.checkEqual("… with σ = threshold / 10: rank 1", 1, detail::smallNumericalRank<S>(MatX<S>(Mab + thr / S(10) * Mbb)));
  }
  // x₀² + x₁² splits only over C: (x₀ + i x₁)(x₀ − i x₁), i.e. M = ½(αβᵀ + βαᵀ) with α = (1, i, 0),
  // β = (1, −i, 0) (complex products kept as real pairs), and its only real point is (0 : 0 : 1).
  {
    const Eigen::Matrix<S, 3, 1> ar(1, 0, 0), ai(0, 1, 0), br(1, 0, 0), bi(0, -1, 0);
    const Eigen::Matrix<S, 3, 3> re = (ar * br.transpose() - ai * bi.transpose() + br * ar.transpose() - bi * ai.transpose()) / S(2);
    const Eigen::Matrix<S, 3, 3> im = (ar * bi.transpose() + ai * br.transpose() + br * ai.transpose() + bi * ar.transpose()) / S(2);
    const Eigen::Matrix<S, 3, 3> M = Eigen::Matrix<S, 3, 1>(1, 1, 0).asDiagonal();
    c.checkResidual("x₀² + x₁² = (x₀ + ix₁)(x₀ − ix₁): ½(αβᵀ + βαᵀ) = diag(1, 1, 0), imaginary part 0",
                    maxOf(maxAbs(Eigen::Matrix<S, 3, 3>(re - M)), maxAbs(im)), Tolerance<S>::identity(4));
    S least = std::numeric_limits<S>::max();
    for (int k = 0; k < 50; ++k) {
      Eigen::Matrix<S, 3, 1> x(uniform<S>(g), uniform<S>(g), uniform<S>(g));
      const S r2 = x(0) * x(0) + x(1) * x(1);
      const S q = x.dot(M * x) / r2;
      least = q < least ? q : least;
    }
    c.checkNear("… over R: xᵀMx / (x₀² + x₁²) = 1 on 50 random points, so only the vertex (0:0:1) is real", S(1), least,
                Tolerance<S>::identity(4));
  }
}

// ---- GF-1.3-linear-projection -----------------------------------------------------------------
template <class S> void linearProjection(Context& c) {
  std::mt19937_64 g(1305);
  const Eigen::Index n1 = 5;  // PR⁴ onto a hyperplane PR³
  const VecX<S> cc = randomVec<S>(g, n1), a = randomVec<S>(g, n1);
  auto L = [&](const VecX<S>& x) { return a.dot(x); };
  auto pr = [&](const VecX<S>& x) { return VecX<S>(L(cc) * x - L(x) * cc); };  // GF §1.3
  S worstL(0), worstAffine(0);
  int collinear = 0;
  for (int k = 0; k < 100; ++k) {
    VecX<S> x = randomVec<S>(g, n1);
    const VecX<S> y = pr(x);
    worstL = maxOf(worstL, abs(L(y)) / (maxAbs(a) * maxAbs(a) * maxAbs(cc) * maxAbs(x) * S(n1)));
    MatX<S> m(n1, 3);
    m << cc, x, y;
    collinear += detail::smallNumericalRank<S>(m) == 2;
    // Independent: in the affine chart x₀ = 1 the line from C to X meets the affine hyperplane
    // a₀ + a'·Y = 0 at Y = C + s(X − C), s = −(a₀ + a'·C) / (a'·(X − C)).
    const VecX<S> C = cc.tail(n1 - 1) / cc(0), X = x.tail(n1 - 1) / x(0);
    const VecX<S> ap = a.tail(n1 - 1);
    const S s = -(a(0) + ap.dot(C)) / ap.dot(VecX<S>(X - C));
    VecX<S> Y(n1);
    Y << S(1), VecX<S>(C + s * (X - C));
    // the same point of PR⁴: the largest 2×2 minor of the normalised vectors
    const VecX<S> yn = y / maxAbs(y), Yn = Y / maxAbs(Y);
    S minor(0);
    for (Eigen::Index i = 0; i < n1; ++i)
      for (Eigen::Index j = i + 1; j < n1; ++j) minor = maxOf(minor, abs(yn(i) * Yn(j) - yn(j) * Yn(i)));
    // the affine solve divides by a'·(X − C) and by x₀: scale its rounding by those factors
    const S amp = maxAbs(ap) * maxAbs(VecX<S>(X - C)) / abs(ap.dot(VecX<S>(X - C))) * (S(1) + maxAbs(X) + maxAbs(C));
    worstAffine = maxOf(worstAffine, minor / amp);
  }
  c.checkResidual("L(pr(x)) = 0: the image lies in the hyperplane (100 random x, relative)", worstL, Tolerance<S>::identity(16));
  c.checkEqual("c, x, pr(x) are collinear: rank [c, x, pr(x)] = 2 (SVD, 100 random x)", 100, collinear);
  c.checkResidual("pr(x) is the point where the line cx meets the hyperplane, computed in the affine chart x₀ = 1 "
                  "(largest 2×2 minor / the affine solve's amplification, 100 x)",
                  worstAffine, Tolerance<S>::identity(256));
  // On the hyperplane the map is the identity of PR³; the centre is the exceptional point.
  {
    VecX<S> x = randomVec<S>(g, n1);
    x -= (L(x) / a.squaredNorm()) * a;
    c.checkResidual("L(x) = 0 ⇒ pr(x) = L(c)x (a point of the hyperplane is fixed)",
                    maxAbs(VecX<S>(pr(x) - L(cc) * x)) / (maxAbs(a) * maxAbs(cc) * maxAbs(cc) * maxAbs(x) * S(n1)),
                    Tolerance<S>::identity(16));
    const MatX<S> P = L(cc) * MatX<S>::Identity(n1, n1) - cc * a.transpose();
    c.checkEqual("the matrix L(c)I − caᵀ has rank 4: its kernel is the centre (pr(c) = 0, undefined there)", 4,
                 detail::smallNumericalRank<S>(P));
    c.checkResidual("… and that kernel is spanned by c", maxAbs(VecX<S>(P * cc)) / (maxAbs(P) * maxAbs(cc) * S(n1)),
                    Tolerance<S>::identity(16));
    // Extreme: the centre on the hyperplane (L(c) = 0): x ↦ −L(x)c, a constant point (rank 1).
    VecX<S> c0 = cc - (L(cc) / a.squaredNorm()) * a;
    const MatX<S> P0 = L(c0) * MatX<S>::Identity(n1, n1) - c0 * a.transpose();
    c.checkEqual("centre on the hyperplane (L(c) = 0): the map degenerates to the constant point c (rank 1)", 1,
                 detail::smallNumericalRank<S>(P0));
  }
  // A centre of dimension j = 1 (a line span(c₁, c₂) of PR³) projects onto a line L₁ = L₂ = 0
  // disjoint from it (n − j − 1 = 1). Two constructions: (i) x − αc₁ − βc₂ with Lᵢ = 0 solved;
  // (ii) the cofactor formula det[[L₁(c₁), L₁(c₂), L₁(x)], [L₂(c₁), L₂(c₂), L₂(x)], [c₁, c₂, x]]
  // (expanded along the vector row), which for j = 0 is the book's L(c)x − L(x)c.
  {
    using V4 = Eigen::Matrix<S, 4, 1>;
    auto r4 = [&] { return V4(uniform<S>(g), uniform<S>(g), uniform<S>(g), uniform<S>(g)); };
    const V4 c1 = r4(), c2 = r4(), l1 = r4(), l2 = r4();
    S worstAgree(0);
    MatX<S> images(4, 20);
    for (int k = 0; k < 20; ++k) {
      const V4 x = r4();
      Eigen::Matrix<S, 2, 2> A;
      A << l1.dot(c1), l1.dot(c2), l2.dot(c1), l2.dot(c2);
      Eigen::Matrix<S, 2, 1> rhs(l1.dot(x), l2.dot(x));
      detail::smallSolveInPlace<S, 2>(A, rhs);
      const V4 y1 = x - rhs(0) * c1 - rhs(1) * c2;
      const S m11 = l1.dot(c1), m12 = l1.dot(c2), m13 = l1.dot(x), m21 = l2.dot(c1), m22 = l2.dot(c2), m23 = l2.dot(x);
      const V4 y2 = (m12 * m23 - m13 * m22) * c1 - (m11 * m23 - m13 * m21) * c2 + (m11 * m22 - m12 * m21) * x;
      const V4 a1 = y1 / maxAbs(y1), a2 = y2 / maxAbs(y2);
      S minor(0);
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) minor = maxOf(minor, abs(a1(i) * a2(j) - a1(j) * a2(i)));
      worstAgree = maxOf(worstAgree, maxOf(minor, maxOf(abs(l1.dot(a1)), abs(l2.dot(a1)))));
      images.col(k) = a1;
    }
    c.checkResidual("centre a line of PR³: the solve and the cofactor formula give the same point of the line "
                    "L₁ = L₂ = 0 (20 x)",
                    worstAgree, Tolerance<S>::identity(1024));
    c.checkEqual("… and the 20 images span that line: rank 2 = (n − j − 1) + 1", 2, detail::smallNumericalRank<S>(images));
  }
}

}  // namespace

SOMA_STUDY_SCALAR("GF-1.3-projective-equality", "(x₀:…:xₙ) = (λx₀:…:λxₙ): equality by 2×2 minors, and by the SVD rank",
                  "GF §1.3", projectiveEquality);
SOMA_STUDY_SCALAR("GF-1.3-quadric-polar", "Tangent and polar hyperplanes pᵀMx = 0; the polar of a k-plane has dimension n − k − 1",
                  "GF §1.3", quadricPolar);
SOMA_STUDY_SCALAR("GF-1.3-quadric-singularity-rank", "Singular quadrics: rank 1 a double hyperplane, rank 2 a pair, singular along the null space",
                  "GF §1.3", quadricSingularityRank);
SOMA_STUDY_SCALAR("GF-1.3-linear-projection", "Projection from a centre: pr(x) = L(c)x − L(x)c, and from a line of PR³",
                  "GF §1.3", linearProjection);

}  // namespace soma::studies::gf01::SOMA_UNITY_ID
