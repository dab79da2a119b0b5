// Studies of GF chapter 7, §7.3–7.4: the ladder basis of so(3), its irreducible representations
// L_j, and their plethysm (L₁ ⊗ L₁, Clebsch–Gordan, Sym^n L_½, ⋀² L₁).
#include "gf07/common.hpp"
#include "soma/render/svg.hpp"

namespace soma::studies::gf07::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

/// The L₁ chain of the book in the 3×3 representation: u₁ with J₃u₁ = iu₁, u₀ = J₋u₁, u₋₁ = J₋u₀.
template <class S> std::array<CVec<S>, 3> l1Chain(const Ladder<S>& L) {
  const C<S> i = imagUnit<S>();
  CVec<S> u1(3);
  u1 << C<S>(S(1)), -i, C<S>(S(0));
  const CVec<S> u0 = L.Jm * u1;
  return {u1, u0, CVec<S>(L.Jm * u0)};
}

// ---- GF §7.3, GF-7.3-so3-ladder-relations -----------------------------------------------------
template <class S> void ladderRelations(Context& c) {
  const auto gen = so3Generators<S>();
  const Ladder<S> L = ladderOf<S>(gen[0], gen[1], gen[2]);
  const C<S> i = imagUnit<S>();
  c.checkResidual("[X, Y] = Z, [Y, Z] = X, [Z, X] = Y (exact)",
                  maxOf(maxOf(maxAbs(Matrix<S>(comm(gen[0], gen[1]) - gen[2])), maxAbs(Matrix<S>(comm(gen[1], gen[2]) - gen[0]))),
                        maxAbs(Matrix<S>(comm(gen[2], gen[0]) - gen[1]))), S(0));
  c.checkResidual("[J₃, J₊] = iJ₊ (exact)", maxAbs(CMat<S>(comm(L.J3, L.Jp) - i * L.Jp)), S(0));
  c.checkResidual("[J₃, J₋] = −iJ₋ (exact)", maxAbs(CMat<S>(comm(L.J3, L.Jm) + i * L.Jm)), S(0));
  c.checkResidual("[J₊, J₋] = 2iJ₃ (exact)", maxAbs(CMat<S>(comm(L.Jp, L.Jm) - S(2) * i * L.J3)), S(0));
  // The same relations in every L_j built by the library (J₃ = iH), j = 0 … 5.
  S worst(0);
  for (int twoJ = 0; twoJ <= 10; ++twoJ) {
    const rep::So3Irrep<S> l = rep::so3Irrep<S>(twoJ);
    const CMat<S> j3 = l.J3(), jp = toComplex<S>(l.Jp), jm = toComplex<S>(l.Jm);
    worst = maxOf(worst, maxAbs(CMat<S>(comm(j3, jp) - i * jp)));
    worst = maxOf(worst, maxAbs(CMat<S>(comm(j3, jm) + i * jm)));
    worst = maxOf(worst, maxAbs(CMat<S>(comm(jp, jm) - S(2) * i * j3)));
  }
  c.checkResidual("the three relations in the library's L_j, j = 0, ½, …, 5 (exact)", worst, S(0));
}
SOMA_STUDY_SCALAR("GF-7.3-so3-ladder-relations", "J₃ = Z, J± = Y ± iX: [J₃, J±] = ±iJ±, [J₊, J₋] = 2iJ₃", "GF §7.3",
                  ladderRelations);

// ---- GF §7.3, GF-7.3-so3-irreps ---------------------------------------------------------------------
template <class S> void so3Irreps(Context& c) {
  auto g = rng(731);
  const C<S> i = imagUnit<S>();
  // f(k) = (2in + k − 1)k solves f(k + 1) = f(k) + 2i(n − ki), f(1) = 2in; n = ij at the top of L_j.
  S rec(0), term(0);
  for (int twoJ = 0; twoJ <= 10; ++twoJ) {
    const C<S> n = i * (S(twoJ) / S(2));
    auto f = [&](int k) { return (S(2) * i * n + C<S>(S(k - 1))) * C<S>(S(k)); };
    rec = maxOf(rec, absOf(C<S>(f(1) - S(2) * i * n)));
    rec = maxOf(rec, absOf(C<S>(f(2) - S(2) * i * (S(2) * n - i))));
    for (int k = 1; k <= twoJ + 1; ++k) rec = maxOf(rec, absOf(C<S>(f(k + 1) - f(k) - S(2) * i * (n - S(k) * i))));
    term = maxOf(term, absOf(f(twoJ + 1)));  // the chain ends: (2in + m) = 0 at n = mi/2
  }
  c.checkResidual("f(k) = (2in + k − 1)k solves the recurrence, f(1) = 2in, f(2) = 2i(2n − i) (exact)", rec, S(0));
  c.checkResidual("termination f(m + 1) = (2in + m)(m + 1) = 0 at n = mi/2, m = 0 … 10 (exact)", term, S(0));
  // In the 3×3 representation (n = i): J₊u₀ = f(1)u₁ = −2u₁, J₊u₋₁ = f(2)u₀ = −2u₀, J₋³u₁ = 0.
  const auto gen = so3Generators<S>();
  const Ladder<S> L = ladderOf<S>(gen[0], gen[1], gen[2]);
  const auto u = l1Chain(L);
  c.checkResidual("3×3: J₃u₁ = iu₁, J₃u₀ = 0, J₃u₋₁ = −iu₋₁ (exact)",
                  maxOf(maxOf(maxAbs(CVec<S>(L.J3 * u[0] - i * u[0])), maxAbs(CVec<S>(L.J3 * u[1]))),
                        maxAbs(CVec<S>(L.J3 * u[2] + i * u[2]))), S(0));
  c.checkResidual("3×3: J₊u₀ = −2u₁ = f(1)u₁, J₊u₋₁ = −2u₀ = f(2)u₀, J₋³u₁ = 0 (exact)",
                  maxOf(maxOf(maxAbs(CVec<S>(L.Jp * u[1] + S(2) * u[0])), maxAbs(CVec<S>(L.Jp * u[2] + S(2) * u[1]))),
                        maxAbs(CVec<S>(L.Jm * u[2]))), S(0));
  // The 3×3 representation is equivalent to the library's L₁: M = (u₁ u₀ u₋₁) intertwines.
  const rep::So3Irrep<S> l1 = rep::so3Irrep<S>(2);
  CMat<S> M(3, 3);
  M << u[0], u[1], u[2];
  c.checkResidual("M = (u₁ u₀ u₋₁): ρ(J*) M = M L₁(J*) for J₃, J₊, J₋ (exact)",
                  maxOf(maxOf(maxAbs(CMat<S>(L.J3 * M - M * l1.J3())), maxAbs(CMat<S>(L.Jp * M - M * toComplex<S>(l1.Jp)))),
                        maxAbs(CMat<S>(L.Jm * M - M * toComplex<S>(l1.Jm)))), S(0));
  c.checkEqual("M is invertible (the chain spans ℂ³)", 0, nullity<S>(M));
  // Every L_j is a representation of so(3) (real elements: complex matrices), irreducible
  // (Schur: only multiples of 1 commute with it), with Casimir −j(j + 1).
  S rep3(0), cas(0);
  long long schur = 0;
  for (int twoJ = 0; twoJ <= 8; ++twoJ) {
    const rep::So3Irrep<S> l = rep::so3Irrep<S>(twoJ);
    const S tol = Tolerance<S>::identity(64) * S((twoJ + 1) * (twoJ + 1));
    for (int n = 0; n < 3; ++n) {
      const Vec3<S> x = randomVec<S, 3>(g), y = randomVec<S, 3>(g);
      rep3 = maxOf(rep3, maxAbs(CMat<S>(comm(l.element(x), l.element(y)) - l.element(Vec3<S>(x.cross(y))))) / tol);
    }
    const S j = S(twoJ) / S(2);
    cas = maxOf(cas, maxAbs(Matrix<S>(l.casimir() + j * (j + S(1)) * Matrix<S>::Identity(twoJ + 1, twoJ + 1))));
    // commutant: M with [H, M] = [J₊, M] = [J₋, M] = 0, as a linear system on vec M
    const Matrix<S> I = Matrix<S>::Identity(twoJ + 1, twoJ + 1);
    std::vector<Matrix<S>> ops;
    for (const Matrix<S>* a : {&l.H, &l.Jp, &l.Jm})
      ops.push_back(Matrix<S>(rep::groupTensor(*a, I) - rep::groupTensor(I, Matrix<S>(a->transpose()))));
    if (nullity<S>(stack<S>(ops)) != 1) ++schur;
  }
  c.checkResidual("L_j(xX + yY + zZ): [L(x), L(y)] = L(x × y), j ≤ 4 (in units of 64 eps (2j+1)²)", rep3, S(1));
  c.checkResidual("Casimir J₃² + ½(J₊J₋ + J₋J₊) = −j(j + 1)·1, j ≤ 4 (exact)", cas, S(0));
  c.checkEqual("Schur: the commutant of L_j is 1-dimensional (irreducible), j ≤ 4: failures", 0, schur);
  c.checkResidual("m = 0 is allowed: L₀ is the trivial representation (the book says \"positive m\")",
                  maxOf(maxAbs(rep::so3Irrep<S>(0).Jp), maxAbs(rep::so3Irrep<S>(0).H)), S(0));
  // su(2): the book's J₃ = [[0, i/2], [i/2, 0]] has eigenvalues ±i/2; e^{2πJ₃} = −1 on L_½.
  CMat<S> j3s(2, 2);
  j3s << C<S>(S(0)), i / S(2), i / S(2), C<S>(S(0));
  S eigs(0);
  for (const C<S>& lambda : {i / S(2), -i / S(2)}) {
    const CMat<S> m = j3s - lambda * CMat<S>::Identity(2, 2);
    eigs = maxOf(eigs, absOf(C<S>(m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0))));
  }
  c.checkResidual("su(2): det(J₃ ∓ i/2) = 0 (eigenvalues ±i/2; exact)", eigs, S(0));
  // e^{tJ₃} by its power series (J₃² = −¼): at t = 2π it is −1 on L_½; e^{2πJ₃} on L_j is
  // (−1)^{2j} (diagonal J₃ = iH: cos 2πm + i sin 2πm).
  CMat<S> e = CMat<S>::Identity(2, 2), t = CMat<S>::Identity(2, 2);
  const CMat<S> a = (S(2) * pi<S>() / S(64)) * j3s;  // scaled by 2⁻⁶, squared back
  for (int k = 1; k < 200; ++k) {
    t = CMat<S>(t * a / S(k));
    e += t;
    if (maxAbs(t) < Tolerance<S>::epsilon() * Tolerance<S>::epsilon()) break;
  }
  for (int k = 0; k < 6; ++k) e = CMat<S>(e * e);
  c.checkResidual("e^{2πJ₃} = −1 on L_½ (power series, scaling and squaring; ≤ 64·64 eps)",
                  maxAbs(CMat<S>(e + CMat<S>::Identity(2, 2))), Tolerance<S>::identity(64) * S(64));
  S kernel(0);
  for (int twoJ = 0; twoJ <= 6; ++twoJ) {
    const rep::So3Irrep<S> l = rep::so3Irrep<S>(twoJ);
    for (int k = 0; k <= twoJ; ++k) {
      const S angle = S(2) * pi<S>() * l.H(k, k);
      kernel = maxOf(kernel, abs(cos(angle) - (twoJ % 2 == 0 ? S(1) : S(-1))) + abs(sin(angle)));
    }
  }
  c.checkResidual("e^{2πJ₃} = (−1)^{2j}: the half-integer L_j do not pass to SO(3) (≤ 64 eps·2π j)", kernel,
                  Tolerance<S>::identity(64) * S(20));
}
SOMA_STUDY_SCALAR("GF-7.3-so3-irreps", "Irreducible representations L_j of so(3) from the ladder; f(k); SU(2) vs SO(3)",
                  "GF §7.3", so3Irreps);

// ---- GF §7.4, GF-7.4-L1xL1 (errata E7.2, E7.3) ------------------------------------------------------
template <class S> void l1xl1(Context& c) {
  const auto gen = so3Generators<S>();
  const Ladder<S> L = ladderOf<S>(gen[0], gen[1], gen[2]);
  const auto u = l1Chain(L);  // u[0] = u₁, u[1] = u₀, u[2] = u₋₁ (and v the same)
  auto uv = [&](int a, int b) { return kronVec<C<S>>(u[std::size_t(1 - a)], u[std::size_t(1 - b)]); };
  const CMat<S> T3 = rep::algebraTensor(L.J3, L.J3), Tp = rep::algebraTensor(L.Jp, L.Jp), Tm = rep::algebraTensor(L.Jm, L.Jm);
  // eigenvalue multiplicities 1, 2, 3, 2, 1 of 2i … −2i
  long long bad = 0;
  for (int w = -2; w <= 2; ++w)
    if (nullity<S>(CMat<S>(T3 - C<S>(S(0), S(w)) * CMat<S>::Identity(9, 9))) != 3 - std::abs(w)) ++bad;
  c.checkEqual("J₃ on L₁ ⊗ L₁: eigenvalues 2i, i, 0, −i, −2i with multiplicities 1, 2, 3, 2, 1 (mismatches)", 0, bad);
  const rep::So3Irrep<S> l1 = rep::so3Irrep<S>(2);
  const auto dec = rep::so3Decomposition<S>(rep::algebraTensor(l1.H, l1.H));
  c.checkEqual("L₁ ⊗ L₁ = L₂ ⊕ L₁ ⊕ L₀", "L2 + L1 + L0", dec == std::map<int, int>{{4, 1}, {2, 1}, {0, 1}} ? "L2 + L1 + L0" : "other");
  // the L₂ chain J₋^k(u₁ ⊗ v₁), as printed
  CVec<S> w = uv(1, 1);
  std::vector<CVec<S>> chain{w};
  for (int k = 0; k < 5; ++k) chain.push_back(CVec<S>(Tm * chain.back()));
  const CVec<S> printed[4] = {CVec<S>(uv(1, 0) + uv(0, 1)), CVec<S>(uv(1, -1) + S(2) * uv(0, 0) + uv(-1, 1)),
                              CVec<S>(S(3) * uv(0, -1) + S(3) * uv(-1, 0)), CVec<S>(S(6) * uv(-1, -1))};
  S ch(0);
  for (int k = 0; k < 4; ++k) ch = maxOf(ch, maxAbs(CVec<S>(chain[std::size_t(k + 1)] - printed[k])));
  c.checkResidual("J₋^k(u₁ ⊗ v₁), k = 1 … 4, as printed (exact)", ch, S(0));
  c.checkResidual("J₋⁵(u₁ ⊗ v₁) = 0: the L₂ chain has 5 vectors (exact)", maxAbs(chain[5]), S(0));
  // L₁ summand: top u₁⊗v₀ − u₀⊗v₁ (killed by J₊), then J₋ of it.
  const CVec<S> top = uv(1, 0) - uv(0, 1);
  c.checkResidual("L₁ top vector u₁⊗v₀ − u₀⊗v₁: J₊ kills it, J₃ eigenvalue i (exact)",
                  maxOf(maxAbs(CVec<S>(Tp * top)), maxAbs(CVec<S>(T3 * top - imagUnit<S>() * top))), S(0));
  const CVec<S> mid = Tm * top;
  c.checkPrintedFails("L₁ middle vector u₁⊗v₁ − u₁⊗v₁ (= 0) is J₋ of the top one", "E7.3",
                      maxAbs(CVec<S>(mid - CVec<S>(uv(1, 1) - uv(1, 1)))), S(0));
  c.checkResidual("corrected: J₋(u₁⊗v₀ − u₀⊗v₁) = u₁⊗v₋₁ − u₋₁⊗v₁ (exact)", maxAbs(CVec<S>(mid - (uv(1, -1) - uv(-1, 1)))), S(0));
  c.checkResidual("J₋ of that = u₀⊗v₋₁ − u₋₁⊗v₀, the printed third vector (exact)",
                  maxAbs(CVec<S>(Tm * mid - (uv(0, -1) - uv(-1, 0)))), S(0));
  // L₀: the printed invariant is not invariant; the corrected one is, and it is the scalar product.
  const CVec<S> p0 = uv(1, -1) + uv(0, 0) + uv(-1, 1), q0 = uv(1, -1) - uv(0, 0) + uv(-1, 1);
  c.checkPrintedFails("L₀ = u₁⊗v₋₁ + u₀⊗v₀ + u₋₁⊗v₁ is killed by J₋", "E7.2", maxAbs(CVec<S>(Tm * p0)), S(0));
  c.checkResidual("corrected u₁⊗v₋₁ − u₀⊗v₀ + u₋₁⊗v₁: killed by J₃, J₊, J₋ (exact)",
                  maxOf(maxOf(maxAbs(CVec<S>(T3 * q0)), maxAbs(CVec<S>(Tp * q0))), maxAbs(CVec<S>(Tm * q0))), S(0));
  // The same in the library's own L₁ (e_k = J₋ᵏe₀, the book's normalisation; real form H, J±).
  {
    const Matrix<S> H = rep::algebraTensor(l1.H, l1.H), P = rep::algebraTensor(l1.Jp, l1.Jp), M = rep::algebraTensor(l1.Jm, l1.Jm);
    Eigen::Matrix<S, Eigen::Dynamic, 1> lib0 = Eigen::Matrix<S, Eigen::Dynamic, 1>::Zero(9), libP = lib0;
    lib0(2) = S(1), lib0(4) = S(-1), lib0(6) = S(1);  // e₀⊗e₂ − e₁⊗e₁ + e₂⊗e₀
    libP(2) = S(1), libP(4) = S(1), libP(6) = S(1);
    c.checkResidual("library's L₁: e₀⊗e₂ − e₁⊗e₁ + e₂⊗e₀ is killed by H, J₊, J₋ (exact)",
                    maxOf(maxOf(maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(H * lib0)), maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(P * lib0))),
                          maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(M * lib0))), S(0));
    c.checkPrintedFails("library's L₁: e₀⊗e₂ + e₁⊗e₁ + e₂⊗e₀ is killed by J₋", "E7.2",
                        maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(M * libP)), S(0));
  }
  CVec<S> dotTensor = CVec<S>::Zero(9);
  for (int a = 0; a < 3; ++a) dotTensor(4 * a) = C<S>(S(1));  // Σ e_a ⊗ e_a: the scalar product
  const C<S> scale = q0(0);
  c.checkResidual("the corrected L₀ vector is " + str(scale.real(), 3) + "·Σ e_a ⊗ e_a (the scalar product)",
                  maxAbs(CVec<S>(q0 - scale * dotTensor)), S(0));
  // ⋀²: the L₁ triple spans the antisymmetric tensors (the vector product).
  CMat<S> l1span(9, 3);
  l1span << top, mid, CVec<S>(uv(0, -1) - uv(-1, 0));
  CMat<S> both(9, 6);
  both << l1span, toComplex<S>(rep::exteriorPowerBasis<S>(3, 2));
  c.checkEqual("span(L₁ summand) = ⋀²ℂ³ (rank of the 6 columns together)", 3, 6 - nullity<S>(both));
}
SOMA_STUDY_SCALAR("GF-7.4-L1xL1", "L₁ ⊗ L₁ = L₂ ⊕ L₁ ⊕ L₀ with explicit bases (errata E7.2, E7.3)", "GF §7.4", l1xl1);

// ---- GF §7.4, GF-7.4-clebsch-gordan (erratum E7.1) --------------------------------------------------
template <class S> void clebschGordan(Context& c) {
  long long badCasimir = 0, badDim = 0, badDecomp = 0, cases = 0;
  long long printedCount = 0, printedPlateau = 0, badPlateau = 0;
  for (int twoM = 0; twoM <= 6; ++twoM)
    for (int twoN = 0; twoN <= 6; ++twoN) {
      if ((twoM + 1) * (twoN + 1) > 25) continue;  // FullPivLU sizes stay ≤ 25 (mpfr)
      ++cases;
      const rep::So3Irrep<S> a = rep::so3Irrep<S>(twoM), b = rep::so3Irrep<S>(twoN);
      const Matrix<S> H = rep::algebraTensor(a.H, b.H), Jp = rep::algebraTensor(a.Jp, b.Jp), Jm = rep::algebraTensor(a.Jm, b.Jm);
      const int d = int(H.rows());
      const Matrix<S> Cas = -H * H + (Jp * Jm + Jm * Jp) / S(2);
      int sum = 0;
      std::map<int, int> expected;
      for (int twoK : rep::clebschGordan(twoM, twoN)) {
        const S k = S(twoK) / S(2);
        if (nullity<S>(Matrix<S>(Cas + k * (k + S(1)) * Matrix<S>::Identity(d, d))) != twoK + 1) ++badCasimir;
        sum += twoK + 1;
        expected[twoK] = 1;
      }
      if (sum != d) ++badDim;
      if (rep::so3Decomposition<S>(H) != expected) ++badDecomp;
      printedCount += std::abs(twoM * twoN - d);  // the book's "2m × 2n eigenvectors"
      // the plateau: for m > n the eigenvalue (m − n)i has 2n + 1 eigenvectors (book: 2n)
      if (twoM > twoN) {
        const int plateau = nullity<S>(Matrix<S>(H - (S(twoM - twoN) / S(2)) * Matrix<S>::Identity(d, d)));
        if (plateau != twoN + 1) ++badPlateau;
        printedPlateau += std::abs(plateau - twoN);
      }
    }
  c.note("Cases: m, n ∈ {0, ½, …, 3} with (2m + 1)(2n + 1) ≤ 25 (FullPivLU sizes kept small for mpfr): " +
         std::to_string(cases) + " pairs.");
  c.checkEqual("Casimir −k(k+1) has multiplicity 2k + 1 for each k = |m−n| … m+n (mismatches)", 0, badCasimir);
  c.checkEqual("Σ_{k=|m−n|}^{m+n} (2k + 1) = (2m + 1)(2n + 1) (mismatches)", 0, badDim);
  c.checkEqual("weights decompose as L_{m+n} ⊕ … ⊕ L_{|m−n|} (mismatches)", 0, badDecomp);
  c.checkEqual("for m > n the eigenvalue (m − n)i has 2n + 1 eigenvectors (mismatches)", 0, badPlateau);
  c.checkPrintedFails("L_m ⊗ L_n has 2m × 2n eigenvectors (Σ |2m·2n − (2m+1)(2n+1)| over the cases)", "E7.1",
                      S(double(printedCount)), S(0));
  c.checkPrintedFails("2n terms with eigenvalue (m − n)i (Σ |count − 2n| over m > n)", "E7.1", S(double(printedPlateau)), S(0));
  // m < n: the lowest summand is L_{n−m} = L_{|m−n|}; the printed ⌊m − n⌋ (OCR of |m − n|) would be
  // negative. Example m = ½, n = 2: lowest Casimir eigenvalue −k(k+1) at k = 3/2.
  const rep::So3Irrep<S> a = rep::so3Irrep<S>(1), b = rep::so3Irrep<S>(4);
  const auto dec = rep::so3Decomposition<S>(rep::algebraTensor(a.H, b.H));
  c.checkEqual("L_½ ⊗ L₂: lowest summand 2k = 2|m − n| = 3", 3, dec.begin()->first);
  // Figure: the book's grid argument for L₃ ⊗ L₁ — the multiplicity of each J₃ eigenvalue iw
  // (measured: nullity of H − w) and the summands L₄, L₃, L₂ stacked as bars over −k … k.
  if (c.makeFigures()) {
    const rep::So3Irrep<S> l3 = rep::so3Irrep<S>(6), l1 = rep::so3Irrep<S>(2);
    const Matrix<S> H = rep::algebraTensor(l3.H, l1.H);
    std::vector<double> ws, mult;
    for (int w = -4; w <= 4; ++w) {
      ws.push_back(w);
      mult.push_back(nullity<S>(Matrix<S>(H - S(w) * Matrix<S>::Identity(H.rows(), H.cols()))));
    }
    render::Plot plot;
    plot.title = "GF §7.4: weights of L₃ ⊗ L₁ = L₄ ⊕ L₃ ⊕ L₂";
    plot.x.label = "w (J₃ eigenvalue iw)";
    plot.y.label = "multiplicity";
    plot.y.min = 0, plot.y.max = 4.5;
    const render::Color colours[3] = {render::palette::blue, render::palette::orange, render::palette::bluishGreen};
    int layer = 0;
    for (int twoK : {8, 6, 4}) {  // L₄ at the bottom, then L₃, L₂
      const double k = twoK / 2.0, y = layer + 0.5;
      const std::string sub[5] = {"₀", "₁", "₂", "₃", "₄"}, kk = std::to_string(twoK / 2);
      auto& s = plot.add("L" + sub[twoK / 2] + " (weights −" + kk + " … " + kk + ")", {-k, k}, {y, y}, colours[layer]);
      s.width = 10;
      ++layer;
    }
    auto& m = plot.add("measured multiplicity (nullity of H − w)", ws, mult, render::palette::black);
    m.markers = true;
    m.markerRadius = 7;
    render::renderPlotPngAndSvg(plot, c.figurePath("GF-7.4-clebsch-gordan.png"), 1100, 700);
    c.figure("GF-7.4-clebsch-gordan.png",
             "The grid argument of §7.4 for m = 3, n = 1: the 21 weights of L₃ ⊗ L₁ have multiplicities 1, 2, 3, 3, 3, 3, 3, "
             "2, 1 (black, measured); peeling off strings from the top leaves L₄, L₃, L₂ (bars, one per summand, each over "
             "its weights −k … k), so the plateau of 2n + 1 = 3 ends at |w| = m − n = 2.");
  }
}
SOMA_STUDY_SCALAR("GF-7.4-clebsch-gordan", "L_m ⊗ L_n = L_{m+n} ⊕ … ⊕ L_{|m−n|} by Casimir multiplicities (erratum E7.1)",
                  "GF §7.4", clebschGordan);

// ---- GF §7.4, GF-7.4-sym-and-wedge ------------------------------------------------------------------
template <class S> void symAndWedge(Context& c) {
  const rep::So3Irrep<S> half = rep::so3Irrep<S>(1), one = rep::so3Irrep<S>(2);
  // Sym² L_½: the three printed eigenvectors v½⊗v½, v½⊗v₋½ + v₋½⊗v½, v₋½⊗v₋½ with eigenvalues i, 0, −i.
  const Matrix<S> H2 = rep::algebraTensor(half.H, half.H);
  Matrix<S> printed = Matrix<S>::Zero(4, 3);
  printed(0, 0) = S(1), printed(1, 1) = printed(2, 1) = S(1), printed(3, 2) = S(1);
  const Matrix<S> sym = rep::symmetricPowerBasis<S>(2, 2);
  c.checkResidual("Sym² L_½ basis = the printed eigenvectors (exact)", maxAbs(Matrix<S>(sym - printed)), S(0));
  c.checkResidual("their J₃ eigenvalues i, 0, −i (−iJ₃ = H: 1, 0, −1; exact)",
                  maxAbs(Matrix<S>(H2 * printed - printed * Matrix<S>(Vec3<S>(S(1), S(0), S(-1)).asDiagonal()))), S(0));
  // Sym^n L_½ = L_{n/2}, n = 1 … 8: decomposition and the Casimir −(n/2)(n/2 + 1) on the restriction.
  long long badSym = 0;
  S cas(0);
  for (int n = 1; n <= 8; ++n) {
    const Matrix<S> basis = rep::symmetricPowerBasis<S>(2, n);
    const Matrix<S> h = rep::restrictToSubspace(rep::algebraTensorPower(half.H, n), basis);
    const Matrix<S> jp = rep::restrictToSubspace(rep::algebraTensorPower(half.Jp, n), basis);
    const Matrix<S> jm = rep::restrictToSubspace(rep::algebraTensorPower(half.Jm, n), basis);
    if (rep::so3Decomposition<S>(h) != std::map<int, int>{{n, 1}}) ++badSym;
    const S j = S(n) / S(2);
    const Matrix<S> Cm = -h * h + (jp * jm + jm * jp) / S(2);
    cas = maxOf(cas, maxAbs(Matrix<S>(Cm + j * (j + S(1)) * Matrix<S>::Identity(n + 1, n + 1))) / (j * (j + S(1))));
  }
  c.checkEqual("Sym^n L_½ = L_{n/2}, n = 1 … 8 (mismatches)", 0, badSym);
  c.checkResidual("Casimir on Sym^n L_½ = −(n/2)(n/2 + 1) (relative, ≤ 256 eps)", cas, Tolerance<S>::identity(256));
  // ⋀² L₁ = L₁: the restriction of Ω ⊗ 1 + 1 ⊗ Ω to ⋀²ℝ³ is Ω itself under e₁∧e₂ ↦ e₃, e₁∧e₃ ↦ −e₂,
  // e₂∧e₃ ↦ e₁ (the vector product).
  auto g = rng(743);
  const Matrix<S> wb = rep::exteriorPowerBasis<S>(3, 2);
  Matrix<S> P = Matrix<S>::Zero(3, 3);
  P(2, 0) = S(1), P(1, 1) = S(-1), P(0, 2) = S(1);
  S cross(0);
  for (int n = 0; n < 10; ++n) {
    const Mat3<S> W = skew(randomVec<S, 3>(g));
    const Matrix<S> A = rep::restrictToSubspace(rep::algebraTensor(Matrix<S>(W), Matrix<S>(W)), wb);
    cross = maxOf(cross, maxAbs(Matrix<S>(P * A - Matrix<S>(W) * P)));
  }
  c.checkResidual("⋀²L₁ ≅ L₁ through the vector product: P (Ω∧Ω) = Ω P", cross, Tolerance<S>::identity(64));
  c.checkEqual("⋀² L₁ = L₁ (weights)", "L1",
               rep::so3Decomposition<S>(rep::restrictToSubspace(rep::algebraTensor(one.H, one.H), wb)) == std::map<int, int>{{2, 1}}
                   ? "L1" : "other");
  c.checkEqual("Sym² L₁ = L₂ ⊕ L₀ (the rest of L₁ ⊗ L₁)", "L2 + L0",
               rep::so3Decomposition<S>(rep::restrictToSubspace(rep::algebraTensor(one.H, one.H), rep::symmetricPowerBasis<S>(3, 2))) ==
                       std::map<int, int>{{4, 1}, {0, 1}}
                   ? "L2 + L0" : "other");
}
SOMA_STUDY_SCALAR("GF-7.4-sym-and-wedge", "Sym² L_½ = L₁, Sym^n L_½ = L_{n/2}, ⋀² L₁ = L₁ (vector product)", "GF §7.4",
                  symAndWedge);

}  // namespace
}  // namespace soma::studies::gf07::SOMA_UNITY_ID
