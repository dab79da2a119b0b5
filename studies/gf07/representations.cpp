// Studies of GF chapter 7, §7.1–7.2: the representation axioms, equivalence, the dual, direct
// sum and tensor product, Sym^n and ⋀^n, forms and Grassmannians as representations.
#include "gf07/common.hpp"

namespace soma::studies::gf07::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF §7.1, GF-7.1-representation-axioms -------------------------------------------------------
template <class S> void representationAxioms(Context& c) {
  auto g = rng(71);
  const S tol = Tolerance<S>::identity(64);
  // (R1) R_g R_h = R_gh for the 4×4 representation P_g and the adjoint Ad_g; (R2) R_e = 1.
  S p4(0), ad(0), inv(0);
  for (int n = 0; n < 50; ++n) {
    const SE3<S> a = SE3<S>::Random(g), b = SE3<S>::Random(g);
    p4 = maxOf(p4, maxAbs(Mat4<S>(a.matrix() * b.matrix() - (a * b).matrix())));
    ad = maxOf(ad, maxAbs(Mat6<S>(a.adjoint() * b.adjoint() - (a * b).adjoint())));
    inv = maxOf(inv, maxAbs(Mat6<S>(a.adjoint() * a.inverse().adjoint() - Mat6<S>::Identity())));
  }
  c.checkResidual("(R1) P_g P_h = P_gh, 4×4 representation (50 random pairs)", p4, tol);
  c.checkResidual("(R1) Ad_g Ad_h = Ad_gh, adjoint representation", ad, S(4) * tol);
  c.checkResidual("R_g R_{g⁻¹} = 1 (inverse from (R1), (R2))", inv, S(4) * tol);
  c.checkResidual("(R2) P_e = I₄, Ad_e = I₆ (exact)",
                  maxOf(maxAbs(Mat4<S>(SE3<S>().matrix() - Mat4<S>::Identity())),
                        maxAbs(Mat6<S>(SE3<S>().adjoint() - Mat6<S>::Identity()))), S(0));
  // Extreme: a long composition. 200 random factors: the matrix product drifts from the group
  // (each product adds ≈ eps); the error of ‖RᵀR − I‖ of the accumulated rotation block grows
  // at most linearly: bound 200 · 16 eps.
  Mat6<S> prod = Mat6<S>::Identity();
  SE3<S> acc;
  for (int n = 0; n < 200; ++n) {
    const SE3<S> a = SE3<S>::Random(g);
    prod = Mat6<S>(prod * a.adjoint());
    acc = acc * a;
  }
  const Mat3<S> rb = prod.template topLeftCorner<3, 3>();
  c.checkResidual("200-fold product of Ad_g: rotation block stays orthogonal (≤ 200·16 eps)",
                  maxAbs(Mat3<S>(rb.transpose() * rb - Mat3<S>::Identity())), S(200) * Tolerance<S>::identity(16));
  c.checkResidual("200-fold product of Ad_g = Ad of the composed motion (≤ 200·64 eps·|t|)",
                  maxAbs(Mat6<S>(prod - acc.adjoint())) / (S(1) + maxAbs(acc.translation())), S(200) * tol);
  // Rotation by π: R_g² = R_{g²} = 1.
  const SE3<S> half(SO3<S>::fromAxisAngle(randomUnit<S>(g), pi<S>()), Vec3<S>::Zero());
  c.checkResidual("rotation by π: Ad_g Ad_g = 1", maxAbs(Mat6<S>(half.adjoint() * half.adjoint() - Mat6<S>::Identity())),
                  S(4) * tol);
  // The Lie-algebra representation is the differential at the identity: central difference of
  // Ad(exp(hs)), error O(h²) + eps/h, h = eps^(1/3).
  const S h = pow(Tolerance<S>::epsilon(), S(1) / S(3));
  S diff(0);
  for (int n = 0; n < 5; ++n) {
    const SE3Tangent<S> s(randomVec<S, 6>(g));
    const Mat6<S> fd = (SE3Tangent<S>(Vec6<S>(s.coeffs() * h)).exp().adjoint() -
                        SE3Tangent<S>(Vec6<S>(-s.coeffs() * h)).exp().adjoint()) / (S(2) * h);
    diff = maxOf(diff, maxAbs(Mat6<S>(fd - s.ad())));
  }
  c.checkResidual("d/dt Ad(exp(ts)) at t = 0 = ad(s) (central difference: h²/6·|ad³| + eps/h ≤ 64 h², h = eps^⅓)", diff, S(64) * h * h);
  // L_[X,Y] = [L_X, L_Y] in the 4×4 and adjoint representations.
  S b4(0), b6(0);
  for (int n = 0; n < 50; ++n) {
    const SE3Tangent<S> x(randomVec<S, 6>(g)), y(randomVec<S, 6>(g));
    b4 = maxOf(b4, maxAbs(Mat4<S>(comm(x.hat(), y.hat()) - bracket(x, y).hat())));
    b6 = maxOf(b6, maxAbs(Mat6<S>(comm(x.ad(), y.ad()) - bracket(x, y).ad())));
  }
  c.checkResidual("L_[X,Y] = L_X L_Y − L_Y L_X, 4×4", b4, tol);
  c.checkResidual("L_[X,Y] = L_X L_Y − L_Y L_X, adjoint", b6, tol);
  // Equivalence: R'_g = M R_g M⁻¹ is again a representation.
  Mat6<S> M;
  for (int i = 0; i < 6; ++i) M.col(i) = randomVec<S, 6>(g);
  M += S(3) * Mat6<S>::Identity();  // well conditioned
  const Mat6<S> Mi = M.inverse();
  S eq(0);
  for (int n = 0; n < 20; ++n) {
    const SE3<S> a = SE3<S>::Random(g), b = SE3<S>::Random(g);
    eq = maxOf(eq, maxAbs(Mat6<S>(M * a.adjoint() * Mi * (M * b.adjoint() * Mi) - M * (a * b).adjoint() * Mi)));
  }
  c.checkResidual("equivalent representation M Ad_g M⁻¹ satisfies (R1) (M = 3I + random)", eq, S(64) * tol);
  // SU(2) → SO(3): the 2×2 matrices U(q) = wI − i(xσ_x + yσ_y + zσ_z) of unit quaternions are a
  // representation of SU(2) (U(q₁)U(q₂) = U(q₁q₂)), but q and −q (U and −U) give the same rotation,
  // so U is not a representation of SO(3).
  auto U = [](const Quat<S>& q) {
    CMat<S> u(2, 2);
    u << C<S>(q.w(), -q.z()), C<S>(-q.y(), -q.x()), C<S>(q.y(), -q.x()), C<S>(q.w(), q.z());
    return u;
  };
  S su2(0);
  for (int n = 0; n < 20; ++n) {
    const Quat<S> q1 = SO3<S>::Random(g).quaternion(), q2 = SO3<S>::Random(g).quaternion();
    su2 = maxOf(su2, maxAbs(CMat<S>(U(q1) * U(q2) - U(Quat<S>(q1 * q2)))));
  }
  c.checkResidual("U(q₁)U(q₂) = U(q₁q₂): the 2×2 representation of SU(2) (20 random pairs)", su2, S(4) * tol);
  const Quat<S> q = SO3<S>::Random(g).quaternion();
  const Quat<S> mq(-q.w(), -q.x(), -q.y(), -q.z());
  c.checkResidual("q and −q (U and −U) give the same rotation matrix: the kernel {±1} of SU(2) → SO(3)",
                  maxAbs(Mat3<S>(SO3<S>::fromQuaternion(q).matrix() - SO3<S>::fromQuaternion(mq).matrix())), tol);
  c.note("(R3) prints R_q for R_g (OCR); linearity holds because R_g are matrices.");
}
SOMA_STUDY_SCALAR("GF-7.1-representation-axioms", "Representation axioms (R1)–(R3) for P_g and Ad_g; Lie representations; equivalence",
                  "GF §7.1", representationAxioms);

// ---- GF §7.2, GF-7.2-dual-sum-tensor -----------------------------------------------------------
template <class S> void dualSumTensor(Context& c) {
  auto g = rng(72);
  const S tol = Tolerance<S>::identity(64);
  // Dual of a group representation: R*_g = R_{g⁻¹}ᵀ keeps the evaluation f(v).
  S eval(0), hom(0);
  for (int n = 0; n < 20; ++n) {
    const SE3<S> a = SE3<S>::Random(g), b = SE3<S>::Random(g);
    const Vec6<S> f = randomVec<S, 6>(g), v = randomVec<S, 6>(g);
    eval = maxOf(eval, abs(Vec6<S>(rep::coadjoint(a) * f).dot(Vec6<S>(a.adjoint() * v)) - f.dot(v)));
    hom = maxOf(hom, maxAbs(Mat6<S>(rep::coadjoint(a * b) - rep::coadjoint(a) * rep::coadjoint(b))));
  }
  c.checkResidual("(R*_g f)(R_g v) = f(v), R*_g = R_{g⁻¹}ᵀ (adjoint → coadjoint)", eval, S(16) * tol);
  c.checkResidual("R*_gh = R*_g R*_h", hom, S(16) * tol);
  // Lie algebra dual: (L*_X f)(v) + f(L_X v) = 0 with L* = −Lᵀ; the eigenvalues change sign.
  S lev(0), lbr(0);
  for (int n = 0; n < 20; ++n) {
    const SE3Tangent<S> x(randomVec<S, 6>(g)), y(randomVec<S, 6>(g));
    const Vec6<S> f = randomVec<S, 6>(g), v = randomVec<S, 6>(g);
    const Mat6<S> lx = rep::dualOfAlgebra(x.ad()), ly = rep::dualOfAlgebra(y.ad());
    lev = maxOf(lev, abs(Vec6<S>(lx * f).dot(v) + f.dot(Vec6<S>(x.ad() * v))));
    lbr = maxOf(lbr, maxAbs(Mat6<S>(comm(lx, ly) - rep::dualOfAlgebra(bracket(x, y).ad()))));
  }
  c.checkResidual("(L*_X f)(v) + f(L_X v) = 0", lev, tol);
  c.checkResidual("L* = −Lᵀ is a representation: [L*_X, L*_Y] = L*_[X,Y]", lbr, tol);
  const rep::So3Irrep<S> l1 = rep::so3Irrep<S>(2), lh = rep::so3Irrep<S>(1), l32 = rep::so3Irrep<S>(3);
  // The dual of L_{3/2}: (−Hᵀ, −J₊ᵀ, −J₋ᵀ) keeps the relations; its weights are the negatives,
  // which is the same set again: L_j* ≅ L_j.
  const Matrix<S> dh = rep::dualOfAlgebra(l32.H), dp = rep::dualOfAlgebra(l32.Jp), dm = rep::dualOfAlgebra(l32.Jm);
  c.checkResidual("L_{3/2}*: [H*, J₊*] = J₊*, [J₊*, J₋*] = −2H* with L* = −Lᵀ (exact)",
                  maxOf(maxAbs(Matrix<S>(comm(dh, dp) - dp)), maxAbs(Matrix<S>(comm(dp, dm) + S(2) * dh))), S(0));
  c.checkResidual("eigenvalues of L*(J₃) are those of L(J₃) with opposite sign (exact)",
                  maxAbs(Matrix<S>(dh.diagonal() + l32.H.diagonal())), S(0));
  c.checkEqual("L_{3/2}* ≅ L_{3/2} (weights)", "L3/2", rep::so3Decomposition<S>(dh) == std::map<int, int>{{3, 1}} ? "L3/2" : "other");
  // Direct sum: block diagonal, eigenvalues together.
  const Matrix<S> hs = rep::directSum(l1.H, lh.H), ps = rep::directSum(l1.Jp, lh.Jp), ms = rep::directSum(l1.Jm, lh.Jm);
  c.checkResidual("L₁ ⊕ L_½ keeps [J₊, J₋] = 2iJ₃ (real form −2H; exact)", maxAbs(Matrix<S>(comm(ps, ms) + S(2) * hs)), S(0));
  const auto dec = rep::so3Decomposition<S>(hs);
  c.checkEqual("weights of L₁ ⊕ L_½ decompose as {L₁, L_½}", "L1 + L1/2",
               dec == std::map<int, int>{{2, 1}, {1, 1}} ? "L1 + L1/2" : "other");
  // Tensor product: eigenvectors e ⊗ f with eigenvalue λ + μ (3×3 representation, J₃ = Z).
  const auto gen = so3Generators<S>();
  const Ladder<S> L = ladderOf<S>(gen[0], gen[1], gen[2]);
  const C<S> i = imagUnit<S>();
  CVec<S> u1(3);
  u1 << C<S>(S(1)), -i, C<S>(S(0));  // J₃ u₁ = i u₁
  const CVec<S> u0 = L.Jm * u1, um = L.Jm * u0;
  const CMat<S> T3 = rep::algebraTensor(L.J3, L.J3);
  S eig(0);
  const CVec<S> us[3] = {u1, u0, um};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const CVec<S> e = kronVec<C<S>>(us[a], us[b]);
      eig = maxOf(eig, maxAbs(CVec<S>(T3 * e - C<S>(S(0), S(2 - a - b)) * e)));
    }
  c.checkResidual("(L⊗L)(J₃) u_a ⊗ u_b = i(a + b) u_a ⊗ u_b: eigenvalues add (exact)", eig, S(0));
  // Group tensor product differentiates to the algebra tensor product (central difference).
  const S h = pow(Tolerance<S>::epsilon(), S(1) / S(3));
  const SE3Tangent<S> s(randomVec<S, 6>(g));
  auto R = [&](const S& t) {
    const SE3<S> e = SE3Tangent<S>(Vec6<S>(s.coeffs() * t)).exp();
    return rep::groupTensor(e.matrix(), e.adjoint());
  };
  const Matrix<S> fd = (R(h) - R(-h)) / (S(2) * h);
  c.checkResidual("d/dt (P ⊗ Ad)(e^{tX}) at 0 = L₁(X) ⊗ 1 + 1 ⊗ L₂(X) (central difference, ≤ 64 h²)",
                  maxAbs(Matrix<S>(fd - rep::algebraTensor(s.hat(), s.ad()))), S(64) * h * h);
  // (U ⊕ V) ⊗ W = (U ⊗ W) ⊕ (V ⊗ W): with the basis order of soma the matrices are equal.
  const SE3Tangent<S> x(randomVec<S, 6>(g));
  const Matrix<S> lhs = rep::algebraTensor(rep::directSum(x.hat(), x.ad()), l1.H);
  const Matrix<S> rhs = rep::directSum(rep::algebraTensor(x.hat(), l1.H), rep::algebraTensor(x.ad(), l1.H));
  c.checkResidual("(U ⊕ V) ⊗ W = (U ⊗ W) ⊕ (V ⊗ W) (exact)", maxAbs(Matrix<S>(lhs - rhs)), S(0));
  // dim Sym^n V = C(n + d − 1, n), dim ⋀^n V = C(d, n): ranks of the symmetriser / antisymmetriser.
  long long badS = 0, badA = 0;
  for (int d = 1; d <= 6; ++d)
    for (int n = 1; n <= 3; ++n) {
      const Eigen::Index size = Eigen::Index(rep::detail::tensorPowerSize(d, n));
      if (size > 64) continue;  // FullPivLU of d^n × d^n: kept small for mpfr
      const long long rs = nullity<S>(Matrix<S>(rep::symmetriser<S>(d, n) - Matrix<S>::Identity(size, size)));
      const long long ra = nullity<S>(Matrix<S>(rep::antisymmetriser<S>(d, n) - Matrix<S>::Identity(size, size)));
      // the projector's rank = the dimension of its fixed space; binomials by Pascal's rule
      long long pascal[10][10] = {};
      for (int a = 0; a < 10; ++a) {
        pascal[a][0] = 1;
        for (int b = 1; b <= a; ++b) pascal[a][b] = pascal[a - 1][b - 1] + (b < a ? pascal[a - 1][b] : 0);
      }
      if (rs != pascal[n + d - 1][n]) ++badS;
      if (ra != (n <= d ? pascal[d][n] : 0)) ++badA;
    }
  c.checkEqual("rank of the symmetriser = C(n+d−1, n), d ≤ 6, n ≤ 3, dⁿ ≤ 64: mismatches", 0, badS);
  c.checkEqual("rank of the antisymmetriser = C(d, n): mismatches", 0, badA);
  c.checkEqual("book: Sym² of a 3-space has 6 generators", 6, rep::symmetricPowerDimension(3, 2));
  c.checkEqual("book: ⋀² of a 3-space has 3 generators", 3, rep::exteriorPowerDimension(3, 2));
  // The 4×4 representation of se(3) is indecomposable but not irreducible: (x, y, z, 0) is
  // invariant (last rows of all generators vanish) and no vector outside it is invariant (a
  // complement would be a 1-dimensional invariant line; the common null space of the
  // translations and the rotations restricted to multiples is empty: the stacked generators have
  // trivial null space and the quotient V/U is the trivial representation).
  const auto gen4 = rep::se3StandardGenerators<S>();
  S lastRow(0);
  for (const auto& m : gen4) lastRow = maxOf(lastRow, maxAbs(m.row(3)));
  c.checkResidual("4×4: U = {(x, y, z, 0)} is invariant (last row of every generator is 0)", lastRow, S(0));
  std::vector<Matrix<S>> all(gen4.begin(), gen4.end());
  c.checkEqual("4×4: no non-zero vector is killed by all of se(3) (no invariant complement of U)", 0,
               nullity<S>(stack<S>(all)));
  c.note("The book's \"for the direct product V ⊕ U both the subspaces V and W are invariant\" mixes its letters (typo).");
}
SOMA_STUDY_SCALAR("GF-7.2-dual-sum-tensor", "Dual, direct sum and tensor product of representations; Sym^n, ⋀^n dimensions",
                  "GF §7.2", dualSumTensor);

// ---- GF §7.2, GF-7.2-forms-and-grassmannians ------------------------------------------------------
template <class S> void formsAndGrassmannians(Context& c) {
  auto g = rng(73);
  const S tol = Tolerance<S>::identity(64);
  // V ⊗ V* = endomorphisms: (R_g ⊗ R*_g) vec(M) = vec(R_g M R_g⁻¹) (vec by rows, as the Kronecker order).
  auto vecRows = [](const Matrix<S>& m) {
    Eigen::Matrix<S, Eigen::Dynamic, 1> v(m.size());
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      for (Eigen::Index j = 0; j < m.cols(); ++j) v(i * m.cols() + j) = m(i, j);
    return v;
  };
  S endo(0), quad(0), evalq(0);
  for (int n = 0; n < 10; ++n) {
    const SE3<S> a = SE3<S>::Random(g);
    Matrix<S> M(6, 6);
    for (int r = 0; r < 6; ++r) M.row(r) = randomVec<S, 6>(g).transpose();
    const Matrix<S> Ad = a.adjoint(), AdInv = a.inverse().adjoint();
    endo = maxOf(endo, maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(rep::groupTensor(Ad, rep::dualOfGroup(AdInv)) * vecRows(M) -
                                                                  vecRows(Matrix<S>(Ad * M * AdInv)))));
    // Sym² V*: bilinear forms transform as M ↦ R_{g⁻¹}ᵀ M R_{g⁻¹}.
    const Matrix<S> Ms = M + M.transpose();
    const Matrix<S> Dg = rep::dualOfGroup(AdInv);
    quad = maxOf(quad, maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(rep::groupTensor(Dg, Dg) * vecRows(Ms) -
                                                                  vecRows(Matrix<S>(AdInv.transpose() * Ms * AdInv)))));
    const Vec6<S> u = randomVec<S, 6>(g), v = randomVec<S, 6>(g);
    const Matrix<S> gm = AdInv.transpose() * Ms * AdInv;
    evalq = maxOf(evalq, abs(Vec6<S>(Ad * u).dot(Vec6<S>(gm * Vec6<S>(Ad * v))) - u.dot(Vec6<S>(Ms * v))));
  }
  c.checkResidual("V ⊗ V*: (R_g ⊗ R*_g) vec M = vec(R_g M R_g⁻¹)", endo, S(256) * tol);
  c.checkResidual("Sym² V*: (R*_g ⊗ R*_g) vec M = vec(R_{g⁻¹}ᵀ M R_{g⁻¹})", quad, S(256) * tol);
  c.checkResidual("the transformed form evaluates the same: (g·M)(g u, g v) = M(u, v)", evalq, S(1024) * tol);
  // Invariants = trivial summands of Sym² of the coadjoint representation: the symmetric bilinear
  // forms on se(3) killed by every generator. Two of them (Q_∞ and Q₀ of GF §6.4).
  const auto co = rep::se3CoadjointGenerators<S>();
  const Matrix<S> basis = rep::symmetricPowerBasis<S>(6, 2);
  std::vector<Matrix<S>> restricted;
  for (const auto& m : co) restricted.push_back(rep::restrictToSubspace(rep::algebraTensor(m, m), basis));
  c.checkEqual("invariant symmetric bilinear forms on se(3): dim of the trivial part of Sym²(ad*)", 2,
               nullity<S>(stack<S>(restricted)));
  const Mat6<S> Q0 = bookQ0<S>(), Qi = bookQinf<S>();
  S fixed(0);
  for (int n = 0; n < 10; ++n) {
    const Mat6<S> Ad = SE3<S>::Random(g).adjoint();
    fixed = maxOf(fixed, maxOf(maxAbs(Mat6<S>(Ad.transpose() * Q0 * Ad - Q0)), maxAbs(Mat6<S>(Ad.transpose() * Qi * Ad - Qi))));
  }
  c.checkResidual("Q₀ and Q_∞ are fixed points: Adᵀ Q Ad = Q", fixed, S(64) * tol);
  // G(2, 4) ⊂ ⋀²ℝ⁴: the line through two points, x ∧ y, moves by ⋀²P_g; its Plücker coordinates
  // stay on the Klein quadric.
  const Matrix<S> B = rep::exteriorPowerBasis<S>(4, 2);  // columns 01, 02, 03, 12, 13, 23
  auto coords = [&](const Vec4<S>& x, const Vec4<S>& y) {
    Eigen::Matrix<S, Eigen::Dynamic, 1> xv = x, yv = y;
    const Eigen::Matrix<S, Eigen::Dynamic, 1> w = kronVec<S>(xv, yv) - kronVec<S>(yv, xv);
    return Eigen::Matrix<S, Eigen::Dynamic, 1>((B.transpose() * B).inverse() * B.transpose() * w);
  };
  S wedge(0), klein(0);
  for (int n = 0; n < 10; ++n) {
    const SE3<S> a = SE3<S>::Random(g);
    Vec4<S> x, y;
    x << randomVec<S, 3>(g), S(1);
    y << randomVec<S, 3>(g), S(1);
    const Matrix<S> w2 = rep::restrictToSubspace(rep::groupTensor(a.matrix(), a.matrix()), B);
    const auto moved = coords(Vec4<S>(a.matrix() * x), Vec4<S>(a.matrix() * y));
    wedge = maxOf(wedge, maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(w2 * coords(x, y) - moved)));
    klein = maxOf(klein, abs(moved(0) * moved(5) - moved(1) * moved(4) + moved(2) * moved(3)));
  }
  c.checkResidual("⋀²P_g (x ∧ y) = (P_g x) ∧ (P_g y) on G(2, 4)", wedge, S(64) * tol);
  c.checkResidual("the moved line stays on the Klein quadric p₀₁p₂₃ − p₀₂p₁₃ + p₀₃p₁₂ = 0", klein, S(64) * tol);
}
SOMA_STUDY_SCALAR("GF-7.2-forms-and-grassmannians", "V ⊗ V* = End V, Sym² V* = forms, invariants, G(n, m) ⊂ ⋀^n",
                  "GF §7.2", formsAndGrassmannians);

}  // namespace
}  // namespace soma::studies::gf07::SOMA_UNITY_ID
