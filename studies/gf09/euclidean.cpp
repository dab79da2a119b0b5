// Studies of GF chapter 9, §9.2–9.3: the Euclidean group in Cℓ(0,n,1), planar rotors and the
// planar Campbell–Baker–Hausdorff formula, SE(3) as dual quaternions (isomorphism, Study quadric,
// Lie algebra and adjoint, transference, exponential), in the scalar asked for. The independent methods
// are soma's DualQuaternion / SE3 / StudyParameters (for §9.3), homogeneous 3×3 matrices (§9.2)
// and power series.
#include "gf09/common.hpp"

#include "soma/algebra/study_parameters.hpp"

namespace soma::studies::gf09::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

// ---- GF §9.2, GF-9.2-euclidean-group-Cl0n1 ---------------------------------------------------
template <class S> void euclideanGroup(Context& c) {
  auto g = rng(921);
  const S tol = Tolerance<S>::identity(64);
  S act = 0, prod = 0, rot = 0, cover = 0, conjForm = 0;
  for (int t = 0; t < 20; ++t) {
    const Motor<S> r1 = randomRotor<S>(g), r2 = randomRotor<S>(g);
    const Vec3<S> t1 = randVec<S>(g), t2 = randVec<S>(g), x = randVec<S>(g);
    const Motor<S> m1 = motor(r1, t1), m2 = motor(r2, t2);
    // (g + ½tg𝐞)(1 + x𝐞)(g − ½tg𝐞)* = 1 + (g x g* + t)𝐞
    const Motor<S> moved = Motor<S>(Motor<S>(m1 * point<S>(x)) * dagger(m1));
    const Dense<PGA, S> gx(r1 * vec3<S>(x) * r1.conjugate());
    const Vec3<S> gxv(gx.coeff(1), gx.coeff(2), gx.coeff(4));
    act = std::max(act, maxAbsDiff(moved, point<S>(gxv + t1)));
    // (g − ½tg𝐞)* = g* + ½g*t𝐞
    const Motor<S> gstar = r1.conjugate();
    conjForm = std::max(conjForm, maxAbsDiff(dagger(m1), Motor<S>(gstar + Motor<S>(Dense<PGA, S>(gstar * vec3<S>(t1) * nullE<S>()).template grades<PGA::evenGrades>() * S(0.5)))));
    // and g x g* is the rotation of the quaternion (a₀, a₁, a₂, a₃) = (g₀, g₂₃, g₃₁, g₁₂)
    const Vec8<S> q8 = dqCoeffs(r1);
    rot = std::max(rot, (gxv - Quat<S>(q8(0), q8(1), q8(2), q8(3)).toRotationMatrix() * x).cwiseAbs().maxCoeff());
    // (g + ½tg𝐞)(g' + ½t'g'𝐞) = gg' + ½(t + g t' g*) g g' 𝐞
    const Dense<PGA, S> gt2(r1 * vec3<S>(t2) * r1.conjugate());
    const Vec3<S> tt = t1 + Vec3<S>(gt2.coeff(1), gt2.coeff(2), gt2.coeff(4));
    prod = std::max(prod, maxAbsDiff(m1 * m2, motor(Motor<S>(r1 * r2), tt)));
    // −M acts like M: double cover of SE(3)
    const Motor<S> neg = -m1;
    cover = std::max(cover, maxAbsDiff(Motor<S>(Motor<S>(neg * point<S>(x)) * dagger(neg)), moved));
  }
  c.checkResidual("point action (g + ½tg𝐞)(1 + x𝐞)(g − ½tg𝐞)* = 1 + (gxg* + t)𝐞 (20 random, n = 3)", act, tol);
  c.checkResidual("(g − ½tg𝐞)* = g* + ½g*t𝐞", conjForm, tol);
  c.checkResidual("g x g* = R x with R the rotation of the quaternion (g₀, g₂₃, g₃₁, g₁₂)", rot, tol);
  c.checkResidual("product (g + ½tg𝐞)(g' + ½t'g'𝐞) = gg' + ½(t + gt'g*)gg'𝐞", prod, tol);
  c.checkResidual("−(g + ½tg𝐞) gives the same motion (double cover)", cover, tol);
  // n = 2 (the plane, Cℓ(0,2,1)): the same action formula.
  using P2 = Signature<0, 2, 1>;
  const S th = frac<S>(13, 10);
  const Even<P2, S> g2 = Even<P2, S>(Dense<P2, S>(Dense<P2, S>(S(cos(th / 2))) + gens<P2, S>({0, 1}) * S(sin(th / 2))).template grades<P2::evenGrades>());
  const Vector<P2, S> tv = Vector<P2, S>(Dense<P2, S>(gens<P2, S>({0}) * frac<S>(2, 5) + gens<P2, S>({1}) * frac<S>(-7, 10)).template grades<gradeBit(1)>());
  const Vector<P2, S> xv = Vector<P2, S>(Dense<P2, S>(gens<P2, S>({0}) * frac<S>(1, 4) + gens<P2, S>({1}) * frac<S>(3, 5)).template grades<gradeBit(1)>());
  const auto en = Vector<P2, S>::generator(2);
  const Dense<P2, S> M2 = Dense<P2, S>(g2) + Dense<P2, S>(tv * g2 * en) * S(0.5);
  const Dense<P2, S> M2d = [&] {
    Dense<P2, S> d = (Dense<P2, S>(g2) - Dense<P2, S>(tv * g2 * en) * S(0.5)).conjugate();
    return d;
  }();
  const Dense<P2, S> moved2 = M2 * (Dense<P2, S>(S(1)) + Dense<P2, S>(xv * en)) * M2d;
  const Dense<P2, S> want2 = Dense<P2, S>(S(1)) + Dense<P2, S>((Dense<P2, S>(g2 * xv * g2.conjugate()) + Dense<P2, S>(tv)) * Dense<P2, S>(en));
  c.checkResidual("the same action in Cℓ(0,2,1) (n = 2, θ = 1.3)", maxAbsDiff(moved2, want2), tol);
  // Erratum E9.1: the isotropy group of a point is not {1, −1}: every rotation about the point
  // fixes it. The rotation g = exp(0.8·unit bivector) (t = 0) fixes the origin.
  const Motor<S> rr = randomRotor<S>(g);
  const Motor<S> fixedOrigin = Motor<S>(Motor<S>(rr * point<S>(Vec3<S>::Zero())) * dagger(rr));
  const S notPm1 = std::min(maxAbsDiff(rr, Motor<S>(S(1))), maxAbsDiff(rr, Motor<S>(S(-1))));
  c.checkResidual("a rotor g ≠ ±1 (distance to ±1 = " + str(notPm1) + ") fixes the origin", maxAbsDiff(fixedOrigin, point<S>(Vec3<S>::Zero())), tol);
  c.checkPrintedFails("\"the isotropy group of any point consists of 1 and −1\": distance of that fixing element from ±1", "E9.1",
              notPm1, tol);
  c.note("E9.1 (wording): the isotropy group of a point is a copy of Spin(3); the kernel of the action "
         "(elements fixing every point) is {±1}. Catalogue note: in Ch. 10 points are grade-3 and the plain "
         "conjugate is used; here (§9.2) the point is 1 + x𝐞 and the right factor is (g − ½tg𝐞)*.");
}
SOMA_STUDY_SCALAR("GF-9.2-euclidean-group-Cl0n1", "SE(n) double-covered by g + ½tg𝐞 in Cℓ⁺(0,n,1)", "GF §9.2", euclideanGroup);

// ---- GF §9.2 planar: Cℓ(0,2,1), e₁, e₂ ↦ 0, 1 and 𝐞 ↦ 2 --------------------------------------
using P2 = Signature<0, 2, 1>;
template <class S> using E2 = Even<P2, S>;
inline constexpr Blade k12 = 0b011, k1n = 0b101, k2n = 0b110;
template <class S> E2<S> e2of(const S& s, const S& b12, const S& b1n, const S& b2n) {
  E2<S> m(s);
  m.setCoeff(k12, b12), m.setCoeff(k1n, b1n), m.setCoeff(k2n, b2n);
  return m;
}
template <class S> E2<S> daggerP2(const E2<S>& m) {
  E2<S> d = m.conjugate();
  for (int i = 0; i < d.size; ++i)
    if (d.blade(i) & 0b100) d[i] = -d[i];
  return d;
}
/// The point 1 + (x e₁ + y e₂)𝐞 moved by m (GF §9.2 action).
template <class S> Vec2<S> movePoint(const E2<S>& m, const Vec2<S>& p) {
  const E2<S> q = E2<S>(E2<S>(m * e2of(S(1), S(0), p(0), p(1))) * daggerP2(m));
  return Vec2<S>(q.coeff(k1n), q.coeff(k2n));
}

// ---- GF §9.2, GF-9.2-SE2-rotors --------------------------------------------------------------
template <class S> void se2Rotors(Context& c) {
  const S tol = Tolerance<S>::identity(64);
  const S th = frac<S>(11, 10), x = frac<S>(3, 10), y = frac<S>(-8, 10);
  const E2<S> g = e2of(cos(th / 2), sin(th / 2), S(0), S(0));
  Vector<P2, S> tv;
  tv.setCoeff(1, x), tv.setCoeff(2, y);
  const E2<S> M = E2<S>(g + E2<S>(Dense<P2, S>(tv * g * Vector<P2, S>::generator(2)).template grades<P2::evenGrades>() * S(0.5)));
  const E2<S> printed = e2of(cos(th / 2), sin(th / 2), (x * cos(th / 2) + y * sin(th / 2)) / 2,
                          -(x * sin(th / 2) - y * cos(th / 2)) / 2);
  c.checkResidual("g + ½tg𝐞 = cos + sin e₁e₂ + ½(x cos + y sin)e₁𝐞 − ½(x sin − y cos)e₂𝐞 (θ = 1.1, t = (0.3, −0.8))",
                  maxAbsDiff(M, printed), tol);
  // Rotation about c: (1 + ½c𝐞) g (1 − ½c𝐞) = cos θ/2 + sin θ/2 (e₁e₂ + c_y e₁𝐞 − c_x e₂𝐞).
  const S cx = frac<S>(7, 10), cy = frac<S>(-4, 10);
  const E2<S> tc = e2of(S(1), S(0), cx / 2, cy / 2), tcInv = e2of(S(1), S(0), -cx / 2, -cy / 2);
  const E2<S> rc = E2<S>(E2<S>(tc * g) * tcInv);
  c.checkResidual("(1 + ½c𝐞)g(1 − ½c𝐞) = cos + sin(e₁e₂ + c_y e₁𝐞 − c_x e₂𝐞), c = (0.7, −0.4)",
                  maxAbsDiff(rc, e2of(cos(th / 2), sin(th / 2), sin(th / 2) * cy, -sin(th / 2) * cx)), tol);
  c.checkResidual("… and it fixes the point c", (movePoint(rc, Vec2<S>(cx, cy)) - Vec2<S>(cx, cy)).cwiseAbs().maxCoeff(), tol);
  // Library formula: centre (c_x, c_y) = (−h_{e₂𝐞}/h_{e₁e₂}, h_{e₁𝐞}/h_{e₁e₂}).
  c.checkNear("centre of rotation from the element: c_x = −h_{e₂𝐞}/h_{e₁e₂}", cx, -rc.coeff(k2n) / rc.coeff(k12), tol);
  c.checkNear("c_y = h_{e₁𝐞}/h_{e₁e₂}", cy, rc.coeff(k1n) / rc.coeff(k12), tol);
  // B = e₁e₂ + c_y e₁𝐞 − c_x e₂𝐞: B² = −1, so exp(θ/2 B) = cos θ/2 + sin θ/2 B.
  Bivector<P2, S> B;
  B.setCoeff(k12, S(1)), B.setCoeff(k1n, cy), B.setCoeff(k2n, -cx);
  c.checkResidual("B² = −1", maxAbsDiff(B * B, E2<S>(S(-1))), tol);
  c.checkResidual("exp(θ/2 B) (soma's bivector exp) = cos θ/2 + sin θ/2 B", maxAbsDiff(exp(B * S(th / 2)), rc), tol);
  // Commutators of the planar Lie algebra.
  const auto h12 = Bivector<P2, S>::basisBlade(k12, S(0.5)), h1n = Bivector<P2, S>::basisBlade(k1n, S(0.5)),
             h2n = Bivector<P2, S>::basisBlade(k2n, S(0.5));
  auto br = [](const auto& a, const auto& b) { return Dense<P2, S>(a * b - b * a); };
  c.checkResidual("[½e₁e₂, ½e₁𝐞] = ½e₂𝐞", maxAbsDiff(br(h12, h1n), Dense<P2, S>(h2n)), tol);
  c.checkResidual("[½e₁e₂, ½e₂𝐞] = −½e₁𝐞", maxAbsDiff(br(h12, h2n), Dense<P2, S>(-h1n)), tol);
  c.checkResidual("[½e₁𝐞, ½e₂𝐞] = 0", br(h1n, h2n).maxAbs(), tol);
  // Translations: exp(½(t_x e₁𝐞 + t_y e₂𝐞)) = 1 + ½t_x e₁𝐞 + ½t_y e₂𝐞, moving points by t.
  Bivector<P2, S> T;
  T.setCoeff(k1n, x / 2), T.setCoeff(k2n, y / 2);
  c.checkResidual("exp(½(t_x e₁𝐞 + t_y e₂𝐞)) = 1 + ½t_x e₁𝐞 + ½t_y e₂𝐞", maxAbsDiff(exp(T), e2of(S(1), S(0), x / 2, y / 2)), tol);
  c.checkResidual("… which translates the point (0.7, −0.4) by t",
                  (movePoint(exp(T), Vec2<S>(cx, cy)) - Vec2<S>(cx + x, cy + y)).cwiseAbs().maxCoeff(), tol);
  // θ = π: still a rotation about c (centre formula valid); θ → 0: h_{e₁e₂} → 0, centre → ∞.
  const E2<S> rpi = exp(B * S(pi<S>() / 2));
  c.checkNear("θ = π: centre recovered, c_x", cx, -rpi.coeff(k2n) / rpi.coeff(k12), tol);
  // a translation followed by a rotation by δ = 2e-7 about the origin: the centre is at distance
  // ~|t|/δ (θ → 0), and a pure translation has h_{e₁e₂} = 0 exactly (no centre).
  // Exactly, |h_{e₁𝐞} + i h_{e₂𝐞}| = |t|/2 and h_{e₁e₂} = sin δ/2, so the distance is |t|/(2 sin δ/2) =
  // |t|/δ (1 + δ²/24 + …); computed to a few ulps relative (64 ε).
  const S delta = frac<S>(2, 10000000);
  const E2<S> nearT = E2<S>(exp(T) * exp(Bivector<P2, S>::basisBlade(k12, delta / 2)));
  const S dist = sqrt(nearT.coeff(k2n) * nearT.coeff(k2n) + nearT.coeff(k1n) * nearT.coeff(k1n)) / abs(nearT.coeff(k12));
  const S tNorm = sqrt(x * x + y * y);
  c.checkNear("θ → 0 (δ = 2e-7): centre distance |t|/(2 sin δ/2) ≈ |t|/δ, the centre runs off to ∞ (64 ε relative)",
              tNorm / (2 * sin(delta / 2)), dist, tNorm / delta * Tolerance<S>::identity(64));
  c.checkResidual("pure translation: h_{e₁e₂} = 0 exactly (centre undefined)", abs(exp(T).coeff(k12)), S(0));
  // Minor erratum: "identifying ½e₁e₂ with i": (½e₁e₂)² = −¼, it is e₁e₂ that squares to −1.
  c.checkPrintedFails("(½e₁e₂)² = −1 (\"identifying ½e₁e₂ with i\")", "minor 5566",
              maxAbsDiff(h12 * h12, E2<S>(S(-1))), tol);
}
SOMA_STUDY_SCALAR("GF-9.2-SE2-rotors", "Planar rigid motions as rotors of Cℓ⁺(0,2,1); centre of rotation", "GF §9.2", se2Rotors);

// ---- GF §9.2, GF-9.2-planar-BCH --------------------------------------------------------------
template <class S> void planarBch(Context& c) {
  const S tol = Tolerance<S>::identity(256);
  const S t1 = frac<S>(7, 10), t2 = frac<S>(19, 10);
  const Vec2<S> a(frac<S>(4, 10), frac<S>(-9, 10)), b(frac<S>(-12, 10), frac<S>(5, 10));
  auto Cof = [](const Vec2<S>& p) {
    Bivector<P2, S> C;
    C.setCoeff(k12, S(0.5)), C.setCoeff(k1n, p(1) / 2), C.setCoeff(k2n, -p(0) / 2);
    return C;
  };
  const auto Ca = Cof(a), Cb = Cof(b);
  const E2<S> P = exp(Ca * t1) * exp(Cb * t2);
  const S ta = tan(t1 / 2), tb = tan(t2 / 2), den = ta + tb;
  const S al = ta / den, be = tb / den, ga = ta * tb / den;
  const S phi = t1 + t2;
  const S y = al * a(1) + be * b(1) + ga * (b(0) - a(0));
  const S xCorr = al * a(0) + be * b(0) - ga * (b(1) - a(1));
  const S xPrinted = al * a(0) + be * b(0) + ga * (b(1) - a(1));
  auto closed = [&](S x) { return e2of(cos(phi / 2), sin(phi / 2), sin(phi / 2) * y, -sin(phi / 2) * x); };
  c.checkResidual("e^{θ₁C_a}e^{θ₂C_b} = cos φ/2 + sin φ/2 (e₁e₂ + y e₁𝐞 − x e₂𝐞), x corrected (θ₁ = 0.7, θ₂ = 1.9)",
                  maxAbsDiff(P, closed(xCorr)), tol);
  c.checkPrintedFails("x = αa_x + βb_x + γ(b_y − a_y)", "E9.2", maxAbsDiff(P, closed(xPrinted)), tol);
  const Dense<P2, S> comm(Ca * Cb - Cb * Ca);
  Bivector<P2, S> commWant;
  commWant.setCoeff(k1n, (b(0) - a(0)) / 2), commWant.setCoeff(k2n, (b(1) - a(1)) / 2);
  c.checkResidual("[C_a, C_b] = ½(b_x − a_x)e₁𝐞 + ½(b_y − a_y)e₂𝐞", maxAbsDiff(comm, Dense<P2, S>(commWant)), tol);
  const Bivector<P2, S> X = Bivector<P2, S>(Dense<P2, S>(Ca * al + Cb * be + comm * ga).template grades<gradeBit(2)>()) * phi;
  c.checkResidual("e^{θ₁C_a}e^{θ₂C_b} = exp(φ(αC_a + βC_b + γ[C_a, C_b])), φ = θ₁ + θ₂", maxAbsDiff(P, exp(X)), tol);
  // Cross-check with 3×3 homogeneous matrices: the composite centre is the fixed point of
  // Rot(a, θ₁)·Rot(b, θ₂) (rotation sense read off the rotor's action on e₁).
  const Vec2<S> r1 = movePoint(exp(Cof(Vec2<S>(Vec2<S>::Zero())) * S(0.5)), Vec2<S>(S(1), S(0)));
  const S sense = r1(1) > 0 ? S(1) : S(-1);
  auto hom = [&](const Vec2<S>& cc, S th) {
    Mat3<S> m = Mat3<S>::Identity();
    const S cs = cos(sense * th), sn = sin(sense * th);
    m.template topLeftCorner<2, 2>() << cs, -sn, sn, cs;
    m.template topRightCorner<2, 1>() = cc - m.template topLeftCorner<2, 2>() * cc;
    return m;
  };
  const Mat3<S> Mab = hom(a, t1) * hom(b, t2);
  const Vec2<S> fixedPt = (Mat2<S>(Mat2<S>::Identity()) - Mab.template topLeftCorner<2, 2>()).lu().solve(Mab.template topRightCorner<2, 1>());
  c.checkResidual("composite centre (x, y) = fixed point of the 3×3 product Rot(a,θ₁)Rot(b,θ₂)",
                  (fixedPt - Vec2<S>(xCorr, y)).cwiseAbs().maxCoeff(), tol);
  c.checkResidual("… and the rotor acts on points as that matrix", (movePoint(P, Vec2<S>(frac<S>(3, 10), frac<S>(2, 10))) -
                  (Mab * Vec3<S>(frac<S>(3, 10), frac<S>(2, 10), S(1))).template head<2>()).cwiseAbs().maxCoeff(), tol);
  // Extreme: θ₁ + θ₂ = 2π: tan θ₁/2 + tan θ₂/2 = 0, α, β, γ blow up — the composition is a translation.
  const S u1 = S(2), u2 = 2 * pi<S>() - S(2);
  const E2<S> Pt = exp(Ca * u1) * exp(Cb * u2);
  c.checkResidual("θ₁ + θ₂ = 2π: the product has no e₁e₂ part (a translation, times −1)", abs(Pt.coeff(k12)), tol);
  c.checkNear("… tan θ₁/2 + tan θ₂/2 = 0 (α, β, γ undefined)", S(0), tan(u1 / 2) + tan(u2 / 2), tol);
  c.note("E9.2: the printed x = αa_x + βb_x + γ(b_y − a_y) must read −γ(b_y − a_y); the expansion at "
         "5619–5621 and the final single-exponential formula (which passes here) already imply the minus sign.");
}
SOMA_STUDY_SCALAR("GF-9.2-planar-BCH", "Planar Campbell–Baker–Hausdorff: composing two rotations", "GF §9.2", planarBch);

// ---- GF §9.3, GF-9.3-dual-quaternion-isomorphism ---------------------------------------------
template <class S> void dqIsomorphism(Context& c) {
  auto g = rng(931);
  const S tol = Tolerance<S>::identity(64);
  S expansion = 0, imgErr = 0, hom = 0, commEps = 0;
  for (int t = 0; t < 20; ++t) {
    const Motor<S> r = randomRotor<S>(g);
    const Vec3<S> bt = randVec<S>(g);
    const Vec8<S> q = dqCoeffs(r);
    const S a0 = q(0), a1 = q(1), a2 = q(2), a3 = q(3), b1 = bt(0), b2 = bt(1), b3 = bt(2);
    const Motor<S> M = motor(r, bt);
    // The book's 8-term expansion (seed 5687–5696).
    Motor<S> printed;
    printed.setCoeff(0, a0), printed.setCoeff(kE23, a1), printed.setCoeff(kE13, -a2), printed.setCoeff(kE12, a3);
    printed.setCoeff(kE1n, (a0 * b1 - a2 * b3 + a3 * b2) / 2);
    printed.setCoeff(kE2n, (a0 * b2 + a1 * b3 - a3 * b1) / 2);
    printed.setCoeff(kE3n, (a0 * b3 - a1 * b2 + a2 * b1) / 2);
    printed.setCoeff(kI, (a1 * b1 + a2 * b2 + a3 * b3) / 2);
    expansion = std::max(expansion, maxAbsDiff(M, printed));
    // Its image under e₂e₃ ↦ i, …, −e₁e₂e₃𝐞 ↦ ε is soma's DualQuaternion of (R, t).
    const auto h = DualQuaternion<S>::fromSE3(SE3<S>(SO3<S>::fromQuaternion(Quat<S>(a0, a1, a2, a3)), bt));
    imgErr = std::max(imgErr, (dqCoeffs(M) - dqCoeffs(h)).cwiseAbs().maxCoeff());
    // Products correspond (random, not unit).
    Motor<S> x, y;
    for (int i = 0; i < x.size; ++i) x[i] = uni<S>(g), y[i] = uni<S>(g);
    const Vec8<S> xv = dqCoeffs(x), yv = dqCoeffs(y);
    const DualQuaternion<S> hx(Quat<S>(xv(0), xv(1), xv(2), xv(3)), Quat<S>(xv(4), xv(5), xv(6), xv(7)));
    const DualQuaternion<S> hy(Quat<S>(yv(0), yv(1), yv(2), yv(3)), Quat<S>(yv(4), yv(5), yv(6), yv(7)));
    hom = std::max(hom, (dqCoeffs(Motor<S>(x * y)) - dqCoeffs(hx * hy)).cwiseAbs().maxCoeff());
    // ε = −e₁e₂e₃𝐞 commutes with the even subalgebra
    const Motor<S> eps = Motor<S>::basisBlade(kI, -1);
    commEps = std::max(commEps, maxAbsDiff(x * eps, eps * x));
  }
  c.checkResidual("g + ½tg𝐞 = the book's 8-term expansion (20 random g, t)", expansion, tol);
  c.checkResidual("image under e₂e₃ ↦ i, e₃e₁ ↦ j, e₁e₂ ↦ k, −e₁e₂e₃𝐞 ↦ ε = soma's DualQuaternion::fromSE3", imgErr, tol);
  c.checkResidual("Cℓ⁺(0,3,1) products = dual-quaternion products (20 random pairs)", hom, tol);
  const Motor<S> eps = Motor<S>::basisBlade(kI, -1);
  c.checkResidual("ε² = 0", (eps * eps).maxAbs(), S(0));
  c.checkResidual("ε commutes with Cℓ⁺(0,3,1)", commEps, tol);
  const PDense<S> epsD(eps);
  c.checkResidual("… but anticommutes with the generator e₁ (fine: ℍ ⊗ 𝔻 lives in Cℓ⁺)",
                  maxAbsDiff(PDense<S>(gens<PGA, S>({0}) * epsD), PDense<S>(-(epsD * gens<PGA, S>({0})))), S(0));
  c.checkResidual("e₂e₃ ε = e₁𝐞 (so e₁𝐞 ↦ iε), e₃e₁ ε = e₂𝐞, e₁e₂ ε = e₃𝐞",
                  std::max({maxAbsDiff(PDense<S>(gens<PGA, S>({1, 2}) * epsD), gens<PGA, S>({0, 3})),
                            maxAbsDiff(PDense<S>(gens<PGA, S>({2, 0}) * epsD), gens<PGA, S>({1, 3})),
                            maxAbsDiff(PDense<S>(gens<PGA, S>({0, 1}) * epsD), gens<PGA, S>({2, 3}))}), S(0));
  // Cℓ(0,2,1) = Cℓ(0,2,0) ⊗ 𝔻 via e₁e₂𝐞 ↦ ε (k = 1): e₁e₂𝐞 squares to 0 and is central.
  using P21 = Signature<0, 2, 1>;
  const auto e12n = gens<P21, S>({0, 1, 2});
  S central = 0;
  for (int i = 0; i < 3; ++i)
    central = std::max(central, maxAbsDiff(Dense<P21, S>(e12n * gens<P21, S>({i})), Dense<P21, S>(gens<P21, S>({i}) * e12n)));
  c.checkResidual("Cℓ(0,2,1): e₁e₂𝐞 is central and squares to 0 (Cℓ(0,2,1) = ℍ ⊗ 𝔻)", std::max(central, (e12n * e12n).maxAbs()), S(0));
  // Extremes: a₀ = 0 (rotation by π), b = 0.
  const Motor<S> rpi = toMotor(Vec4<S>(S(0), S(0), frac<S>(3, 5), frac<S>(4, 5)), Vec4<S>(Vec4<S>::Zero()));
  const auto hpi = DualQuaternion<S>::fromSE3(SE3<S>(SO3<S>::fromQuaternion(Quat<S>(S(0), S(0), frac<S>(3, 5), frac<S>(4, 5))), Vec3<S>(S(1), S(2), S(3))));
  c.checkResidual("extreme a₀ = 0 (θ = π), t = (1, 2, 3)", (dqCoeffs(motor(rpi, Vec3<S>(S(1), S(2), S(3)))) - dqCoeffs(hpi)).cwiseAbs().maxCoeff(), tol);
  c.checkResidual("extreme t = 0: g + ½tg𝐞 = g", maxAbsDiff(motor(rpi, Vec3<S>(Vec3<S>::Zero())), rpi), S(0));
}
SOMA_STUDY_SCALAR("GF-9.3-dual-quaternion-isomorphism", "Cℓ⁺(0,3,1) ≅ ℍ ⊗ 𝔻: the book's expansion against soma's DualQuaternion",
           "GF §9.3", dqIsomorphism);

// ---- GF §9.3, GF-9.3-study-quadric -----------------------------------------------------------
template <class S> void studyQuadric(Context& c) {
  auto g = rng(932);
  const S tol = Tolerance<S>::identity(64);
  S quadric = 0, unit = 0, trans = 0, act = 0, proj = 0;
  bool allOn = true;
  for (int t = 0; t < 20; ++t) {
    const Vec3<S> tv = randVec<S>(g), x = randVec<S>(g);
    const Motor<S> M = motor(randomRotor<S>(g), tv);
    const Vec8<S> v = dqCoeffs(M);
    quadric = std::max(quadric, abs(v.template head<4>().dot(v.template tail<4>())));
    allOn = allOn && StudyParameters<S>(v).onStudyQuadric();
    // ȟȟ* = 1 ⇔ h₀h₀* = 1 and h₀h₁* + h₁h₀* = 0
    const DualQuaternion<S> h(Quat<S>(v(0), v(1), v(2), v(3)), Quat<S>(v(4), v(5), v(6), v(7)));
    const DualQuaternion<S> hh = h * h.conjugate();
    unit = std::max(unit, (dqCoeffs(hh) - Vec8<S>(Vec8<S>::Unit(0))).cwiseAbs().maxCoeff());
    // h₁h₀* − h₀h₁* = t
    const Quat<S> h0 = h.real(), h1 = h.dual();
    const Quat<S> d = Quat<S>((h1 * h0.conjugate()).coeffs() - (h0 * h1.conjugate()).coeffs());
    trans = std::max(trans, std::max(abs(d.w()), (d.vec() - tv).cwiseAbs().maxCoeff()));
    // point action (h₀ + h₁ε)(1 + xε)(h₀* − h₁*ε) = 1 + (Rx + t)ε, in the Clifford algebra
    act = std::max(act, (pointOf(Motor<S>(Motor<S>(M * point<S>(x)) * dagger(M))) - h.act(x)).cwiseAbs().maxCoeff());
    // Projection of a perturbed 8-vector onto the quadric: h₁ ← h₁ − (h₀·h₁/|h₀|²)h₀, scale by |h₀|.
    Vec8<S> w = v * frac<S>(17, 10);
    for (int i = 0; i < 8; ++i) w(i) += uni<S>(g) / 1000;
    Vec4<S> a = w.template head<4>(), cc = w.template tail<4>();
    cc -= (a.dot(cc) / a.squaredNorm()) * a;
    const S n = a.norm();
    a /= n, cc /= n;
    proj = std::max(proj, abs(a.dot(cc)) + abs(a.squaredNorm() - 1));
  }
  c.checkResidual("Study quadric a₀c₀ + a₁c₁ + a₂c₂ + a₃c₃ = 0 for 20 motors g + ½tg𝐞", quadric, tol);
  c.checkEqual("StudyParameters::onStudyQuadric for all 20", "yes", allOn ? "yes" : "no");
  c.checkResidual("ȟȟ* = 1 (so h₀h₀* = 1, h₀h₁* + h₁h₀* = 0)", unit, tol);
  c.checkResidual("h₁h₀* − h₀h₁* = t (h₁h₀* = −h₀h₁* = t/2)", trans, tol);
  c.checkResidual("point action through the Clifford algebra = DualQuaternion::act (R x + t)", act, tol);
  c.checkResidual("normalisation of a perturbed 8-vector lands on the quadric with |h₀| = 1", proj, tol);
  // Extremes: the exceptional 3-plane a = 0 is not a motion; ±ȟ are the same point of PR⁷.
  const StudyParameters<S> ideal((Vec8<S>() << S(0), S(0), S(0), S(0), frac<S>(3, 10), frac<S>(1, 10), frac<S>(-2, 10), frac<S>(5, 10)).finished());
  c.checkEqual("a = 0 lies in the exceptional plane a₀² + ⋯ + a₃² = 0 (not a motion)", "yes",
               ideal.inExceptionalPlane() ? "yes" : "no");
  const Motor<S> M = motor(randomRotor<S>(g), randVec<S>(g));
  c.checkEqual("±ȟ: the same point of PR⁷", "yes",
               StudyParameters<S>(dqCoeffs(M)).isApprox(StudyParameters<S>(Vec8<S>(-dqCoeffs(M))), tol) ? "yes" : "no");
}
SOMA_STUDY_SCALAR("GF-9.3-study-quadric", "Unit dual quaternions and the Study quadric", "GF §9.3", studyQuadric);

// ---- GF §9.3, GF-9.3-lie-algebra-adjoint -----------------------------------------------------
template <class S> void lieAdjoint(Context& c) {
  auto g = rng(933);
  const S tol = Tolerance<S>::identity(64);
  S cross = 0, dot = 0, adj = 0, printedErr = 0;
  for (int t = 0; t < 20; ++t) {
    const Vec3<S> v0 = randVec<S>(g), v1 = randVec<S>(g), u0 = randVec<S>(g), u1 = randVec<S>(g);
    const auto V = twistBivector<S>(v0, v1), U = twistBivector<S>(u0, u1);  // ½(v₀ + εv₁)
    // ½[v̌, ǔ] with v̌ = ½(…): the bracket of the bivectors is ½ of the dual cross product image
    const Bivector<PGA, S> br = Dense<PGA, S>(V * U - U * V).template grades<gradeBit(2)>();
    Vec6<S> want;
    want << v0.cross(u0), v0.cross(u1) + v1.cross(u0);
    cross = std::max(cross, (twistOf(br) - want).cwiseAbs().maxCoeff());
    // v̌·ǔ = v₀·u₀ + ε(v₀·u₁ + v₁·u₀): from −½(v̌ǔ + ǔv̌) with v̌ = v₀ + εv₁ (scalar and ε parts).
    const auto V2 = twistBivector<S>(Vec3<S>(S(2) * v0), Vec3<S>(S(2) * v1)), U2 = twistBivector<S>(Vec3<S>(S(2) * u0), Vec3<S>(S(2) * u1));
    const Motor<S> sym = Motor<S>(Dense<PGA, S>(V2 * U2 + U2 * V2).template grades<PGA::evenGrades>()) * S(-0.5);
    dot = std::max(dot, std::max(abs(sym.coeff(0) - v0.dot(u0)), abs(-sym.coeff(kI) - (v0.dot(u1) + v1.dot(u0)))));
    // Adjoint: ȟ(v₀ + εv₁)ȟ* = (Rv₀, Rv₁ + t × Rv₀) — against SE3's adjoint matrix.
    const SE3<S> X = SE3<S>::Random(g);
    const Motor<S> M = toMotor(DualQuaternion<S>::fromSE3(X));
    const Bivector<PGA, S> moved = Motor<S>(M * V * ~M).template grades<gradeBit(2)>();
    Vec6<S> xi;
    xi << v0, v1;
    const Vec6<S> ad = X.adjoint() * xi;
    adj = std::max(adj, (twistOf(moved) - ad).cwiseAbs().maxCoeff());
    // As printed: dual part Rv₁ + (Rv₁) × t ("h₀v₁h₀* + [h₀v₁h₀*, t]/2").
    const Mat3<S> R = X.rotation();
    const Vec3<S> tt = X.translation();
    const Vec3<S> printedDual = R * v1 + (R * v1).cross(tt);
    printedErr = std::max(printedErr, (printedDual - ad.template tail<3>()).cwiseAbs().maxCoeff());
  }
  c.checkResidual("½[v̌, ǔ] = v̌ × ǔ = v₀ × u₀ + ε(v₀ × u₁ + v₁ × u₀) (20 random)", cross, tol);
  c.checkResidual("v̌·ǔ = v₀·u₀ + ε(v₀·u₁ + v₁·u₀)", dot, tol);
  c.checkResidual("ȟ(v₀ + εv₁)ȟ* = (Rv₀, Rv₁ + t × Rv₀) = Ad(X)(ω; v) of SE3::adjoint()", adj, tol);
  c.checkPrintedFails("dual part h₀v₁h₀* + [h₀v₁h₀*, t]/2 = Rv₁ + Rv₁ × t", "E9.3", printedErr, tol);
  // [i, j] = 2ij = 2k in the Clifford picture: [e₂e₃, e₃e₁] = 2 e₂e₃e₃e₁ = 2e₁e₂·(−1)·(−1)…
  const Dense<PGA, S> i = gens<PGA, S>({1, 2}), j = gens<PGA, S>({2, 0}), k = gens<PGA, S>({0, 1});
  c.checkResidual("[i, j] = 2ij = 2k with i = e₂e₃, j = e₃e₁, k = e₁e₂", maxAbsDiff(Dense<PGA, S>(i * j - j * i), Dense<PGA, S>(k * S(2))), S(0));
  c.note("E9.3: the adjoint's dual part is h₀v₁h₀* + ½[t, h₀v₀h₀*] = Rv₁ + t × Rv₀, i.e. Ad = [[R, 0], [TR, R]] "
         "with T x = t × x; the printed form uses v₁ in the commutator and the wrong order.");
}
SOMA_STUDY_SCALAR("GF-9.3-lie-algebra-adjoint", "se(3) as dual vectors: bracket, dot product, adjoint action", "GF §9.3", lieAdjoint);

// ---- GF §9.3, GF-9.3-quaternion-product-transference -----------------------------------------
template <class S> void transference(Context& c) {
  auto g = rng(934);
  const S tol = Tolerance<S>::identity(64);
  S worst = 0, real = 0;
  for (int t = 0; t < 20; ++t) {
    // (a₀ + a)(b₀ + b) = a₀b₀ − a·b + a₀b + b₀a + a × b with dual scalars and dual vectors.
    const DualNumber<S> a0(uni<S>(g), uni<S>(g)), b0(uni<S>(g), uni<S>(g));
    const Vec3<S> ar = randVec<S>(g), ad = randVec<S>(g), br = randVec<S>(g), bd = randVec<S>(g);
    // dual dot and cross
    const DualNumber<S> dotAB(ar.dot(br), ar.dot(bd) + ad.dot(br));
    const Vec3<S> crR = ar.cross(br), crD = ar.cross(bd) + ad.cross(br);
    const DualNumber<S> s = a0 * b0 - dotAB;
    const Vec3<S> vr = a0.re * br + b0.re * ar + crR;
    const Vec3<S> vd = a0.re * bd + a0.du * br + b0.re * ad + b0.du * ar + crD;
    Vec8<S> formula;
    formula << s.re, vr, s.du, vd;
    // the same product as 8-component dual quaternions and as Clifford elements
    const DualQuaternion<S> A(Quat<S>(a0.re, ar(0), ar(1), ar(2)), Quat<S>(a0.du, ad(0), ad(1), ad(2)));
    const DualQuaternion<S> B(Quat<S>(b0.re, br(0), br(1), br(2)), Quat<S>(b0.du, bd(0), bd(1), bd(2)));
    worst = std::max(worst, (dqCoeffs(A * B) - formula).cwiseAbs().maxCoeff());
    const Motor<S> MA = toMotor(A), MB = toMotor(B);
    worst = std::max(worst, (dqCoeffs(Motor<S>(MA * MB)) - formula).cwiseAbs().maxCoeff());
    // the real-quaternion formula it is transferred from
    const Quat<S> p(a0.re, ar(0), ar(1), ar(2)), q(b0.re, br(0), br(1), br(2));
    const Quat<S> pq = p * q;
    real = std::max(real, std::max(abs(pq.w() - (a0.re * b0.re - ar.dot(br))),
                                   (pq.vec() - (a0.re * br + b0.re * ar + ar.cross(br))).cwiseAbs().maxCoeff()));
  }
  c.checkResidual("quaternion product (a₀ + a)(b₀ + b) = a₀b₀ − a·b + a₀b + b₀a + a×b (20 random)", real, tol);
  c.checkResidual("transferred to dual scalars/vectors = 8-component product (DualQuaternion and Cℓ⁺(0,3,1))", worst, tol);
}
SOMA_STUDY_SCALAR("GF-9.3-quaternion-product-transference", "The principle of transference for the quaternion product",
           "GF §9.3", transference);

// ---- GF §9.3, GF-9.3-exp-log -----------------------------------------------------------------
template <class S> void expLog(Context& c) {
  auto g = rng(935);
  const S tol = Tolerance<S>::identity(256);
  S closedErr = 0, seriesErr = 0, dqErr = 0, tErr = 0, footErr = 0;
  for (int t = 0; t < 20; ++t) {
    // unit line v̌ = v₀ + εv₁ (v₀·v₀ = 1, v₀·v₁ = 0) through the point r: v₁ = r × v₀
    const Vec3<S> v0 = randUnit<S>(g), r = randVec<S>(g);
    const Vec3<S> v1 = r.cross(v0);
    const S th = uni<S>(g, 0.1, 3.0), p = uni<S>(g);
    // s = ½θ̌v̌ = ½(θv₀ + ε(θv₁ + pv₀)) as a bivector
    const auto B = twistBivector<S>(Vec3<S>(th * v0), Vec3<S>(th * v1 + p * v0));
    const Motor<S> E = exp(B);
    // closed form (cos θ/2 + sin θ/2 v₀) + ε(sin θ/2 v₁ + p/2 cos θ/2 v₀ − p/2 sin θ/2)
    const Vec4<S> a(cos(th / 2), sin(th / 2) * v0(0), sin(th / 2) * v0(1), sin(th / 2) * v0(2));
    const Vec3<S> dv = sin(th / 2) * v1 + (p / 2 * cos(th / 2)) * v0;
    const Vec4<S> cc(-p / 2 * sin(th / 2), dv(0), dv(1), dv(2));
    closedErr = std::max(closedErr, maxAbsDiff(E, toMotor(a, cc)));
    // The power series of the bivector in soma's products, summed until a term is below ε·|sum|
    // (a fixed 40 terms left a truncation error of 2e-43, visible in mpfr-256).
    Motor<S> sum(S(1)), term(S(1));
    for (int m = 1; m <= 400; ++m) {
      term = Motor<S>(term * B) / S(m);
      sum += term;
      if (term.maxAbs() <= Tolerance<S>::epsilon() * sum.maxAbs()) break;
    }
    seriesErr = std::max(seriesErr, maxAbsDiff(E, sum));
    // soma's DualQuaternion::exp of the twist (ω, v) = (θv₀, θv₁ + pv₀)
    Vec6<S> xi;
    xi << th * v0, th * v1 + p * v0;
    dqErr = std::max(dqErr, (dqCoeffs(E) - dqCoeffs(DualQuaternion<S>::exp(SE3Tangent<S>(xi)))).cwiseAbs().maxCoeff());
    // t = sin θ v₁ + (1 − cos θ) v₀ × v₁ + p v₀, read off the motor as 2 c a*
    const auto h = DualQuaternion<S>(Quat<S>(a(0), a(1), a(2), a(3)), Quat<S>(cc(0), cc(1), cc(2), cc(3)));
    const Vec3<S> tBook = sin(th) * v1 + (S(1) - cos(th)) * v0.cross(v1) + p * v0;
    tErr = std::max(tErr, (h.translation() - tBook).cwiseAbs().maxCoeff());
    // t = (I − R) r + p v₀ for the axis through r (convention A: v₁ = r × v₀)
    const Mat3<S> R = Quat<S>(a(0), a(1), a(2), a(3)).toRotationMatrix();
    footErr = std::max(footErr, (tBook - ((Mat3<S>::Identity() - R) * r + p * v0)).cwiseAbs().maxCoeff());
  }
  c.checkResidual("exp(½θ̌v̌) (soma's bivector exp) = the book's dual-angle closed form (20 random lines, θ, p)", closedErr, tol);
  c.checkResidual("… = the power series Σ Bᵐ/m! (summed to ε)", seriesErr, tol);
  c.checkResidual("… = DualQuaternion::exp of the twist (θv₀, θv₁ + pv₀)", dqErr, tol);
  c.checkResidual("t = sin θ v₁ + (1 − cos θ) v₀ × v₁ + p v₀", tErr, tol);
  c.checkResidual("t = (I − R) r + p v₀ with v₁ = r × v₀ (axis through r)", footErr, tol);
  // Extremes: θ → 0 (pure translation: 1 + ½t𝐞-part), θ = 2π (ȟ = −1), log near θ = π.
  const Vec3<S> tr(frac<S>(3, 10), frac<S>(-2, 10), frac<S>(9, 10));
  const Motor<S> pure = exp(twistBivector<S>(Vec3<S>::Zero(), tr));
  Motor<S> want(S(1));
  want.setCoeff(kE1n, tr(0) / 2), want.setCoeff(kE2n, tr(1) / 2), want.setCoeff(kE3n, tr(2) / 2);
  c.checkResidual("θ = 0: exp(½ε t) = 1 + ½t𝐞 (v̌ undefined, no division by θ)", maxAbsDiff(pure, want), tol);
  const Vec3<S> ax = randUnit<S>(g);
  const Motor<S> full = exp(twistBivector<S>(Vec3<S>(S(2) * pi<S>() * ax), Vec3<S>(Vec3<S>::Zero())));
  c.checkResidual("θ = 2π (p = 0): ȟ = −1", maxAbsDiff(full, Motor<S>(S(-1))), tol);
  const Vec3<S> w = (pi<S>() - frac<S>(1, 1000000)) * ax;
  Vec6<S> xi;
  xi << w, Vec3<S>(frac<S>(2, 10), frac<S>(1, 10), frac<S>(-4, 10));
  const Motor<S> nearPi = exp(twistBivector<S>(w, xi.template tail<3>()));
  const Vec8<S> nv = dqCoeffs(nearPi);
  const DualQuaternion<S> hn(Quat<S>(nv(0), nv(1), nv(2), nv(3)), Quat<S>(nv(4), nv(5), nv(6), nv(7)));
  c.checkResidual("log near θ = π (θ = π − 1e-6): DualQuaternion::log(exp) = the twist",
                  (hn.log().coeffs() - xi).cwiseAbs().maxCoeff(), tol);
  c.note("p is the translation along the axis (pitch × θ). The bivector exponential of multivector.hpp "
         "uses the closed form for Cℓ(0,3,1), whose B² = a + R has R ∝ the null pseudoscalar.");
}
SOMA_STUDY_SCALAR("GF-9.3-exp-log", "Exponential of a dual-angle screw; translation formula", "GF §9.3", expLog);

}  // namespace
}  // namespace soma::studies::gf09::SOMA_UNITY_ID
