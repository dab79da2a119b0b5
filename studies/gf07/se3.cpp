// Studies of GF chapter 7, §7.5: se(3) in the ladder basis J₃, J±, P₃, P±; the adjoint and
// coadjoint representations; the invariant forms in Sym² of the coadjoint; Casimirs and pitch.
#include "gf07/common.hpp"

namespace soma::studies::gf07::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

/// The complex matrix Σ a_k G_k of a complexified se(3) element a in a representation.
template <class S> CMat<S> elementC(const rep::Se3Generators<S>& gen, const CVec<S>& a) {
  CMat<S> m = CMat<S>::Zero(gen[0].rows(), gen[0].cols());
  for (int k = 0; k < 6; ++k) m += a(k) * toComplex<S>(gen[std::size_t(k)]);
  return m;
}
/// The ladder basis of se(3) as complex 6-vectors (ω_i, ω_j, ω_k, v_i, v_j, v_k coordinates).
template <class S> struct Se3Ladder {
  CVec<S> J3, Jp, Jm, P3, Pp, Pm;
};
template <class S> Se3Ladder<S> se3Ladder() {
  const C<S> i = imagUnit<S>();
  auto e = [](int k) { return CVec<S>(CVec<S>::Unit(6, k)); };
  return {e(2), CVec<S>(e(1) + i * e(0)), CVec<S>(e(1) - i * e(0)), e(5), CVec<S>(e(4) + i * e(3)), CVec<S>(e(4) - i * e(3))};
}
/// The adjoint chains ω₁ = J₊, ω₀ = ad(J₋)ω₁, ω₋₁ = ad(J₋)ω₀ and the same from v₁ = P₊; and the
/// dual basis a_m, b_m of se(3)* (a₁(ω₋₁) = a₀(ω₀) = a₋₁(ω₁) = 1, …) as rows.
template <class S> struct Se3Chains {
  std::array<CVec<S>, 3> w, v;                   // index 0 ↔ m = 1, 1 ↔ 0, 2 ↔ −1
  std::array<Eigen::Matrix<C<S>, 1, Eigen::Dynamic>, 3> a, b;  // index 0 ↔ m = 1, 1 ↔ 0, 2 ↔ −1
  CMat<S> basis;                                 // columns ω₁ ω₀ ω₋₁ v₁ v₀ v₋₁
};
template <class S> Se3Chains<S> se3Chains() {
  const auto ad = rep::se3AdjointGenerators<S>();
  const Se3Ladder<S> L = se3Ladder<S>();
  const CMat<S> adJm = elementC(ad, L.Jm);
  Se3Chains<S> ch;
  ch.w = {L.Jp, CVec<S>(adJm * L.Jp), CVec<S>(adJm * adJm * L.Jp)};
  ch.v = {L.Pp, CVec<S>(adJm * L.Pp), CVec<S>(adJm * adJm * L.Pp)};
  ch.basis = CMat<S>(6, 6);
  ch.basis << ch.w[0], ch.w[1], ch.w[2], ch.v[0], ch.v[1], ch.v[2];
  const CMat<S> inv = complexInverse<S>(ch.basis);  // row r is the functional dual to column r
  for (int m = 0; m < 3; ++m) {
    ch.a[std::size_t(m)] = inv.row(2 - m);  // a_m is 1 on ω_{−m}
    ch.b[std::size_t(m)] = inv.row(5 - m);
  }
  return ch;
}

// ---- GF §7.5, GF-7.5-se3-commutation-table --------------------------------------------------------
template <class S> void commutationTable(Context& c) {
  const Se3Ladder<S> L = se3Ladder<S>();
  const C<S> i = imagUnit<S>();
  const CVec<S> zero = CVec<S>::Zero(6);
  struct Rel {
    const CVec<S>*x, *y;
    CVec<S> rhs;
  };
  const std::vector<Rel> table{
      {&L.J3, &L.Jp, i * L.Jp},          {&L.J3, &L.Jm, -i * L.Jm},         {&L.Jp, &L.Jm, S(2) * i * L.J3},
      {&L.J3, &L.Pp, i * L.Pp},          {&L.J3, &L.Pm, -i * L.Pm},         {&L.J3, &L.P3, zero},
      {&L.Jp, &L.Pp, zero},              {&L.Jp, &L.Pm, S(2) * i * L.P3},   {&L.Jp, &L.P3, -i * L.Pp},
      {&L.Jm, &L.Pp, -S(2) * i * L.P3},  {&L.Jm, &L.Pm, zero},              {&L.Jm, &L.P3, i * L.Pm},
      {&L.P3, &L.Pp, zero},              {&L.P3, &L.Pm, zero},              {&L.Pp, &L.Pm, zero}};
  const auto ad = rep::se3AdjointGenerators<S>(), p4 = rep::se3StandardGenerators<S>(), co = rep::se3CoadjointGenerators<S>();
  S vec(0), m4(0), mco(0);
  for (const Rel& r : table) {
    vec = maxOf(vec, maxAbs(CVec<S>(elementC(ad, *r.x) * *r.y - r.rhs)));
    m4 = maxOf(m4, maxAbs(CMat<S>(comm(elementC(p4, *r.x), elementC(p4, *r.y)) - elementC(p4, r.rhs))));
    mco = maxOf(mco, maxAbs(CMat<S>(comm(elementC(co, *r.x), elementC(co, *r.y)) - elementC(co, r.rhs))));
  }
  c.checkEqual("relations in the printed table", 15, (long long)table.size());
  c.checkResidual("all 15 relations with the 6-vector bracket ad(x)y, extended complex-bilinearly (exact)", vec, S(0));
  c.checkResidual("all 15 as commutators of 4×4 matrices (exact)", m4, S(0));
  c.checkResidual("all 15 as commutators in the coadjoint representation (exact)", mco, S(0));
  // R(P₊), R(P₃), R(P₋) span an L₁ of so(3) under the adjoint action: ad(J₋) lowers P₊ → P₃ → P₋ (up to constants).
  const CMat<S> adJm = elementC(ad, L.Jm);
  c.checkResidual("ad(J₋)P₊ = −2iP₃, ad(J₋)P₃ = iP₋, ad(J₋)P₋ = 0 (an L₁ string; exact)",
                  maxOf(maxOf(maxAbs(CVec<S>(adJm * L.Pp + S(2) * i * L.P3)), maxAbs(CVec<S>(adJm * L.P3 - i * L.Pm))),
                        maxAbs(CVec<S>(adJm * L.Pm))), S(0));
}
SOMA_STUDY_SCALAR("GF-7.5-se3-commutation-table", "se(3) in the basis J₃, J±, P₃, P±: the 15 printed commutators", "GF §7.5",
                  commutationTable);

// ---- GF §7.5, GF-7.5-adjoint-ladder (erratum E7.4) --------------------------------------------------
template <class S> void adjointLadder(Context& c) {
  const Se3Ladder<S> L = se3Ladder<S>();
  const Se3Chains<S> ch = se3Chains<S>();
  const auto ad = rep::se3AdjointGenerators<S>();
  const C<S> i = imagUnit<S>();
  c.checkResidual("ω₀ = −2iJ₃, ω₋₁ = 2J₋, v₀ = −2iP₃, v₋₁ = 2P₋ (exact)",
                  maxOf(maxOf(maxAbs(CVec<S>(ch.w[1] + S(2) * i * L.J3)), maxAbs(CVec<S>(ch.w[2] - S(2) * L.Jm))),
                        maxOf(maxAbs(CVec<S>(ch.v[1] + S(2) * i * L.P3)), maxAbs(CVec<S>(ch.v[2] - S(2) * L.Pm)))), S(0));
  const CMat<S> adJ3 = elementC(ad, L.J3);
  S weights(0);
  for (int m = 0; m < 3; ++m) {
    const C<S> lambda(S(0), S(1 - m));
    weights = maxOf(weights, maxOf(maxAbs(CVec<S>(adJ3 * ch.w[std::size_t(m)] - lambda * ch.w[std::size_t(m)])),
                                   maxAbs(CVec<S>(adJ3 * ch.v[std::size_t(m)] - lambda * ch.v[std::size_t(m)]))));
  }
  c.checkResidual("ad(J₃)ω_m = imω_m, ad(J₃)v_m = imv_m: the subscript is the weight (exact)", weights, S(0));
  const CMat<S> adPp = elementC(ad, L.Pp);
  S table = maxOf(maxAbs(CVec<S>(adPp * ch.w[0])), maxAbs(CVec<S>(adPp * ch.w[1] + S(2) * ch.v[0])));
  table = maxOf(table, maxAbs(CVec<S>(adPp * ch.w[2] + S(2) * ch.v[1])));
  for (int m = 0; m < 3; ++m) table = maxOf(table, maxAbs(CVec<S>(adPp * ch.v[std::size_t(m)])));
  c.checkResidual("ad(P₊): ω₁ ↦ 0, ω₀ ↦ −2v₁, ω₋₁ ↦ −2v₀, v_* ↦ 0 (as printed; exact)", table, S(0));
  const CVec<S> adP3w1 = elementC(ad, L.P3) * ch.w[0];
  c.checkPrintedFails("ad(P₃)ω₁ = −2v₁", "E7.4", maxAbs(CVec<S>(adP3w1 + S(2) * ch.v[0])), S(0));
  c.checkResidual("corrected: ad(P₃)ω₁ = [P₃, J₊] = iv₁ (exact)", maxAbs(CVec<S>(adP3w1 - i * ch.v[0])), S(0));
  // The book's derivation: P₃ = (1/2i)[P₊, J₋], so ad(P₃) = (1/2i)(ad P₊ ad J₋ − ad J₋ ad P₊); it
  // dropped 1/(2i) and reversed the order.
  const CMat<S> adJm = elementC(ad, L.Jm);
  const CVec<S> viaDerivation = (adPp * adJm - adJm * adPp) * ch.w[0] / (S(2) * i);
  c.checkResidual("ad(P₃)ω₁ = (1/2i)(ad P₊ ad J₋ − ad J₋ ad P₊)ω₁ = (1/2i)(−2v₁) = iv₁ (exact)",
                  maxAbs(CVec<S>(viaDerivation - adP3w1)), S(0));
}
SOMA_STUDY_SCALAR("GF-7.5-adjoint-ladder", "Adjoint representation in the basis ω_m, v_m; ad(P₊) table (erratum E7.4)", "GF §7.5",
                  adjointLadder);

// ---- GF §7.5, GF-7.5-coadjoint (erratum E7.5, new E7.7) ------------------------------------------------
template <class S> void coadjointStudy(Context& c) {
  const Se3Ladder<S> L = se3Ladder<S>();
  const Se3Chains<S> ch = se3Chains<S>();
  const auto ad = rep::se3AdjointGenerators<S>();
  const C<S> i = imagUnit<S>();
  using Row = Eigen::Matrix<C<S>, 1, Eigen::Dynamic>;
  // ad*(X) f = −f ∘ ad(X): on a row vector f, −f ad(X).
  auto adStar = [&](const CVec<S>& x, const Row& f) { return Row(-f * elementC(ad, x)); };
  const S tol = Tolerance<S>::identity(16);  // the dual basis comes from a 12×12 real inverse
  S dual(0);
  for (int m = 0; m < 3; ++m)
    for (int k = 0; k < 3; ++k) {
      const C<S> want = (m + k == 2) ? C<S>(S(1)) : C<S>(S(0));
      dual = maxOf(dual, absOf(C<S>((ch.a[std::size_t(m)] * ch.w[std::size_t(k)])(0, 0) - want)));
      dual = maxOf(dual, absOf(C<S>((ch.b[std::size_t(m)] * ch.v[std::size_t(k)])(0, 0) - want)));
      dual = maxOf(dual, absOf(C<S>((ch.a[std::size_t(m)] * ch.v[std::size_t(k)])(0, 0))));
    }
  c.checkResidual("dual basis: a₁(ω₋₁) = a₀(ω₀) = a₋₁(ω₁) = 1, b likewise on v, other pairings 0", dual, tol);
  const Row a1star = adStar(L.J3, ch.a[0]);
  c.checkPrintedFails("ad*(J₃)a₁ = a₁", "E7.5", maxAbs(Row(a1star - ch.a[0])), tol);
  c.checkResidual("corrected: ad*(J₃)a₁ = ia₁ (ad(J₃)ω₋₁ = −iω₋₁)", maxAbs(Row(a1star - i * ch.a[0])), tol);
  // ad*(P₊): a_* ↦ 0, b₁ ↦ 0, b₀ ↦ 2a₁, b₋₁ ↦ 2a₀ (as printed).
  S pp(0);
  for (int m = 0; m < 3; ++m) pp = maxOf(pp, maxAbs(adStar(L.Pp, ch.a[std::size_t(m)])));
  pp = maxOf(pp, maxAbs(adStar(L.Pp, ch.b[0])));
  pp = maxOf(pp, maxAbs(Row(adStar(L.Pp, ch.b[1]) - S(2) * ch.a[0])));
  pp = maxOf(pp, maxAbs(Row(adStar(L.Pp, ch.b[2]) - S(2) * ch.a[1])));
  c.checkResidual("ad*(P₊): a_* ↦ 0, b₁ ↦ 0, b₀ ↦ 2a₁, b₋₁ ↦ 2a₀ (as printed)", pp, tol);
  // Restricted to so(3), ad* is L₁ ⊕ L₁: ad*(J₃) has eigenvalues i, 0, −i twice (on a_m, b_m: weight m).
  S w(0);
  for (int m = 0; m < 3; ++m) {
    const C<S> lambda(S(0), S(1 - m));
    w = maxOf(w, maxOf(maxAbs(Row(adStar(L.J3, ch.a[std::size_t(m)]) - lambda * ch.a[std::size_t(m)])),
                       maxAbs(Row(adStar(L.J3, ch.b[std::size_t(m)]) - lambda * ch.b[std::size_t(m)]))));
  }
  c.checkResidual("ad*(J₃)a_m = im a_m, ad*(J₃)b_m = im b_m: ad* restricted to so(3) is L₁ ⊕ L₁", w, tol);
  // The isomorphism se(3) → se(3)*. As printed, ω_m ↦ b_m, v_m ↦ −a_m; as a matrix Φ = F B⁻¹ (F's
  // columns the images), an intertwiner needs Φ ad(X) = −ad(X)ᵀ Φ for every X.
  auto intertwinerDefect = [&](const std::array<Row, 6>& images) {
    CMat<S> F(6, 6);
    for (int k = 0; k < 6; ++k) F.col(k) = images[std::size_t(k)].transpose();
    const CMat<S> phi = F * complexInverse<S>(ch.basis);
    S d(0);
    for (const auto& G : ad) d = maxOf(d, maxAbs(CMat<S>(phi * toComplex<S>(G) + toComplex<S>(Matrix<S>(G.transpose())) * phi)));
    return std::pair<S, CMat<S>>{d, phi};
  };
  const auto printed = intertwinerDefect({ch.b[0], ch.b[1], ch.b[2], Row(-ch.a[0]), Row(-ch.a[1]), Row(-ch.a[2])});
  c.checkPrintedFails("ω_m ↦ b_m, v_m ↦ −a_m intertwines ad and ad*", "E7.7 (new)", printed.first, tol);
  const auto fixed = intertwinerDefect({ch.b[0], Row(-ch.b[1]), ch.b[2], ch.a[0], Row(-ch.a[1]), ch.a[2]});
  c.checkResidual("corrected: ω_m ↦ (−1)^m b_m, v_m ↦ (−1)^m a_m intertwines ad and ad*", fixed.first, tol);
  const Mat6<S> Q0 = bookQ0<S>();
  c.checkResidual("… and it is ¼ Q₀ (the Klein form of GF §6.4) in 6-vector coordinates",
                  maxAbs(CMat<S>(fixed.second - toComplex<S>(Mat6<S>(Q0 / S(4))))), tol);
  // All intertwiners ad → ad*: X with X ad(G) + ad(G)ᵀX = 0, i.e. (Gᵀ ⊗ 1 + 1 ⊗ Gᵀ) vec X = 0 (vec by rows).
  std::vector<Matrix<S>> ops;
  for (const auto& G : ad) ops.push_back(rep::algebraTensor(Matrix<S>(G.transpose()), Matrix<S>(G.transpose())));
  c.checkEqual("the intertwiners ad → ad* (invariant bilinear forms) form a 2-dimensional space (Q₀, Q_∞)", 2,
               nullity<S>(stack<S>(ops)));
  S q0(0);
  for (const auto& G : ad) q0 = maxOf(q0, maxAbs(Matrix<S>(Q0 * G + G.transpose() * Q0)));
  c.checkResidual("Q₀ ad(X) = −ad(X)ᵀ Q₀ for every generator: adjoint ≅ coadjoint (exact)", q0, S(0));
}
SOMA_STUDY_SCALAR("GF-7.5-coadjoint", "Coadjoint representation on a_m, b_m; ad* ≅ ad through Q₀ (errata E7.5, E7.7 new)",
                  "GF §7.5", coadjointStudy);

// ---- GF §7.5, GF-7.5-invariant-forms-sym2 -----------------------------------------------------------
template <class S> void invariantFormsSym2(Context& c) {
  auto g = rng(755);
  const Se3Ladder<S> L = se3Ladder<S>();
  const Se3Chains<S> ch = se3Chains<S>();
  const auto ad = rep::se3AdjointGenerators<S>();
  const C<S> i = imagUnit<S>();
  const S tol = Tolerance<S>::identity(16);
  using Row = Eigen::Matrix<C<S>, 1, Eigen::Dynamic>;
  // so(3) content: Sym²(L₁ ⊕ L₁) = 3L₂ ⊕ L₁ ⊕ 3L₀ (21-dimensional).
  const rep::So3Irrep<S> l1 = rep::so3Irrep<S>(2);
  const Matrix<S> h2 = rep::directSum(l1.H, l1.H), basis = rep::symmetricPowerBasis<S>(6, 2);
  c.checkEqual("dim Sym²(se(3)*) = 21", 21, (long long)basis.cols());
  c.checkEqual("Sym²(L₁ ⊕ L₁) = L₂ ⊕ L₂ ⊕ L₂ ⊕ L₁ ⊕ L₀ ⊕ L₀ ⊕ L₀", "3 L2 + L1 + 3 L0",
               rep::so3Decomposition<S>(rep::restrictToSubspace(rep::algebraTensor(h2, h2), basis)) ==
                       std::map<int, int>{{4, 3}, {2, 1}, {0, 3}}
                   ? "3 L2 + L1 + 3 L0" : "other");
  // The symmetric product as a bilinear form: (fg)(s₁, s₂) = f(s₁)g(s₂) + f(s₂)g(s₁), matrix fᵀg + gᵀf.
  auto sym = [](const Row& f, const Row& h) { return CMat<S>(f.transpose() * h + h.transpose() * f); };
  const auto &a = ch.a, &b = ch.b;  // index 0 ↔ m = 1, 1 ↔ 0, 2 ↔ −1
  const CMat<S> K1 = CMat<S>(sym(a[1], a[1]) - S(2) * sym(a[0], a[2]));  // a₀a₀ − 2a₁a₋₁
  const CMat<S> K2 = CMat<S>(sym(b[1], b[1]) - S(2) * sym(b[0], b[2]));  // b₀b₀ − 2b₁b₋₁
  const CMat<S> K3 = CMat<S>(sym(a[1], b[1]) - sym(a[0], b[2]) - sym(a[2], b[0]));     // a₀b₀ − a₁b₋₁ − a₋₁b₁
  // Q(X) on a form M: −(ad(X)ᵀ M + M ad(X)).
  auto act = [&](const CVec<S>& x, const CMat<S>& M) {
    const CMat<S> A = elementC(ad, x);
    return CMat<S>(-(A.transpose() * M + M * A));
  };
  S so3inv(0);
  for (const CMat<S>* M : {&K1, &K2, &K3})
    for (const CVec<S>* x : {&L.J3, &L.Jp, &L.Jm}) so3inv = maxOf(so3inv, maxAbs(act(*x, *M)));
  c.checkResidual("the three forms are so(3)-invariant: Q(J₃), Q(J₊), Q(J₋) kill them", so3inv, tol);
  S se3inv(0);
  for (const CMat<S>* M : {&K1, &K3})
    for (const CVec<S>* x : {&L.P3, &L.Pp, &L.Pm}) se3inv = maxOf(se3inv, maxAbs(act(*x, *M)));
  c.checkResidual("a₀a₀ − 2a₁a₋₁ and a₀b₀ − a₁b₋₁ − a₋₁b₁ are se(3)-invariant (Q(P_*) kills them)", se3inv, tol);
  const CMat<S> printedImage = S(4) * sym(a[0], b[1]) - S(4) * sym(a[1], b[0]);  // 4a₁b₀ − 4a₀b₁
  c.checkResidual("Q(P₊)(b₀b₀ − 2b₁b₋₁) = 4a₁b₀ − 4a₀b₁ ≠ 0 (as printed)", maxAbs(CMat<S>(act(L.Pp, K2) - printedImage)), tol);
  c.checkEqual("… and 4a₁b₀ − 4a₀b₁ is not 0: b₀b₀ − 2b₁b₋₁ is not se(3)-invariant", "non-zero",
               maxAbs(printedImage) > tol ? "non-zero" : "zero");
  // The printed pairings with the original basis (ω_i, ω_j, ω_k) = e₀, e₁, e₂.
  auto at = [](const Row& f, int k) { return f(0, k); };
  const C<S> one(S(1));
  S pair = absOf(C<S>(at(a[0], 0) - (-one / (S(4) * i))));
  pair = maxOf(pair, absOf(C<S>(at(a[0], 1) - one / S(4))));
  pair = maxOf(pair, absOf(C<S>(at(a[1], 2) - (-one / (S(2) * i)))));
  pair = maxOf(pair, absOf(C<S>(at(a[2], 0) - one / (S(2) * i))));
  pair = maxOf(pair, absOf(C<S>(at(a[2], 1) - one / S(2))));
  pair = maxOf(pair, absOf(C<S>(at(b[0], 3) - (-one / (S(4) * i)))));
  pair = maxOf(pair, absOf(C<S>(at(b[0], 4) - one / S(4))));
  pair = maxOf(pair, absOf(C<S>(at(b[1], 5) - (-one / (S(2) * i)))));
  pair = maxOf(pair, absOf(C<S>(at(b[2], 3) - one / (S(2) * i))));
  pair = maxOf(pair, absOf(C<S>(at(b[2], 4) - one / S(2))));
  c.checkResidual("pairings a₁(ω_i) = −1/4i, a₁(ω_j) = ¼, a₀(ω_k) = −1/2i, a₋₁(ω_i) = 1/2i, a₋₁(ω_j) = ½ (and b on v)", pair, tol);
  // The two invariant forms on general elements: −½(x₁x₂ + y₁y₂ + z₁z₂), −¼(x₁p₂ + … + r₁z₂).
  S f1(0), f3(0), typo(0), pitch(0);
  for (int n = 0; n < 20; ++n) {
    const Vec6<S> s1 = randomVec<S, 6>(g), s2 = randomVec<S, 6>(g);
    const CVec<S> c1 = toComplex<S>(s1), c2 = toComplex<S>(s2);
    f1 = maxOf(f1, absOf(C<S>((c1.transpose() * K1 * c2)(0, 0) + s1.template head<3>().dot(s2.template head<3>()) / S(2))));
    f3 = maxOf(f3, absOf(C<S>((c1.transpose() * K3 * c2)(0, 0) + reciprocalProduct(s1, s2) / S(4))));
    // the printed s₂ = x₂ω_i + y₂ω_i + … (typo for y₂ω_j)
    Vec6<S> s2typo = s2;
    s2typo(0) += s2(1), s2typo(1) = S(0);
    typo = maxOf(typo, absOf(C<S>((c1.transpose() * K1 * toComplex<S>(s2typo))(0, 0) +
                                  s1.template head<3>().dot(s2.template head<3>()) / S(2))));
    // pitch = ratio of the two forms = ω·v/ω·ω
    const S p = ((c1.transpose() * K3 * c1)(0, 0) / (c1.transpose() * K1 * c1)(0, 0)).real();
    const S direct = s1.template head<3>().dot(s1.template tail<3>()) / s1.template head<3>().squaredNorm();
    // δp·|ω|² ≤ c·eps·|ω||v| (quotient of two rounded dot products): scaled error
    const S w2 = s1.template head<3>().squaredNorm(), wv = sqrt(w2 * s1.template tail<3>().squaredNorm());
    pitch = maxOf(pitch, abs(p - direct) * w2 / (S(1) + wv));
    pitch = maxOf(pitch, abs(rep::pitchFromInvariantForms(SE3Tangent<S>(s1)) - direct) * w2 / (S(1) + wv));
  }
  c.checkResidual("(a₀a₀ − 2a₁a₋₁)(s₁, s₂) = −½(x₁x₂ + y₁y₂ + z₁z₂) (20 random pairs)", f1, S(4) * tol);
  c.checkResidual("(a₀b₀ − a₁b₋₁ − a₋₁b₁)(s₁, s₂) = −¼(x₁p₂ + y₁q₂ + z₁r₂ + p₁x₂ + q₁y₂ + r₁z₂)", f3, S(4) * tol);
  c.checkPrintedFails("with s₂ = x₂ω_i + y₂ω_i + … as printed", "minor (typo y₂ω_j)", typo, S(4) * tol);
  c.checkResidual("pitch = ratio of the two forms = ω·v/ω·ω (also rep::pitchFromInvariantForms; |δp|·|ω|² ≤ 64 eps (1 + |ω||v|))",
                  pitch, Tolerance<S>::identity(64));
  c.note("Seed line 4280 repeats \"with all other pairings gave\" before \"with all other pairings zero\" (OCR).");
}
SOMA_STUDY_SCALAR("GF-7.5-invariant-forms-sym2", "Invariants of Sym² of the coadjoint: Killing form and reciprocal product; pitch",
                  "GF §7.5", invariantFormsSym2);

// ---- GF §7.5, GF-7.5-casimirs-and-pitch (erratum E7.6) ------------------------------------------------
template <class S> void casimirsAndPitch(Context& c) {
  auto g = rng(756);
  const Se3Ladder<S> L = se3Ladder<S>();
  const S tol = Tolerance<S>::identity(64);
  const std::array<rep::Se3Generators<S>, 3> reps{rep::se3StandardGenerators<S>(), rep::se3AdjointGenerators<S>(),
                                                 rep::se3CoadjointGenerators<S>()};
  const char* names[3] = {"4×4", "adjoint", "coadjoint"};
  for (int r = 0; r < 3; ++r) {
    const auto& gen = reps[std::size_t(r)];
    const std::string nm = names[r];
    // the book's J_t and P_t in the ladder basis equal Σ J_a² and Σ P_a J_a
    const CMat<S> j3 = elementC(gen, L.J3), jp = elementC(gen, L.Jp), jm = elementC(gen, L.Jm);
    const CMat<S> p3 = elementC(gen, L.P3), pp = elementC(gen, L.Pp), pm = elementC(gen, L.Pm);
    const CMat<S> Jt = j3 * j3 + (jp * jm + jm * jp) / S(2), Pt = p3 * j3 + (pp * jm + pm * jp) / S(2);
    const rep::Se3QuadraticElements<S> q = rep::se3QuadraticElements(gen);
    c.checkResidual(nm + ": J₃² + ½J₊J₋ + ½J₋J₊ = Σ J_a², P₃J₃ + ½P₊J₋ + ½P₋J₊ = Σ P_a J_a (exact)",
                    maxOf(maxAbs(CMat<S>(Jt - toComplex<S>(q.rotationSquare))), maxAbs(CMat<S>(Pt - toComplex<S>(q.mixed)))), S(0));
    S pc(0), tc(0), jc(0);
    for (const auto& G : gen) {
      pc = maxOf(pc, maxAbs(comm(q.mixed, G)));
      tc = maxOf(tc, maxAbs(comm(q.translationSquare, G)));
      jc = maxOf(jc, maxAbs(comm(q.rotationSquare, G)));
    }
    c.checkResidual(nm + ": P_t commutes with every generator (Casimir; exact)", pc, S(0));
    c.checkResidual(nm + ": Σ P_a² commutes with every generator (the second Casimir; exact)", tc, S(0));
    if (r == 0)
      c.checkPrintedFails(nm + ": J_t commutes with all of se(3)", "E7.6", jc, S(0));
    else
      c.checkResidual(nm + ": J_t commutes here (J_t = −2·1)",
                      maxOf(jc, maxAbs(Matrix<S>(q.rotationSquare + S(2) * Matrix<S>::Identity(6, 6)))), S(0));
    // Tr(X P_t Y) vanishes identically, so it is no multiple of the reciprocal product.
    S trace(0), recip(0);
    for (int n = 0; n < 20; ++n) {
      const Vec6<S> s1 = randomVec<S, 6>(g), s2 = randomVec<S, 6>(g);
      const Matrix<S> X = rep::se3Element(gen, s1), Y = rep::se3Element(gen, s2);
      trace = maxOf(trace, abs(Matrix<S>(X * q.mixed * Y).trace()));
      recip = maxOf(recip, abs(reciprocalProduct(s1, s2)));
    }
    c.checkResidual(nm + ": Tr(X P_t Y) = 0 for 20 random pairs", trace, tol);
    c.checkPrintedFails(nm + ": Tr(X P_t Y) is the reciprocal product (largest |ω₁·v₂ + v₁·ω₂| of the pairs)", "E7.6",
                        recip, tol);
  }
  // The pitch formula Tr(X P_t X)/Tr(X J_t X) gives 0 for a screw of pitch 0.37 (adjoint representation).
  const SE3Tangent<S> s(Vec3<S>(S(0), S(0), S(1)), Vec3<S>(S(1) / S(2), S(0), S(37) / S(100)));
  const auto gen6 = rep::se3AdjointGenerators<S>();
  const rep::Se3QuadraticElements<S> q6 = rep::se3QuadraticElements(gen6);
  const Matrix<S> X = rep::se3Element(gen6, s.coeffs());
  const S printedPitch = Matrix<S>(X * q6.mixed * X).trace() / Matrix<S>(X * q6.rotationSquare * X).trace();
  c.checkPrintedFails("p = Tr(X P_t X)/Tr(X J_t X) recovers the pitch 0.37 of (k; ½i + 0.37k)", "E7.6",
                      abs(printedPitch - S(37) / S(100)), tol);
  c.checkNear("corrected: pitch as the ratio of the invariant forms (rep::pitchFromInvariantForms)", S(37) / S(100),
              rep::pitchFromInvariantForms(s), tol);
  // The invariant forms through traces that do work: the dual Killing form Tr(Š₁Š₂) (GF §7.6).
  S dk(0);
  for (int n = 0; n < 20; ++n) {
    const SE3Tangent<S> a(randomVec<S, 6>(g)), b(randomVec<S, 6>(g));
    const DualNumber<S> k = rep::dualKillingForm(a, b);
    dk = maxOf(dk, abs(k.re + S(2) * a.ang().dot(b.ang())) + abs(k.du + S(2) * reciprocalProduct(a.coeffs(), b.coeffs())));
  }
  c.checkResidual("Tr(Š₁Š₂) = −2ω₁·ω₂ − 2ε(ω₁·v₂ + v₁·ω₂): Killing form and reciprocal product", dk, tol);
  // Extreme: a pure translation has Tr(X J_t X) = 0 (infinite pitch).
  const SE3Tangent<S> t(Vec3<S>::Zero(), Vec3<S>(S(1), S(2), S(3)));
  const Matrix<S> Xt = rep::se3Element(gen6, t.coeffs());
  c.checkResidual("pure translation: Tr(X J_t X) = 0 (exact)", abs(Matrix<S>(Xt * q6.rotationSquare * Xt).trace()), S(0));
  c.checkEqual("pure translation: pitch +∞", "inf", isFinite(rep::pitchFromInvariantForms(t)) ? "finite" : "inf");
}
SOMA_STUDY_SCALAR("GF-7.5-casimirs-and-pitch", "Casimirs P_t, ΣP_a² of se(3); J_t only in the adjoint; pitch (erratum E7.6)",
                  "GF §7.5", casimirsAndPitch);

}  // namespace
}  // namespace soma::studies::gf07::SOMA_UNITY_ID
