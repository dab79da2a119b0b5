// Studies of GF chapter 4, §4.1: tangent algebras, the twist velocity of a screw motion, the
// hat map.
#include "gf04/common.hpp"

#include <Eigen/LU>

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF §4.1, GF-4.1-tangent-algebras (erratum E4.1) --------------------------------------

/// Nullity of the real-linear constraint map L (dimension of its solution space) by full-pivot
/// LU with the Tolerance rank threshold.
template <class S> int nullity(const MatX<S>& l) {
  Eigen::FullPivLU<MatX<S>> lu(l);
  lu.setThreshold(Tolerance<S>::rank());
  return int(l.cols()) - int(lu.rank());
}

template <class S> void tangentAlgebras(Context& c) {
  // so(n): kernel of X ↦ Xᵀ + X on n×n real matrices (the linearised MᵀM = I).
  for (int n = 2; n <= 5; ++n) {
    MatX<S> l = MatX<S>::Zero(n * n, n * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        l(i * n + j, i * n + j) += S(1);  // X_ij
        l(i * n + j, j * n + i) += S(1);  // (Xᵀ)_ij = X_ji
      }
    c.checkEqual("dim so(" + std::to_string(n) + ") = n(n−1)/2 (nullity of Ẋᵀ + Ẋ = 0)",
                 n * (n - 1) / 2, nullity(l));
  }
  // u(n), su(n): X = A + iB, X† + X = (A + Aᵀ) + i(B − Bᵀ); su(n) adds Im Tr X = Tr B = 0.
  for (int n = 2; n <= 4; ++n) {
    const int m = n * n;
    MatX<S> l = MatX<S>::Zero(2 * m + 1, 2 * m);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        l(i * n + j, i * n + j) += S(1);
        l(i * n + j, j * n + i) += S(1);
        l(m + i * n + j, m + i * n + j) += S(1);
        l(m + i * n + j, m + j * n + i) -= S(1);
      }
    const MatX<S> lu = l.topRows(2 * m);
    c.checkEqual("dim u(" + std::to_string(n) + ") = n² (nullity of U̇† + U̇ = 0)", m, nullity(lu));
    for (int i = 0; i < n; ++i) l(2 * m, m + i * n + i) = S(1);
    c.checkEqual("dim su(" + std::to_string(n) + ") = n² − 1 (adds Tr U̇ = 0)", m - 1, nullity(l));
  }
  // The book's su(2) element [[ai, b+ci], [−b+ci, −ai]] is anti-Hermitian, not Hermitian (E4.1).
  auto g = rng(41);
  const S a = uniform<S>(g), b = uniform<S>(g), cc = uniform<S>(g);
  Mat2<S> re, im;
  re << S(0), b, -b, S(0);
  im << a, cc, cc, -a;
  const S antiHerm = maxOf(maxAbs(Mat2<S>(re.transpose() + re)), maxAbs(Mat2<S>(im - im.transpose())));
  c.checkResidual("book's su(2) element: M† + M = 0 (anti-Hermitian)", antiHerm, S(0));
  c.checkResidual("book's su(2) element: Tr M = 0", abs(im.trace()) + abs(re.trace()), S(0));
  const S herm = maxOf(maxAbs(Mat2<S>(re.transpose() - re)), maxAbs(Mat2<S>(im.transpose() + im)));
  c.checkPrintedFails("\"the Lie algebra of the unitary groups consists of Hermitian matrices\": M† − M = 0",
              "E4.1", herm, Tolerance<S>::identity());
  // exp(M) (power series of the real 4×4 form [[Re, −Im], [Im, Re]]) lies in SU(2).
  Mat4<S> big;
  big << re, -im, im, re;
  const Mat4<S> u = expSeries(big);
  const Mat2<S> ur = u.template topLeftCorner<2, 2>(), ui = u.template bottomLeftCorner<2, 2>();
  const Mat2<S> uhuRe = ur.transpose() * ur + ui.transpose() * ui;
  const Mat2<S> uhuIm = ur.transpose() * ui - ui.transpose() * ur;
  c.checkResidual("exp(M) (power series) is unitary: |U†U − I|",
                  maxOf(maxAbs(Mat2<S>(uhuRe - Mat2<S>::Identity())), maxAbs(uhuIm)),
                  Tolerance<S>::identity(64));
  const S detRe = ur(0, 0) * ur(1, 1) - ui(0, 0) * ui(1, 1) - (ur(0, 1) * ur(1, 0) - ui(0, 1) * ui(1, 0));
  const S detIm = ur(0, 0) * ui(1, 1) + ui(0, 0) * ur(1, 1) - (ur(0, 1) * ui(1, 0) + ui(0, 1) * ur(1, 0));
  c.checkResidual("exp(M) has det 1 (det e^X = e^{Tr X}, Tr M = 0)",
                  maxOf(abs(detRe - S(1)), abs(detIm)), Tolerance<S>::identity(64));
  // Extremes: projection of a noisy matrix onto so(4) and su(3).
  MatX<S> noisy(4, 4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) noisy(i, j) = uniform<S>(g);
  const MatX<S> proj = (noisy - noisy.transpose()) / S(2);
  c.checkResidual("projection ½(A − Aᵀ) onto so(4) is antisymmetric", maxAbs(MatX<S>(proj + proj.transpose())), S(0));
  const S orth = ((noisy - proj).cwiseProduct(proj)).sum();
  c.checkResidual("A − ½(A − Aᵀ) is Frobenius-orthogonal to so(4) (nearest point)", abs(orth),
                  Tolerance<S>::identity(64) * S(16));
  MatX<S> xr(3, 3), xi(3, 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) xr(i, j) = uniform<S>(g), xi(i, j) = uniform<S>(g);
  MatX<S> hr = (xr - xr.transpose()) / S(2), hi = (xi + xi.transpose()) / S(2);  // ½(X − X†)
  const S tr = hi.trace() / S(3);
  for (int i = 0; i < 3; ++i) hi(i, i) -= tr;
  c.checkResidual("su(3) projection ½(X − X†) − Tr/3: anti-Hermitian and traceless",
                  maxOf(maxOf(maxAbs(MatX<S>(hr + hr.transpose())), maxAbs(MatX<S>(hi - hi.transpose()))),
                        abs(hi.trace())),
                  Tolerance<S>::identity(16));
}
SOMA_STUDY_SCALAR("GF-4.1-tangent-algebras",
           "so(n), u(n), su(n) as tangent spaces: dimensions, su(2) is anti-Hermitian (E4.1)",
           "GF §4.1", tangentAlgebras);

// ---- GF §4.1, GF-4.1-se3-twist-velocity ---------------------------------------------------
template <class S> void se3TwistVelocity(Context& c) {
  auto g = rng(42);
  const Vec3<S> axis = randomUnit<S>(g), u = randomVec<S, 3>(g), p0 = randomVec<S, 3>(g);
  const S h = S(3) / S(10);  // pitch per radian (the book's p/2π)
  for (const S& theta0 : {S(0), S(7) / S(10)}) {
    auto path = [&](const S& d) { return screwMotion<S>(axis, u, h, theta0 + d).act(p0); };
    const Vec3<S> fd = derivative<S>(path);
    const Vec3<S> p = path(S(0));
    // GF §4.1: ṗ = Ω(p − u) + θ̇ h â, and with v = u × ω + θ̇ h â: ṗ = ω × p + v.
    const Vec3<S> book1 = axis.cross(p - u) + h * axis;
    const Vec3<S> v = u.cross(axis) + h * axis;
    const Vec3<S> book2 = axis.cross(p) + v;
    const std::string at = " at θ = " + str(theta0);
    c.checkResidual("finite-difference velocity of screwMotion = Ω(p − u) + θ̇ p/2π v̂" + at,
                    maxAbs(Vec3<S>(fd - book1)), fdTolerance<S>(S(4)));
    c.checkResidual("ω × p + v with v = u × ω + θ̇ p/2π v̂ equals Ω(p − u) + …" + at,
                    maxAbs(Vec3<S>(book2 - book1)), Tolerance<S>::identity(16));
  }
  // Moment convention v = u × ω (= −ω × u): exp(θ s) reproduces the screw motion.
  const SE3Tangent<S> s(axis, Vec3<S>(u.cross(axis) + h * axis));
  const S th = S(13) / S(10);
  c.checkResidual("exp(θ(ω; u × ω + hω)) = screw motion about the line through u",
                  maxAbs(Mat4<S>((s * th).exp().matrix() - screwMotion<S>(axis, u, h, th).matrix())),
                  Tolerance<S>::identity(64));
  // Extreme: ω = 0, a pure translation: ṗ = v.
  const Vec3<S> vt = randomVec<S, 3>(g);
  auto trans = [&](const S& d) { return (SE3Tangent<S>(Vec3<S>::Zero(), vt) * d).exp().act(p0); };
  c.checkResidual("ω = 0 (pure translation): ṗ = v", maxAbs(Vec3<S>(derivative<S>(trans) - vt)),
                  fdTolerance<S>());
  // Extreme: |u| = 1e6: v = u × ω is 1e6 but ṗ is O(1) for p near the axis (cancellation).
  const S big(1000000);
  const Vec3<S> uBig = u * (big / sqrt(u.squaredNorm())), pNear = uBig + randomVec<S, 3>(g);
  const Vec3<S> direct = axis.cross(pNear) + (uBig.cross(axis) + h * axis);
  const Vec3<S> stable = axis.cross(pNear - uBig) + h * axis;
  c.checkResidual("|u| = 1e6: ω × p + v vs Ω(p − u) + hω (error ≤ 64 eps |u|: cancellation)",
                  maxAbs(Vec3<S>(direct - stable)), Tolerance<S>::identity(64) * big);
}
SOMA_STUDY_SCALAR("GF-4.1-se3-twist-velocity",
           "Point velocity under a screw motion: ṗ = ω × p + v with moment v = u × ω + h ω",
           "GF §4.1", se3TwistVelocity);

// ---- GF §4.1, GF-4.1-hat-map (erratum E4.2) -------------------------------------------------
template <class S> int levi(int i, int j, int k) {
  if (i == j || j == k || i == k) return 0;
  return ((j - i + 3) % 3 == 1) ? 1 : -1;  // even permutations of (0,1,2) are cyclic shifts
}
template <class S> void hatMap(Context& c) {
  Mat3<S> X, Y, Z;
  X << 0, 0, 0, 0, 0, -1, 0, 1, 0;
  Y << 0, 0, 1, 0, 0, 0, -1, 0, 0;
  Z << 0, -1, 0, 1, 0, 0, 0, 0, 0;
  c.checkResidual("hat(e_x) = X", maxAbs(Mat3<S>(skew<S>(Vec3<S>::UnitX()) - X)), S(0));
  c.checkResidual("hat(e_y) = Y", maxAbs(Mat3<S>(skew<S>(Vec3<S>::UnitY()) - Y)), S(0));
  c.checkResidual("hat(e_z) = Z", maxAbs(Mat3<S>(skew<S>(Vec3<S>::UnitZ()) - Z)), S(0));
  auto g = rng(43);
  S worst(0), worstEps(0), worstFixed(0), worstVee(0);
  for (int n = 0; n < 100; ++n) {
    const Vec3<S> w = randomVec<S, 3>(g), x = randomVec<S, 3>(g);
    const Mat3<S> W = SO3Tangent<S>(w).hat();
    worst = maxOf(worst, maxAbs(Vec3<S>(W * x - w.cross(x))));
    Mat3<S> printed = Mat3<S>::Zero(), fixed = Mat3<S>::Zero();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) {
          printed(i, j) += S(levi<S>(i, j, k)) * w(k);
          fixed(i, j) -= S(levi<S>(i, j, k)) * w(k);
        }
    worstEps = maxOf(worstEps, maxAbs(Mat3<S>(printed - W)));
    worstFixed = maxOf(worstFixed, maxAbs(Mat3<S>(fixed - W)));
    worstVee = maxOf(worstVee, maxAbs(Vec3<S>(SO3Tangent<S>::vee(W).coeffs() - w)));
  }
  c.checkResidual("Ω x = ω × x (100 random pairs)", worst, Tolerance<S>::identity(8));
  c.checkPrintedFails("(Ω)_ij = E_ijk ω_k", "E4.2", worstEps, Tolerance<S>::identity(8));
  c.checkResidual("corrected (Ω)_ij = −E_ijk ω_k (100 random ω)", worstFixed, S(0));
  c.checkResidual("vee(hat(ω)) = ω", worstVee, S(0));
  const Vec3<S> w = randomVec<S, 3>(g);
  c.checkResidual("Ω = ad(ω) (so(3) adjoint)", maxAbs(Mat3<S>(SO3Tangent<S>(w).ad() - skew(w))), S(0));
}
SOMA_STUDY_SCALAR("GF-4.1-hat-map", "The hat map ω ↦ Ω, Ωx = ω × x; the ε-tensor formula's sign (E4.2)",
           "GF §4.1", hatMap);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
