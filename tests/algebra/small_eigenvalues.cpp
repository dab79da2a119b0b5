// Eigenvalues of small real matrices (algebra/small_eigenvalues.hpp: Gaussian Hessenberg
// reduction + Francis double-shift QR on fixed-size storage) against known spectra and against
// Eigen's EigenSolver, with tolerances from the backward error of the two methods.
#include "soma/algebra/small_eigenvalues.hpp"

#include "support/scalars.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;

namespace {

using Mat24 = Eigen::Matrix<double, 24, 24>;
using MatX = Eigen::MatrixXd;
using CMatX = Eigen::MatrixXcd;

/// Backward error of an elementary (Gauss) Hessenberg reduction followed by Francis QR: the
/// computed eigenvalues are exact for A + E with ‖E‖ ≤ c·n²·g·eps·‖A‖ (Wilkinson; g the growth
/// factor of the pivoted elimination, ~1 in practice), taken with c·g = 1.
double backwardError(const MatX& a) {
  const double n = double(a.rows());
  return n * n * Tolerance<double>::epsilon() * a.norm();
}

/// Greedy matching of two eigenvalue lists: for each of `got`, the nearest unused of `want`.
std::vector<std::pair<std::complex<double>, int>> match(const std::vector<std::complex<double>>& got,
                                                        const std::vector<std::complex<double>>& want) {
  std::vector<bool> used(want.size(), false);
  std::vector<std::pair<std::complex<double>, int>> out;
  for (const auto& z : got) {
    int best = -1;
    for (int j = 0; j < int(want.size()); ++j)
      if (!used[j] && (best < 0 || std::abs(want[j] - z) < std::abs(want[best] - z))) best = j;
    if (best >= 0) used[best] = true;
    out.emplace_back(z, best);
  }
  return out;
}

/// A = Q D Qᵀ with Q orthogonal (the QR of a random matrix) and D block diagonal: real eigenvalues
/// and 2×2 blocks [[a, b], [−b, a]] (the pair a ± ib), at random. A is normal, so every eigenvalue's
/// condition number is 1. Returns A and its spectrum.
template <class S, class Rng>
std::pair<Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>, std::vector<std::complex<S>>> normalWithSpectrum(Rng& g,
                                                                                                             int n) {
  using M = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
  M d = M::Zero(n, n);
  std::vector<std::complex<S>> want;
  for (int i = 0; i < n;) {
    if (i + 1 < n && test::uniform<double>(g) > 0) {
      const S a = test::uniform<S>(g, -2, 2), b = test::uniform<S>(g, 0.1, 2);
      d(i, i) = d(i + 1, i + 1) = a;
      d(i, i + 1) = b;
      d(i + 1, i) = -b;
      want.emplace_back(a, b);
      want.emplace_back(a, -b);
      i += 2;
    } else {
      d(i, i) = test::uniform<S>(g, -2, 2);
      want.emplace_back(d(i, i), S(0));
      ++i;
    }
  }
  M r(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) r(i, j) = test::uniform<S>(g);
  const M q = Eigen::HouseholderQR<M>(r).householderQ();
  return {q * d * q.transpose(), want};
}

/// Each computed eigenvalue z of a matrix scaled by `scale`, divided by it, within tol of the
/// nearest unused eigenvalue of the known spectrum (greedy matching).
template <class S>
void checkScaledSpectrum(const std::vector<std::complex<S>>& got, const std::vector<std::complex<S>>& want,
                         const S& scale, const S& tol, int n, int e) {
  using C = std::complex<S>;
  std::vector<bool> used(want.size(), false);
  for (const auto& z : got) {
    const C zu(z.real() / scale, z.imag() / scale);
    int best = -1;
    for (int j = 0; j < int(want.size()); ++j)
      if (!used[j] && (best < 0 || std::abs(want[j] - zu) < std::abs(want[best] - zu))) best = j;
    REQUIRE(best >= 0);
    used[best] = true;
    INFO("n " << n << " scale 2^" << e << " eigenvalue/scale " << toDouble(zu.real()) << " + "
              << toDouble(zu.imag()) << "i");
    CHECK(std::abs(zu - want[best]) <= tol);
  }
}

}  // namespace

TEMPLATE_TEST_CASE("small eigenvalues: normal matrices with a known spectrum, sizes 1 to 24", "[small_eigenvalues]",
                   float, double, long double) {
  using S = TestType;
  using C = std::complex<S>;
  auto& g = test::rng(20261204);
  for (int n = 1; n <= 24; ++n)
    for (int trial = 0; trial < 4; ++trial) {
      // A normal: the error of each eigenvalue is at most the backward error (plus the rounding
      // of forming A, ~n eps ‖A‖).
      const auto [a, want] = normalWithSpectrum<S>(g, n);
      Eigen::Matrix<S, 24, 24> h = Eigen::Matrix<S, 24, 24>::Zero();
      h.topLeftCorner(n, n) = a;
      std::vector<C> got;
      REQUIRE(detail::smallEigenvalues<S, 24>(h, n, got));
      REQUIRE(int(got.size()) == n);
      const S tol = S(n) * S(n + 1) * Tolerance<S>::epsilon() * a.norm();  // backward error + forming A
      std::vector<bool> used(want.size(), false);
      for (const auto& z : got) {
        int best = -1;
        for (int j = 0; j < int(want.size()); ++j)
          if (!used[j] && (best < 0 || std::abs(want[j] - z) < std::abs(want[best] - z))) best = j;
        REQUIRE(best >= 0);
        used[best] = true;
        INFO("n " << n << " eigenvalue " << toDouble(z.real()) << " + " << toDouble(z.imag()) << "i");
        CHECK(std::abs(z - want[best]) <= tol);
      }
    }
}

TEMPLATE_TEST_CASE("small eigenvalues: a matrix so small that p² + q² + r² leaves the normal range", "[small_eigenvalues]",
                   float, double, long double) {
  // Every entry is ~2^e with e = (min_exponent + digits/2)/2, so every square is below min/eps
  // (the products of two entries that form the shifts still normal). The iteration first scales
  // such a matrix by a power of two to a norm in [1/2, 1) (the next test runs every scale);
  // before it did, this was the test of the bulge steps' scaled reflectors. Scaling by a power of
  // two is exact, so the spectrum is 2^e times the known one, and the error bound 2^e times the
  // unscaled one.
  using S = TestType;
  using C = std::complex<S>;
  auto& g = test::rng(20261205);
  const int e = (std::numeric_limits<S>::min_exponent + std::numeric_limits<S>::digits / 2) / 2;
  const S scale = std::ldexp(S(1), e);
  for (int n = 3; n <= 16; ++n)
    for (int trial = 0; trial < 2; ++trial) {
      const auto [a, want] = normalWithSpectrum<S>(g, n);
      Eigen::Matrix<S, 24, 24> h = Eigen::Matrix<S, 24, 24>::Zero();
      h.topLeftCorner(n, n) = a * scale;
      REQUIRE(h.cwiseAbs2().maxCoeff() < std::numeric_limits<S>::min() / Tolerance<S>::epsilon());
      std::vector<C> got;
      REQUIRE(detail::smallEigenvalues<S, 24>(h, n, got));
      REQUIRE(int(got.size()) == n);
      const S tol = S(n) * S(n + 1) * Tolerance<S>::epsilon() * a.norm();  // as above, before scaling
      checkScaledSpectrum<S>(got, want, scale, tol, n, e);
    }
}

TEMPLATE_TEST_CASE("small eigenvalues: the same relative accuracy at every scale of the input", "[small_eigenvalues]",
                   float, double, long double) {
  // The bulge steps form products of three entries (β's multiply-adds); a norm outside 2^±16
  // (float) or 2^±64 is scaled by a power of two first. A normal matrix with a known spectrum times
  // 2^e, for e from the subnormal edge to the overflow edge, both sides of the band and of the
  // range where p² + q² + r² leaves the normal range: the spectrum is 2^e times the known one
  // (scaling by a power of two is exact), to 2^e times the unscaled error bound.
  using S = TestType;
  using C = std::complex<S>;
  using L = std::numeric_limits<S>;
  auto& g = test::rng(20261206);
  const int band = std::is_same_v<S, float> ? 16 : 64;
  const std::vector<int> exps = {L::min_exponent + L::digits / 2, L::min_exponent / 2, (L::min_exponent + L::digits / 2) / 2,
                                 -band - 1, -band, -1, 0, 1, band, band + 1, L::max_exponent / 3,
                                 L::max_exponent / 2, L::max_exponent - 12};
  for (const int e : exps)
    for (int n = 3; n <= 16; n += 13)
      for (int trial = 0; trial < 2; ++trial) {
        const S scale = std::ldexp(S(1), e);
        const auto [a, want] = normalWithSpectrum<S>(g, n);
        Eigen::Matrix<S, 24, 24> h = Eigen::Matrix<S, 24, 24>::Zero();
        h.topLeftCorner(n, n) = a * scale;
        REQUIRE(h.allFinite());
        std::vector<C> got;
        REQUIRE(detail::smallEigenvalues<S, 24>(h, n, got));
        REQUIRE(int(got.size()) == n);
        // as in the first test, before scaling; near the subnormal edge the entries below
        // 2^(min exponent) lose bits: n² of them, each off by at most the smallest subnormal
        const S tol = S(n) * S(n + 1) * Tolerance<S>::epsilon() * a.norm() + S(n * n) * L::denorm_min() / scale;
        checkScaledSpectrum<S>(got, want, scale, tol, n, e);
      }
}

TEST_CASE("small eigenvalues: random matrices agree with Eigen's EigenSolver within κ × backward error",
          "[small_eigenvalues]") {
  auto& g = test::rng(20261205);
  int compared = 0;
  for (int n = 1; n <= 24; ++n)
    for (int trial = 0; trial < 20; ++trial) {
      MatX a(n, n);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) a(i, j) = test::uniform<double>(g);
      if (trial % 5 == 4)  // a companion matrix, the structure of the 6R eigenproblem
        for (int i = 0; i + 1 < n; ++i) {
          a.row(i).setZero();
          a(i, i + 1) = 1;
        }
      Eigen::EigenSolver<MatX> es(a, true);
      REQUIRE(es.info() == Eigen::Success);
      const CMatX v = es.eigenvectors();
      const CMatX w = v.inverse();  // rows: left eigenvectors with w_i v_i = 1
      std::vector<std::complex<double>> want;
      for (int i = 0; i < n; ++i) want.push_back(es.eigenvalues()(i));
      // Both builds of the double kernels: the one chosen at run time (AVX2 + FMA when the CPU
      // has them, soma/algebra/cpu_dispatch.hpp) and the portable bodies called directly.
      for (const bool portable : {false, true}) {
        Mat24 h = Mat24::Zero();
        h.topLeftCorner(n, n) = a;
        std::vector<std::complex<double>> got;
        if (portable) {
          detail::smallHessenbergGaussBody<double, 24>(h, n);
          REQUIRE(detail::smallHessenbergEigenvaluesBody<double, 24>(h, n, got));
        } else {
          REQUIRE(detail::smallEigenvalues<double, 24>(h, n, got));
        }
        REQUIRE(int(got.size()) == n);
        for (const auto& [z, j] : match(got, want)) {
          REQUIRE(j >= 0);
          // Condition number of the eigenvalue: ‖x‖·‖y‖ / |yᴴx| = ‖v_j‖·‖w_j‖ (w_j v_j = 1); both
          // methods err by at most κ × their backward error (first order).
          const double kappa = v.col(j).norm() * w.row(j).norm();
          INFO("n " << n << " trial " << trial << (portable ? " portable" : " dispatched (AVX2 + FMA: ")
                    << (portable ? "" : detail::cpuHasAvx2Fma() ? "yes)" : "no)") << " eigenvalue " << z
                    << " Eigen " << want[j] << " κ " << kappa);
          CHECK(std::abs(z - want[j]) <= 2 * kappa * backwardError(a));
          ++compared;
        }
      }
    }
  CHECK(compared == 2 * 20 * 24 * 25 / 2);
}

TEST_CASE("small eigenvalues: no convergence is reported, not hidden", "[small_eigenvalues]") {
  // A NaN never passes the negligible-subdiagonal test: after 60 iterations the routine returns
  // false (the general-6R solver then calls Eigen's EigenSolver and says so in its notes).
  Mat24 h = Mat24::Zero();
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) h(i, j) = 1.0 / double(i + j + 1);
  h(3, 2) = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::complex<double>> got;
  CHECK_FALSE(detail::smallEigenvalues<double, 24>(h, 6, got));
  CHECK(got.size() < 6);
}

}  // namespace SOMA_UNITY_ID
