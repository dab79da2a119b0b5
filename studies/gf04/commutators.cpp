// Studies of GF chapter 4, §4.3: the Lie bracket, structure constants, commutators of so(3),
// su(2), so(4) and se(3).
#include "gf04/common.hpp"

#include <Eigen/LU>

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF §4.3, GF-4.3-bracket-structure-constants ------------------------------------------
/// Structure constants C^k_ij = k-th coordinate of [e_i, e_j]; ad(e_i) built with (k, j) entry
/// C^k_ij, compared with the library's ad(); also C^k_ji = −C^k_ij.
template <class T, int n> std::pair<typename T::Scalar, typename T::Scalar> structureConstantsDefect() {
  using S = typename T::Scalar;
  using D = Eigen::Matrix<S, n, 1>;
  using M = Eigen::Matrix<S, n, n>;
  S adDefect(0), antiDefect(0);
  for (int i = 0; i < n; ++i) {
    M adi;
    for (int j = 0; j < n; ++j) {
      const D cij = lieBracket(T(D(D::Unit(i))), T(D(D::Unit(j)))).coeffs();
      const D cji = lieBracket(T(D(D::Unit(j))), T(D(D::Unit(i)))).coeffs();
      antiDefect = maxOf(antiDefect, maxAbs(D(cij + cji)));
      for (int k = 0; k < n; ++k) adi(k, j) = cij(k);
    }
    adDefect = maxOf(adDefect, maxAbs(M(adi - T(D(D::Unit(i))).ad())));
  }
  return {adDefect, antiDefect};
}
template <class T> typename T::Scalar jacobiResidual(const T& a, const T& b, const T& d) {
  using S = typename T::Scalar;
  const auto j = (lieBracket(a, lieBracket(b, d)).coeffs() + lieBracket(b, lieBracket(d, a)).coeffs() +
                  lieBracket(d, lieBracket(a, b)).coeffs()).eval();
  const S scale = sqrt(a.coeffs().squaredNorm() * b.coeffs().squaredNorm() * d.coeffs().squaredNorm());
  return maxAbs(j) / scale;
}
template <class S> void bracketStructureConstants(Context& c) {
  auto g = rng(46);
  // (I + tX) Y (I − tX) = Y + t[X, Y] − t² XYX (exact algebra; t = 2⁻¹⁰ is exact).
  const Mat4<S> X = SE3Tangent<S>(randomVec<S, 6>(g)).hat(), Y = SE3Tangent<S>(randomVec<S, 6>(g)).hat();
  const S t = S(1) / S(1024);
  const Mat4<S> I = Mat4<S>::Identity();
  const Mat4<S> lhs = (I + t * X) * Y * (I - t * X);
  c.checkResidual("(I + tX)Y(I − tX) = Y + t(XY − YX) + O(t²) (remainder −t²XYX)",
                  maxAbs(Mat4<S>(lhs - (Y + t * (X * Y - Y * X) - t * t * X * Y * X))), Tolerance<S>::identity(16));
  // Jacobi identity, relative to |X₁||X₂||X₃|, on so(3), se(3), se(2) and su(2).
  S jSo3(0), jSe3(0), jSe2(0), jMixed(0), jDeriv(0), anti(0);
  for (int n = 0; n < 100; ++n) {
    const SO3Tangent<S> a(randomVec<S, 3>(g)), b(randomVec<S, 3>(g)), d(randomVec<S, 3>(g));
    jSo3 = maxOf(jSo3, jacobiResidual(a, b, d));
    const SE3Tangent<S> p(randomVec<S, 6>(g)), q(randomVec<S, 6>(g)), r(randomVec<S, 6>(g));
    jSe3 = maxOf(jSe3, jacobiResidual(p, q, r));
    const SE2Tangent<S> e(randomVec<S, 3>(g)), f(randomVec<S, 3>(g)), h(randomVec<S, 3>(g));
    jSe2 = maxOf(jSe2, jacobiResidual(e, f, h));
    // mixed magnitudes 1e-8, 1e8, 1
    jMixed = maxOf(jMixed, jacobiResidual(p * (S(1) / S(100000000)), q * S(100000000), r));
    // derivation form [X₁,[X₂,X₃]] = [[X₁,X₂],X₃] + [X₂,[X₁,X₃]]
    const Vec6<S> der = bracket(p, bracket(q, r)).coeffs() - bracket(bracket(p, q), r).coeffs() -
                     bracket(q, bracket(p, r)).coeffs();
    jDeriv = maxOf(jDeriv, maxAbs(der));
    anti = maxOf(anti, maxAbs(Vec6<S>(bracket(p, q).coeffs() + bracket(q, p).coeffs())));
  }
  const S tol = Tolerance<S>::identity(64);
  c.checkResidual("Jacobi identity so(3) (100 random triples, relative)", jSo3, tol);
  c.checkResidual("Jacobi identity se(3)", jSe3, tol);
  c.checkResidual("Jacobi identity se(2)", jSe2, tol);
  c.checkResidual("Jacobi identity se(3), magnitudes 1e-8, 1e8, 1 (relative)", jMixed, tol);
  c.checkResidual("bracket is a derivation: [X₁,[X₂,X₃]] = [[X₁,X₂],X₃] + [X₂,[X₁,X₃]]", jDeriv, tol);
  c.checkResidual("antisymmetry [X, Y] = −[Y, X]", anti, tol);
  // su(2) as complex 2×2 matrices (independent of any ad()).
  S jSu2(0);
  using C2 = CMat<Mat2<S>>;
  auto su2 = [&](const Vec3<S>& v) {
    Mat2<S> re, im;
    re << S(0), v(1), -v(1), S(0);
    im << v(0), v(2), v(2), -v(0);
    return C2{re, im};
  };
  auto br = [](const C2& x, const C2& y) { return x * y - y * x; };
  for (int n = 0; n < 100; ++n) {
    const C2 a = su2(randomVec<S, 3>(g)), b = su2(randomVec<S, 3>(g)), d = su2(randomVec<S, 3>(g));
    jSu2 = maxOf(jSu2, (br(a, br(b, d)) + br(b, br(d, a)) + br(d, br(a, b))).maxAbs());
  }
  c.checkResidual("Jacobi identity su(2) (complex 2×2 matrices)", jSu2, tol);
  // ad built from structure constants (kj entry of ad(X_i) = C^k_ij) equals the library's ad().
  const auto so3 = structureConstantsDefect<SO3Tangent<S>, 3>();
  const auto se3 = structureConstantsDefect<SE3Tangent<S>, 6>();
  const auto se2 = structureConstantsDefect<SE2Tangent<S>, 3>();
  c.checkResidual("so(3): ad(X_i)_kj = C^k_ij equals SO3Tangent::ad()", so3.first, S(0));
  c.checkResidual("se(3): ad(X_i)_kj = C^k_ij equals SE3Tangent::ad()", se3.first, S(0));
  c.checkResidual("se(2): ad(X_i)_kj = C^k_ij equals SE2Tangent::ad()", se2.first, S(0));
  c.checkResidual("C^k_ji = −C^k_ij (so(3), se(3), se(2))",
                  maxOf(so3.second, maxOf(se3.second, se2.second)), S(0));
}
SOMA_STUDY_SCALAR("GF-4.3-bracket-structure-constants",
           "Lie bracket XY − YX: bilinear, antisymmetric, Jacobi; ad from structure constants",
           "GF §4.3", bracketStructureConstants);

// ---- GF §4.3, GF-4.3-so3-su2-commutators --------------------------------------------------
template <class S> void so3Su2Commutators(Context& c) {
  Mat3<S> X, Y, Z;
  X << 0, 0, 0, 0, 0, -1, 0, 1, 0;
  Y << 0, 0, 1, 0, 0, 0, -1, 0, 0;
  Z << 0, -1, 0, 1, 0, 0, 0, 0, 0;
  auto com = [](const Mat3<S>& a, const Mat3<S>& b) { return Mat3<S>(a * b - b * a); };
  c.checkResidual("[X, Y] = Z (exact)", maxAbs(Mat3<S>(com(X, Y) - Z)), S(0));
  c.checkResidual("[Y, Z] = X (exact)", maxAbs(Mat3<S>(com(Y, Z) - X)), S(0));
  c.checkResidual("[Z, X] = Y (exact)", maxAbs(Mat3<S>(com(Z, X) - Y)), S(0));
  const Mat3<S> basis[3] = {X, Y, Z};
  // ad(X) in the basis {X, Y, Z}: column j = coordinates of [X_i, X_j] (vee).
  S adSo3(0);
  for (int i = 0; i < 3; ++i) {
    Mat3<S> ad;
    for (int j = 0; j < 3; ++j) ad.col(j) = SO3Tangent<S>::vee(com(basis[i], basis[j])).coeffs();
    adSo3 = maxOf(adSo3, maxAbs(Mat3<S>(ad - basis[i])));
  }
  c.checkResidual("ad(X) = X, ad(Y) = Y, ad(Z) = Z (exact)", adSo3, S(0));
  // su(2): σx = ½ diag(i, −i), σy = ½ [[0, 1], [−1, 0]], σz = ½ [[0, i], [i, 0]].
  using C2 = CMat<Mat2<S>>;
  const S h = S(1) / S(2);
  C2 sx{Mat2<S>::Zero(), Mat2<S>::Zero()}, sy = sx, sz = sx;
  sx.im << h, S(0), S(0), -h;
  sy.re << S(0), h, -h, S(0);
  sz.im << S(0), h, h, S(0);
  auto br = [](const C2& a, const C2& b) { return a * b - b * a; };
  c.checkResidual("[σx, σy] = σz (exact)", (br(sx, sy) - sz).maxAbs(), S(0));
  c.checkResidual("[σy, σz] = σx (exact)", (br(sy, sz) - sx).maxAbs(), S(0));
  c.checkResidual("[σz, σx] = σy (exact)", (br(sz, sx) - sy).maxAbs(), S(0));
  auto coords = [&](const C2& m) { return Vec3<S>(S(2) * m.im(0, 0), S(2) * m.re(0, 1), S(2) * m.im(0, 1)); };
  const C2 sig[3] = {sx, sy, sz};
  S adSu2(0);
  for (int i = 0; i < 3; ++i) {
    Mat3<S> ad;
    for (int j = 0; j < 3; ++j) ad.col(j) = coords(br(sig[i], sig[j]));
    adSu2 = maxOf(adSu2, maxAbs(Mat3<S>(ad - basis[i])));
  }
  c.checkResidual("ad(σx) = X, ad(σy) = Y, ad(σz) = Z (exact)", adSu2, S(0));
  // "These are the Pauli spin matrices": they are (i/2)·(σ₃, σ₂, σ₁) of physics.
  C2 p1{Mat2<S>::Zero(), Mat2<S>::Zero()}, p2 = p1, p3 = p1;
  p1.re << 0, 1, 1, 0;
  p2.im << 0, -1, 1, 0;
  p3.re << 1, 0, 0, -1;
  const Cx<S> ih(S(0), h);
  const S pauli = maxOf((sx - ih * p3).maxAbs(), maxOf((sy - ih * p2).maxAbs(), (sz - ih * p1).maxAbs()));
  c.checkResidual("σx, σy, σz = (i/2)·(Pauli σ₃, σ₂, σ₁) (not the Pauli matrices themselves)", pauli, S(0));
}
SOMA_STUDY_SCALAR("GF-4.3-so3-su2-commutators", "Commutators of so(3) and su(2); ad(X) = X, ad(σx) = X",
           "GF §4.3", so3Su2Commutators);

// ---- GF §4.3, GF-4.3-so4-commutators (erratum E4.3) ---------------------------------------
template <class S> void so4Commutators(Context& c) {
  for (const bool bookConvention : {true, false}) {
    auto Xm = [&](int i, int j) {  // 1-based indices; E_ji − E_ij (book-consistent) or E_ij − E_ji
      Mat4<S> m = Mat4<S>::Zero();
      m(j - 1, i - 1) = bookConvention ? S(1) : S(-1);
      m(i - 1, j - 1) = bookConvention ? S(-1) : S(1);
      return m;
    };
    auto com = [](const Mat4<S>& a, const Mat4<S>& b) { return Mat4<S>(a * b - b * a); };
    int held = 0, total = 0, heldIndexed = 0, totalIndexed = 0;
    auto tally = [&](const Mat4<S>& lhs, const Mat4<S>& rhs, bool sharesIndex) {
      const bool ok = maxAbs(Mat4<S>(lhs - rhs)) == S(0);
      ++total;
      held += ok;
      if (sharesIndex) ++totalIndexed, heldIndexed += ok;
    };
    for (int i = 1; i <= 4; ++i)
      for (int j = i + 1; j <= 4; ++j)
        for (int k = j + 1; k <= 4; ++k) {
          tally(com(Xm(i, j), Xm(i, k)), Xm(j, k), true);     // [X_ij, X_ik] = X_jk
          tally(com(Xm(i, j), Xm(j, k)), -Xm(i, k), true);    // [X_ij, X_jk] = −X_ik
        }
    for (int i = 1; i <= 4; ++i)
      for (int k = i + 1; k <= 4; ++k)
        for (int j = k + 1; j <= 4; ++j) tally(com(Xm(i, j), Xm(k, j)), Xm(i, k), true);  // i<k<j
    for (int i = 1; i <= 4; ++i)
      for (int j = i + 1; j <= 4; ++j)
        for (int k = 1; k <= 4; ++k)
          for (int l = k + 1; l <= 4; ++l)
            if (i != k && i != l && j != k && j != l) tally(com(Xm(i, j), Xm(k, l)), Mat4<S>::Zero(), false);
    if (bookConvention) {
      c.checkEqual("X_ij = E_ji − E_ij: all so(4) relations hold (exact)", total, held);
      Mat3<S> X;
      X << 0, 0, 0, 0, 0, -1, 0, 1, 0;
      c.checkResidual("X₂₃ restricted to the first three coordinates is the so(3) X",
                      maxAbs(Mat3<S>(Xm(2, 3).template topLeftCorner<3, 3>() - X)), S(0));
    } else {
      c.record("X_ij = E_ij − E_ji: relations sharing an index [convention never stated]",
               "fails (erratum E4.3)", std::to_string(heldIndexed) + " of " + std::to_string(totalIndexed) + " hold",
               double(heldIndexed), 0.0, heldIndexed == 0);
    }
  }
}
SOMA_STUDY_SCALAR("GF-4.3-so4-commutators", "so(4) commutation relations; the basis convention (E4.3)",
           "GF §4.3", so4Commutators);

// ---- GF §4.3, GF-4.3-se3-commutators-ad --------------------------------------------------
template <class S> void se3CommutatorsAd(Context& c) {
  auto gen = [](int idx) {  // 0..2: ω_i, ω_j, ω_k; 3..5: v_i, v_j, v_k as 4×4 matrices
    Vec6<S> e = Vec6<S>::Zero();
    e(idx) = S(1);
    return SE3Tangent<S>(e).hat();
  };
  auto com = [](const Mat4<S>& a, const Mat4<S>& b) { return Mat4<S>(a * b - b * a); };
  S table(0);
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, k = (a + 2) % 3;
    table = maxOf(table, maxAbs(Mat4<S>(com(gen(a), gen(b)) - gen(k))));           // [ω_i, ω_j] = ω_k
    table = maxOf(table, maxAbs(Mat4<S>(com(gen(a), gen(3 + b)) - gen(3 + k))));   // [ω_i, v_j] = v_k
    table = maxOf(table, maxAbs(Mat4<S>(com(gen(b), gen(3 + a)) + gen(3 + k))));   // [ω_j, v_i] = −v_k
    table = maxOf(table, maxAbs(com(gen(a), gen(3 + a))));                         // [ω_i, v_i] = 0
    for (int d = 0; d < 3; ++d) table = maxOf(table, maxAbs(com(gen(3 + a), gen(3 + d))));  // [v, v] = 0
  }
  c.checkResidual("restored commutator table of the 4×4 generators (exact)", table, S(0));
  S gen36(0), adBlocks(0);
  Mat3<S> basis3[3];
  for (int a = 0; a < 3; ++a) basis3[a] = skew<S>(Vec3<S>(Vec3<S>::Unit(a)));
  for (int a = 0; a < 6; ++a) {
    for (int b = 0; b < 6; ++b) {
      const SE3Tangent<S> s1(Vec6<S>(Vec6<S>::Unit(a))), s2(Vec6<S>(Vec6<S>::Unit(b)));
      const Vec6<S> formula = (Vec6<S>() << s1.ang().cross(s2.ang()),
                               Vec3<S>(s1.ang().cross(s2.lin()) - s2.ang().cross(s1.lin()))).finished();
      gen36 = maxOf(gen36, maxAbs(Vec6<S>(SE3Tangent<S>::vee(com(s1.hat(), s2.hat())).coeffs() - formula)));
    }
    Mat6<S> expect = Mat6<S>::Zero();
    const Mat3<S>& B = basis3[a % 3];
    if (a < 3) expect << B, Mat3<S>::Zero(), Mat3<S>::Zero(), B;
    else expect.template bottomLeftCorner<3, 3>() = B;
    adBlocks = maxOf(adBlocks, maxAbs(Mat6<S>(SE3Tangent<S>(Vec6<S>(Vec6<S>::Unit(a))).ad() - expect)));
  }
  c.checkResidual("[s₁, s₂] = (ω₁ × ω₂; ω₁ × v₂ − ω₂ × v₁) on all 36 generator pairs", gen36, S(0));
  c.checkResidual("ad(ω_i) = [[X,0],[0,X]], ad(v_i) = [[0,0],[X,0]] (and Y, Z) = SE3Tangent::ad()",
                  adBlocks, S(0));
  auto g = rng(47);
  S rnd(0), mixed(0), nil(0);
  for (int n = 0; n < 100; ++n) {
    const SE3Tangent<S> s1(randomVec<S, 6>(g)), s2(randomVec<S, 6>(g));
    rnd = maxOf(rnd, maxAbs(Vec6<S>(s1.ad() * s2.coeffs() - SE3Tangent<S>::vee(com(s1.hat(), s2.hat())).coeffs())));
    // huge moment 1e6 with tiny rotation 1e-6: error relative to the largest product (1)
    const SE3Tangent<S> m1(Vec3<S>(randomVec<S, 3>(g) / S(1000000)), Vec3<S>(randomVec<S, 3>(g) * S(1000000)));
    mixed = maxOf(mixed, maxAbs(Vec6<S>(m1.ad() * s2.coeffs() - SE3Tangent<S>::vee(com(m1.hat(), s2.hat())).coeffs())));
    const SE3Tangent<S> tr(Vec3<S>::Zero(), randomVec<S, 3>(g));
    nil = maxOf(nil, maxAbs(Mat6<S>(tr.ad() * tr.ad())));
  }
  c.checkResidual("ad(s₁)s₂ = vee([ŝ₁, ŝ₂]) (100 random pairs)", rnd, Tolerance<S>::identity(16));
  c.checkResidual("|ω| = 1e-6, |v| = 1e6: ad(s₁)s₂ = vee([ŝ₁, ŝ₂]) (error ≤ 64 eps · 1e6)", mixed,
                  Tolerance<S>::identity(64) * S(1000000));
  c.checkResidual("pure translation: ad(0; v)² = 0 (nilpotent)", nil, S(0));
}
SOMA_STUDY_SCALAR("GF-4.3-se3-commutators-ad",
           "se(3) commutator table (restored from OCR loss) and ad(s) = [[Ω, 0], [V, Ω]]", "GF §4.3",
           se3CommutatorsAd);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
