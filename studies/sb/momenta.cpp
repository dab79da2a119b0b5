// Studies of Selig & Bayro-Corrochano (2010) §5: co-screws and the bar involution, Q0, the
// inertia elements, the momentum A ∨ (N ∧ s), covariance of ∧ and ∨, the inertia transformation and
// SB's translated example, kinetic energy. Independent references as in sb/screws_cl031_shuffle.cpp.
// Every study runs in the scalar asked for (--scalar); SB's values (d = (1.3, 0.7, 2.1), m = 3,
// t_x = 0.8) are exact fractions in S. Thresholds are k ε of S for unit-scale data, k from the length
// of the sums (a dense Cl(0,6,2) product sums 256 terms per coefficient).
#include "sb/common.hpp"

#include "soma/algebra/clifford/multivector.hpp"
#include "soma/algebra/small_linalg.hpp"

namespace soma::studies::sb::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {
using namespace soma::clifford_dynamics;

/// SB's diagonal body: d = (1.3, 0.7, 2.1), m = 3, as S rounds them.
template <class S> Vec3<S> sbD() { return Vec3<S>(frac<S>(13, 10), frac<S>(7, 10), frac<S>(21, 10)); }

// ---------------------------------------------------------------- §5: co-screws, Q0, inertias
template <class S> void coScrewBar(Context& c) {
  auto g = rng(501);
  S eAuto = 0, eInv = 0, eAct = 0, gOnly = 0;
  for (int k = 0; k < 20; ++k) {
    D<S> x, y;
    for (int i = 0; i < x.size; ++i) x[i] = uni<S>(g), y[i] = uni<S>(g);
    eAuto = maxOf(eAuto, mx(D<S>(bar(D<S>(x * y)) - D<S>(bar(x) * bar(y)))));
    eInv = maxOf(eInv, mx(D<S>(bar(bar(x)) - x)));
    const SE3<S> m = randMotion<S>(g);
    const V6<S> P = rv6<S>(g);
    const Ev<S> gm = motorElement(m);
    eAct = maxOf(eAct, mxm(V6<S>(coScrewOf(actCoScrew(gm, coScrewElement(P))) - coadjointAct(m, P))));
    const Biv<S> Pe = coScrewElement(P);
    const S miss = mxm(V6<S>(coScrewOf(actScrew(gm, Pe)) - coadjointAct(m, P)));
    gOnly = k == 0 ? miss : minOf(gOnly, miss);
  }
  // a dense product sums 256 products per coefficient: 256 ε (5.7e-14 in double; 1e-13 before)
  c.checkResidual("bar is an automorphism: (xy)‾ = x̄ ȳ (20 random dense pairs, 256 ε)", eAuto, tol<S>(256));
  c.checkResidual("bar is an involution", eInv, S(0));
  c.checkResidual("ḡ P ḡ* = H^{-T} P (20 motions, 32 ε)", eAct, tol<S>(32));
  c.checkPrintedFails("P → q̄ P q̄* read with g for ḡ: g P g* leaves P unchanged, so it is not H^{-T}P (smallest miss)", "2",
                      gOnly, tol<S>(32));
  c.note("Erratum 2 (OCR): the printed action P → q̄ P q̄* and N → (q q̄) N (q q̄)* mean g (the motor).");
}

template <class S> void q0Evaluation(Context& c) {
  auto g = rng(502);
  S e1_ = 0, e2_ = 0, e3_ = 0;
  const Quad<S> Q0 = elementQ0<S>();
  const D<S> E = word<S>({e1, e2, e3, e});
  for (int k = 0; k < 50; ++k) {
    const T6<S> s(rv6<S>(g));
    const V6<S> P = rv6<S>(g);
    const Biv<S> Se = screwElement(s), Pe = coScrewElement(P);
    const S ref = P.dot(s.coeffs());  // ω·l + v·p
    using std::abs;
    e1_ = maxOf(e1_, S(abs(shuffle(Pe, clifford::outer(Q0, Se)).scalarPart() - ref)));
    e2_ = maxOf(e2_, S(abs(shuffle(clifford::outer(Pe, Q0), Se).scalarPart() - ref)));
    const D<S> printed = D<S>(D<S>(word<S>({a2, a3}, s.ang().x()) + word<S>({a3, a1}, s.ang().y()) + word<S>({a1, a2}, s.ang().z()) +
                                   word<S>({a1, a}, s.lin().x()) + word<S>({a2, a}, s.lin().y()) + word<S>({a3, a}, s.lin().z())) *
                              E);
    e3_ = maxOf(e3_, mx(D<S>(D<S>(clifford::outer(Q0, Se)) - printed)));
  }
  // six-term dot products of unit-scale numbers: 16 ε (3.6e-15; 1e-14 before); Q0 ∧ s places the
  // coefficients with signs: 4 ε (1e-15 before)
  c.checkResidual("P ∨ (Q0 ∧ s) = ω·l + v·p (50 pairs, 16 ε)", e1_, tol<S>(16));
  c.checkResidual("(P ∧ Q0) ∨ s = ω·l + v·p (16 ε)", e2_, tol<S>(16));
  c.checkResidual("Q0 ∧ s = (ω_x a₂a₃ + … + v_z a₃a) e₁e₂e₃e (4 ε)", e3_, tol<S>(4));
}

template <class S> void q0Invariance(Context& c) {
  auto g = rng(503);
  S eInv = 0, gMin = 0, gbMin = 0;
  const Quad<S> Q0 = elementQ0<S>();
  for (int k = 0; k < 20; ++k) {
    const Ev<S> gm = motorElement(randMotion<S>(g)), gb = bar(gm), G = Ev<S>(gm * gb);
    eInv = maxOf(eInv, mx(D<S>(D<S>(G * Q0 * G.conjugate()) - D<S>(Q0))));
    const S dg = mx(D<S>(D<S>(gm * Q0 * gm.conjugate()) - D<S>(Q0)));
    const S dgb = mx(D<S>(D<S>(gb * Q0 * gb.conjugate()) - D<S>(Q0)));
    gMin = k == 0 ? dg : minOf(gMin, dg);
    gbMin = k == 0 ? dgb : minOf(gbMin, dgb);
  }
  // two sandwich products of unit motors: 32 ε (7.1e-15; 1e-14 before). The ≠ claims: the smallest
  // difference exceeds 1000 × that bound.
  const S bound = tol<S>(32), far = S(1000) * bound;
  c.checkResidual("(g ḡ) Q0 (g ḡ)* = Q0 (20 motions, 32 ε)", eInv, bound);
  c.recordIn("g Q0 g* ≠ Q0 (smallest |difference| > 1000 × 32 ε)", "≠ 0", toString(toDouble(gMin), 3), gMin, far, gMin > far);
  c.recordIn("ḡ Q0 ḡ* ≠ Q0 (smallest |difference| > 1000 × 32 ε)", "≠ 0", toString(toDouble(gbMin), 3), gbMin, far, gbMin > far);
  M6<S> klein = M6<S>::Zero();
  klein.template topRightCorner<3, 3>().setIdentity();
  klein.template bottomLeftCorner<3, 3>().setIdentity();
  c.checkResidual("Q0 is the Klein form: its 6×6 matrix is [[0, I], [I, 0]]", mxm(M6<S>(formMatrix(elementQ0<S>()) - klein)), S(0));
}

template <class S> void diagonalInertia(Context& c) {
  const Vec3<S> d = sbD<S>();
  const S m = 3;
  const D<S> printed = printedDiagonalInertia<S>(d.x(), d.y(), d.z(), m);
  const Quad<S> N = inertiaElement(SpatialInertia<S>::diagonal(m, d).matrix());
  c.checkResidual("SB's printed N = soma's inertia element of diag(d_x, d_y, d_z, m, m, m)", mx(D<S>(printed - D<S>(N))), S(0));
  c.checkResidual("N is pure grade 4", mx(D<S>(printed - D<S>(printed.gradeProject(4)))), S(0));
  M6<S> diag = M6<S>::Zero();
  diag.diagonal() << d.x(), d.y(), d.z(), m, m, m;
  c.checkResidual("s ↦ A ∨ (N ∧ s) has matrix diag(d, m)", mxm(M6<S>(formMatrix(N) - diag)), S(0));
  c.note("d_i = m k_i² (k_i the radius of gyration about principal axis i).");
}

template <class S> void momentumA(Context& c) {
  const Vec3<S> d = sbD<S>();
  const S dx = d.x(), dy = d.y(), dz = d.z(), m = 3;
  const Quad<S> N = inertiaElement(SpatialInertia<S>::diagonal(m, d).matrix());
  auto g = rng(504);
  S eP = 0, printedMin = 0, eA = 0;
  const D<S> A = word<S>({a1, a2, a3, a});
  for (int k = 0; k < 20; ++k) {
    const T6<S> s(rv6<S>(g));
    const Vec3<S> w = s.ang(), v = s.lin();
    const D<S> P = D<S>(momentum(N, screwElement(s)));
    const D<S> expect = D<S>(word<S>({a2, a3}, m * v.x()) + word<S>({a3, a1}, m * v.y()) + word<S>({a1, a2}, m * v.z()) +
                             word<S>({a1, a}, dx * w.x()) + word<S>({a2, a}, dy * w.y()) + word<S>({a3, a}, dz * w.z()));
    eP = maxOf(eP, mx(D<S>(P - expect)));
    const D<S> printed = D<S>(word<S>({a2, a3}, m * v.x()) + word<S>({a3, a1}, m * v.y()) + word<S>({a1, a2}, m * v.z()) +
                              word<S>({a1, a1}, dx * w.x()) + word<S>({a2, a2}, dy * w.y()) + word<S>({a3, a1}, dz * w.z()));
    const S miss = mx(D<S>(P - printed));
    printedMin = k == 0 ? miss : minOf(printedMin, miss);
    const Ev<S> gm = motorElement(randMotion<S>(g)), gb = bar(gm);
    eA = maxOf(eA, S(mx(D<S>(D<S>(gm * A * gm.conjugate()) - A)) + mx(D<S>(D<S>(gb * A * gb.conjugate()) - A))));
  }
  // one product per coefficient (m v_x, d_x ω_x): 4 ε (1e-15 before); sandwiches: 32 ε (1e-14 before)
  c.checkResidual("A ∨ (N ∧ s) = m v·(a₂a₃, a₃a₁, a₁a₂) + d_x ω_x a₁a + d_y ω_y a₂a + d_z ω_z a₃a (4 ε)", eP, tol<S>(4));
  c.checkPrintedFails("A ∨ (N ∧ s) with a₁a₁, a₂a₂, a₃a₁ on the angular terms (smallest miss)", "1", printedMin, tol<S>(4));
  c.checkResidual("A = g A g* = ḡ A ḡ* (20 motions, 32 ε)", eA, tol<S>(32));
}

template <class S> void covariance(Context& c) {
  auto g = rng(505);
  S eW = 0, eS = 0, eDet = 0, eVec = 0;
  using Vc = clifford::Vector<Sig, S>;
  for (int k = 0; k < 10; ++k) {
    const Ev<S> gm = motorElement(randMotion<S>(g));
    const Ev<S> h = Ev<S>(gm * bar(gm));
    D<S> x, y;
    for (int i = 0; i < x.size; ++i) x[i] = uni<S>(g), y[i] = uni<S>(g);
    const auto sand = [&](const D<S>& z) { return D<S>(D<S>(h * z) * h.conjugate()); };
    eW = maxOf(eW, mx(D<S>(sand(D<S>(clifford::outer(x, y))) - D<S>(clifford::outer(sand(x), sand(y))))));
    eS = maxOf(eS, mx(D<S>(sand(D<S>(shuffle(x, y))) - D<S>(shuffle(sand(x), sand(y))))));
    // x ↦ h x h* on vectors: a linear map with det 1 (the lemma), and it maps vectors to vectors
    detail::SmallMat<S> Mv(8, 8);
    for (int j = 0; j < 8; ++j) {
      const D<S> im = sand(D<S>(Vc::generator(j)));
      eVec = maxOf(eVec, mx(D<S>(im - D<S>(im.gradeProject(1)))));
      for (int i = 0; i < 8; ++i) Mv(i, j) = im.coeff(Blade(1) << i);
    }
    using std::abs;
    eDet = maxOf(eDet, S(abs(detail::smallDeterminant<S>(Mv) - S(1))));
  }
  // dense ∧ and ∨ of 256-coefficient elements, sandwiched twice: 1024 ε (2.3e-13; 1e-12 before);
  // the vector images: 32 ε (1e-14 before); the 8×8 LU determinant: 256 ε (5.7e-14; 1e-13 before)
  c.checkResidual("h (x ∧ y) h* = (h x h*) ∧ (h y h*), h = g ḡ (10 motions, random dense x, y; 1024 ε)", eW, tol<S>(1024));
  c.checkResidual("h (x ∨ y) h* = (h x h*) ∨ (h y h*) (1024 ε)", eS, tol<S>(1024));
  c.checkResidual("h x h* is a vector for every vector x (32 ε)", eVec, tol<S>(32));
  c.checkResidual("det of x ↦ h x h* on vectors = 1 (SB's lemma; 8×8 LU, 256 ε)", eDet, tol<S>(256));
  c.note("Erratum 7 (rigor gap): SB argues with 'the matrices representing h and h*' on vectors, but h x alone "
         "is not a vector; the map x ↦ h x h* is linear on vectors and has det 1, measured above.");
}

template <class S> void inertiaTransformation(Context& c) {
  auto g = rng(506);
  S eMat = 0, eDeriv = 0, eAlt = 0;
  for (int k = 0; k < 30; ++k) {
    const SpatialInertia<S> b = randBody<S>(g);
    const SE3<S> x = randMotion<S>(g);
    const Ev<S> gm = motorElement(x), gb = bar(gm), G = Ev<S>(gm * gb);
    const Quad<S> N = inertiaElement(b.matrix());
    const Quad<S> Nm = actInertia(gm, N);
    const M6<S> Hi = x.inverse().adjoint();
    // relative to (1 + |t|)² ‖N‖: the translation enters H^{-1} and H^{-T} once each
    const S t1 = S(1) + x.translation().norm();
    eMat = maxOf(eMat, S(mxm(M6<S>(formMatrix(Nm) - Hi.transpose() * b.matrix() * Hi)) / (t1 * t1 * mxm(b.matrix()))));
    // SB's derivation: ḡ P ḡ* = A ∨ ((gḡ) N (gḡ)* ∧ g s g*)
    const Biv<S> s = screwElement(T6<S>(rv6<S>(g)));
    const Biv<S> lhs = actCoScrew(gm, momentum(N, s));
    eDeriv = maxOf(eDeriv, mx(Biv<S>(lhs - momentum(Nm, actScrew(gm, s)))));
    // the same law for screws: (gḡ) s (gḡ)* = g s g*
    eAlt = maxOf(eAlt, mx(Biv<S>(((G * s) * G.conjugate()).template grade<2>() - actScrew(gm, s))));
  }
  // 6×6 triple products against sandwiches of |t| ≤ 2√3 motors: 32 ε of (1 + |t|)² ‖N‖ (7.1e-15; 1e-14 before),
  // the momenta (two sandwiches and a shuffle, unscaled): 256 ε (5.7e-14; 1e-13 before), 32 ε (1e-14 before)
  c.checkResidual("s ↦ A ∨ ((gḡ)N(gḡ)* ∧ s) has matrix H^{-T} N H^{-1} (30 bodies, relative to (1+|t|)² ‖N‖, 32 ε)", eMat, tol<S>(32));
  c.checkResidual("ḡ P ḡ* = A ∨ ((gḡ)N(gḡ)* ∧ g s g*) (256 ε)", eDeriv, tol<S>(256));
  c.checkResidual("(gḡ) s (gḡ)* = g s g* (ḡ commutes with screws; 32 ε)", eAlt, tol<S>(32));
}

template <class S> void translatedExample(Context& c) {
  const Vec3<S> d = sbD<S>();
  const S dx = d.x(), dy = d.y(), dz = d.z(), m = 3, tx = frac<S>(4, 5);
  const Ev<S> gt = toEven(D<S>(word<S>({}, S(1)) + word<S>({e1, e}, tx / 2)));
  const Ev<S> G = Ev<S>(gt * bar(gt));
  const D<S> Gprinted = D<S>(word<S>({}, S(1)) + word<S>({a1, a}, tx / 2) + word<S>({e1, e}, tx / 2) +
                             word<S>({a1, a, e1, e}, tx * tx / 4));
  // products of 1 and t_x/2 (t_x²/4 rounds once): 1 ε (1e-16 before)
  c.checkResidual("g ḡ = 1 + ½t_x a₁a + ½t_x e₁e + ¼t_x² a₁ae₁e (t_x = 0.8; 1 ε)", mx(D<S>(D<S>(G) - Gprinted)), tol<S>(1));
  const Quad<S> N = actInertia(gt, inertiaElement(SpatialInertia<S>::diagonal(m, d).matrix()));
  const D<S> printed = D<S>(word<S>({a1, a, e1, e}, dx) + word<S>({a2, a, e2, e}, dy + m * tx * tx) +
                            word<S>({a3, a, e3, e}, dz + m * tx * tx) + word<S>({a3, a, e3, e1}, m * tx) +
                            word<S>({a2, a, e1, e2}, -m * tx) + word<S>({a3, a1, e3, e}, m * tx) +
                            word<S>({a1, a2, e2, e}, -m * tx) + word<S>({a2, a3, e2, e3}, m) + word<S>({a3, a1, e3, e1}, m) +
                            word<S>({a1, a2, e1, e2}, m));
  // entries up to d + m t_x² ≈ 4, each a few roundings: 4 ε (8.9e-16; 1e-15 before)
  c.checkResidual("g ḡ N ḡ* g* = SB's printed expansion, term by term (4 ε)", mx(D<S>(D<S>(N) - printed)), tol<S>(4));
  M6<S> P6;
  P6 << dx, 0, 0, 0, 0, 0, 0, dy + m * tx * tx, 0, 0, 0, -m * tx, 0, 0, dz + m * tx * tx, 0, m * tx, 0, 0, 0, 0, m, 0, 0,
      0, 0, m * tx, 0, m, 0, 0, -m * tx, 0, 0, 0, m;
  c.checkResidual("its action s ↦ A ∨ (N ∧ s) is the printed 6×6 matrix (4 ε)", mxm(M6<S>(formMatrix(N) - P6)), tol<S>(4));
  const SE3<S> x(SO3<S>::Identity(), Vec3<S>(tx, 0, 0));
  c.checkResidual("= the skew-axis theorem H^{-T} N H^{-1} (GF §13.1) = the direct parallel-axis move (4 ε)",
                  mxm(M6<S>(SpatialInertia<S>::diagonal(m, d).transformed(x).matrix() - P6)), tol<S>(4));
  const D<S> flipped = D<S>(printed - word<S>({a3, a, e3, e1}, 2 * m * tx));
  const S miss = mx(D<S>(D<S>(N) - flipped));
  const S far = S(1000) * tol<S>(4);
  c.recordIn("negative control: one printed term with its sign flipped is detected (miss > 1000 × 4 ε)", "fails",
             toString(toDouble(miss), 3), miss, far, miss > far);
}

template <class S> void kineticEnergyStudy(Context& c) {
  auto g = rng(507);
  S eBar = 0, eEk = 0, eEk2 = 0;
  const Quad<S> Q0 = elementQ0<S>();
  const Quad<S> A = elementA<S>();
  using std::abs;
  for (int k = 0; k < 30; ++k) {
    const SpatialInertia<S> b = randBody<S>(g);
    const Quad<S> N = inertiaElement(b.matrix());
    const T6<S> s(rv6<S>(g));
    const Biv<S> se = screwElement(s);
    eBar = maxOf(eBar, mx(Biv<S>(shuffle(A, clifford::outer(Q0, se)) - bar(se))));
    eEk = maxOf(eEk, S(abs(kineticEnergy(N, se) - b.kineticEnergy(s))));
    eEk2 = maxOf(eEk2, S(abs(pairing(momentum(N, se), se) / 2 - b.kineticEnergy(s))));
  }
  // s̄ is a signed copy: 4 ε (1e-15 before); ½ sᵀ N s of a body with |N| ≲ 10 (the inertia about the
  // origin, c ∈ [−1, 1]³): 256 ε (5.7e-14; 1e-13 before)
  c.checkResidual("A ∨ (Q0 ∧ s) = s̄ (30 draws, 4 ε)", eBar, tol<S>(4));
  c.checkResidual("½ s̄ ∨ (N ∧ s) = ½ sᵀ N s (general inertias, 256 ε)", eEk, tol<S>(256));
  c.checkResidual("½ P ∨ (Q0 ∧ s) with P = A ∨ (N ∧ s) gives the same (256 ε)", eEk2, tol<S>(256));
  const Vec3<S> d = sbD<S>();
  const S m = 3;
  const Vec3<S> w(frac<S>(3, 10), frac<S>(-11, 10), frac<S>(2, 5)), v(frac<S>(9, 10), frac<S>(1, 5), frac<S>(-1, 2));
  const Quad<S> Nd = inertiaElement(SpatialInertia<S>::diagonal(m, d).matrix());
  // a sum of six products, E ≈ 2.3: 4 ε absolute (8.9e-16; 1e-15 before)
  c.checkNear("diagonal body: ½ s̄ ∨ (N ∧ s) = ½(Σ d_i ω_i² + m|v|²) (4 ε)",
              S((d.x() * w.x() * w.x() + d.y() * w.y() * w.y() + d.z() * w.z() * w.z() + m * v.squaredNorm()) / 2),
              kineticEnergy(Nd, screwElement(T6<S>(w, v))), tol<S>(4));
}

}  // namespace

SOMA_STUDY_SCALAR("SB-5-coscrew-element-bar-involution", "Co-screws as a-bivectors; the bar involution; ḡ P ḡ*", "SB §5", coScrewBar);
SOMA_STUDY_SCALAR("SB-5-Q0-evaluation", "P(s) = P ∨ (Q0 ∧ s) = (P ∧ Q0) ∨ s", "SB §5", q0Evaluation);
SOMA_STUDY_SCALAR("SB-5-Q0-invariance", "Q0 invariant under g ḡ, not under g or ḡ alone", "SB §5", q0Invariance);
SOMA_STUDY_SCALAR("SB-5-diagonal-inertia-element", "The diagonal inertia as a grade-4 element", "SB §5", diagonalInertia);
SOMA_STUDY_SCALAR("SB-5-momentum-A-shuffle", "P = A ∨ (N ∧ s); A invariant", "SB §5", momentumA);
SOMA_STUDY_SCALAR("SB-5-wedge-shuffle-covariance", "h(a∧b)h* and h(a∨b)h* covariance; det lemma", "SB §5", covariance);
SOMA_STUDY_SCALAR("SB-5-inertia-transformation", "N → (gḡ) N (gḡ)* equals H^{-T} N H^{-1}", "SB §5", inertiaTransformation);
SOMA_STUDY_SCALAR("SB-5-translated-inertia-example", "Diagonal inertia translated by t_x (printed expansion and matrix)", "SB §5", translatedExample);
SOMA_STUDY_SCALAR("SB-5-kinetic-energy", "E_k = ½ s̄ ∨ (N ∧ s)", "SB §5", kineticEnergyStudy);

}  // namespace soma::studies::sb::SOMA_UNITY_ID
