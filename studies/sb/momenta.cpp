// Studies of Selig & Bayro-Corrochano (2010) §5: co-screws and the bar involution, Q0, the
// inertia elements, the momentum A ∨ (N ∧ s), covariance of ∧ and ∨, the inertia transformation and
// SB's translated example, kinetic energy. Independent references as in sb/screws_cl031_shuffle.cpp.
#include "sb/common.hpp"

#include "soma/algebra/clifford/multivector.hpp"

namespace soma::studies::sb::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {
using namespace soma::clifford_dynamics;

// ---------------------------------------------------------------- §5: co-screws, Q0, inertias
void coScrewBar(Context& c) {
  auto g = rng(501);
  double eAuto = 0, eInv = 0, eAct = 0, gOnly = 1e300;
  for (int k = 0; k < 20; ++k) {
    D x, y;
    for (int i = 0; i < x.size; ++i) x[i] = uni(g), y[i] = uni(g);
    eAuto = std::max(eAuto, mx(D(bar(D(x * y)) - D(bar(x) * bar(y)))));
    eInv = std::max(eInv, mx(D(bar(bar(x)) - x)));
    const SE3<double> m = randMotion(g);
    const V6 P = randV6(g);
    const Ev gm = motorElement(m);
    eAct = std::max(eAct, mxm(V6(coScrewOf(actCoScrew(gm, coScrewElement(P))) - coadjointAct(m, P))));
    const Biv Pe = coScrewElement(P);
    gOnly = std::min(gOnly, mxm(V6(coScrewOf(actScrew(gm, Pe)) - coadjointAct(m, P))));
  }
  c.checkResidual("bar is an automorphism: (xy)‾ = x̄ ȳ (20 random dense pairs)", eAuto, 1e-13);
  c.checkResidual("bar is an involution", eInv, 0.0);
  c.checkResidual("ḡ P ḡ* = H^{-T} P (20 motions)", eAct, 1e-14);
  c.record("g P g* (g instead of ḡ) leaves P unchanged, so it is not H^{-T}P (smallest miss)", "fails",
           std::to_string(gOnly), gOnly, 1e-6, gOnly > 1e-6);
  c.note("Erratum 2 (OCR): the printed action P → q̄ P q̄* and N → (q q̄) N (q q̄)* mean g (the motor).");
}

void q0Evaluation(Context& c) {
  auto g = rng(502);
  double e1_ = 0, e2_ = 0, e3_ = 0;
  const Quad Q0 = elementQ0<double>();
  const D E = word({e1, e2, e3, e});
  for (int k = 0; k < 50; ++k) {
    const T6 s(randV6(g));
    const V6 P = randV6(g);
    const Biv Se = screwElement(s), Pe = coScrewElement(P);
    const double ref = P.dot(s.coeffs());  // ω·l + v·p
    e1_ = std::max(e1_, std::abs(shuffle(Pe, clifford::outer(Q0, Se)).scalarPart() - ref));
    e2_ = std::max(e2_, std::abs(shuffle(clifford::outer(Pe, Q0), Se).scalarPart() - ref));
    const D printed = D(D(word({a2, a3}, s.ang().x()) + word({a3, a1}, s.ang().y()) + word({a1, a2}, s.ang().z()) +
                          word({a1, a}, s.lin().x()) + word({a2, a}, s.lin().y()) + word({a3, a}, s.lin().z())) * E);
    e3_ = std::max(e3_, mx(D(D(clifford::outer(Q0, Se)) - printed)));
  }
  c.checkResidual("P ∨ (Q0 ∧ s) = ω·l + v·p (50 pairs)", e1_, 1e-14);
  c.checkResidual("(P ∧ Q0) ∨ s = ω·l + v·p", e2_, 1e-14);
  c.checkResidual("Q0 ∧ s = (ω_x a₂a₃ + … + v_z a₃a) e₁e₂e₃e", e3_, 1e-15);
}

void q0Invariance(Context& c) {
  auto g = rng(503);
  double eInv = 0, gMin = 1e300, gbMin = 1e300;
  const Quad Q0 = elementQ0<double>();
  for (int k = 0; k < 20; ++k) {
    const Ev gm = motorElement(randMotion(g)), gb = bar(gm), G = Ev(gm * gb);
    eInv = std::max(eInv, mx(D(D(G * Q0 * G.conjugate()) - D(Q0))));
    gMin = std::min(gMin, mx(D(D(gm * Q0 * gm.conjugate()) - D(Q0))));
    gbMin = std::min(gbMin, mx(D(D(gb * Q0 * gb.conjugate()) - D(Q0))));
  }
  c.checkResidual("(g ḡ) Q0 (g ḡ)* = Q0 (20 motions)", eInv, 1e-14);
  c.record("g Q0 g* ≠ Q0 (smallest |difference|)", "≠ 0", std::to_string(gMin), gMin, 1e-6, gMin > 1e-6);
  c.record("ḡ Q0 ḡ* ≠ Q0 (smallest |difference|)", "≠ 0", std::to_string(gbMin), gbMin, 1e-6, gbMin > 1e-6);
  c.checkResidual("Q0 is the Klein form: its 6×6 matrix is [[0, I], [I, 0]]",
                  mxm(M6(formMatrix(elementQ0<double>()) - (M6() << Mat3<double>::Zero(), Mat3<double>::Identity(),
                                                             Mat3<double>::Identity(), Mat3<double>::Zero()).finished())), 0.0);
}

void diagonalInertia(Context& c) {
  const double dx = 1.3, dy = 0.7, dz = 2.1, m = 3;
  const D printed = printedDiagonalInertia(dx, dy, dz, m);
  const Quad N = inertiaElement(SpatialInertia<double>::diagonal(m, Vec3<double>(dx, dy, dz)).matrix());
  c.checkResidual("SB's printed N = soma's inertia element of diag(d_x, d_y, d_z, m, m, m)", mx(D(printed - D(N))), 0.0);
  c.checkResidual("N is pure grade 4", mx(D(printed - D(printed.gradeProject(4)))), 0.0);
  M6 diag = M6::Zero();
  diag.diagonal() << dx, dy, dz, m, m, m;
  c.checkResidual("s ↦ A ∨ (N ∧ s) has matrix diag(d, m)", mxm(M6(formMatrix(N) - diag)), 0.0);
  c.note("d_i = m k_i² (k_i the radius of gyration about principal axis i).");
}

void momentumA(Context& c) {
  const double dx = 1.3, dy = 0.7, dz = 2.1, m = 3;
  const Quad N = inertiaElement(SpatialInertia<double>::diagonal(m, Vec3<double>(dx, dy, dz)).matrix());
  auto g = rng(504);
  double eP = 0, printedMin = 1e300, eA = 0;
  const D A = word({a1, a2, a3, a});
  for (int k = 0; k < 20; ++k) {
    const T6 s(randV6(g));
    const Vec3<double> w = s.ang(), v = s.lin();
    const D P = D(momentum(N, screwElement(s)));
    const D expect = D(word({a2, a3}, m * v.x()) + word({a3, a1}, m * v.y()) + word({a1, a2}, m * v.z()) +
                       word({a1, a}, dx * w.x()) + word({a2, a}, dy * w.y()) + word({a3, a}, dz * w.z()));
    eP = std::max(eP, mx(D(P - expect)));
    const D printed = D(word({a2, a3}, m * v.x()) + word({a3, a1}, m * v.y()) + word({a1, a2}, m * v.z()) +
                        word({a1, a1}, dx * w.x()) + word({a2, a2}, dy * w.y()) + word({a3, a1}, dz * w.z()));
    printedMin = std::min(printedMin, mx(D(P - printed)));
    const Ev gm = motorElement(randMotion(g)), gb = bar(gm);
    eA = std::max(eA, mx(D(D(gm * A * gm.conjugate()) - A)) + mx(D(D(gb * A * gb.conjugate()) - A)));
  }
  c.checkResidual("A ∨ (N ∧ s) = m v·(a₂a₃, a₃a₁, a₁a₂) + d_x ω_x a₁a + d_y ω_y a₂a + d_z ω_z a₃a", eP, 1e-15);
  c.record("as printed (a₁a₁, a₂a₂, a₃a₁ on the angular terms) it fails (smallest miss, erratum 1)", "fails",
           std::to_string(printedMin), printedMin, 1e-6, printedMin > 1e-6);
  c.checkResidual("A = g A g* = ḡ A ḡ* (20 motions)", eA, 1e-14);
}

void covariance(Context& c) {
  auto g = rng(505);
  double eW = 0, eS = 0, eDet = 0, eVec = 0;
  using Vc = clifford::Vector<Sig, double>;
  for (int k = 0; k < 10; ++k) {
    const Ev gm = motorElement(randMotion(g));
    const Ev h = Ev(gm * bar(gm));
    D x, y;
    for (int i = 0; i < x.size; ++i) x[i] = uni(g), y[i] = uni(g);
    const auto sand = [&](const D& z) { return D(D(h * z) * h.conjugate()); };
    eW = std::max(eW, mx(D(sand(D(clifford::outer(x, y))) - D(clifford::outer(sand(x), sand(y))))));
    eS = std::max(eS, mx(D(sand(D(shuffle(x, y))) - D(shuffle(sand(x), sand(y))))));
    // x ↦ h x h* on vectors: a linear map with det 1 (the lemma), and it maps vectors to vectors
    Eigen::Matrix<double, 8, 8> Mv;
    for (int j = 0; j < 8; ++j) {
      const D im = sand(D(Vc::generator(j)));
      eVec = std::max(eVec, mx(D(im - D(im.gradeProject(1)))));
      for (int i = 0; i < 8; ++i) Mv(i, j) = im.coeff(Blade(1) << i);
    }
    eDet = std::max(eDet, std::abs(Mv.determinant() - 1));
  }
  c.checkResidual("h (x ∧ y) h* = (h x h*) ∧ (h y h*), h = g ḡ (10 motions, random dense x, y)", eW, 1e-12);
  c.checkResidual("h (x ∨ y) h* = (h x h*) ∨ (h y h*)", eS, 1e-12);
  c.checkResidual("h x h* is a vector for every vector x", eVec, 1e-14);
  c.checkResidual("det of x ↦ h x h* on vectors = 1 (SB's lemma)", eDet, 1e-13);
  c.note("Erratum 7 (rigor gap): SB argues with 'the matrices representing h and h*' on vectors, but h x alone "
         "is not a vector; the map x ↦ h x h* is linear on vectors and has det 1, measured above.");
}

void inertiaTransformation(Context& c) {
  auto g = rng(506);
  double eMat = 0, eDeriv = 0, eAlt = 0;
  for (int k = 0; k < 30; ++k) {
    const SpatialInertia<double> b = randBody(g);
    const SE3<double> x = randMotion(g);
    const Ev gm = motorElement(x), gb = bar(gm), G = Ev(gm * gb);
    const Quad N = inertiaElement(b.matrix());
    const Quad Nm = actInertia(gm, N);
    const M6 Hi = x.inverse().adjoint();
    eMat = std::max(eMat, mxm(M6(formMatrix(Nm) - Hi.transpose() * b.matrix() * Hi)) / mxm(b.matrix()));
    // SB's derivation: ḡ P ḡ* = A ∨ ((gḡ) N (gḡ)* ∧ g s g*)
    const Biv s = screwElement(T6(randV6(g)));
    const Biv lhs = actCoScrew(gm, momentum(N, s));
    eDeriv = std::max(eDeriv, mx(Biv(lhs - momentum(Nm, actScrew(gm, s)))));
    // the same law for screws: (gḡ) s (gḡ)* = g s g*
    eAlt = std::max(eAlt, mx(Biv(((G * s) * G.conjugate()).template grade<2>() - actScrew(gm, s))));
  }
  c.checkResidual("s ↦ A ∨ ((gḡ)N(gḡ)* ∧ s) has matrix H^{-T} N H^{-1} (30 bodies, relative)", eMat, 1e-14);
  c.checkResidual("ḡ P ḡ* = A ∨ ((gḡ)N(gḡ)* ∧ g s g*)", eDeriv, 1e-13);
  c.checkResidual("(gḡ) s (gḡ)* = g s g* (ḡ commutes with screws)", eAlt, 1e-14);
}

void translatedExample(Context& c) {
  const double dx = 1.3, dy = 0.7, dz = 2.1, m = 3, tx = 0.8;
  const Ev gt = toEven(D(word({}, 1) + word({e1, e}, tx / 2)));
  const Ev G = Ev(gt * bar(gt));
  const D Gprinted = D(word({}, 1) + word({a1, a}, tx / 2) + word({e1, e}, tx / 2) + word({a1, a, e1, e}, tx * tx / 4));
  c.checkResidual("g ḡ = 1 + ½t_x a₁a + ½t_x e₁e + ¼t_x² a₁ae₁e (t_x = 0.8)", mx(D(D(G) - Gprinted)), 1e-16);
  const Quad N = actInertia(gt, inertiaElement(SpatialInertia<double>::diagonal(m, Vec3<double>(dx, dy, dz)).matrix()));
  const D printed = D(word({a1, a, e1, e}, dx) + word({a2, a, e2, e}, dy + m * tx * tx) + word({a3, a, e3, e}, dz + m * tx * tx) +
                      word({a3, a, e3, e1}, m * tx) + word({a2, a, e1, e2}, -m * tx) + word({a3, a1, e3, e}, m * tx) +
                      word({a1, a2, e2, e}, -m * tx) + word({a2, a3, e2, e3}, m) + word({a3, a1, e3, e1}, m) +
                      word({a1, a2, e1, e2}, m));
  c.checkResidual("g ḡ N ḡ* g* = SB's printed expansion, term by term", mx(D(D(N) - printed)), 1e-15);
  M6 P6;
  P6 << dx, 0, 0, 0, 0, 0, 0, dy + m * tx * tx, 0, 0, 0, -m * tx, 0, 0, dz + m * tx * tx, 0, m * tx, 0, 0, 0, 0, m, 0, 0,
      0, 0, m * tx, 0, m, 0, 0, -m * tx, 0, 0, 0, m;
  c.checkResidual("its action s ↦ A ∨ (N ∧ s) is the printed 6×6 matrix", mxm(M6(formMatrix(N) - P6)), 1e-15);
  const SE3<double> x(SO3<double>::Identity(), Vec3<double>(tx, 0, 0));
  c.checkResidual("= the skew-axis theorem H^{-T} N H^{-1} (GF §13.1) = the direct parallel-axis move",
                  mxm(M6(SpatialInertia<double>::diagonal(m, Vec3<double>(dx, dy, dz)).transformed(x).matrix() - P6)), 1e-15);
  const D flipped = D(printed - word({a3, a, e3, e1}, 2 * m * tx));
  const double miss = mx(D(D(N) - flipped));
  c.record("negative control: one printed term with its sign flipped is detected", "fails", std::to_string(miss), miss,
           1e-6, miss > 1e-6);
}

void kineticEnergyStudy(Context& c) {
  auto g = rng(507);
  double eBar = 0, eEk = 0, eEk2 = 0;
  const Quad Q0 = elementQ0<double>();
  const Quad A = elementA<double>();
  for (int k = 0; k < 30; ++k) {
    const SpatialInertia<double> b = randBody(g);
    const Quad N = inertiaElement(b.matrix());
    const T6 s(randV6(g));
    const Biv se = screwElement(s);
    eBar = std::max(eBar, mx(Biv(shuffle(A, clifford::outer(Q0, se)) - bar(se))));
    eEk = std::max(eEk, std::abs(kineticEnergy(N, se) - b.kineticEnergy(s)));
    eEk2 = std::max(eEk2, std::abs(0.5 * pairing(momentum(N, se), se) - b.kineticEnergy(s)));
  }
  c.checkResidual("A ∨ (Q0 ∧ s) = s̄ (30 draws)", eBar, 1e-15);
  c.checkResidual("½ s̄ ∨ (N ∧ s) = ½ sᵀ N s (general inertias)", eEk, 1e-13);
  c.checkResidual("½ P ∨ (Q0 ∧ s) with P = A ∨ (N ∧ s) gives the same", eEk2, 1e-13);
  const double dx = 1.3, dy = 0.7, dz = 2.1, m = 3;
  const Vec3<double> w(0.3, -1.1, 0.4), v(0.9, 0.2, -0.5);
  const Quad Nd = inertiaElement(SpatialInertia<double>::diagonal(m, Vec3<double>(dx, dy, dz)).matrix());
  c.checkNear("diagonal body: ½ s̄ ∨ (N ∧ s) = ½(Σ d_i ω_i² + m|v|²)",
              0.5 * (dx * w.x() * w.x() + dy * w.y() * w.y() + dz * w.z() * w.z() + m * v.squaredNorm()),
              kineticEnergy(Nd, screwElement(T6(w, v))), 1e-15);
}

}  // namespace

SOMA_STUDY_DOUBLE("SB-5-coscrew-element-bar-involution", "Co-screws as a-bivectors; the bar involution; ḡ P ḡ*", "SB §5", coScrewBar);
SOMA_STUDY_DOUBLE("SB-5-Q0-evaluation", "P(s) = P ∨ (Q0 ∧ s) = (P ∧ Q0) ∨ s", "SB §5", q0Evaluation);
SOMA_STUDY_DOUBLE("SB-5-Q0-invariance", "Q0 invariant under g ḡ, not under g or ḡ alone", "SB §5", q0Invariance);
SOMA_STUDY_DOUBLE("SB-5-diagonal-inertia-element", "The diagonal inertia as a grade-4 element", "SB §5", diagonalInertia);
SOMA_STUDY_DOUBLE("SB-5-momentum-A-shuffle", "P = A ∨ (N ∧ s); A invariant", "SB §5", momentumA);
SOMA_STUDY_DOUBLE("SB-5-wedge-shuffle-covariance", "h(a∧b)h* and h(a∨b)h* covariance; det lemma", "SB §5", covariance);
SOMA_STUDY_DOUBLE("SB-5-inertia-transformation", "N → (gḡ) N (gḡ)* equals H^{-T} N H^{-1}", "SB §5", inertiaTransformation);
SOMA_STUDY_DOUBLE("SB-5-translated-inertia-example", "Diagonal inertia translated by t_x (printed expansion and matrix)", "SB §5", translatedExample);
SOMA_STUDY_DOUBLE("SB-5-kinetic-energy", "E_k = ½ s̄ ∨ (N ∧ s)", "SB §5", kineticEnergyStudy);

}  // namespace soma::studies::sb::SOMA_UNITY_ID
