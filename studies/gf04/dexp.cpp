// Studies of GF chapter 4, §4.5.2: the Hausdorff formula for the derivative of the exponential
// (dexp), spatial and body, as a series, an integral and the closed forms.
#include "gf04/common.hpp"

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF §4.5.2, GF-4.5.2-dexp-hausdorff (erratum E4.9) -----------------------------------------
/// d/dt e^{X + tẊ} at t = 0 exactly, as the top-right block of exp([[X, Ẋ], [0, X]]) (power series).
template <class S, int N> Eigen::Matrix<S, N, N> expDerivative(const Eigen::Matrix<S, N, N>& X, const Eigen::Matrix<S, N, N>& Xd) {
  MatX<S> big = MatX<S>::Zero(2 * N, 2 * N);
  big.topLeftCorner(N, N) = X;
  big.topRightCorner(N, N) = Xd;
  big.bottomRightCorner(N, N) = X;
  return expSeries(big).topRightCorner(N, N);
}
/// Gauss–Legendre nodes and weights on [0, 1] (Newton on the Legendre recurrence, in S).
template <class S> void gaussLegendre(int n, std::vector<S>& x, std::vector<S>& w) {
  x.assign(n, S(0));
  w.assign(n, S(0));
  for (int i = 0; i < n; ++i) {
    S z = cos(pi<S>() * (S(i) + S(3) / S(4)) / (S(n) + S(1) / S(2)));
    S dp(0);
    for (int it = 0; it < 100; ++it) {
      S p0(1), p1 = z;
      for (int k = 2; k <= n; ++k) {
        const S p2 = (S(2 * k - 1) * z * p1 - S(k - 1) * p0) / S(k);
        p0 = p1;
        p1 = p2;
      }
      dp = S(n) * (z * p1 - p0) / (z * z - S(1));
      const S dz = p1 / dp;
      z -= dz;
      if (abs(dz) <= Tolerance<S>::epsilon()) break;
    }
    x[i] = (S(1) - z) / S(2);
    w[i] = S(1) / ((S(1) - z * z) * dp * dp);  // 2/((1−z²)p'²) on [−1,1], halved for [0,1]
  }
}
template <class S> void dexpHausdorff(Context& c) {
  auto g = rng(59);
  const S tol = Tolerance<S>::identity(64);
  // SO(3): spatial (d/dt e^X)e^{−X} and body e^{−X}(d/dt e^X).
  const SO3Tangent<S> r(randomVec<S, 3>(g));
  const Vec3<S> rd = randomVec<S, 3>(g);
  const Mat3<S> D3 = expDerivative<S, 3>(r.hat(), skew(rd));
  const Mat3<S> E3 = r.exp().matrix();
  const Vec3<S> spatial3 = SO3Tangent<S>::vee(Mat3<S>(D3 * E3.transpose())).coeffs();
  const Vec3<S> body3 = SO3Tangent<S>::vee(Mat3<S>(E3.transpose() * D3)).coeffs();
  c.checkResidual("SO(3): (d/dt e^X)e^{−X} = Σ ad^k/(k+1)! ẋ (exact derivative by block exp)",
                  maxAbs(Vec3<S>(spatial3 - dexpSeries(r, 120) * rd)), tol);
  c.checkResidual("SO(3): … = ljac() ẋ", maxAbs(Vec3<S>(spatial3 - r.ljac() * rd)), tol);
  c.checkResidual("SO(3): body e^{−X}(d/dt e^X) = Σ (−1)^k ad^k/(k+1)! ẋ = rjac() ẋ",
                  maxOf(maxAbs(Vec3<S>(body3 - dexpSeries(r, 120, true) * rd)), maxAbs(Vec3<S>(body3 - r.rjac() * rd))), tol);
  // SE(3), 4×4 → 8×8 block.
  const SE3Tangent<S> s(randomVec<S, 6>(g));
  const Vec6<S> sd = randomVec<S, 6>(g);
  const Mat4<S> D4 = expDerivative<S, 4>(s.hat(), SE3Tangent<S>(sd).hat());
  const SE3<S> E4 = s.exp();
  const Vec6<S> spatial6 = SE3Tangent<S>::vee(Mat4<S>(D4 * E4.inverse().matrix())).coeffs();
  const Vec6<S> body6 = SE3Tangent<S>::vee(Mat4<S>(E4.inverse().matrix() * D4)).coeffs();
  c.checkResidual("SE(3): spatial x_d = Σ ad^k/(k+1)! ẋ = ljac() ẋ",
                  maxOf(maxAbs(Vec6<S>(spatial6 - dexpSeries(s, 150) * sd)), maxAbs(Vec6<S>(spatial6 - s.ljac() * sd))), tol * S(4));
  c.checkResidual("SE(3): body x_b = Σ (−1)^k ad^k/(k+1)! ẋ = rjac() ẋ",
                  maxOf(maxAbs(Vec6<S>(body6 - dexpSeries(s, 150, true) * sd)), maxAbs(Vec6<S>(body6 - s.rjac() * sd))), tol * S(4));
  c.checkResidual("d/dt e^X = X_d e^X", maxAbs(Mat4<S>(D4 - SE3Tangent<S>(spatial6).hat() * E4.matrix())), tol * S(4));
  // x_d = ∫₀¹ e^{ad(μx)} dμ ẋ with e^{ad(μx)} = Ad(e^{μx}) (Gauss–Legendre, 40 nodes).
  std::vector<S> xs, ws;
  gaussLegendre<S>(40, xs, ws);
  Vec6<S> integral = Vec6<S>::Zero();
  for (std::size_t k = 0; k < xs.size(); ++k) integral += ws[k] * ((s * xs[k]).exp().adjoint() * sd);
  c.checkResidual("x_d = ∫₀¹ Ad(e^{μX}) dμ ẋ (Gauss–Legendre)", maxAbs(Vec6<S>(integral - spatial6)), tol * S(4));
  // E4.9: the printed 4th term repeats [X,[X,Ẋ]]. Truncations after 4 terms at |X| ≈ 0.3.
  const SE3Tangent<S> x3 = SE3Tangent<S>(randomVec<S, 6>(g)) * (S(3) / S(10) / sqrt(S(3)));
  const Vec6<S> xd = randomVec<S, 6>(g);
  const Vec6<S> exact = x3.ljac() * xd;
  const S errCorrect = maxAbs(Vec6<S>(dexpSeries(x3, 4) * xd - exact));
  const Mat6<S> ad = x3.ad();
  // GF §4.5.2 seed line 2067 as printed (erratum E4.9): I + ad/2! + ad²/3! + ad²/4!
  const Mat6<S> printed4 = Mat6<S>::Identity() + ad / S(2) + ad * ad / S(6) + ad * ad / S(24);
  const S errPrinted = maxAbs(Vec6<S>(printed4 * xd - exact));
  const S a = ad.cwiseAbs().rowwise().sum().maxCoeff();  // induced ‖ad‖∞: remainder ≤ Σ_{k≥4} ‖ad‖^k/(k+1)! |ẋ|
  const S remainder = ipow(a, 4) / S(120) * exp(a) * maxAbs(xd);
  c.checkResidual("correct 4-term truncation ẋ + [X,ẋ]/2! + [X,[X,ẋ]]/3! + [X,[X,[X,ẋ]]]/4! (≤ ‖ad‖⁴e^‖ad‖/5! |ẋ|)",
                  errCorrect, remainder);
  // The printed 4-term series against the corrected one, both evaluated in S: they differ by
  // (ad² − ad³)ẋ/4!, far above rounding. Rounding bound of the difference: each series sums
  // ad^k ẋ/(k+1)! (k ≤ 3) with 6-term dot products, ≤ 6(k+1)ε‖ad‖^k/(k+1)! |ẋ| per term, summed ≤ 6ε e^‖ad‖ |ẋ|;
  // two series: 12ε e^‖ad‖ |ẋ|. (In float the miss is 1.6e3× this bound: the rule's 10³ holds with room.)
  const S roundingBound = Tolerance<S>::identity(12) * exp(a) * maxAbs(xd);
  c.checkPrintedFails("4th term (1/4!)[X,[X,Ẋ]]: |printed − corrected 4-term truncation| (≤ 12ε e^‖ad‖|ẋ| is rounding)", "E4.9",
                      maxAbs(Vec6<S>(printed4 * xd - dexpSeries(x3, 4) * xd)), roundingBound);
  c.record("4th term (1/4!)[X,[X,Ẋ]]: truncation error exceeds the correct series' bound ‖ad‖⁴e^‖ad‖/5! |ẋ| [as printed]",
           "fails (erratum E4.9)", "error " + str(errPrinted) + " vs bound " + str(remainder), toDouble(errPrinted),
           toDouble(remainder), errPrinted > remainder, io::numberText(errPrinted), io::numberText(remainder));
  c.note("4-term truncation errors at |X| ≈ 0.3: correct " + str(errCorrect) + ", printed " + str(errPrinted) + ".");
}
SOMA_STUDY_SCALAR("GF-4.5.2-dexp-hausdorff",
           "Hausdorff formula (d/dt e^X)e^{−X} = Σ ad^k/(k+1)! ẋ, spatial and body; 4th term (E4.9)",
           "GF §4.5.2", dexpHausdorff);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
