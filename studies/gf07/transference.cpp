// Studies of GF chapter 7, §7.6: the principle of transference se(3) ≅ so(3) ⊗ 𝔻, the invariant
// 3-tensors Q_∞ and Q₀, the dual Killing form and the dual angle/axis of an SO(3, 𝔻) matrix.
#include "gf07/common.hpp"
#include "soma/algebra/screw.hpp"
#include "soma/geometry/lines/ruled_surface.hpp"

namespace soma::studies::gf07::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

/// [D(a), D(b)] = D([a, b]) over random real twists: the largest defect.
template <class T, class S> S bracketDefect(const rep::Se3Generators<T>& gen, std::mt19937_64& g, int samples) {
  S worst(0);
  for (int n = 0; n < samples; ++n) {
    const SE3Tangent<S> a(randomVec<S, 6>(g)), b(randomVec<S, 6>(g));
    const Matrix<T> da = rep::se3Element(gen, a.coeffs()), db = rep::se3Element(gen, b.coeffs());
    worst = maxOf(worst, maxAbs(Matrix<T>(comm(da, db) - rep::se3Element(gen, bracket(a, b).coeffs()))));
  }
  return worst;
}

// ---- GF §7.6, GF-7.6-transference -------------------------------------------------------------------
template <class S> void transferenceStudy(Context& c) {
  auto g = rng(761);
  const S tol = Tolerance<S>::identity(64);
  const auto so3 = so3Generators<S>();
  const rep::Se3Generators<S> D = rep::transference(so3);
  // The partitioned matrices [[L, 0], [0, L]] and [[0, 0], [L, 0]] are I₂ ⊗ L and E ⊗ L.
  S part(0);
  for (std::size_t a = 0; a < 3; ++a) {
    Matrix<S> rot = Matrix<S>::Zero(6, 6), tr = Matrix<S>::Zero(6, 6);
    rot.topLeftCorner(3, 3) = so3[a], rot.bottomRightCorner(3, 3) = so3[a];
    tr.bottomLeftCorner(3, 3) = so3[a];
    part = maxOf(part, maxOf(maxAbs(Matrix<S>(D[a] - rot)), maxAbs(Matrix<S>(D[a + 3] - tr))));
  }
  c.checkResidual("D(J_*) = [[L, 0], [0, L]] = I₂ ⊗ L, D(P_*) = [[0, 0], [L, 0]] = E ⊗ L (exact)", part, S(0));
  // The printed L ⊗ I₂, L ⊗ E are the same up to the perfect-shuffle permutation Π.
  Matrix<S> Pi = Matrix<S>::Zero(6, 6);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 2; ++b) Pi(a * 2 + b, b * 3 + a) = S(1);
  Matrix<S> i2 = Matrix<S>::Identity(2, 2), e = Matrix<S>::Zero(2, 2);
  e(1, 0) = S(1);
  S shuffle(0), literal(0);
  for (std::size_t a = 0; a < 3; ++a) {
    shuffle = maxOf(shuffle, maxAbs(Matrix<S>(rep::groupTensor(so3[a], i2) - Pi * D[a] * Pi.transpose())));
    shuffle = maxOf(shuffle, maxAbs(Matrix<S>(rep::groupTensor(so3[a], e) - Pi * D[a + 3] * Pi.transpose())));
    literal = maxOf(literal, maxAbs(Matrix<S>(rep::groupTensor(so3[a], i2) - D[a])));
  }
  c.checkResidual("the printed L ⊗ I₂, L ⊗ E = Π (I₂ ⊗ L, E ⊗ L) Πᵀ (perfect shuffle; exact)", shuffle, S(0));
  c.checkEqual("… but not equal to the partitioned matrices without the permutation", "differ", literal > S(0) ? "differ" : "equal");
  c.checkResidual("L ⊗ 𝔻 of the 3×3 representation satisfies the se(3) brackets", bracketDefect<S, S>(D, g, 20), tol);
  const rep::Se3Generators<S> ad = rep::se3AdjointGenerators<S>();
  S adj(0);
  for (std::size_t a = 0; a < 6; ++a) adj = maxOf(adj, maxAbs(Matrix<S>(D[a] - ad[a])));
  c.checkResidual("… and is the adjoint representation (exact)", adj, S(0));
  // "All representations of SO(3) become representations of SE(3) when tensored with 𝔻": L_j ⊗ 𝔻.
  S lj(0);
  for (int twoJ = 1; twoJ <= 4; ++twoJ) {
    const rep::So3Irrep<S> l = rep::so3Irrep<S>(twoJ);
    const std::array<CMat<S>, 3> gens{l.element(Vec3<S>(Vec3<S>::UnitX())), l.element(Vec3<S>(Vec3<S>::UnitY())),
                                      l.element(Vec3<S>(Vec3<S>::UnitZ()))};
    lj = maxOf(lj, bracketDefect<C<S>, S>(rep::transference(gens), g, 5) / S((twoJ + 1) * (twoJ + 1)));
  }
  c.checkResidual("L_j ⊗ 𝔻, j = ½, 1, 3/2, 2: representations of se(3) (defect/(2j+1)²)", lj, tol);
  // The dual numbers: aI + bE ↔ a + εb (E² = 0, E and I commute).
  S ring(0);
  for (int n = 0; n < 10; ++n) {
    const DualNumber<S> x(uniform<S>(g), uniform<S>(g)), y(uniform<S>(g), uniform<S>(g));
    const Matrix<S> mx = x.re * i2 + x.du * e, my = y.re * i2 + y.du * e;
    const DualNumber<S> p = x * y;
    ring = maxOf(ring, maxAbs(Matrix<S>(mx * my - (p.re * i2 + p.du * e))));
  }
  c.checkResidual("2×2 matrices aI + bE multiply as the dual numbers a + εb (E² = 0)", maxOf(ring, maxAbs(Matrix<S>(e * e))), tol);
  // se(3) ≅ so(3, 𝔻): the dual cross product is the bracket, the dual dot product is the
  // so(3) Killing form (−¼ of se(3)'s) with the reciprocal product as dual part.
  const Mat6<S> K = killingForm<SE3Tangent<S>>();
  S crossB(0), dotK(0), bac(0), jac(0);
  for (int n = 0; n < 20; ++n) {
    const Vec6<S> a = randomVec<S, 6>(g), b = randomVec<S, 6>(g), d = randomVec<S, 6>(g);
    const DualVec3<S> A = DualVec3<S>::of(a), B = DualVec3<S>::of(b), Dd = DualVec3<S>::of(d);
    crossB = maxOf(crossB, maxAbs(Vec6<S>(A.cross(B).coords() - screwBracket(a, b))));
    const DualNumber<S> dot = A.dot(B);
    dotK = maxOf(dotK, abs(dot.re + a.dot(Vec6<S>(K * b)) / S(4)) + abs(dot.du - reciprocalProduct(a, b)));
    // an identity between 3-vectors, a × (b × d) = b(a·d) − d(a·b), holds for dual vectors (lines)
    const DualNumber<S> ad_ = A.dot(Dd), ab = A.dot(B);
    DualVec3<S> rhs;
    rhs.re = B.re * ad_.re - Dd.re * ab.re;
    rhs.du = B.re * ad_.du + B.du * ad_.re - Dd.re * ab.du - Dd.du * ab.re;
    const DualVec3<S> lhs = A.cross(B.cross(Dd));
    bac = maxOf(bac, maxAbs(Vec6<S>(lhs.coords() - rhs.coords())));
    jac = maxOf(jac, maxAbs(Vec6<S>(A.cross(B.cross(Dd)).coords() + B.cross(Dd.cross(A)).coords() + Dd.cross(A.cross(B)).coords())));
  }
  c.checkResidual("dual cross product (ω₁ + εv₁) × (ω₂ + εv₂) = the se(3) bracket", crossB, tol);
  c.checkResidual("dual dot product = −¼ Killing form + ε reciprocal product", dotK, tol);
  c.checkResidual("transference: a × (b × c) = b(a·c) − c(a·b) holds with dual vectors", bac, S(4) * tol);
  c.checkResidual("transference: the Jacobi identity holds with dual vectors", jac, S(4) * tol);
  // Extremes: zero divisors have no inverse; functions of dual arguments f(a + εb) = f(a) + εbf'(a).
  bool threw = false;
  try {
    (void)(DualNumber<S>(S(1), S(2)) / DualNumber<S>(S(0), S(1)));
  } catch (const InvalidInput&) {
    threw = true;
  }
  c.checkEqual("ε (real part 0) is a zero divisor: division by it is refused", "throws", threw ? "throws" : "returned");
  const DualNumber<S> x(S(3) / S(2), S(7) / S(10)), r = x.sqrt();
  const DualNumber<S> r2 = r * r;
  c.checkResidual("√(a + εb)² = a + εb with √(a + εb) = √a + εb/(2√a)", abs(r2.re - x.re) + abs(r2.du - x.du), tol);
}
SOMA_STUDY_SCALAR("GF-7.6-transference", "Principle of transference: se(3) ≅ so(3) ⊗ 𝔻; L ⊗ 𝔻 is a representation of se(3)",
                  "GF §7.6", transferenceStudy);

// ---- GF §7.6, GF-7.6-invariant-3-tensors ---------------------------------------------------------------
/// Coefficients T_ijk (index 36i + 6j + k, 0-based) of the printed Q₀: 18 entries ±1 (seed 4415).
template <class S> Eigen::Matrix<S, Eigen::Dynamic, 1> printedQ0() {
  // (u, v, w) 1-based triples with their signs, row by row as printed
  const int t[18][4] = {{4, 2, 3, 1},  {6, 1, 2, 1},  {5, 3, 1, 1},  {5, 1, 3, -1}, {6, 2, 1, -1}, {4, 3, 2, -1},
                        {1, 5, 3, 1},  {3, 4, 2, 1},  {2, 6, 1, 1},  {2, 4, 3, -1}, {3, 5, 1, -1}, {1, 6, 2, -1},
                        {1, 2, 6, 1},  {3, 1, 5, 1},  {2, 3, 4, 1},  {2, 1, 6, -1}, {3, 2, 4, -1}, {1, 3, 5, -1}};
  Eigen::Matrix<S, Eigen::Dynamic, 1> q = Eigen::Matrix<S, Eigen::Dynamic, 1>::Zero(216);
  for (const auto& e : t) q(36 * (e[0] - 1) + 6 * (e[1] - 1) + (e[2] - 1)) = S(e[3]);
  return q;
}
template <class S> S trilinear(const Eigen::Matrix<S, Eigen::Dynamic, 1>& t, const Vec6<S>& u, const Vec6<S>& v, const Vec6<S>& w) {
  S sum(0);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) sum += t(36 * i + 6 * j + k) * u(i) * v(j) * w(k);
  return sum;
}
template <class S> void invariant3Tensors(Context& c) {
  auto g = rng(762);
  const S tol = Tolerance<S>::identity(64);
  const rep::So3Irrep<S> l1 = rep::so3Irrep<S>(2);
  // L₁ ⊗ L₁ ⊗ L₁ = (L₃ ⊕ L₂ ⊕ L₁) ⊕ (L₂ ⊕ L₁ ⊕ L₀) ⊕ L₁: one rotation invariant.
  const Matrix<S> h3 = rep::algebraTensorPower(l1.H, 3), p3 = rep::algebraTensorPower(l1.Jp, 3), m3 = rep::algebraTensorPower(l1.Jm, 3);
  c.checkEqual("L₁^⊗3 = L₃ ⊕ 2L₂ ⊕ 3L₁ ⊕ L₀ (27 = 7 + 10 + 9 + 1)", "L3 + 2 L2 + 3 L1 + L0",
               rep::so3Decomposition<S>(h3) == std::map<int, int>{{6, 1}, {4, 2}, {2, 3}, {0, 1}} ? "L3 + 2 L2 + 3 L1 + L0" : "other");
  c.checkEqual("one rotation-invariant 3-tensor (common null space of H, J₊, J₋ on ℂ²⁷)", 1, nullity<S>(stack<S>({h3, p3, m3})));
  // The printed 𝓘 in the basis u₀ = u₃, u± = u₁ ± iu₂ equals −2i times the alternating tensor.
  const C<S> i = imagUnit<S>();
  auto e = [](int k) { return CVec<S>(CVec<S>::Unit(3, k)); };
  const CVec<S> u0 = e(2), up = CVec<S>(e(0) + i * e(1)), um = CVec<S>(e(0) - i * e(1));
  auto t3 = [](const CVec<S>& a, const CVec<S>& b, const CVec<S>& d) { return kronVec<C<S>>(kronVec<C<S>>(a, b), d); };
  const CVec<S> I = t3(u0, up, um) - t3(u0, um, up) - t3(up, u0, um) + t3(um, u0, up) + t3(up, um, u0) - t3(um, up, u0);
  CVec<S> eps = CVec<S>::Zero(27);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int d = 0; d < 3; ++d)
        if (a != b && b != d && a != d) eps(9 * a + 3 * b + d) = C<S>(S(((b - a + 3) % 3 == 1) ? 1 : -1));
  c.checkResidual("𝓘 = u₀⊗v₊⊗w₋ − u₀⊗v₋⊗w₊ − … = −2i 𝓔 (the alternating tensor; exact)", maxAbs(CVec<S>(I + S(2) * i * eps)), S(0));
  S rot(0);
  for (int n = 0; n < 5; ++n) {
    const Matrix<S> W = skew(randomVec<S, 3>(g));
    rot = maxOf(rot, maxAbs(CVec<S>(toComplex<S>(rep::algebraTensorPower(W, 3)) * eps)));
  }
  c.checkResidual("𝓔 is rotation invariant: (Ω ⊗ 1 ⊗ 1 + 1 ⊗ Ω ⊗ 1 + 1 ⊗ 1 ⊗ Ω)𝓔 = 0", rot, tol);
  // Dualise: ǔ = u + εu', … in the triple product ǔ·(v̌ × w̌) (dual arithmetic on basis 6-vectors).
  Eigen::Matrix<S, Eigen::Dynamic, 1> re(216), du(216);
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b)
      for (int d = 0; d < 6; ++d) {
        const DualNumber<S> tp = DualVec3<S>::of(Vec6<S>(Vec6<S>::Unit(a))).dot(
            DualVec3<S>::of(Vec6<S>(Vec6<S>::Unit(b))).cross(DualVec3<S>::of(Vec6<S>(Vec6<S>::Unit(d)))));
        re(36 * a + 6 * b + d) = tp.re, du(36 * a + 6 * b + d) = tp.du;
      }
  // The printed Q_∞: −2 on even permutations of 123, +2 on odd ones, 0 otherwise (i, j, k = 1 … 6).
  Eigen::Matrix<S, Eigen::Dynamic, 1> Qinf = Eigen::Matrix<S, Eigen::Dynamic, 1>::Zero(216);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int d = 0; d < 3; ++d)
        if (a != b && b != d && a != d) Qinf(36 * a + 6 * b + d) = S(((b - a + 3) % 3 == 1) ? -2 : 2);
  const Eigen::Matrix<S, Eigen::Dynamic, 1> Q0 = printedQ0<S>();
  c.checkEqual("printed Q₀ has 18 non-zero entries", 18, (long long)(Q0.array() != S(0)).count());
  c.checkResidual("the printed Q_∞ is −2 × the real part of 𝓔(ǔ, v̌, w̌) (𝓔 extended by zeros; exact)",
                  maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(Qinf + S(2) * re)), S(0));
  c.checkResidual("the dual part of 𝓔(ǔ, v̌, w̌) is the printed Q₀ (exact)", maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(du - Q0)), S(0));
  // So 𝓘̌ = −2i(𝓔 + ε Q₀) = i(Q_∞ − 2εQ₀): the printed "𝓘̌ ∝ Q_∞ + εQ₀" has the factor κ = −2 from
  // the real part, and then κ·(dual part) = −2Q₀ ≠ Q₀.
  c.checkPrintedFails("𝓘̌ ∝ Q_∞ + εQ₀ (κ fixed by Q_∞ = κ𝓔: residual ‖Q₀ − κ·dual part‖)", "minor (normalisation)",
                      maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(Q0 - S(-2) * du)), S(0));
  c.checkResidual("corrected: 𝓘̌ ∝ Q_∞ − 2εQ₀, i.e. (Q_∞, −2Q₀) = κ(real, dual part) with κ = −2 (exact)",
                  maxOf(maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(Qinf + S(2) * re)),
                        maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(-S(2) * Q0 + S(2) * du))), S(0));
  // Both are SE(3)-invariant trilinear forms: killed by the coadjoint tensor cube of every generator.
  const auto co = rep::se3CoadjointGenerators<S>();
  S inv(0);
  for (const auto& G : co) {
    const Matrix<S> G3 = rep::algebraTensorPower(G, 3);
    inv = maxOf(inv, maxOf(maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(G3 * Qinf)), maxAbs(Eigen::Matrix<S, Eigen::Dynamic, 1>(G3 * Q0))));
  }
  c.checkResidual("Q_∞ and Q₀ are se(3)-invariant (coadjoint ⊗3 of every generator kills them; exact)", inv, S(0));
  // (Q)_ijk s_u s_v s_w = s_uᵀ Q [s_v, s_w] with Q_∞ = diag(−2I, 0), Q₀ = [[0, I], [I, 0]] of GF §6.4.
  const Mat6<S> qi = bookQinf<S>(), q0 = bookQ0<S>();
  S ci(0), c0(0);
  for (int n = 0; n < 20; ++n) {
    const Vec6<S> su = randomVec<S, 6>(g), sv = randomVec<S, 6>(g), sw = randomVec<S, 6>(g);
    const Vec6<S> br = screwBracket(sv, sw);
    ci = maxOf(ci, abs(trilinear(Qinf, su, sv, sw) - su.dot(Vec6<S>(qi * br))));
    c0 = maxOf(c0, abs(trilinear(Q0, su, sv, sw) - su.dot(Vec6<S>(q0 * br))));
  }
  c.checkResidual("(Q_∞)_ijk s_u s_v s_w = s_uᵀ Q_∞ [s_v, s_w]", ci, tol);
  c.checkResidual("(Q₀)_ijk s_u s_v s_w = s_uᵀ Q₀ [s_v, s_w]", c0, tol);
  c.note("The 3rd and 5th rows of the printed Q₀ lack their leading \"+\" (OCR); the entries are read as +1.");
}
SOMA_STUDY_SCALAR("GF-7.6-invariant-3-tensors", "Invariant 3-tensors: 𝓘 = −2i𝓔, dualised to Q_∞ and Q₀ (normalisation erratum)",
                  "GF §7.6", invariant3Tensors);

// ---- GF §7.6, GF-7.6-dual-killing-and-dual-angle ------------------------------------------------------
template <class S> void dualKillingAndAngle(Context& c) {
  auto g = rng(763);
  const S tol = Tolerance<S>::identity(64);
  S kill(0);
  for (int n = 0; n < 20; ++n) {
    const SE3Tangent<S> s1(randomVec<S, 6>(g)), s2(randomVec<S, 6>(g));
    const Mat3<S> O1 = skew(s1.ang()), O2 = skew(s2.ang()), T1 = skew(s1.lin()), T2 = skew(s2.lin());
    const DualNumber<S> k = rep::dualKillingForm(s1, s2);
    kill = maxOf(kill, abs(k.re - Mat3<S>(O1 * O2).trace()) + abs(k.du - Mat3<S>(O1 * T2 + T1 * O2).trace()));
    kill = maxOf(kill, abs(k.re + S(2) * s1.ang().dot(s2.ang())) + abs(k.du + S(2) * reciprocalProduct(s1.coeffs(), s2.coeffs())));
  }
  c.checkResidual("Tr(Š₁Š₂) = Tr(Ω₁Ω₂) + ε Tr(Ω₁T₂ + T₁Ω₂) = −2ω₁·ω₂ − 2ε(ω₁·v₂ + v₁·ω₂)", kill, tol);
  // The screw motion about (v; u = r × v) by θ = 0.9 with slide d = 0.35: Ř = R + εTR.
  const Vec3<S> v = randomUnit<S>(g), r = randomVec<S, 3>(g);
  const S theta = S(9) / S(10), d = S(35) / S(100);
  const SE3<S> m = screwMotion<S>(v, r, d / theta, theta);
  const rep::DualMat3<S> R = rep::dualRotation(m);
  const DualNumber<S> tr = R.trace();
  c.checkResidual("Tr Ř = 1 + 2cos θ − 2εd sin θ", abs(tr.re - S(1) - S(2) * cos(theta)) + abs(tr.du + S(2) * d * sin(theta)), tol);
  const rep::DualMat3<S> anti = R - R.transpose();
  const Mat3<S> U = skew(Vec3<S>(r.cross(v))), V = skew(v);
  c.checkResidual("Ř − Řᵀ = 2sin θ V + 2ε(sin θ U + d cos θ V)",
                  maxOf(maxAbs(Mat3<S>(anti.re - S(2) * sin(theta) * V)),
                        maxAbs(Mat3<S>(anti.du - S(2) * (sin(theta) * U + d * cos(theta) * V)))), tol);
  // Reading θ̌ and v̌ back: the book's route (divide by sin θ) against rep::dualAngleAxis (the log).
  auto bookRoute = [](const rep::DualMat3<S>& M) {
    const rep::DualMat3<S> A = M - M.transpose();
    const Vec3<S> a0 = SO3Tangent<S>::vee(A.re).coeffs() / S(2), a1 = SO3Tangent<S>::vee(A.du).coeffs() / S(2);
    const DualNumber<S> t = M.trace();
    const S s = sqrt(a0.squaredNorm()), th = atan2(s, (t.re - S(1)) / S(2));
    const S dd = -t.du / (S(2) * s);
    const Vec3<S> dir = a0 / s;
    const Vec3<S> mom = (a1 - dd * cos(th) * dir) / s;
    return std::tuple<S, S, Vec3<S>, Vec3<S>>{th, dd, dir, mom};
  };
  const auto [th, dd, dir, mom] = bookRoute(R);
  const rep::DualAngleAxis<S> da = rep::dualAngleAxis(R);
  c.checkResidual("book route at θ = 0.9: θ, d, v, u recovered", abs(th - theta) + abs(dd - d) + maxAbs(Vec3<S>(dir - v)) +
                                                                   maxAbs(Vec3<S>(mom - r.cross(v))), S(16) * tol);
  c.checkResidual("rep::dualAngleAxis at θ = 0.9: θ, d, v, u recovered", abs(da.angle.re - theta) + abs(da.angle.du - d) +
                  maxAbs(Vec3<S>(da.direction - v)) + maxAbs(Vec3<S>(da.moment - r.cross(v))), S(16) * tol);
  // Extremes: θ = π (the antisymmetric part vanishes: the book's route is 0/0) and θ = 0 (pure
  // translation). The half-turn about the z-axis through r = (1, 2, 0) with slide d is exact:
  // R = diag(−1, −1, 1), t = (I − R)r + d e_z = (2, 4, d).
  Mat3<S> Rpi = Mat3<S>::Zero();
  Rpi(0, 0) = S(-1), Rpi(1, 1) = S(-1), Rpi(2, 2) = S(1);
  const Vec3<S> rpi(S(1), S(2), S(0)), ez(S(0), S(0), S(1));
  const SE3<S> mpi(SO3<S>::fromMatrix(Rpi), Vec3<S>(S(2), S(4), d));
  const rep::DualMat3<S> Rdpi = rep::dualRotation(mpi);
  const rep::DualMat3<S> antiPi = Rdpi - Rdpi.transpose();
  c.checkResidual("θ = π exactly: Ř − Řᵀ = 2sin θ V + 2ε(sin θ U + d cos θ V) = −2εdV: real part 0 (exact)",
                  maxOf(maxAbs(antiPi.re), maxAbs(Mat3<S>(antiPi.du + S(2) * d * skew(ez)))), S(0));
  const rep::DualAngleAxis<S> dpi = rep::dualAngleAxis(Rdpi);
  const S sgn = dpi.direction.dot(ez) < S(0) ? S(-1) : S(1);
  c.checkResidual("θ = π: rep::dualAngleAxis gives θ = π, d, v = e_z, u = r × v (up to the sign of the axis)",
                  abs(dpi.angle.re - pi<S>()) + abs(sgn * dpi.angle.du - d) + maxAbs(Vec3<S>(sgn * dpi.direction - ez)) +
                      maxAbs(Vec3<S>(sgn * dpi.moment - rpi.cross(ez))), S(64) * tol);
  const auto [thp, ddp, dirp, momp] = bookRoute(Rdpi);
  c.checkEqual("θ = π: the book's route divides 0 by sin θ = 0", "not finite",
               (!isFinite(ddp) || !allFinite(dirp) || !allFinite(momp)) ? "not finite" : "finite");
  (void)thp;
  const SE3<S> tr0(SO3<S>(), Vec3<S>(S(0), S(3), S(4)));
  const rep::DualAngleAxis<S> d0 = rep::dualAngleAxis(rep::dualRotation(tr0));
  c.checkEqual("θ = 0: a pure translation (dual angle εd, direction only)", "pure translation",
               d0.pureTranslation ? "pure translation" : "screw");
  c.checkNear("θ = 0: d = |t| = 5", S(5), d0.angle.du, tol);
}
SOMA_STUDY_SCALAR("GF-7.6-dual-killing-and-dual-angle", "Dual Killing form; dual angle and axis of an SO(3, 𝔻) matrix",
                  "GF §7.6", dualKillingAndAngle);

}  // namespace
}  // namespace soma::studies::gf07::SOMA_UNITY_ID
