// Studies of GF chapter 9, §9.1: Clifford algebras Cℓ(p,q,r) — definition from a quadratic
// form, the small algebras, grading and the even subalgebra, conjugation and involution, a zero
// divisor, Pin and Spin, the exterior product. Run in the scalar asked for (--scalar).
#include "gf09/common.hpp"

#include "soma/algebra/clifford/quadratic_form.hpp"
#include "soma/algebra/so3.hpp"

namespace soma::studies::gf09::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF §9.1, GF-9.1-clifford-definition-signature ------------------------------------------
template <class S> void definitionSignature(Context& c) {
  auto g = rng(901);
  // A non-diagonal Q of inertia (1,2,1): Q = A diag(1,−1,−1,0) Aᵀ with A random.
  FormMatrix<S> A = FormMatrix<S>::Identity(4, 4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) A(i, j) += S(2) / S(5) * uni<S>(g);
  FormMatrix<S> D = FormMatrix<S>::Zero(4, 4);
  D.diagonal() << 1, -1, -1, 0;
  const FormMatrix<S> Q = A * D * A.transpose();
  using Sig = Signature<1, 2, 1>;
  const FormBasis<Sig, S> fb(Q);
  const auto& cg = fb.congruence();
  c.checkEqual("Sylvester inertia (p, q, r) of Q = A diag(1,−1,−1,0) Aᵀ", "(1,2,1)",
               "(" + std::to_string(cg.p) + "," + std::to_string(cg.q) + "," + std::to_string(cg.r) + ")");
  FormMatrix<S> want = FormMatrix<S>::Zero(4, 4);
  want.diagonal() << 1, -1, -1, 0;
  const S tol = Tolerance<S>::identity(256);
  c.checkResidual("congruence M Q Mᵀ = diag(1, −1, −1, 0) (book: e_ie_j + e_je_i = 2(MQMᵀ)_ij)",
                  (cg.M * Q * cg.M.transpose() - want).cwiseAbs().maxCoeff(), tol);
  // The defining relations x_i x_j + x_j x_i = 2 Q_ij, evaluated in Cℓ(1,2,1) after the change of
  // generators x = M⁻¹ e: the anticommutation table of the non-diagonal form.
  S worst = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const auto xi = fb.generator(i), xj = fb.generator(j);
      const Dense<Sig, S> ac(xi * xj + xj * xi);
      worst = std::max(worst, abs(ac.scalarPart() - 2 * Q(i, j)));
      worst = std::max(worst, ac.template grades<gradeBit(2)>().maxAbs());
    }
  c.checkResidual("x_i x_j + x_j x_i = 2 Q_ij for all 16 pairs (non-diagonal Q, in Cℓ(1,2,1))", worst, tol);
  // The orthogonal generators of soma's Cℓ(p,q,r) square to +1, −1, 0 in the book's order.
  using G = Signature<1, 2, 1>;
  std::string squares;
  for (int i = 0; i < 4; ++i) {
    const auto e = Vector<G, S>::generator(i);
    squares += std::to_string(int(toDouble((e * e).scalarPart()))) + (i < 3 ? "," : "");
  }
  c.checkEqual("generator squares of Cℓ(1,2,1)", "1,-1,-1,0", squares);
  // Dimension 2^n: number of basis monomials e_i e_j ⋯ e_k, i < j < ⋯ < k.
  c.checkEqual("dim Cℓ(1,2,1) = 2⁴", 16, Dense<G, S>::size);
  c.checkEqual("dim Cℓ(0,6,2) = 2⁸", 256, Dense<Signature<0, 6, 2>, S>::size);
  // Degenerate extreme: a null vector has no inverse.
  bool threw = false;
  try {
    (void)inverse(Vector<G, S>::generator(3));
  } catch (const InvalidInput&) {
    threw = true;
  }
  c.checkEqual("the null generator e₄ (e₄² = 0) has no inverse", "InvalidInput",
               threw ? "InvalidInput" : "inverted");
  c.note("soma computes in the diagonal basis only (the blade tables need orthogonal generators); "
         "clifford/quadratic_form.hpp is the book's change of generators for a non-diagonal Q, "
         "tested against a direct Chevalley evaluation in tests/algebra/clifford_form.cpp. "
         "Typo: the double sum printed Σ_k Σ_j m_ik m_jl is Σ_k Σ_l (j is the free index).");
}
SOMA_STUDY_SCALAR("GF-9.1-clifford-definition-signature", "Cℓ(Q) from a non-diagonal form; Sylvester's congruence to Cℓ(p,q,r)",
           "GF §9.1", definitionSignature);

// ---- GF §9.1, GF-9.1-small-algebras ---------------------------------------------------------
template <class S> void smallAlgebras(Context& c) {
  auto g = rng(902);
  const S tol = Tolerance<S>::identity(16);
  {  // ℂ = Cℓ(0,1,0): (x + y e₁)(w + z e₁) = (xw − yz) + (xz + yw) e₁
    using C = Signature<0, 1, 0>;
    const S x = uni<S>(g), y = uni<S>(g), w = uni<S>(g), z = uni<S>(g);
    Dense<C, S> u, v;
    u[0] = x, u[1] = y, v[0] = w, v[1] = z;
    const auto uv = u * v;
    c.checkResidual("Cℓ(0,1,0): (x + ye₁)(w + ze₁) = (xw − yz) + (xz + yw)e₁ (random)",
                    std::max(abs(uv[0] - (x * w - y * z)), abs(uv[1] - (x * z + y * w))), tol);
  }
  {  // 𝔻 = Cℓ(0,0,1): dual numbers
    using Dd = Signature<0, 0, 1>;
    const S x = uni<S>(g), y = uni<S>(g), w = uni<S>(g), z = uni<S>(g);
    Dense<Dd, S> u, v;
    u[0] = x, u[1] = y, v[0] = w, v[1] = z;
    const auto uv = u * v;
    c.checkResidual("Cℓ(0,0,1) = 𝔻: (x + yε)(w + zε) = xw + (xz + yw)ε",
                    std::max(abs(uv[0] - x * w), abs(uv[1] - (x * z + y * w))), tol);
  }
  // ℍ = Cℓ(0,2,0): i ↦ e₁, j ↦ e₂, k ↦ e₁e₂.
  using H = Signature<0, 2, 0>;
  const auto i = gens<H, S>({0}), j = gens<H, S>({1}), k = gens<H, S>({0, 1}), m1 = Dense<H, S>(S(-1));
  c.checkResidual("ℍ: i² = j² = k² = −1 (line 5358 omits \"= −1\" after j² = e₂²)",
                  std::max({maxAbsDiff(i * i, m1), maxAbsDiff(j * j, m1), maxAbsDiff(k * k, m1)}), S(0));
  c.checkResidual("ℍ: ij = k, jk = e₂e₁e₂ = i, ki = e₁e₂e₁ = j",
                  std::max({maxAbsDiff(i * j, k), maxAbsDiff(j * k, i), maxAbsDiff(k * i, j)}), S(0));
  c.checkResidual("ℍ: anticommutation ij = −ji, jk = −kj, ki = −ik",
                  std::max({maxAbsDiff(i * j, -(j * i)), maxAbsDiff(j * k, -(k * j)),
                            maxAbsDiff(k * i, -(i * k))}), S(0));
  // Against soma's Quaternion (Hamilton product) for random elements.
  S worst = 0;
  for (int t = 0; t < 20; ++t) {
    const Quat<S> p(uni<S>(g), uni<S>(g), uni<S>(g), uni<S>(g)), q(uni<S>(g), uni<S>(g), uni<S>(g), uni<S>(g));
    auto cl = [&](const Quat<S>& a) { return Dense<H, S>(Dense<H, S>(a.w()) + i * a.x() + j * a.y() + k * a.z()); };
    const Quat<S> pq = p * q;
    worst = std::max(worst, maxAbsDiff(cl(p) * cl(q), cl(pq)));
  }
  c.checkResidual("Cℓ(0,2,0) products = Hamilton products of Eigen quaternions (20 random)", worst, tol);
}
SOMA_STUDY_SCALAR("GF-9.1-small-algebras", "Cℓ(0,1,0) ≅ ℂ, Cℓ(0,0,1) = 𝔻, Cℓ(0,2,0) ≅ ℍ", "GF §9.1", smallAlgebras);

// ---- GF §9.1, GF-9.1-grading-even-subalgebra -------------------------------------------------
/// Cℓ(p,q,r) → Cℓ⁺(p,q+1,r), e_i ↦ e_i e₀ with the new e₀ (e₀² = −1) inserted after the q
/// negative generators; returns the largest defect of the relations and of the homomorphism.
template <class S, class Small, class Big> std::pair<S, S> evenIso(std::mt19937_64& g) {
  const int e0 = Small::p + Small::q;
  auto gen = [&](int i) {
    const int bi = i < e0 ? i : i + 1;
    return Even<Big, S>(Dense<Big, S>(Vector<Big, S>::generator(bi) * Vector<Big, S>::generator(e0))
                            .template grades<Big::evenGrades>());
  };
  S rel = 0;
  for (int i = 0; i < Small::n; ++i)
    for (int j = 0; j < Small::n; ++j)
      rel = std::max(rel, maxAbsDiff(gen(i) * gen(j) + gen(j) * gen(i),
                                     Even<Big, S>(S(i == j ? 2 * Small::square(i) : 0))));
  std::vector<Even<Big, S>> img(Small::dim);
  for (int b = 0; b < Small::dim; ++b) {
    Even<Big, S> m(S(1));
    for (int i = 0; i < Small::n; ++i)
      if (b & (1 << i)) m = Even<Big, S>(m * gen(i));
    img[std::size_t(b)] = m;
  }
  auto phi = [&](const Dense<Small, S>& a) {
    Even<Big, S> m;
    for (int i = 0; i < a.size; ++i) m += img[std::size_t(a.blade(i))] * a[i];
    return m;
  };
  S hom = 0;
  for (int t = 0; t < 10; ++t) {
    Dense<Small, S> a, b;
    for (int i = 0; i < a.size; ++i) a[i] = uni<S>(g), b[i] = uni<S>(g);
    hom = std::max(hom, maxAbsDiff(phi(a * b), phi(a) * phi(b)));
  }
  return {rel, hom};
}
template <class S> void gradingEven(Context& c) {
  auto g = rng(903);
  const S tol = Tolerance<S>::identity(64);
  c.checkEqual("dim Cℓ⁺(0,3,1) = 2^{p+q+r−1}", 8, Even<PGA, S>::size);
  c.checkEqual("dim Cℓ⁺(0,6,2) = 2⁷", 128, Even<Signature<0, 6, 2>, S>::size);
  // Grade dimensions C(n,k) and the basis-independent split Cℓ = Cℓ⁺ ⊕ Cℓ⁻.
  c.checkEqual("dim V₂ of Cℓ(0,3,1) = C(4,2)", 6, Bivector<PGA, S>::size);
  c.checkEqual("dim Cℓ⁻(0,3,1)", 8, Odd<PGA, S>::size);
  // Products respect the Z₂-grading: even·odd is odd (the result type has no even grade).
  c.checkEqual("Cℓ⁺ · Cℓ⁻ ⊆ Cℓ⁻ (grades of the product type of Even × Odd)", "odd",
               (decltype(Even<PGA, S>() * Odd<PGA, S>())::mask & PGA::evenGrades) == 0 ? "odd" : "mixed");
  auto [r1, h1] = evenIso<S, Signature<1, 1, 1>, Signature<1, 2, 1>>(g);
  c.checkResidual("Cℓ(1,1,1) → Cℓ⁺(1,2,1), e_i ↦ e_ie₀: images satisfy the relations", r1, S(0));
  c.checkResidual("… and the map is a homomorphism (10 random pairs)", h1, tol);
  auto [r2, h2] = evenIso<S, Signature<0, 2, 0>, Signature<0, 3, 0>>(g);
  c.checkResidual("Cℓ⁺(0,3,0) ≅ Cℓ(0,2,0) = ℍ: relations", r2, S(0));
  c.checkResidual("… homomorphism", h2, tol);
  auto [r3, h3] = evenIso<S, Signature<0, 2, 1>, Signature<0, 3, 1>>(g);
  c.checkResidual("Cℓ⁺(0,3,1) ≅ Cℓ(0,2,1) (the §9.3 route to ℍ ⊗ 𝔻): relations", r3, S(0));
  c.checkResidual("… homomorphism", h3, tol);
  c.note("The book's computation e_ie₀e_je₀ + e_je₀e_ie₀ = −(e_ie_j + e_je_i)e₀² holds because "
         "e₀ anticommutes with e_i, e_j; with e₀² = −1 the images obey the original relations.");
}
SOMA_STUDY_SCALAR("GF-9.1-grading-even-subalgebra", "Grading, Cℓ⁺, and Cℓ(p,q,r) ≅ Cℓ⁺(p,q+1,r)", "GF §9.1", gradingEven);

// ---- GF §9.1, GF-9.1-conjugation-involution --------------------------------------------------
template <class S> void conjugationInvolution(Context& c) {
  auto g = rng(904);
  using G = Signature<1, 2, 1>;
  const S tol = Tolerance<S>::identity(64);
  S anti = 0, hom = 0, comm = 0, invol = 0;
  for (int t = 0; t < 20; ++t) {
    Dense<G, S> a, b;
    for (int i = 0; i < a.size; ++i) a[i] = uni<S>(g), b[i] = uni<S>(g);
    anti = std::max(anti, maxAbsDiff((a * b).conjugate(), b.conjugate() * a.conjugate()));
    hom = std::max(hom, maxAbsDiff((a * b).involute(), a.involute() * b.involute()));
    comm = std::max(comm, maxAbsDiff(a.involute().conjugate(), a.conjugate().involute()));
    invol = std::max(invol, maxAbsDiff(a.conjugate().conjugate(), a));
  }
  c.checkResidual("(c₁c₂)* = c₂*c₁* in Cℓ(1,2,1) (20 random pairs)", anti, tol);
  c.checkResidual("c** = c", invol, S(0));
  c.checkResidual("α(c₁c₂) = α(c₁)α(c₂)", hom, tol);
  c.checkResidual("α(c)* = α(c*)", comm, S(0));
  // (e₁e₂⋯e_k)* = (−1)^k e_k⋯e₂e₁, by grade: + − − + +.
  S blades = 0;
  for (int k = 0; k <= 4; ++k) {
    std::vector<int> up, down;
    for (int i = 0; i < k; ++i) up.push_back(i);
    for (int i = k - 1; i >= 0; --i) down.push_back(i);
    Dense<G, S> u(S(1)), d(S(1));
    for (int i : up) u = Dense<G, S>(u * Vector<G, S>::generator(i));
    for (int i : down) d = Dense<G, S>(d * Vector<G, S>::generator(i));
    blades = std::max(blades, maxAbsDiff(u.conjugate(), d * S(k % 2 ? -1 : 1)));
  }
  c.checkResidual("(e₁⋯e_k)* = (−1)^k e_k⋯e₁, k = 0…4 (signs + − − + +)", blades, S(0));
  // ℍ: (a + bi + cj + dk)* = a − bi − cj − dk.
  using H = Signature<0, 2, 0>;
  Dense<H, S> q;
  q[0] = 1, q[1] = 2, q[2] = 3, q[3] = 4;
  const auto qc = q.conjugate();
  c.checkResidual("ℍ: (1 + 2i + 3j + 4k)* = 1 − 2i − 3j − 4k",
                  std::max({abs(qc[0] - 1), abs(qc[1] + 2), abs(qc[2] + 3), abs(qc[3] + 4)}), S(0));
  // x x* = −x₁² − ⋯ − x_p² + x_{p+1}² + ⋯ + x_{p+q}² (null generators contribute nothing).
  Vector<G, S> x;
  const S x1 = uni<S>(g), x2 = uni<S>(g), x3 = uni<S>(g), x4 = uni<S>(g);
  x.setCoeff(1, x1), x.setCoeff(2, x2), x.setCoeff(4, x3), x.setCoeff(8, x4);
  const Dense<G, S> xx(x * x.conjugate());
  c.checkNear("x x* = −x₁² + x₂² + x₃² in Cℓ(1,2,1) (x₄ null)", -x1 * x1 + x2 * x2 + x3 * x3,
              xx.scalarPart(), tol);
  c.checkResidual("… and x x* is a scalar", (xx - xx.scalarPart()).maxAbs(), tol);
}
SOMA_STUDY_SCALAR("GF-9.1-conjugation-involution", "Clifford conjugation c* and the main involution α", "GF §9.1",
           conjugationInvolution);

// ---- GF §9.1, GF-9.1-zero-divisor ------------------------------------------------------------
template <class S, class G> void zeroDivisorIn(Context& c, const std::string& name) {
  const auto e1 = gens<G, S>({0}), e2 = gens<G, S>({1}), e23 = gens<G, S>({1, 2}), e13 = gens<G, S>({0, 2});
  const Dense<G, S> a = e1 + e23, b = e2 + e13;
  c.checkResidual(name + ": (e₁ + e₂e₃)(e₂ + e₁e₃) = 0 exactly", (a * b).maxAbs(), S(0));
  int threw = 0;
  for (const auto* x : {&a, &b}) try {
      (void)inverse(*x);
    } catch (const InvalidInput&) {
      ++threw;
    }
  c.checkEqual(name + ": neither factor is invertible (inverse() throws InvalidInput)", 2, threw);
}
template <class S> void zeroDivisor(Context& c) {
  zeroDivisorIn<S, Signature<0, 3, 0>>(c, "Cℓ(0,3,0)");
  zeroDivisorIn<S, Signature<0, 4, 0>>(c, "Cℓ(0,4,0)");
  zeroDivisorIn<S, Signature<0, 5, 0>>(c, "Cℓ(0,5,0)");
  // Why: (e₁ + e₂e₃)² = e₁² + (e₂e₃)² + e₁e₂e₃ + e₂e₃e₁ = −2 + 2e₁e₂e₃, and e₁e₂e₃ squares to +1
  // in Cℓ(0,3,0), giving the idempotents ½(1 ± e₁e₂e₃).
  using G = Signature<0, 3, 0>;
  const auto I = gens<G, S>({0, 1, 2});
  c.checkResidual("(e₁e₂e₃)² = +1 in Cℓ(0,3,0): ½(1 ± e₁e₂e₃) are idempotents", maxAbsDiff(I * I, Dense<G, S>(S(1))), S(0));
  // A non-example: in ℍ = Cℓ(0,2,0) every nonzero element is invertible.
  using H = Signature<0, 2, 0>;
  const Dense<H, S> h = gens<H, S>({0}) + gens<H, S>({0, 1});
  c.checkResidual("in ℍ the analogue e₁ + e₁e₂ is invertible: h h⁻¹ = 1",
                  maxAbsDiff(h * inverse(h), Dense<H, S>(S(1))), Tolerance<S>::identity(16));
}
SOMA_STUDY_SCALAR("GF-9.1-zero-divisor", "A zero divisor in Cℓ(0,n,0), n ≥ 3", "GF §9.1", zeroDivisor);

// ---- GF §9.1, GF-9.1-pin-spin ----------------------------------------------------------------
template <class S> void pinSpin(Context& c) {
  auto g = rng(906);
  using G = Signature<0, 3, 0>;
  using V = Vector<G, S>;
  const S tol = Tolerance<S>::identity(64);
  auto vec = [](const Vec3<S>& x) {
    V v;
    for (int i = 0; i < 3; ++i) v.setCoeff(Blade(1) << i, x(i));
    return v;
  };
  auto coords = [](const auto& v) { return Vec3<S>(v.coeff(1), v.coeff(2), v.coeff(4)); };
  // Reflections: v unit (v v* = 1), α(v) v v* = −v, α(v) w v* = w for w ⊥ v.
  const Vec3<S> n = randUnit<S>(g);
  Vec3<S> w = randVec<S>(g);
  w -= w.dot(n) * n;
  const V v = vec(n);
  const Dense<G, S> vv(v * v.conjugate());
  c.checkResidual("unit vector: v v* = 1 (v v* = x₁² + x₂² + x₃² in Cℓ(0,3,0))", maxAbsDiff(vv, Dense<G, S>(S(1))), tol);
  c.checkResidual("α(v) v v* = −v", maxAbsDiff(Dense<G, S>(v.involute() * v * v.conjugate()), Dense<G, S>(-v)), tol);
  c.checkResidual("α(v) w v* = w for w ⊥ v",
                  maxAbsDiff(Dense<G, S>(v.involute() * vec(w) * v.conjugate()), Dense<G, S>(vec(w))), tol);
  // The action preserves x·y = ½(xy* + yx*): reflection of two random vectors.
  const Vec3<S> x = randVec<S>(g), y = randVec<S>(g);
  auto refl = [&](const Vec3<S>& p) { return coords(Dense<G, S>(v.involute() * vec(p) * v.conjugate())); };
  const Dense<G, S> dot(vec(x) * vec(y).conjugate() + vec(y) * vec(x).conjugate());
  c.checkNear("x·y = ½(xy* + yx*)", x.dot(y), dot.scalarPart() / S(2), tol);
  c.checkNear("… preserved by the reflection", x.dot(y), refl(x).dot(refl(y)), tol);
  c.checkResidual("… which is the matrix reflection I − 2nnᵀ",
                  (refl(x) - (x - S(2) * n.dot(x) * n)).cwiseAbs().maxCoeff(), tol);
  // Spin(3): rotation about e₃: (cos θ/2 + sin θ/2 e₁e₂) e₁ (cos θ/2 − sin θ/2 e₁e₂).
  const S th = S(9) / S(10);
  const Dense<G, S> rg = Dense<G, S>(S(cos(th / S(2)))) + gens<G, S>({0, 1}) * S(sin(th / S(2)));
  const Dense<G, S> rc = rg.conjugate();
  const Vec3<S> i1 = coords(Dense<G, S>(rg * gens<G, S>({0}) * rc)), i2 = coords(Dense<G, S>(rg * gens<G, S>({1}) * rc)),
                i3 = coords(Dense<G, S>(rg * gens<G, S>({2}) * rc));
  c.checkResidual("g e₁ g* = cos θ e₁ + sin θ e₂ (θ = 0.9)", (i1 - Vec3<S>(cos(th), sin(th), S(0))).cwiseAbs().maxCoeff(), tol);
  c.checkResidual("g e₂ g* = −sin θ e₁ + cos θ e₂", (i2 - Vec3<S>(-sin(th), cos(th), S(0))).cwiseAbs().maxCoeff(), tol);
  c.checkResidual("g e₃ g* = e₃", (i3 - Vec3<S>(S(0), S(0), S(1))).cwiseAbs().maxCoeff(), tol);
  // g = a₀ + a₁e₂e₃ + a₂e₃e₁ + a₃e₁e₂ with Σa² = 1 is the unit quaternion of the same rotation.
  const Vec3<S> ax = randUnit<S>(g);
  const S phi = uni<S>(g, 0, 3);
  const Quat<S> q(cos(phi / S(2)), sin(phi / S(2)) * ax(0), sin(phi / S(2)) * ax(1), sin(phi / S(2)) * ax(2));
  const Dense<G, S> gq = Dense<G, S>(S(q.w())) + gens<G, S>({1, 2}) * q.x() + gens<G, S>({2, 0}) * q.y() + gens<G, S>({0, 1}) * q.z();
  c.checkNear("Spin(3): g g* = a₀² + a₁² + a₂² + a₃² = 1", S(1), Dense<G, S>(gq * gq.conjugate()).scalarPart(), tol);
  c.checkResidual("g x g* = R(q) x (random axis, angle, x)",
                  (coords(Dense<G, S>(gq * vec(x) * gq.conjugate())) - q.toRotationMatrix() * x).cwiseAbs().maxCoeff(), tol);
  // Extremes: θ = π (g = e₁e₂ flips e₁, e₂) and θ = 2π (g = −1, acting as the identity: the
  // double cover; kernel {±1}).
  const auto e12 = gens<G, S>({0, 1});
  c.checkResidual("θ = π: g = e₁e₂ sends e₁ ↦ −e₁", maxAbsDiff(Dense<G, S>(e12 * gens<G, S>({0}) * e12.conjugate()), -gens<G, S>({0})), S(0));
  const Dense<G, S> g2pi = Dense<G, S>(S(cos(pi<S>()))) + e12 * S(sin(pi<S>()));
  c.checkNear("θ = 2π: g = cos π + sin π e₁e₂ = −1", S(-1), g2pi.scalarPart(), tol);
  c.checkResidual("… and −1 acts trivially: (−1) x (−1)* = x",
                  (coords(Dense<G, S>(g2pi * vec(x) * g2pi.conjugate())) - x).cwiseAbs().maxCoeff(), tol);
}
SOMA_STUDY_SCALAR("GF-9.1-pin-spin", "Pin(n), Spin(n): reflections and rotations, the double cover", "GF §9.1", pinSpin);

// ---- GF §9.1, GF-9.1-exterior-product --------------------------------------------------------
template <class S> void exteriorProduct(Context& c) {
  auto g = rng(907);
  using G = Signature<1, 2, 1>;
  const S tol = Tolerance<S>::identity(64);
  S left = 0, right = 0;
  for (int t = 0; t < 20; ++t) {
    Vector<G, S> x;
    Dense<G, S> cc;
    for (int i = 0; i < x.size; ++i) x[i] = uni<S>(g);
    for (int i = 0; i < cc.size; ++i) cc[i] = uni<S>(g);
    left = std::max(left, maxAbsDiff(Dense<G, S>(x ^ cc), Dense<G, S>(x * cc + cc.involute() * x) * S(0.5)));
    right = std::max(right, maxAbsDiff(Dense<G, S>(cc ^ x), Dense<G, S>(cc * x + x * cc.involute()) * S(0.5)));
  }
  c.checkResidual("x ∧ c = ½(xc + α(c)x), soma's metric-free ∧ (20 random, Cℓ(1,2,1))", left, tol);
  c.checkResidual("c ∧ x = ½(cx + xα(c))", right, tol);
  // e_i ∧ e_j = ½(e_ie_j − e_je_i) = e_ie_j − Q_ij for the generators x_i of a non-diagonal Q.
  FormMatrix<S> Q(3, 3);
  const auto r = [](int n, int d) { return S(n) / S(d); };
  Q << S(2), r(1, 2), r(-3, 10), r(1, 2), S(-1), r(1, 5), r(-3, 10), r(1, 5), r(3, 2);
  const FormBasis<Signature<2, 1, 0>, S> fb(Q);
  S wedge = 0, graded = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const auto xi = fb.generator(i), xj = fb.generator(j);
      const Dense<Signature<2, 1, 0>, S> w(xi ^ xj);
      wedge = std::max(wedge, maxAbsDiff(w, Dense<Signature<2, 1, 0>, S>(xi * xj - Q(i, j))));
      graded = std::max(graded, maxAbsDiff(w, Dense<Signature<2, 1, 0>, S>(xi * xj - xj * xi) * S(0.5)));
    }
  c.checkResidual("x_i ∧ x_j = x_ix_j − Q_ij for a non-diagonal Q (all 9 pairs)", wedge, tol);
  c.checkResidual("x_i ∧ x_j = ½(x_ix_j − x_jx_i)", graded, tol);
  // Typos: "x_i ∧ x_j + x_i ∧ x_i = 0" is x_i ∧ x_j + x_j ∧ x_i = 0; "e_i ∧ e_i = e_ie_i" is
  // e_i ∧ e_j = e_ie_j (i ≠ j). The printed forms fail: x_i ∧ x_i = 0 so the first reads
  // x_i ∧ x_j = 0; e_i ∧ e_i = 0 ≠ e_ie_i = ±1.
  using E = Signature<0, 3, 0>;
  const auto e1 = Vector<E, S>::generator(0), e2 = Vector<E, S>::generator(1);
  c.checkPrintedFails("x₁ ∧ x₂ + x₁ ∧ x₁ = 0", "minor 5504", Dense<E, S>((e1 ^ e2) + (e1 ^ e1)).maxAbs(), tol);
  c.checkResidual("corrected: x₁ ∧ x₂ + x₂ ∧ x₁ = 0", Dense<E, S>((e1 ^ e2) + (e2 ^ e1)).maxAbs(), S(0));
  c.checkPrintedFails("e₁ ∧ e₁ = e₁e₁", "minor 5522", maxAbsDiff(Dense<E, S>(e1 ^ e1), Dense<E, S>(e1 * e1)), tol);
  c.checkResidual("corrected: e₁ ∧ e₂ = e₁e₂", maxAbsDiff(Dense<E, S>(e1 ^ e2), Dense<E, S>(e1 * e2)), S(0));
  // Ad(R) = ∧²R: the rotor action on bivectors is the second compound of the 3×3 rotation.
  const Vec3<S> ax = randUnit<S>(g);
  const S phi = S(11) / S(10);
  const Quat<S> q(cos(phi / S(2)), sin(phi / S(2)) * ax(0), sin(phi / S(2)) * ax(1), sin(phi / S(2)) * ax(2));
  const Mat3<S> R = q.toRotationMatrix();
  const Dense<E, S> rg = Dense<E, S>(S(q.w())) + gens<E, S>({1, 2}) * q.x() + gens<E, S>({2, 0}) * q.y() + gens<E, S>({0, 1}) * q.z();
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  S compound = 0;
  for (int a = 0; a < 3; ++a) {
    const Dense<E, S> img(rg * gens<E, S>({pairs[a][0], pairs[a][1]}) * rg.conjugate());
    for (int b = 0; b < 3; ++b) {
      const int i = pairs[b][0], j = pairs[b][1], k = pairs[a][0], l = pairs[a][1];
      const S minor = R(i, k) * R(j, l) - R(i, l) * R(j, k);  // (∧²R) entry
      compound = std::max(compound, abs(img.coeff(Blade((1 << i) | (1 << j))) - minor));
    }
  }
  c.checkResidual("g (e_k ∧ e_l) g* = Σ (∧²R)_{ij,kl} e_i ∧ e_j: Ad(R) = ∧²R", compound, tol);
  // The Lie algebra span{½e_ie_j}: [½e_ie_j, ½e_ke_l] = ¼(e_ie_je_ke_l − e_ke_le_ie_j) closes on
  // bivectors, with the structure constants of so(3).
  const Dense<E, S> A = gens<E, S>({1, 2}) * S(0.5), B = gens<E, S>({2, 0}) * S(0.5), C = gens<E, S>({0, 1}) * S(0.5);
  c.checkResidual("[½e₂e₃, ½e₃e₁] = ½e₁e₂ (so(3) structure [i/2, j/2] = k/2, closes on bivectors)",
                  maxAbsDiff(Dense<E, S>(A * B - B * A), Dense<E, S>(C)), S(0));
  c.note("Typos (catalogue, minor): line 5504 prints x_i∧x_j + x_i∧x_i = 0, line 5522 prints "
         "e_i∧e_i = e_ie_i; both shown failing as printed and passing corrected.");
}
SOMA_STUDY_SCALAR("GF-9.1-exterior-product", "The exterior product inside the Clifford algebra", "GF §9.1", exteriorProduct);

}  // namespace
}  // namespace soma::studies::gf09::SOMA_UNITY_ID
