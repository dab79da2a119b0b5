// Studies of GF chapter 3 — Subgroups, §3.4 (matrix normal forms).
#include "soma/algebra/so3.hpp"
#include "soma/algebra/tolerance.hpp"
#include "soma/studies/study.hpp"

#include "soma/studies/gf02_gf03_support.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <string>
#include <vector>

namespace soma::studies::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

using namespace gf23;
const char* const kChapter = "GF 3 — Subgroups";

// ---- exact integer linear algebra (for Segre symbols) ------------------------------------------
using IMat = std::vector<std::vector<long long>>;

IMat imul(const IMat& a, const IMat& b) {
  const std::size_t n = a.size();
  IMat r(n, std::vector<long long>(n, 0));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t j = 0; j < n; ++j) r[i][j] += a[i][k] * b[k][j];
  return r;
}
IMat ishift(IMat a, long long lam) {
  for (std::size_t i = 0; i < a.size(); ++i) a[i][i] -= lam;
  return a;
}
/// Exact rank by fraction-free (Bareiss) elimination.
int irank(IMat a) {
  const std::size_t n = a.size();
  int rank = 0;
  long long prev = 1;
  std::vector<bool> used(n, false);
  for (std::size_t col = 0; col < n && std::size_t(rank) < n; ++col) {
    std::size_t piv = n;
    for (std::size_t r = std::size_t(rank); r < n; ++r)
      if (a[r][col] != 0) {
        piv = r;
        break;
      }
    if (piv == n) continue;
    std::swap(a[piv], a[std::size_t(rank)]);
    const std::size_t k = std::size_t(rank);
    for (std::size_t r = k + 1; r < n; ++r) {
      for (std::size_t j = col + 1; j < n; ++j) a[r][j] = (a[k][col] * a[r][j] - a[r][col] * a[k][j]) / prev;
      a[r][col] = 0;
    }
    prev = a[k][col];
    ++rank;
  }
  return rank;
}
/// Block sizes (descending) of eigenvalue λ from the ranks r_k of (A − λI)^k (Weyr
/// characteristic): the number of blocks of size ≥ k is r_{k−1} − r_k.
template <class RankFn> std::string segreOf(int n, const RankFn& rankOfPower) {
  std::vector<int> r{n};
  for (int k = 1; k <= n; ++k) r.push_back(rankOfPower(k));
  std::vector<int> atLeast;  // atLeast[k-1] = #blocks of size ≥ k
  for (int k = 1; k <= n; ++k) atLeast.push_back(r[std::size_t(k - 1)] - r[std::size_t(k)]);
  atLeast.push_back(0);
  std::string s = "(";
  for (int k = n; k >= 1; --k)
    for (int c = 0; c < atLeast[std::size_t(k - 1)] - atLeast[std::size_t(k)]; ++c) s += std::to_string(k);
  return s + ")";
}

template <class S> MatX<S> toS(const IMat& a) {
  const int n = int(a.size());
  MatX<S> m(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) m(i, j) = S(int(a[std::size_t(i)][std::size_t(j)]));
  return m;
}

// ---- GF-3.4-rational-jordan-segre -------------------------------------------------------------
// GF §3.4, GF-3.4-rational-jordan-segre: the Jordan matrix diag(λ1, [[λ2,1],[0,λ2]], λ2) has
// Segre symbol [(1),(21)], invariant under similarity; rational normal form by companion blocks.
template <class S> void rationalJordanSegre(Context& c) {
  // The book's example with λ1 = 1, λ2 = 2, hidden by an integer unimodular similarity.
  const IMat J = {{1, 0, 0, 0}, {0, 2, 1, 0}, {0, 0, 2, 0}, {0, 0, 0, 2}};
  const IMat L = {{1, 0, 0, 0}, {2, 1, 0, 0}, {-1, 3, 1, 0}, {1, -2, 1, 1}};
  const IMat U = {{1, 1, -2, 0}, {0, 1, 1, 3}, {0, 0, 1, -1}, {0, 0, 0, 1}};
  // inverses of unit triangular integer matrices, exactly (forward/back substitution)
  const auto invUnitLower = [](const IMat& l) {
    const std::size_t n = l.size();
    IMat r(n, std::vector<long long>(n, 0));
    for (std::size_t j = 0; j < n; ++j) {
      r[j][j] = 1;
      for (std::size_t i = j + 1; i < n; ++i) {
        long long s = 0;
        for (std::size_t k = j; k < i; ++k) s += l[i][k] * r[k][j];
        r[i][j] = -s;
      }
    }
    return r;
  };
  const auto transpose = [](const IMat& a) {
    IMat r = a;
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = 0; j < a.size(); ++j) r[i][j] = a[j][i];
    return r;
  };
  const IMat P = imul(L, U);
  const IMat Pinv = imul(transpose(invUnitLower(transpose(U))), invUnitLower(L));
  const IMat I4 = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  c.checkEqual("P·P⁻¹ = I exactly (integer unimodular similarity)", 1, imul(P, Pinv) == I4 ? 1 : 0);
  const IMat A = imul(imul(P, J), Pinv);
  const auto exactSegre = [&](const IMat& m, long long lam) {
    return segreOf(4, [&](int k) {
      IMat pw = I4;
      for (int i = 0; i < k; ++i) pw = imul(pw, ishift(m, lam));
      return irank(pw);
    });
  };
  c.checkEqual("Segre symbol of the book's Jordan matrix (exact ranks)", "[(1),(21)]",
               "[" + exactSegre(J, 1) + "," + exactSegre(J, 2) + "]");
  c.checkEqual("Segre symbol of A = PJP⁻¹ (similarity invariant, exact ranks)", "[(1),(21)]",
               "[" + exactSegre(A, 1) + "," + exactSegre(A, 2) + "]");
  // Characteristic polynomial by Faddeev–LeVerrier in exact integers: (x − 1)(x − 2)³.
  {
    std::vector<long long> coef{1};  // x⁴ + c1 x³ + … + c4
    IMat m = I4, am;
    for (int k = 1; k <= 4; ++k) {
      am = imul(A, m);
      long long tr = 0;
      for (int i = 0; i < 4; ++i) tr += am[std::size_t(i)][std::size_t(i)];
      const long long ck = -tr / k;
      coef.push_back(ck);
      m = am;
      for (int i = 0; i < 4; ++i) m[std::size_t(i)][std::size_t(i)] += ck;
    }
    const std::vector<long long> expected{1, -7, 18, -20, 8};
    c.checkEqual("char. polynomial of A = x⁴ − 7x³ + 18x² − 20x + 8 = (x − 1)(x − 2)³", 1, coef == expected ? 1 : 0);
  }
  // Rational normal form: invariant factors (x − 2) | (x − 1)(x − 2)² = x³ − 5x² + 8x − 4,
  // companion blocks with the book's layout (ones on the superdiagonal, last row a0 … ap).
  const IMat R = {{0, 1, 0, 0}, {0, 0, 1, 0}, {4, -8, 5, 0}, {0, 0, 0, 2}};
  c.checkEqual("rational normal form diag(B1, B2) has the same Segre symbol (hence similar to A)",
               "[(1),(21)]", "[" + exactSegre(R, 1) + "," + exactSegre(R, 2) + "]");
  const IMat minPoly = imul(ishift(A, 1), imul(ishift(A, 2), ishift(A, 2)));
  const IMat lower = imul(ishift(A, 1), ishift(A, 2));
  bool zero = true, lowerZero = true;
  for (const auto& row : minPoly)
    for (long long v : row) zero = zero && v == 0;
  for (const auto& row : lower)
    for (long long v : row) lowerZero = lowerZero && v == 0;
  c.checkEqual("minimal polynomial (x − 1)(x − 2)² annihilates A; (x − 1)(x − 2) does not", 1,
               (zero && !lowerZero) ? 1 : 0);
  // Numerically in S: ranks with the relative threshold Tolerance<S>::rank() recover the symbol.
  const MatX<S> As = toS<S>(A);
  const auto numSegre = [&](const MatX<S>& m, int lam) {
    return segreOf(4, [&](int k) {
      MatX<S> pw = MatX<S>::Identity(4, 4);
      for (int i = 0; i < k; ++i) pw = pw * MatX<S>(m - S(lam) * MatX<S>::Identity(4, 4));
      return numericalRank<S>(pw, S(16));
    });
  };
  c.checkEqual("Segre symbol from numerical ranks in " + std::string(scalarName<S>()), "[(1),(21)]",
               "[" + numSegre(As, 1) + "," + numSegre(As, 2) + "]");
  // Ill-posed: a perturbation δ of the (3,2) entry of the Jordan block splits λ2 = 2 into
  // 2 ± √δ (so the symbol jumps to [(1),(1),(1),(1)]-type as soon as δ exceeds the tolerance).
  using std::sqrt;
  const S delta = Tolerance<S>::sqrtEpsilon();
  Mat2<S> blk;
  blk << S(2), S(1), delta, S(2);
  const S tr = blk.trace(), det = blk.determinant();
  const S disc = tr * tr / S(4) - det;  // = δ
  // det = 4 − δ rounds by at most ε/2·4 and tr²/4 − det is then exact (Sterbenz), so disc = δ + η with
  // |η| ≤ 2ε: 2√disc − 2√δ ≈ η/√δ ≤ 2ε/√δ, plus the rounding of the square root and the doubling
  const S eps = Tolerance<S>::epsilon();
  c.checkNear("Jordan block perturbed by δ = √ε: eigenvalue split = 2√δ (non-Lipschitz; 2ε/√δ + 2ε√δ)", S(2) * sqrt(delta),
              S(2) * sqrt(disc), S(2) * eps / sqrt(delta) + S(2) * eps * sqrt(delta));
}

SOMA_STUDY({.id = "GF-3.4-rational-jordan-segre",
            .title = "Jordan and rational normal forms; the Segre symbol [(1),(21)]",
            .source = "GF §3.4",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { rationalJordanSegre<S>(c); }); }});

// ---- GF-3.4-symmetric-forms-inertia -----------------------------------------------------------
/// (rank, semi-index) of a symmetric matrix from its eigenvalues, with a threshold relative to
/// the largest |eigenvalue|.
template <class S> std::pair<int, int> inertia(const MatX<S>& m) {
  using std::abs;
  Eigen::SelfAdjointEigenSolver<MatX<S>> es(m);
  const S big = es.eigenvalues().cwiseAbs().maxCoeff();
  int pos = 0, neg = 0;
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
    const S l = es.eigenvalues()(i);
    if (abs(l) <= Tolerance<S>::rank() * S(int(m.rows())) * big) continue;
    (l > S(0) ? pos : neg)++;
  }
  return {pos + neg, pos - neg};
}

// GF §3.4, GF-3.4-symmetric-forms-inertia: orthogonal congruence diagonalises a symmetric M
// (λ roots of det(M − λI)); GL(n) congruence gives Sylvester's ±1/0 form with invariants rank
// and semi-index; a skew matrix is congruent to [[0, I_r, 0], [−I_r, 0, 0], [0, 0, 0]].
template <class S> void symmetricInertia(Context& c) {
  using std::abs;
  using std::sqrt;
  using std::pow;
  auto g = rng(3402);
  const S tol = Tolerance<S>::identity(512);
  const int n = 5;
  // M with eigenvalues (3, 1, −2, 0, 0): rank 3, semi-index 1.
  MatX<S> q1 = MatX<S>::Identity(n, n), q2 = MatX<S>::Identity(n, n);
  q1.block(0, 0, 3, 3) = SO3<S>::Random(g).matrix();
  q2.block(2, 2, 3, 3) = SO3<S>::Random(g).matrix();
  const MatX<S> q = q1 * q2;  // orthogonal
  const VecX<S> ev = (VecX<S>(n) << S(3), S(1), S(-2), S(0), S(0)).finished();
  const MatX<S> m = q * ev.asDiagonal() * q.transpose();
  Eigen::SelfAdjointEigenSolver<MatX<S>> es(m);
  const MatX<S> gq = es.eigenvectors();
  c.checkResidual("orthogonal congruence: gᵀMg = D(λ) with g ∈ O(5)",
                  maxAbs(MatX<S>(gq.transpose() * m * gq - MatX<S>(es.eigenvalues().asDiagonal()))), tol);
  c.checkResidual("g orthogonal", maxAbs(MatX<S>(gq.transpose() * gq - MatX<S>::Identity(n, n))), tol);
  // |det A| = ∏σₖ ≤ σ_min‖A‖ⁿ⁻¹ with σ_min ≤ |Av| for the unit eigenvector v, and the LU's rounding
  // (A + F, ‖F‖ ≤ tol‖A‖) moves det by at most ‖adj A‖‖F‖ ≤ ‖A‖ⁿ⁻¹·tol‖A‖
  S eDet(0), detBound(0);
  for (Eigen::Index i = 0; i < n; ++i) {
    const MatX<S> shifted = m - es.eigenvalues()(i) * MatX<S>::Identity(n, n);
    const S aNorm = shifted.norm();
    eDet = std::max(eDet, abs(shifted.determinant()));
    detBound = std::max(detBound, (VecX<S>(shifted * gq.col(i)).norm() + tol * aNorm) * pow(aNorm, S(n - 1)));
  }
  c.checkResidual("each λ is a root of det(M − λI) (≤ (|(M − λI)v| + tol‖M − λI‖)‖M − λI‖ⁿ⁻¹)", eDet, detBound);
  // Sylvester: rescale by 1/√|λ| → entries +1, −1, 0
  MatX<S> p = gq;
  for (int i = 0; i < n; ++i) {
    const S l = es.eigenvalues()(i);
    if (abs(l) > Tolerance<S>::rank() * S(10)) p.col(i) /= sqrt(abs(l));
  }
  const MatX<S> syl = p.transpose() * m * p;
  int plus = 0, minus = 0, zero = 0;
  S eSyl(0);
  for (int i = 0; i < n; ++i) {
    const S d = syl(i, i);
    if (abs(d - S(1)) < S(1) / S(100)) ++plus, eSyl = std::max(eSyl, abs(d - S(1)));
    else if (abs(d + S(1)) < S(1) / S(100)) ++minus, eSyl = std::max(eSyl, abs(d + S(1)));
    else ++zero, eSyl = std::max(eSyl, abs(d));
  }
  eSyl = std::max(eSyl, maxAbs(MatX<S>(syl - MatX<S>(syl.diagonal().asDiagonal()))));
  c.checkEqual("Sylvester normal form diag(+1, +1, −1, 0, 0): counts (+, −, 0)", "(2,1,2)",
               "(" + std::to_string(plus) + "," + std::to_string(minus) + "," + std::to_string(zero) + ")");
  c.checkResidual("PᵀMP has entries exactly ±1/0 up to rounding", eSyl, tol);
  // invariance of (rank, semi-index) under random GL(5) congruences
  int bad = 0;
  for (int t = 0; t < 30; ++t) {
    const MatX<S> a = uniMat<S>(g, n, n) + MatX<S>::Identity(n, n) * S(2);
    const auto in = inertia<S>(MatX<S>(a.transpose() * m * a));
    if (in != std::make_pair(3, 1)) ++bad;
  }
  c.checkEqual("(rank, semi-index) = (3, 1) after 30 random GL(5) congruences: failures", 0, bad);
  // repeated eigenvalue: the eigenspace (not the vectors) is determined; compare projectors
  {
    const VecX<S> ev2 = (VecX<S>(3) << S(2), S(2), S(-1)).finished();
    const Mat3<S> r = SO3<S>::Random(g).matrix();
    const MatX<S> m2 = MatX<S>(r) * ev2.asDiagonal() * MatX<S>(r).transpose();
    Eigen::SelfAdjointEigenSolver<MatX<S>> e2(m2);  // ascending: −1, 2, 2
    const MatX<S> v = e2.eigenvectors().rightCols(2);
    const MatX<S> w = MatX<S>(r).leftCols(2);
    c.checkResidual("repeated eigenvalue 2: eigenspace projector VVᵀ = WWᵀ",
                    maxAbs(MatX<S>(v * v.transpose() - w * w.transpose())), tol);
  }
  // Skew normal form by a symplectic Gram–Schmidt; rank 2r is the only invariant.
  for (int r : {1, 2, 3}) {
    const int nn = 6;
    MatX<S> a = MatX<S>::Zero(nn, nn);
    for (int k = 0; k < r; ++k) {
      const VecX<S> x = uniMat<S>(g, nn, 1), y = uniMat<S>(g, nn, 1);
      a += x * y.transpose() - y * x.transpose();
    }
    std::vector<VecX<S>> w, us, vs;
    for (int i = 0; i < nn; ++i) w.push_back(VecX<S>::Unit(nn, i));
    const S thr = Tolerance<S>::rank() * S(100) * maxAbs(a);
    while (w.size() >= 2) {
      std::size_t bi = 0, bj = 1;
      S best(0);
      for (std::size_t i = 0; i < w.size(); ++i)
        for (std::size_t j = 0; j < w.size(); ++j)
          if (abs(w[i].dot(a * w[j])) > best) best = abs(w[i].dot(a * w[j])), bi = i, bj = j;
      if (best <= thr) break;  // the rest spans the radical
      const VecX<S> u = w[bi], v = w[bj] / u.dot(a * w[bj]);
      us.push_back(u), vs.push_back(v);
      std::vector<VecX<S>> rest;
      for (std::size_t k = 0; k < w.size(); ++k)
        if (k != bi && k != bj) rest.push_back(VecX<S>(w[k] - w[k].dot(a * v) * u + w[k].dot(a * u) * v));
      w = rest;
    }
    const int rr = int(us.size());
    MatX<S> p2(nn, nn);
    for (int i = 0; i < rr; ++i) p2.col(i) = us[std::size_t(i)], p2.col(rr + i) = vs[std::size_t(i)];
    for (std::size_t k = 0; k < w.size(); ++k) p2.col(2 * rr + int(k)) = w[k];
    MatX<S> nf = MatX<S>::Zero(nn, nn);
    nf.block(0, rr, rr, rr) = MatX<S>::Identity(rr, rr);
    nf.block(rr, 0, rr, rr) = -MatX<S>::Identity(rr, rr);
    c.checkEqual("skew 6×6 of rank " + std::to_string(2 * r) + ": pairs found by symplectic Gram–Schmidt", r, rr);
    // the pairs and the radical are built by projections: rounding tol·‖P‖²‖A‖ (as for E₄ in §3.1)
    c.checkResidual("PᵀAP = [[0, I_r, 0], [−I_r, 0, 0], [0, 0, 0]], rank " + std::to_string(2 * r) + " (tol·‖P‖²‖A‖)",
                    maxAbs(MatX<S>(p2.transpose() * a * p2 - nf)) / (S(1) + maxAbs(a)), tol * p2.squaredNorm() * a.norm() / (S(1) + maxAbs(a)));
    c.checkEqual("P is invertible (a congruence)", nn, numericalRank<S>(p2));
  }
}

SOMA_STUDY({.id = "GF-3.4-symmetric-forms-inertia",
            .title = "Symmetric forms: orthogonal diagonalisation, Sylvester inertia, skew normal form",
            .source = "GF §3.4",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { symmetricInertia<S>(c); }); }});

// ---- GF-3.4-pair-of-forms ---------------------------------------------------------------------
// GF §3.4, GF-3.4-pair-of-forms: for M1 positive definite, g = L⁻ᵀV gives (gᵀM1g, gᵀM2g) =
// (I, D(λ)). The λ are roots of det(M2 − λM1) = 0; the printed det(M1 − λM2) = 0 has the
// reciprocals 1/λ as roots (erratum E3.2).
template <class S> void pairOfForms(Context& c) {
  using std::abs;
  auto g = rng(3403);
  const S tol = Tolerance<S>::identity(512);
  S eI(0), eD(0), eCorr(0), eRecip(0), eGen(0), printedMin(S(1e30));
  for (int t = 0; t < 20; ++t) {
    const int n = 3;
    const MatX<S> b = uniMat<S>(g, n, n), cc = uniMat<S>(g, n, n);
    const MatX<S> m1 = b * b.transpose() + MatX<S>::Identity(n, n), m2 = cc + cc.transpose();
    const MatX<S> l = Eigen::LLT<MatX<S>>(m1).matrixL();
    const MatX<S> g0 = l.inverse().transpose();  // g0ᵀ M1 g0 = I
    Eigen::SelfAdjointEigenSolver<MatX<S>> es(MatX<S>(g0.transpose() * m2 * g0));
    const MatX<S> gg = g0 * es.eigenvectors();
    const VecX<S> lam = es.eigenvalues();
    eI = std::max(eI, maxAbs(MatX<S>(gg.transpose() * m1 * gg - MatX<S>::Identity(n, n))));
    eD = std::max(eD, maxAbs(MatX<S>(gg.transpose() * m2 * gg - MatX<S>(lam.asDiagonal()))));
    const S sc = maxAbs(m1) * maxAbs(m1) * maxAbs(m1) + maxAbs(m2) * maxAbs(m2) * maxAbs(m2);
    S printedWorst(0);  // the printed equation's largest relative residual in this instance
    for (int i = 0; i < n; ++i) {
      const S li = lam(i);
      eCorr = std::max(eCorr, abs(MatX<S>(m2 - li * m1).determinant()) / sc);
      const S sp = maxAbs(m1) + abs(li) * maxAbs(m2);
      printedWorst = std::max(printedWorst, abs(MatX<S>(m1 - li * m2).determinant()) / (sp * sp * sp));
      // the printed equation holds at 1/λ
      if (abs(li) > S(1) / S(100)) {
        const S sr = maxAbs(m1) + maxAbs(m2) / abs(li);
        eRecip = std::max(eRecip, abs(MatX<S>(m1 - m2 / li).determinant()) / (sr * sr * sr));
      }
    }
    printedMin = std::min(printedMin, printedWorst);
    // independent method: Eigen's generalized symmetric-definite solver for M2 v = λ M1 v
    Eigen::GeneralizedSelfAdjointEigenSolver<MatX<S>> ges(m2, m1);
    eGen = std::max(eGen, maxAbs(VecX<S>(ges.eigenvalues() - lam)));
  }
  c.checkResidual("gᵀM1g = I (20 random pairs, M1 positive definite)", eI, tol);
  c.checkResidual("gᵀM2g = D(λ1, λ2, λ3)", eD, tol);
  c.checkResidual("λ = roots of det(M2 − λM1) = 0 (corrected; relative)", eCorr, tol);
  c.checkResidual("λ = eigenvalues of M2 v = λ M1 v by Eigen's generalized solver", eGen, tol);
  c.recordIn("printed det(M1 − λM2) at the λ of the normal form: relative value (min over 20 pairs of the worst λ, > 1e-4)",
             "fails (erratum E3.2)", io::numberText(printedMin), printedMin, S(1) / S(10000), printedMin > S(1) / S(10000));
  c.checkResidual("the printed equation det(M1 − μM2) = 0 holds at μ = 1/λ instead", eRecip, tol);
  c.note("E3.2: the diagonal of the normal form (I, D(λ)) solves det(M2 − λM1) = 0; the book's "
         "det(I − λM̃2) = 0 and det(M1 − λM2) = 0 give the reciprocals.");
}

SOMA_STUDY({.id = "GF-3.4-pair-of-forms",
            .title = "A pair of forms (M1 > 0, M2): normal form (I, D(λ)) and erratum E3.2",
            .source = "GF §3.4",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { pairOfForms<S>(c); }); }});

// ---- GF-3.4-pencil-mobius ---------------------------------------------------------------------
// GF §3.4, GF-3.4-pencil-mobius: changing the basis of a pencil, (M̃1, M̃2) = (aM1 + bM2,
// cM1 + dM2), keeps the eigenvectors of M1v = λM2v and maps λ ↦ (λa + b)/(λc + d); for n = 3
// three distinct eigenvalues can be moved to (1:0), (1:1), (0:1).
template <class S> void pencilMobius(Context& c) {
  using std::abs;
  using std::pow;
  auto g = rng(3404);
  const S tol = Tolerance<S>::identity(1024);
  const int n = 3;
  const MatX<S> b0 = uniMat<S>(g, n, n), c0 = uniMat<S>(g, n, n);
  const MatX<S> m1 = b0 + b0.transpose(), m2 = c0 * c0.transpose() + MatX<S>::Identity(n, n);  // M2 > 0: real λ
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX<S>> es(m1, m2);  // M1 v = λ M2 v
  const VecX<S> lam = es.eigenvalues();
  const MatX<S> v = es.eigenvectors();
  const S a = S(7) / S(10), bb = S(-4) / S(10), cc = S(3) / S(10), d = S(11) / S(10);
  const MatX<S> t1 = a * m1 + bb * m2, t2 = cc * m1 + d * m2;
  // |det A| ≤ (σ_min + tol‖A‖)‖A‖ⁿ⁻¹ with σ_min ≤ |Av|/|v| (see GF-3.4-symmetric-inertia)
  const auto detBound = [&](const MatX<S>& am, const VecX<S>& vi) {
    const S aNorm = am.norm();
    return (VecX<S>(am * vi).norm() / vi.norm() + tol * aNorm) * pow(aNorm, S(n - 1));
  };
  S eVec(0), eDet(0), eDetBound(0);
  for (int i = 0; i < n; ++i) {
    const S mu = (lam(i) * a + bb) / (lam(i) * cc + d);
    const VecX<S> vi = v.col(i);
    const MatX<S> am = t1 - mu * t2;
    const S scale = S(1) + abs(mu) * abs(mu) * abs(mu);
    eVec = std::max(eVec, maxAbs(VecX<S>(t1 * vi - mu * t2 * vi)) / (S(1) + abs(mu)));
    eDet = std::max(eDet, abs(am.determinant()) / scale);
    eDetBound = std::max(eDetBound, detBound(am, vi) / scale);
  }
  c.checkResidual("M̃1 v = μ M̃2 v with the same v and μ = (λa + b)/(λc + d), (a,b,c,d) = (0.7,−0.4,0.3,1.1)", eVec, tol);
  c.checkResidual("det(M̃1 − μM̃2) = 0 at the Möbius-mapped roots (≤ (|Av|/|v| + tol‖A‖)‖A‖ⁿ⁻¹)", eDet, eDetBound);
  // Degenerate members: det(Q0 + λQ1) = 0 at λ = −λ_i (singular member of the pencil).
  S eDeg(0), eDegBound(0);
  for (int i = 0; i < n; ++i) {
    const MatX<S> am = m1 - lam(i) * m2;
    eDeg = std::max(eDeg, abs(am.determinant()));
    eDegBound = std::max(eDegBound, detBound(am, VecX<S>(v.col(i))));
  }
  c.checkResidual("the degenerate members M1 − λ_i M2 are singular (≤ (|Av|/|v| + tol‖A‖)‖A‖ⁿ⁻¹)", eDeg, eDegBound);
  // λc + d = 0 sends λ1 to ∞: M̃2 is then singular with kernel v1.
  {
    const S c1 = S(1), d1 = -lam(0);
    const MatX<S> t2b = c1 * m1 + d1 * m2;
    c.checkResidual("λ1c + d = 0: M̃2 v1 = 0 (eigenvalue sent to ∞)", maxAbs(VecX<S>(t2b * v.col(0))), tol);
  }
  // n = 3: move λ3 ↦ 0 (0:1), λ2 ↦ 1 (1:1), λ1 ↦ ∞ (1:0) by a Möbius map
  // μ = (λ − λ3)(λ2 − λ1)/((λ − λ1)(λ2 − λ3)), i.e. a = (λ2 − λ1), b = −λ3(λ2 − λ1),
  // c = (λ2 − λ3), d = −λ1(λ2 − λ3).
  {
    const S l1 = lam(0), l2 = lam(1), l3 = lam(2);
    const S A = l2 - l1, B = -l3 * (l2 - l1), C = l2 - l3, D = -l1 * (l2 - l3);
    const MatX<S> u1 = A * m1 + B * m2, u2 = C * m1 + D * m2;
    const S sc = S(1) + maxAbs(u1) + maxAbs(u2);
    c.checkResidual("λ3 ↦ 0: M̃1 v3 = 0", maxAbs(VecX<S>(u1 * v.col(2))) / sc, tol);
    c.checkResidual("λ2 ↦ 1: M̃1 v2 = M̃2 v2", maxAbs(VecX<S>((u1 - u2) * v.col(1))) / sc, tol);
    c.checkResidual("λ1 ↦ ∞: M̃2 v1 = 0", maxAbs(VecX<S>(u2 * v.col(0))) / sc, tol);
  }
  c.note("M2 is taken positive definite so that the pencil's eigenvalues are real and Eigen's "
         "generalized symmetric solver applies on every scalar rung.");
}

SOMA_STUDY({.id = "GF-3.4-pencil-mobius",
            .title = "Pencils: a change of basis moves eigenvalues by a Möbius map",
            .source = "GF §3.4",
            .chapter = kChapter,
            .scalarGeneric = true,
            .run = [](Context& c) { withScalar(c.scalar(), [&]<class S>() { pencilMobius<S>(c); }); }});

}  // namespace
}  // namespace soma::studies::SOMA_UNITY_ID
