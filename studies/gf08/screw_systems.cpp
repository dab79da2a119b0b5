// Studies of GF chapter 8 (screw systems), every one in the asked scalar (--scalar; the figure of
// GF-8.3-regulus-quadrics is drawn in double by soma::render): Grassmannian coordinates, reciprocity,
// completion and isotropy algebras, the Gibson–Hunt normal forms (Tables 8.1, 8.2) and their
// identification, the invariants of §8.4 with errata E8.2–E8.11, union and intersection (§8.5),
// and the regulus figure of an IA₁ 3-system.
#include "soma/algebra/small_linalg.hpp"
#include "soma/geometry/screws/identification.hpp"
#include "soma/render/render.hpp"
#include "soma/studies/study.hpp"

#include <cmath>
#include <random>

namespace soma::studies::gf08::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

constexpr const char* kChapter = "GF 8 — Screw systems";
using T = ScrewSystemType;
using std::abs;
using std::cos;
using std::max;
using std::pow;
using std::min;
using std::sin;
using std::sqrt;
using std::tan;

std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }
/// Uniform draw made in double and cast to S (the same inputs on every rung).
template <class S = double> S uni(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return scalarCast<S>(std::uniform_real_distribution<double>(lo, hi)(g));
}
template <class S> Vec6<S> randomScrew(std::mt19937_64& g) {
  Vec6<S> s;
  for (int i = 0; i < 6; ++i) s(i) = uni<S>(g);
  return s;
}
template <class S> ScrewMatX<S> randomGenerators(int n, std::mt19937_64& g) {
  ScrewMatX<S> m(6, n);
  for (int j = 0; j < n; ++j) m.col(j) = randomScrew<S>(g);
  return m;
}
template <class S = double> ScrewMatX<S> randomGL(int n, std::mt19937_64& g) {
  ScrewMatX<S> m(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) m(i, j) = uni<S>(g, -0.5, 0.5) + S(i == j ? 2 : 0);
  return m;
}
/// A screw from six numbers (integers, S values, or the study's decimal inputs cast to S).
template <class S> Vec6<S> scr(const std::type_identity_t<S>& wx, const std::type_identity_t<S>& wy, const std::type_identity_t<S>& wz,
                               const std::type_identity_t<S>& vx, const std::type_identity_t<S>& vy, const std::type_identity_t<S>& vz) {
  Vec6<S> s;
  s << wx, wy, wz, vx, vy, vz;
  return s;
}
template <class S> ScrewMatX<S> cols(std::initializer_list<Vec6<S>> c) {
  ScrewMatX<S> m(6, Eigen::Index(c.size()));
  int j = 0;
  for (const auto& s : c) m.col(j++) = s;
  return m;
}
template <class D> typename D::Scalar maxAbs(const Eigen::MatrixBase<D>& m) {
  return m.size() ? typename D::Scalar(m.cwiseAbs().maxCoeff()) : typename D::Scalar(0);
}
/// Determinant of a small matrix by soma's elimination (small_linalg.hpp): Eigen's LU for five
/// scalars would double this file's compile time.
template <class D> typename D::Scalar detS(const Eigen::MatrixBase<D>& m) {
  using S = typename D::Scalar;
  return detail::smallDeterminant<S>(detail::SmallMat<S>(m));
}
template <class S> ScrewMatX<S> gram(const ScrewMatX<S>& s, const Mat6<S>& q) { return s.transpose() * q * s; }
/// The n-th compound (∧ⁿ) of a 6×6 matrix: minors in the lexicographic order of wedge().
template <class S> ScrewMatX<S> compound(const Mat6<S>& a, int n) {
  std::vector<std::vector<int>> sets;
  std::vector<int> idx(n);
  for (int i = 0; i < n; ++i) idx[i] = i;
  while (true) {
    sets.push_back(idx);
    int i = n - 1;
    while (i >= 0 && idx[i] == 6 - n + i) --i;
    if (i < 0) break;
    ++idx[i];
    for (int j = i + 1; j < n; ++j) idx[j] = idx[j - 1] + 1;
  }
  ScrewMatX<S> c(sets.size(), sets.size());
  for (std::size_t r = 0; r < sets.size(); ++r)
    for (std::size_t k = 0; k < sets.size(); ++k) {
      ScrewMatX<S> m(n, n);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) m(i, j) = a(sets[r][i], sets[k][j]);
      c(r, k) = detS(m);
    }
  return c;
}
/// The local names of a study body in S (V6, M6, MX, Vec3d, SE3d, SO3d, VecX, kTol = 64 ulps).
#define GF08_SCALAR_NAMES                                 \
  using V6 = Vec6<S>;                                     \
  using M6 = Mat6<S>;                                     \
  using MX = ScrewMatX<S>;                                \
  using Vec3d = Vec3<S>;                                  \
  using SE3d = SE3<S>;                                    \
  using SO3d = SO3<S>;                                    \
  using VecX = Eigen::Matrix<S, Eigen::Dynamic, 1>;       \
  const S kTol = Tolerance<S>::identity(64);              \
  (void)kTol
struct Row {
  T t;
  std::array<double, 3> p;
};
std::vector<Row> twoRows() {
  return {{T::IIC_2, {}}, {T::IB0sup_2, {}}, {T::IIA0_2, {}}, {T::IIBp_2, {0.7}}, {T::IIB0_2, {}},
          {T::IBp_2, {0.7}}, {T::IIAp_2, {0.7}}, {T::IA_2, {0.7, -0.3}}};
}
std::vector<Row> threeRows() {
  return {{T::IID_3, {}},           {T::IIA0_3, {}},          {T::IIC0_3, {}},
          {T::IICp_3, {0.7}},       {T::ICp_3, {0.7}},        {T::IC0_3, {}},
          {T::IIB_3, {0.7}},        {T::IB0_3, {0.7, 0.3}},   {T::IB3_3, {0.7, -0.3}},
          {T::IIAp_3, {0.7}},       {T::IA2_3, {0.7, -0.3}},  {T::IA1_3, {1.1, 0.7, -0.3}}};
}

/// Identify posed normal forms of every row of a table.
/// The normal form of a table row in W (its parameters converted exactly from double).
template <class W> ScrewMatX<W> normalFormIn(const Row& r) {
  std::array<W, 3> p;
  for (int i = 0; i < 3; ++i) p[i] = scalarCast<W>(r.p[i]);
  return ScrewMatX<W>(screwSystemNormalForm<W>(r.t, p));
}


// The studies' decimal inputs (p = 0.7, p_b = −0.3, m11 = 0.3, …) are those doubles cast to S, the same
// numbers as the normal forms' parameters (normalFormIn): inputs, never expected values computed in double.

/// A normal form from parameters in S (rows whose parameters the study computes in S).
template <class S> struct RowS {
  T t;
  std::array<S, 3> p;
};
template <class S> ScrewMatX<S> nfS(const RowS<S>& r) { return ScrewMatX<S>(screwSystemNormalForm<S>(r.t, r.p)); }

// ---- GF §8.1 ---------------------------------------------------------------------------------
template <class S> void grassmannian(Context& c) {
  GF08_SCALAR_NAMES;
  auto g = rng(81);
  S worstM = 0, worstAd = 0;
  for (int n = 1; n <= 5; ++n) {
    const MX s = randomGenerators<S>(n, g), m = randomGL<S>(n, g);
    const auto w = wedge<S>(s), wm = wedge<S>(MX(s * m));
    worstM = std::max(worstM, (wm - w * detS(m)).cwiseAbs().maxCoeff() / w.cwiseAbs().maxCoeff());
    const SE3d x = SE3d::Random(g);
    const auto wa = wedge<S>(MX(x.adjoint() * s));
    worstAd = std::max(worstAd, (wa - compound<S>(x.adjoint(), n) * w).cwiseAbs().maxCoeff());
  }
  // Each coordinate is an n×n minor (n ≤ 5) of s·M, by elimination: ≲ n³ε relative to the largest; 256ε
  // (64ε held in double at 57ε by chance; float, long double and float128 reach 130–160ε).
  c.checkResidual<S>("s'_i = Σ m_ij s_j: Plücker vector scales by det M (n = 1…5, relative; bound 256ε ≥ n³ε)", worstM,
                     Tolerance<S>::identity(256));
  c.checkResidual<S>("Plücker vector of Ad(g)Δ = ∧ⁿAd(g) applied to that of Δ (Cauchy–Binet, n = 1…5)",
                  worstAd, Tolerance<S>::identity(256));
  // Nearly dependent generators: the rank decision and how far the input was from it.
  MX s = randomGenerators<S>(3, g);
  // 64ε·r (1.4e-14 in double): below the rank threshold Tolerance::rank() = 1024ε on every rung
  s.col(2) = s.col(0) - s.col(1) + randomScrew<S>(g) * S(S(64) * Tolerance<S>::epsilon());
  const ScrewSystem<S> d(s);
  c.checkEqual("generators s₁, s₂, s₁ − s₂ + 64ε·r span a 2-system", 2, d.dimension());
  c.note("dropped singular-value ratio " + toString(d.droppedRatio(), 3) + " ≤ Tolerance::rank() = " +
         toString(Tolerance<S>::rank(), 3));
}

template <class S> void oneSystems(Context& c) {
  GF08_SCALAR_NAMES;
  auto g = rng(82);
  S worst = 0, worstQ = 0;
  for (int k = 0; k < 20; ++k) {
    const Vec3d w = Vec3d(uni<S>(g), uni<S>(g), uni<S>(g)), q = Vec3d(uni<S>(g), uni<S>(g), uni<S>(g));
    const S p = uni<S>(g, -3, 3);
    const V6 s = scr<S>(w.x(), w.y(), w.z(), 0, 0, 0) + (V6() << Vec3d::Zero(), Vec3d(q.cross(w) + p * w)).finished();
    // Q_p with α = p, β = 1: sᵀQ_p s = 0 iff pitch p.
    M6 qp = M6::Zero();
    qp.template topLeftCorner<3, 3>() = -2 * p * Mat3<S>::Identity();
    qp.template topRightCorner<3, 3>().setIdentity();
    qp.template bottomLeftCorner<3, 3>().setIdentity();
    worstQ = std::max(worstQ, abs(S(s.transpose() * qp * s)) / w.squaredNorm());
    const auto id = identifyScrewSystem<S>(MX(s));
    worst = max(worst, id.type == T::Screw ? S(abs(S(id.parameters[0] - p))) : S(1));
    // p = −sᵀQ₀s / sᵀQ∞s
    worst = std::max(worst, abs(-S(s.transpose() * kleinForm<S>() * s) /
                                S(s.transpose() * infinityForm<S>() * s) - p));
  }
  c.checkResidual<S>("sᵀQ_p s = 0 for 20 random screws of pitch p (Q_p = [[−2pI, I], [I, 0]])", worstQ, kTol * 16);
  c.checkResidual<S>("pitch round trip: identify(span s) = screw(p) and −sᵀQ₀s/sᵀQ∞s = p", worst, kTol * 16);
  const auto tr = identifyScrewSystem<S>(MX(scr<S>(0, 0, 0, 0.3, -1, 2)));
  c.checkEqual("p = ∞: a pure translation", "translation (p=∞)", screwSystemTypeName(tr.type));
}

template <class S> void reciprocal(Context& c) {
  GF08_SCALAR_NAMES;
  auto g = rng(83);
  S worstDual = 0, worstEq = 0, worstProd = 0;
  bool dims = true;
  for (int n = 0; n <= 6; ++n) {
    const ScrewSystem<S> d(randomGenerators<S>(n, g));
    const auto r = d.reciprocal();
    dims = dims && r.dimension() == 6 - n;
    worstDual = std::max(worstDual, r.reciprocal().distanceTo(d));
    const SE3d x = SE3d::Random(g);
    worstEq = std::max(worstEq, d.transformed(x).reciprocal().distanceTo(r.transformed(x)));
    worstProd = std::max(worstProd, maxAbs(MX(d.basis().transpose() * kleinForm<S>() * r.basis())));
  }
  c.checkEqual("dim Δ̄ = 6 − n for n = 0…6", "yes", dims ? "yes" : "no");
  c.checkResidual<S>("s_iᵀQ₀ s̄_j = 0 for bases of Δ and Δ̄", worstProd, kTol);
  c.checkResidual<S>("reciprocal of the reciprocal = Δ (largest principal-angle sine)", worstDual, kTol);
  c.checkResidual<S>("reciprocal of Ad(g)Δ = Ad(g) of the reciprocal", worstEq, kTol * 16);
  // E8.1: the intended invariance (Ad s_i)ᵀQ₀(Ad s_j) = s_iᵀQ₀s_j.
  const SE3d x = SE3d::Random(g);
  const V6 a = randomScrew<S>(g), b = randomScrew<S>(g);
  c.checkNear<S>("(Ad(g)s_i)ᵀQ₀(Ad(g)s_j) = s_iᵀQ₀s_j (E8.1: the printed line has s_i on both sides)",
              reciprocalProduct<S>(a, b), reciprocalProduct<S>(x.adjoint() * a, x.adjoint() * b), kTol * 8);
  // Screws of Δ ∩ Δ̄ are lines: IIA(p=0) (a star of lines) is self-reciprocal.
  const ScrewSystem<S> star(MX(x.adjoint() * normalFormIn<S>({T::IIA0_3, {}})));
  c.checkResidual<S>("IIA(p=0) star of lines is its own reciprocal (every screw a line)",
                  star.reciprocal().distanceTo(star), kTol * 16);
  // 5-systems ↔ the pitch of the reciprocal 1-system; 4-systems ↔ reciprocal 2-systems.
  const ScrewSystem<S> five(MX(x.adjoint() * ScrewSystem<S>(normalFormIn<S>({T::Screw, {0.4}})).reciprocal().basis()));
  const auto id5 = identifyScrewSystem(five);
  c.checkNear<S>("5-system reciprocal to a screw of pitch 0.4: identified pitch", 0.4, id5.parameters[0], kTol * 16);
}

template <class S> void completionStudy(Context& c) {
  GF08_SCALAR_NAMES;
  const std::vector<std::pair<Row, int>> rows = {
      {{T::IIC_2, {}}, 2},   {{T::IB0sup_2, {}}, 2}, {{T::IIA0_2, {}}, 3},     {{T::IIBp_2, {0.7}}, 3},
      {{T::IIB0_2, {}}, 3},  {{T::IBp_2, {0.7}}, 4}, {{T::IIAp_2, {0.7}}, 6},  {{T::IA_2, {0.7, -0.3}}, 6},
      {{T::IID_3, {}}, 3},   {{T::IIA0_3, {}}, 3},   {{T::IIC0_3, {}}, 3},     {{T::IICp_3, {0.7}}, 3},
      {{T::IC0_3, {}}, 4},   {{T::ICp_3, {0.7}}, 4}, {{T::IIB_3, {0.7}}, 6},   {{T::IB3_3, {0.7, -0.3}}, 6},
      {{T::IB0_3, {0.7, -0.3}}, 6}, {{T::IIAp_3, {0.7}}, 6}, {{T::IA2_3, {0.7, -0.3}}, 6},
      {{T::IA1_3, {1.1, 0.7, -0.3}}, 6}};
  std::string seq;
  auto g = rng(84);
  for (const auto& [row, dim] : rows) {
    std::vector<int> dims;
    // Posed: the completion group is conjugated, its dimension is invariant.
    const ScrewSystem<S> d(MX(SE3d::Random(g).adjoint() * normalFormIn<S>(row)));
    const auto comp = completion(d, &dims);
    c.checkEqual("completion dimension of " + screwSystemTypeName(row.t) + " (" +
                     std::to_string(screwSystemTypeDimension(row.t)) + "-system, posed)",
                 dim, comp.dimension());
    c.checkEqual("… Δ_∞ is a subalgebra", "yes", comp.isSubalgebra() ? "yes" : "no");
    if (row.t == T::IA_2 || row.t == T::IBp_2) {
      seq += screwSystemTypeName(row.t) + ": dim Δ_i =";
      for (int k : dims) seq += " " + std::to_string(k);
      seq += "; ";
    }
  }
  c.note("Derived systems Δ_{i+1} = Δ_i ⊕ [Δ₁, Δ_i]: " + seq);
}

template <class S> void isotropyStudy(Context& c) {
  GF08_SCALAR_NAMES;
  const std::vector<std::pair<Row, int>> rows = {
      {{T::IIC_2, {}}, 4},   {{T::IB0sup_2, {}}, 2}, {{T::IIA0_2, {}}, 1},     {{T::IIBp_2, {0.7}}, 2},
      {{T::IIB0_2, {}}, 2},  {{T::IBp_2, {0.7}}, 1}, {{T::IIAp_2, {0.7}}, 1},  {{T::IA_2, {0.7, -0.3}}, 0},
      {{T::IID_3, {}}, 6},   {{T::IIA0_3, {}}, 3},   {{T::IIC0_3, {}}, 4},     {{T::IICp_3, {0.7}}, 4},
      {{T::ICp_3, {0.7}}, 2}, {{T::IC0_3, {}}, 2},   {{T::IIB_3, {0.7}}, 3},   {{T::IB3_3, {0.7, -0.3}}, 2},
      {{T::IB0_3, {0.7, -0.3}}, 0}, {{T::IIAp_3, {0.7}}, 3}, {{T::IA2_3, {0.7, -0.3}}, 1},
      {{T::IA1_3, {1.1, 0.7, -0.3}}, 0}};
  auto g = rng(85);
  S worstWedge = 0;
  for (const auto& [row, dim] : rows) {
    const MX nf = normalFormIn<S>(row);
    const ScrewSystem<S> d(nf);
    const auto iso = isotropyAlgebra(d);
    c.checkEqual("isotropy-algebra dimension of " + screwSystemTypeName(row.t) + " (" +
                     std::to_string(nf.cols()) + "-system)", dim, iso.dimension());
    // The book's form: Σ_k s₁∧…∧[s, s_k]∧…∧s_n = 0 for s in the isotropy algebra.
    for (int k = 0; k < iso.dimension(); ++k) {
      const V6 s = iso.basis().col(k);
      VecX sum = VecX::Zero(wedge<S>(nf).size());
      for (int j = 0; j < nf.cols(); ++j) {
        MX m = nf;
        m.col(j) = screwBracket<S>(s, nf.col(j));
        sum += wedge<S>(m);
      }
      worstWedge = std::max(worstWedge, sum.cwiseAbs().maxCoeff());
    }
  }
  c.checkResidual<S>("isotropy algebra satisfies Σ s₁∧…∧[s,s_k]∧…∧s_n = 0 (GF §8.2, §8.3)", worstWedge, kTol);
  // Group isotropy: discrete symmetries π-rotations (IA 2-system: about x, y, z).
  const ScrewSystem<S> ia(normalFormIn<S>({T::IA_2, {0.7, -0.3}}));
  S worst = 0;
  for (int a = 0; a < 3; ++a) {
    const SE3d rpi(SO3d::fromAxisAngle(Vec3d::Unit(a), pi<S>()), Vec3d::Zero());
    worst = std::max(worst, ia.transformed(rpi).distanceTo(ia));
  }
  c.checkResidual<S>("IA 2-system: π-rotations about x, y, z map it to itself (Z₂×Z₂)", worst, kTol * 16);
  (void)g;
}

/// Every row's normal form posed by a random motion and a random basis change, built in W and
/// identified in W: the type, the parameters and the frame recovered to W's precision.
template <class W> void tableIdentification(Context& c, const std::vector<Row>& rows, std::uint64_t seed, int trials) {
  auto g = rng(seed);
  for (const auto& row : rows) {
    int ok = 0;
    W worstP = 0, worstFrame = 0;
    for (int k = 0; k < trials; ++k) {
      const SE3<W> x = SE3<W>::Random(g);
      const ScrewMatX<W> nf = normalFormIn<W>(row);
      const ScrewMatX<W> gl = randomGL(int(nf.cols()), g).unaryExpr([](double v) { return scalarCast<W>(v); });
      const auto id = identifyScrewSystem<W>(ScrewMatX<W>(x.adjoint() * nf * gl));
      if (id.type != row.t) continue;
      ++ok;
      for (int i = 0; i < id.parameterCount; ++i) {
        const W d = abs(id.parameters[i] - scalarCast<W>(row.p[i]));
        if (d > worstP) worstP = d;
      }
      if (id.frameResidual > worstFrame) worstFrame = id.frameResidual;
    }
    c.checkEqual(screwSystemTypeName(row.t) + ": posed normal forms identified (of " + std::to_string(trials) + ")",
                 trials, ok);
    c.checkResidual<W>("… parameters recovered and frame maps the normal form onto the input",
                       worstP > worstFrame ? worstP : worstFrame, Tolerance<W>::identity(4096));
  }
}

template <class W> void normalForms2(Context& c) {
  tableIdentification<W>(c, twoRows(), 86, 25);
  const auto id = identifyScrewSystem<W>(normalFormIn<W>({T::IBp_2, {-0.7}}));
  c.checkNear<W>("IB: the sign of p is removable (normal form with p = −0.7 identified as p = 0.7)", scalarCast<W>(0.7),
                 id.parameters[0], Tolerance<W>::identity(64));
}

// GF §8.2.7 reduction and erratum E8.2.
template <class S> void reduction2(Context& c) {
  GF08_SCALAR_NAMES;
  auto g = rng(87);
  S worst = 0;
  for (int k = 0; k < 50; ++k) {
    const S pa = uni<S>(g, -2, 2), pb = pa - uni<S>(g, 0.1, 2);
    const auto id = identifyScrewSystem<S>(
        MX(SE3d::Random(g).adjoint() * nfS<S>({T::IA_2, {pa, pb}}) * randomGL<S>(2, g)));
    worst = max(worst, id.type == T::IA_2 ? max(S(abs(S(id.parameters[0] - pa))), S(abs(S(id.parameters[1] - pb)))) : S(1));
  }
  c.checkResidual<S>("50 random Ad(g)-images of IA(p_a, p_b) with random bases: (p_a, p_b) recovered (4096ε, as Tables 8.1/8.2)", worst,
                     Tolerance<S>::identity(4096));
  // E8.2: (M Q' Mᵀ)₁₂ = m11 m21 q11 + (m11 m22 + m12 m21) q12 + m12 m22 q22.
  const S m11 = 0.3, m12 = -1.2, m21 = 0.8, m22 = 0.45, q11 = 1.7, q12 = -0.6, q22 = 0.9;
  Mat2<S> m, q;
  m << m11, m12, m21, m22;
  q << q11, q12, q12, q22;
  const S exact = (m * q * m.transpose())(0, 1);
  const S printed = m11 * m21 * q11 + (m11 * m22 + m12 * m22) * q12 + m12 * m22 * q22;
  const S fixed = m11 * m21 * q11 + (m11 * m22 + m12 * m21) * q12 + m12 * m22 * q22;
  c.checkNear<S>("off-diagonal of MQ'Mᵀ with (m11 m22 + m12 m21) q'12", exact, fixed, kTol);
  c.checkPrintedFails<S>("off-diagonal with (m11 m22 + m12 m22) q'12", "E8.2", abs(printed - exact), kTol);
}

// GF §8.2 IA cylindroid: real lines, angle and distance; pitch and axis position along the cylindroid.
template <class S> void cylindroid(Context& c) {
  GF08_SCALAR_NAMES;
  const S pa = 0.7, pb = -0.3;
  const V6 s1 = scr<S>(sqrt(-pb), sqrt(pa), 0, pa * sqrt(-pb), pb * sqrt(pa), 0);
  const V6 s2 = scr<S>(-sqrt(-pb), sqrt(pa), 0, -pa * sqrt(-pb), pb * sqrt(pa), 0);
  auto pitch = [](const V6& s) { return s.template head<3>().dot(s.template tail<3>()) / s.template head<3>().squaredNorm(); };
  c.checkResidual<S>("s₁' and s₂' (GF §8.2.7) have pitch 0", std::max(abs(pitch(s1)), abs(pitch(s2))), kTol);
  const Vec3d w1 = s1.template head<3>(), w2 = s2.template head<3>();
  c.checkNear<S>("cos φ = (p_a + p_b)/(p_a − p_b)", (pa + pb) / (pa - pb), w1.dot(w2) / (w1.norm() * w2.norm()), kTol);
  c.checkNear<S>("s₁'ᵀQ₀s₂' = 4 p_a p_b", 4 * pa * pb, reciprocalProduct<S>(s1, s2), kTol);
  // Independent: distance between the two lines along their common perpendicular (the z-axis).
  const Vec3d q1 = w1.cross(Vec3d(s1.template tail<3>())) / w1.squaredNorm(), q2 = w2.cross(Vec3d(s2.template tail<3>())) / w2.squaredNorm();
  const Vec3d n = w1.cross(w2).normalized();
  const S l = (q2 - q1).dot(n), sinphi = w1.cross(w2).dot(n) / (w1.norm() * w2.norm());
  c.checkNear<S>("−l sin φ = 4 p_a p_b / (p_a − p_b) (l from the common perpendicular)", 4 * pa * pb / (pa - pb),
              -l * sinphi * w1.norm() * w2.norm() / (pa - pb), kTol * 4);
  // Posed IA system: pitch and axis of the screw at angle θ (in the canonical frame).
  auto g = rng(88);
  const SE3d x = SE3d::Random(g);
  const auto id = identifyScrewSystem<S>(MX(x.adjoint() * nfS<S>({T::IA_2, {pa, pb}}) * randomGL<S>(2, g)));
  S worst = 0;
  for (int k = 0; k < 24; ++k) {
    const S th = pi<S>() * k / 24;
    const V6 local = cos(th) * id.normalForm.col(0) + sin(th) * id.normalForm.col(1);
    const V6 world = id.frame.adjoint() * local;
    const V6 back = id.frame.inverse().adjoint() * world;
    const Vec3d w = back.template head<3>(), v = back.template tail<3>();
    const S p = w.dot(v) / w.squaredNorm();
    const Vec3d foot = w.cross(v) / w.squaredNorm();
    worst = std::max({worst, abs(p - (pa * cos(th) * cos(th) + pb * sin(th) * sin(th))),
                      abs(foot.z() - (pb - pa) / 2 * sin(2 * th)), abs(foot.x()) + abs(foot.y())});
  }
  c.checkResidual<S>("posed IA: p(θ) = p_a cos²θ + p_b sin²θ, axis meets the z-axis at z = (p_b − p_a)/2 sin 2θ",
                  worst, kTol * 64);
}

template <class S> void generalities3(Context& c) {
  GF08_SCALAR_NAMES;
  // G(3,6) has dimension 9 and SE(3) 6: the generic 3-systems (IA₁) have 3 moduli and trivial
  // isotropy algebra; the Segre-type split into I (meets Q₀ in a conic) and II (in a pitch quadric).
  auto g = rng(89);
  const ScrewSystem<S> d(randomGenerators<S>(3, g));
  const auto id = identifyScrewSystem(d);
  c.checkEqual("a random 3-system is of type IA₁ (3 moduli)", "IA₁", screwSystemTypeName(id.type));
  c.checkEqual("… with isotropy algebra of dimension 0", 0, isotropyAlgebra(d).dimension());
  // Type II: contained in one pitch quadric — IIA(p) normal form has Υ_p = Υ₀ + pΥ∞ = 0.
  const MX iia = normalFormIn<S>({T::IIAp_3, {0.7}});
  M6 qp = kleinForm<S>() + 0.7 * infinityForm<S>();
  c.checkResidual<S>("IIA(p = 0.7) lies in the pitch quadric Q_{0.7}: Sᵀ(Q₀ + 0.7 Q∞)S = 0", maxAbs(gram(iia, qp)), kTol);
  // GF §8.3.6 (catalogue ch. 8, minor row 4803): "the condition for three lines to be mutually
  // orthogonal and concurrent is s₁ᵀQ₀[s₂, s₃] = 0" is necessary, not sufficient. Lines through one
  // point r with arbitrary directions satisfy it ([s₂, s₃] is a line through r, which meets s₁);
  // the book's next sentence, sᵢᵀQ_p sⱼ = 0 for all p (meet: Q₀; perpendicular: Q∞), is the condition.
  {
    auto line = [](const Vec3d& w, const Vec3d& r) {
      V6 s;
      s << w.normalized(), r.cross(w.normalized());
      return s;
    };
    auto bracket = [](const V6& a, const V6& b) {
      V6 s;
      s << Vec3d(a.template head<3>()).cross(Vec3d(b.template head<3>())),
          Vec3d(a.template head<3>()).cross(Vec3d(b.template tail<3>())) + Vec3d(a.template tail<3>()).cross(Vec3d(b.template head<3>()));
      return s;
    };
    const M6 Q0 = kleinForm<S>(), Qi = infinityForm<S>();
    auto h = rng(4803);
    std::uniform_real_distribution<double> ud(-1, 1);
    auto u = [&] { return scalarCast<S>(ud(h)); };
    auto rv = [&] {
      const S x = u(), y = u(), z = u();
      return Vec3d(x, y, z);
    };
    S printedCond = 0, orthDefect = 1000, corrOrth = 0, corrFails = 1000;  // 1000: above any |ωᵢ·ωⱼ|, |sᵢᵀQsⱼ| here
    for (int k = 0; k < 20; ++k) {
      const Vec3d r = rv(), w1 = rv(), w2 = rv(), w3 = rv();
      const V6 s1 = line(w1, r), s2 = line(w2, r), s3 = line(w3, r);
      printedCond = std::max(printedCond, abs(S(s1.transpose() * Q0 * bracket(s2, s3))));
      const S orth = std::max({abs(s1.template head<3>().dot(s2.template head<3>())), abs(s1.template head<3>().dot(s3.template head<3>())),
                                    abs(s2.template head<3>().dot(s3.template head<3>()))});
      orthDefect = std::min(orthDefect, orth);
      // the corrected condition: every pair meets (Q₀) and is perpendicular (Q∞)
      S pairs = 0;
      for (const auto& [a, b] : {std::pair{s1, s2}, std::pair{s1, s3}, std::pair{s2, s3}})
        pairs = std::max({pairs, abs(S(a.transpose() * Q0 * b)), abs(S(a.transpose() * Qi * b))});
      corrFails = std::min(corrFails, pairs);
      // an orthogonal concurrent triple (a rotated frame at r) satisfies both
      const S qw = u(), qx = u(), qy = u(), qz = u();
      const Mat3<S> F = Quat<S>(qw, qx, qy, qz).normalized().toRotationMatrix();
      const V6 o1 = line(F.col(0), r), o2 = line(F.col(1), r), o3 = line(F.col(2), r);
      for (const auto& [a, b] : {std::pair{o1, o2}, std::pair{o1, o3}, std::pair{o2, o3}})
        corrOrth = std::max({corrOrth, abs(S(a.transpose() * Q0 * b)), abs(S(a.transpose() * Qi * b))});
      corrOrth = std::max(corrOrth, abs(S(o1.transpose() * Q0 * bracket(o2, o3))));
    }
    c.checkResidual<S>("20 concurrent triples with random directions satisfy s₁ᵀQ₀[s₂, s₃] = 0", printedCond, kTol);
    c.checkPrintedFails<S>("… yet are not mutually orthogonal (smallest largest |ωᵢ·ωⱼ|): the printed condition is not sufficient",
                        "ch. 8 minor 4803", orthDefect, kTol);  // the corrected condition's rounding bound
    c.checkResidual<S>("orthogonal concurrent triples satisfy sᵢᵀQ₀sⱼ = sᵢᵀQ∞sⱼ = 0 (the corrected condition) and the printed one",
                    corrOrth, kTol);
    c.recordIn("… and the random concurrent triples violate the corrected condition (smallest largest |sᵢᵀQsⱼ|)", "> 1e-3",
               io::numberText(corrFails), corrFails, S(1) / S(1000), corrFails > S(1) / S(1000));
  }
}

template <class W> void normalForms3(Context& c) {
  tableIdentification<W>(c, threeRows(), 90, 25);
  // GF §8.3.6 block reduction: the infinite-pitch extra screw gives IB₃/IIB when q'13 = q'23 = 0.
  const auto id = identifyScrewSystem<W>(normalFormIn<W>({T::IB0_3, {0.7, 0.0}}));
  c.checkEqual("IB₀ with p_b = 0 (t in the ω-plane) stays IB₀", "IB₀", screwSystemTypeName(id.type));
}

/// The figure of GF-8.3-regulus-quadrics, drawn in double (soma::render draws double geometry).
void reguliFigure(Context& c) {
  using Vec3d = Vec3<double>;
  const double pa = 0.6, pb = 0.3, pc = -0.4;
  if (c.makeFigures()) {
    namespace rd = soma::render;
    rd::Scene scene;
    scene.title = "IA₁ (0.6, 0.3, −0.4): its lines (blue), the reciprocal's lines (vermillion)";
    const int N = 28;
    for (int k = 0; k < N; ++k) {
      const double t = 2 * M_PI * k / N, a1 = std::cos(t), a2 = std::sin(t);
      const double a3 = sqrt((pa * a1 * a1 + pb * a2 * a2) / -pc);
      for (int rec = 0; rec < 2; ++rec) {
        const double sgn = rec ? -1.0 : 1.0;  // reciprocal IA₁ has pitches −p_i
        const Vec3d ww(a1, a2, a3), vv(sgn * pa * a1, sgn * pb * a2, sgn * pc * a3);
        const Vec3d qq = ww.cross(vv) / ww.squaredNorm();
        const Vec3d d = ww.normalized();
        // clip the line to |z| ≤ 0.9
        const double l0 = (-0.9 - qq.z()) / d.z(), l1 = (0.9 - qq.z()) / d.z();
        rd::Tube tube;
        tube.p = {Vec3d(qq + l0 * d), Vec3d(qq + l1 * d)};
        tube.radius = 0.006;
        tube.c = rec ? rd::palette::vermillion : rd::palette::blue;
        scene.add(tube);
      }
    }
    rd::Polyline waist;
    for (int k = 0; k <= 120; ++k) {
      const double t = 2 * M_PI * k / 120;
      // z = 0 section: p_a x² + p_b y² = −p_a p_b p_c
      waist.p.push_back(Vec3d(sqrt(-pb * pc) * std::cos(t), sqrt(-pa * pc) * std::sin(t), 0));
    }
    waist.c = rd::palette::darkGrey;
    waist.width = 2;
    scene.add(waist);
    const std::string file = "GF-8.3-regulus-IA1.png";
    rd::renderPng(scene, Eigen::Vector3d(-1.0, -0.6, -0.45), {1100, 1000}, c.figurePath(file));
    c.figure(file,
             "The zero-pitch screws (lines) of the IA₁ 3-system (i, 0.6 i), (j, 0.3 j), (k, −0.4 k) form one regulus "
             "of the hyperboloid 0.6x² + 0.3y² − 0.4z² = 0.072 (blue); the lines of its reciprocal system (pitches "
             "negated) form the other regulus (vermillion). Grey: the waist ellipse z = 0.");
}
}

// Lines (pitch-0 screws) of type-I 3-systems and their quadrics; errata E8.7, E8.8.
template <class S> void reguli(Context& c) {
  GF08_SCALAR_NAMES;
  const S pa = 0.6, pb = 0.3, pc = -0.4;
  S worst = 0;
  for (int k = 0; k < 16; ++k) {
    const S t = 2 * pi<S>() * k / 16, c1 = cos(t), c2 = sin(t);
    const S c3 = sqrt((pa * c1 * c1 + pb * c2 * c2) / -pc);
    const Vec3d w(c1, c2, c3), v(pa * c1, pb * c2, pc * c3);
    const Vec3d q = w.cross(v) / w.squaredNorm();
    for (S lam : {-1.0, 0.5, 2.0}) {
      const Vec3d x = q + lam * w;
      worst = std::max(worst, abs(pa * x.x() * x.x() + pb * x.y() * x.y() + pc * x.z() * x.z() + pa * pb * pc));
    }
  }
  c.checkResidual<S>("IA₁ (0.6, 0.3, −0.4): points of its 16 lines satisfy p_a x² + p_b y² + p_c z² + p_a p_b p_c = 0",
                  worst, kTol * 16);
  // IB₀ paraboloid: lines of (i, p_a i), (j, p_a j), (0, i + p_b k).
  const S qa = 0.5, qb = 0.8;
  S worstFixed = 0;
  for (int k = 0; k < 12; ++k) {
    const S ang = S(4) / S(10) + S(k), c1 = cos(ang), c2 = sin(ang);
    // pitch 0: ω = (c1, c2, 0), v = (qa c1 + c3, qa c2, qb c3) with ω·v = qa + c1 c3 = 0.
    if (abs(c1) < 0.1) continue;
    const S c3 = -qa / c1;
    const Vec3d w(c1, c2, 0), v(qa * c1 + c3, qa * c2, qb * c3);
    const Vec3d q = w.cross(v) / w.squaredNorm();
    for (S lam : {-1.0, 0.7}) {
      const Vec3d x = q + lam * w;
      const S fixed = qb * x.z() * x.z() + x.x() * x.z() - qa * x.y() + qa * qa * qb;
      worstFixed = std::max(worstFixed, abs(fixed));
    }
  }
  c.checkResidual<S>("IB₀ lines lie on p_b z² + xz − p_a y + p_a² p_b = 0 (v = x × ω)", worstFixed, kTol * 16);
  S printedWorst = 0;
  {
    const S ang = S(4) / S(10), c1 = cos(ang), c2 = sin(ang), c3 = -qa / c1;
    const Vec3d w(c1, c2, 0), v(qa * c1 + c3, qa * c2, qb * c3), q = w.cross(v) / w.squaredNorm();
    printedWorst = abs(qb * q.z() * q.z() + q.x() * q.z() + qa * q.y() + qa * qa * qb);
  }
  c.checkPrintedFails<S>("IB₀ paraboloid p_b z² + xz + p_a y + p_a² p_b = 0", "E8.7", printedWorst, kTol * 16);
  // IB₃ plane pair: lines of (i, p_a i), (j, p_b j), (0, k) with p_a p_b < 0 sit at z = ±√(−p_a p_b).
  const S ra = 0.5, rb = -0.18;
  const S c1 = sqrt(-rb), c2 = sqrt(ra);  // ra c1² + rb c2² = 0
  const Vec3d w(c1, c2, 0), v(ra * c1, rb * c2, 0);
  const Vec3d q = w.cross(v) / w.squaredNorm();
  c.checkResidual<S>("IB₃ (0.5, −0.18) line lies in z² + p_a p_b = 0", abs(q.z() * q.z() + ra * rb), kTol);
  c.checkPrintedFails<S>("IB₃ planes z² − p_a p_b = 0", "E8.8", abs(q.z() * q.z() - ra * rb), kTol);
  reguliFigure(c);
}

template <class S> void alphaBeta(Context& c) {
  GF08_SCALAR_NAMES;
  struct P { Row row; Mat3<S> m; int rank; };
  const std::vector<P> planes = {
      {{T::IIA0_3, {}}, Mat3<S>::Identity(), 3},
      {{T::IIC0_3, {}}, Vec3<S>(1, -1, -1).asDiagonal(), 1},
      {{T::IIB_3, {0.0}}, Vec3<S>(1, 1, -1).asDiagonal(), 2},
      {{T::IID_3, {}}, -Mat3<S>::Identity(), 0}};
  for (const auto& pl : planes) {
    const MX nf = normalFormIn<S>(pl.row);
    Eigen::Matrix<S, 3, 6> a;
    a << Mat3<S>::Identity() - pl.m, Mat3<S>::Identity() + pl.m;
    c.checkResidual<S>(screwSystemTypeName(pl.row.t) + " satisfies (I − M)ω + (I + M)v = 0", maxAbs(MX(a * nf)), kTol);
    c.checkEqual("… rank(I + M)", pl.rank, detail::smallNumericalRank<S>(MX(Mat3<S>::Identity() + pl.m)));
  }
}

template <class S> void reciprocal3(Context& c) {
  GF08_SCALAR_NAMES;
  auto g = rng(91);
  for (const auto& row : threeRows()) {
    const SE3d x = SE3d::Random(g);
    const ScrewSystem<S> d(MX(x.adjoint() * normalFormIn<S>(row)));
    const auto id = identifyScrewSystem(d.reciprocal());
    c.checkEqual("reciprocal of " + screwSystemTypeName(row.t) + " has the same type", screwSystemTypeName(row.t),
                 screwSystemTypeName(id.type));
  }
  const auto id = identifyScrewSystem(ScrewSystem<S>(normalFormIn<S>({T::IA1_3, {1.1, 0.7, -0.3}})).reciprocal());
  c.checkResidual<S>("reciprocal of IA₁(1.1, 0.7, −0.3) is IA₁(0.3, −0.7, −1.1)",
                  abs(id.parameters[0] - 0.3) + abs(id.parameters[1] + 0.7) + abs(id.parameters[2] + 1.1), kTol * 16);
}

// GF §8.4.1 and erratum E8.4.
template <class S> void pitch15(Context& c) {
  GF08_SCALAR_NAMES;
  auto g = rng(92);
  const S p = 0.45;
  const MX five = ScrewSystem<S>(MX(SE3d::Random(g).adjoint() * nfS<S>({T::Screw, {p}}))).reciprocal().basis();
  const auto w = wedge<S>(MX(five * randomGL<S>(5, g)));
  // W_i = (−1)^i × (minor omitting row i): wedge() lists the minors omitting rows 5, 4, …, 0.
  V6 W;
  for (int i = 0; i < 6; ++i) W(i) = ((i % 2) ? -1.0 : 1.0) * w(5 - i);
  const V6 s = kleinForm<S>() * W;
  c.checkResidual<S>("s = Q₀𝒲 is reciprocal to the five screws", maxAbs(MX(five.transpose() * kleinForm<S>() * s)) / s.norm(), kTol);
  const M6 q0 = kleinForm<S>(), q0s = q0 * q0 * q0, qis = q0 * infinityForm<S>() * q0;
  const S fixed = -S(W.transpose() * q0s * W) / S(W.transpose() * qis * W);
  const S printed = S(W.transpose() * q0s * W) / S(W.transpose() * q0s * W);
  c.checkNear<S>("p = −𝒲ᵀQ₀*𝒲 / 𝒲ᵀQ∞*𝒲", p, fixed, kTol * 16);
  c.checkPrintedFails<S>("p = 𝒲ᵀQ₀*𝒲 / 𝒲ᵀQ₀*𝒲 (= 1 always)", "E8.4", abs(printed - p), kTol * 16);
  const auto id = identifyScrewSystem(ScrewSystem<S>(five));
  c.checkNear<S>("identifyScrewSystem on the 5-system: pitch of the reciprocal screw", p, id.parameters[0], kTol * 16);
  // Extreme: 5-system containing all translations → reciprocal pure translation, denominator 0.
  const auto tr = identifyScrewSystem(ScrewSystem<S>(nfS<S>({T::Translation, {}})).reciprocal());
  c.checkEqual("5-system with all translations: reciprocal screw has p = ∞", "translation (p=∞)", screwSystemTypeName(tr.type));
}

template <class S> struct Inv2 { S i1, i2, i3; };
template <class S> Inv2<S> inv2(const ScrewMatX<S>& s) {
  GF08_SCALAR_NAMES;
  const MX y0 = gram(s, kleinForm<S>()), yi = gram(s, infinityForm<S>());
  // det(αΥ₀ + βΥ∞) = α² i₁ + αβ i₂ + β² i₃
  const S i1 = detS(y0), i3 = detS(yi);
  const S i2 = y0(0, 0) * yi(1, 1) + yi(0, 0) * y0(1, 1) - 2 * y0(0, 1) * yi(0, 1);
  return {i1, i2, i3};
}

template <class S> void invariants2(Context& c) {
  GF08_SCALAR_NAMES;
  auto g = rng(93);
  const MX s = randomGenerators<S>(2, g);
  const Inv2<S> a = inv2<S>(s);
  const V6 b = screwBracket<S>(s.col(0), s.col(1));
  const Vec3d w1 = s.col(0).template head<3>(), w2 = s.col(1).template head<3>();
  c.checkNear<S>("i₂ = −2[s₁,s₂]ᵀQ₀[s₁,s₂]", a.i2, -2 * S(b.transpose() * kleinForm<S>() * b), kTol * 8);
  c.checkNear<S>("i₃ = −2[s₁,s₂]ᵀQ∞[s₁,s₂] = 4(|ω₁|²|ω₂|² − (ω₁·ω₂)²)", a.i3,
              4 * (w1.squaredNorm() * w2.squaredNorm() - w1.dot(w2) * w1.dot(w2)), kTol * 8);
  const MX m = randomGL<S>(2, g);
  const SE3d x = SE3d::Random(g);
  const Inv2<S> bm = inv2<S>(MX(x.adjoint() * s * m));
  const S d2 = detS(m) * detS(m);
  c.checkResidual<S>("i₁, i₂, i₃ scale by det(M)² under a basis change and are Ad-invariant",
                  std::max({abs(bm.i1 - d2 * a.i1), abs(bm.i2 - d2 * a.i2), abs(bm.i3 - d2 * a.i3)}), kTol * 64);
}

template <class S> void table83(Context& c) {
  GF08_SCALAR_NAMES;
  // i₁, i₂, i₃ on the normal forms (Table 8.3) and the E8.3 failure of i₄, i₅.
  const S p = 0.7, pa = 0.7, pb = -0.3;
  struct E { RowS<S> row; S i1, i2, i3; };
  const std::vector<E> rows = {
      {{T::IIC_2, {}}, 0, 0, 0},     {{T::IB0sup_2, {}}, -1, 0, 0},       {{T::IIA0_2, {}}, 0, 0, 4},
      {{T::IIBp_2, {p}}, 0, 0, 0},   {{T::IIB0_2, {}}, 0, 0, 0},          {{T::IBp_2, {p}}, -1, 0, 0},
      {{T::IIAp_2, {p}}, 4 * p * p, -8 * p, 4}, {{T::IA_2, {pa, pb}}, 4 * pa * pb, -4 * (pa + pb), 4}};
  for (const auto& e : rows) {
    const Inv2<S> a = inv2<S>(nfS<S>(e.row));
    c.checkResidual<S>("Table 8.3 " + screwSystemTypeName(e.row.t) + ": i₁, i₂, i₃",
                    std::max({abs(a.i1 - e.i1), abs(a.i2 - e.i2), abs(a.i3 - e.i3)}), kTol);
  }
  // det(A − λQ₀ − μQ∞) with A = s₁s₂ᵀ − s₂s₁ᵀ: coefficient of λ²μ² (i₅) via a polynomial fit.
  auto i5 = [](const MX& s) {
    const M6 A = s.col(0) * s.col(1).transpose() - s.col(1) * s.col(0).transpose();
    // f(λ, μ) = −λ⁶ − i₁λ⁴ − i₄λ³μ − i₅λ²μ²; at λ = 1: f(1, μ) = −1 − i₁ − i₄μ − i₅μ² (exact quadratic in μ).
    auto f = [&](S mu) { return detS(M6(A - kleinForm<S>() - mu * infinityForm<S>())); };
    return -(f(1) + f(-1) - 2 * f(0)) / 2;  // exact: the printed monomials are all there is
  };
  const MX n0 = nfS<S>({T::IIA0_2, {}});
  const SE3d shift(SO3d::Identity(), Vec3d(S(1), S(-2), S(1) / S(3)));
  const S i5n = i5(n0), i5t = i5(MX(shift.adjoint() * n0));
  c.checkNear<S>("i₅ of IIA(p=0) in normal form = 0 (Table 8.3)", 0.0, i5n, kTol * 8);
  c.checkNear<S>("i₅ of IIA(p=0) translated by (1, −2, 1/3) = 184/81 (not invariant)", S(S(184) / S(81)), i5t, kTol * 64);
  c.checkPrintedFails<S>("i₅ is a rigid-motion invariant (IIA(p=0) translated)", "E8.3", abs(i5t - i5n), kTol * 8);
  // A' = det(M) A (not det(M)² A).
  auto g = rng(94);
  const MX s = randomGenerators<S>(2, g), m = randomGL<S>(2, g);
  const MX sm = s * m;
  const M6 A = s.col(0) * s.col(1).transpose() - s.col(1) * s.col(0).transpose();
  const M6 Am = sm.col(0) * sm.col(1).transpose() - sm.col(1) * sm.col(0).transpose();
  c.checkResidual<S>("A' = det(M) A", maxAbs(MX(Am - detS(m) * A)), kTol * 16);
  c.checkPrintedFails<S>("A' = det(M)² A", "E8.3", maxAbs(MX(Am - detS(m) * detS(m) * A)), kTol * 16);
  // IA moduli: roots of i₃x² + i₂x + i₁ = identification's pitches (posed, random basis).
  const MX posed = SE3d::Random(g).adjoint() * nfS<S>({T::IA_2, {pa, pb}}) * randomGL<S>(2, g);
  const Inv2<S> a = inv2<S>(posed);
  const S disc = sqrt(a.i2 * a.i2 - 4 * a.i1 * a.i3);
  const auto id = identifyScrewSystem<S>(posed);
  c.checkResidual<S>("posed IA: roots of i₃x² + i₂x + i₁ = identified (p_a, p_b)",
                  abs((-a.i2 + disc) / (2 * a.i3) - id.parameters[0]) + abs((-a.i2 - disc) / (2 * a.i3) - id.parameters[1]),
                  Tolerance<S>::identity(4096));
  // IB: p² = i∞ / 2i₁ with [s₁, s₂] a pure translation.
  const MX ib = nfS<S>({T::IBp_2, {p}});
  const V6 br = screwBracket<S>(ib.col(0), ib.col(1));
  M6 qis = M6::Zero();
  qis.template bottomRightCorner<3, 3>() = -2 * Mat3<S>::Identity();
  c.checkNear<S>("IB: p² = i∞ / 2i₁", p * p, S(br.transpose() * qis * br) / (2 * inv2<S>(ib).i1), kTol);
}

template <class S> void twoLines(Context& c) {
  GF08_SCALAR_NAMES;
  const S l = 1, phi = pi<S>() / 3;
  const MX s = cols<S>({scr<S>(1, 0, 0, 0, 0, 0), scr<S>(cos(phi), sin(phi), 0, -l * sin(phi), l * cos(phi), 0)});
  const Inv2<S> a = inv2<S>(s);
  c.checkResidual<S>("i₁ = −l² sin²φ, i₂ = −4l sinφ cosφ, i₃ = 4 sin²φ",
                  abs(a.i1 + l * l * sin(phi) * sin(phi)) + abs(a.i2 + 4 * l * sin(phi) * cos(phi)) +
                      abs(a.i3 - 4 * sin(phi) * sin(phi)), kTol);
  const auto id = identifyScrewSystem<S>(s);
  c.checkEqual("two skew lines (l = 1, φ = π/3) span an IA system", "IA", screwSystemTypeName(id.type));
  c.checkNear<S>("p_a = (l/2) cot(φ/2) = 0.866025…", l / 2 / tan(phi / 2), id.parameters[0], kTol * 16);
  c.checkNear<S>("p_b = −(l/2) tan(φ/2) = −0.288675…", -l / 2 * tan(phi / 2), id.parameters[1], kTol * 16);
  c.checkPrintedFails<S>("moduli (l/2) tan(φ/2), −(l/2) cot(φ/2)", "E8.5",
              abs(l / 2 * tan(phi / 2) - id.parameters[0]) + abs(-l / 2 / tan(phi / 2) - id.parameters[1]), kTol);
  const auto id0 = identifyScrewSystem<S>(cols<S>({scr<S>(1, 0, 0, 0, 0, 0), scr<S>(cos(phi), sin(phi), 0, 0, 0, 0)}));
  c.checkEqual("l = 0: IIA(p=0)", "IIA(p=0)", screwSystemTypeName(id0.type));
  const auto idp = identifyScrewSystem<S>(cols<S>({scr<S>(1, 0, 0, 0, 0, 0), scr<S>(1, 0, 0, 0, l, 0)}));
  c.checkEqual("φ = 0: IIB(p=0) (parallel lines)", "IIB(p=0)", screwSystemTypeName(idp.type));
}

template <class S> void fourSystems(Context& c) {
  GF08_SCALAR_NAMES;
  auto g = rng(95);
  const MX s = randomGenerators<S>(2, g);
  const MX four = ScrewSystem<S>(s).reciprocal().basis();
  // p_ij of the reciprocal 2-system and A = s_a s_bᵀ − s_b s_aᵀ.
  const ScrewSystem<S> two(MX(ScrewSystem<S>(four).reciprocal().basis()));
  const V6 x = two.basis().col(0), y = two.basis().col(1);
  auto P = [&](int i, int j) { return x(i - 1) * y(j - 1) - x(j - 1) * y(i - 1); };
  const M6 A = x * y.transpose() - y * x.transpose();
  c.checkResidual<S>("A Q₀ s_i = 0 for the four screws", maxAbs(MX(A * kleinForm<S>() * four)), kTol);
  const Inv2<S> a = inv2<S>(cols<S>({x, y}));
  const S i1 = -(P(1, 4) * P(1, 4) + P(2, 5) * P(2, 5) + P(3, 6) * P(3, 6)) +
                    2 * (P(1, 2) * P(4, 5) + P(1, 3) * P(4, 6) + P(2, 3) * P(5, 6) - P(1, 5) * P(2, 4) - P(1, 6) * P(3, 4) - P(2, 6) * P(3, 5));
  const S i2 = 4 * (P(2, 3) * (P(3, 5) - P(2, 6)) + P(1, 3) * (P(3, 4) - P(1, 6)) + P(1, 2) * (P(2, 4) - P(1, 5)));
  const S i3 = 4 * (P(1, 2) * P(1, 2) + P(2, 3) * P(2, 3) + P(1, 3) * P(1, 3));
  c.checkResidual<S>("i₁, i₂, i₃ from the p_ij (GF §8.4.3) = from Υ₀, Υ∞", abs(i1 - a.i1) + abs(i2 - a.i2) + abs(i3 - a.i3), kTol * 16);
  V6 br;
  br << P(2, 3), -P(1, 3), P(1, 2), P(2, 6) - P(3, 5), P(3, 4) - P(1, 6), P(1, 5) - P(2, 4);
  c.checkResidual<S>("[s_a, s_b] = (p23, −p13, p12, p26 − p35, p34 − p16, p15 − p24)", maxAbs(MX(br - screwBracket<S>(x, y))), kTol);
  M6 qis = M6::Zero();
  qis.template bottomRightCorner<3, 3>() = -2 * Mat3<S>::Identity();
  const S iinf = S(br.transpose() * qis * br);
  const S printed = -(pow(P(1, 5) - P(2, 4), 2) + pow(P(2, 6) - P(3, 5), 2) + pow(P(3, 4) - P(1, 6), 2));
  c.checkNear<S>("i∞ = −2((p15 − p24)² + (p26 − p35)² + (p34 − p16)²)", iinf, 2 * printed, kTol * 8);
  c.checkPrintedFails<S>("i∞ = −((p15 − p24)² + …)", "E8.6", abs(printed - iinf), kTol * 8);
  const auto id = identifyScrewSystem(ScrewSystem<S>(four));
  c.checkEqual("identifyScrewSystem(4-system) reports the reciprocal 2-system's type", "IA", screwSystemTypeName(id.type));
}

template <class S> struct Inv3 { S d0, phi, theta, dinf, i0; };
template <class S> Inv3<S> inv3(const ScrewMatX<S>& s) {
  GF08_SCALAR_NAMES;
  const MX y0 = gram(s, kleinForm<S>()), yi = gram(s, infinityForm<S>());
  auto mixed = [](const MX& a, const MX& b) {  // Σ_k det(a with column k from b)
    S sum = 0;
    for (int k = 0; k < 3; ++k) {
      MX m = a;
      m.col(k) = b.col(k);
      sum += detS(m);
    }
    return sum;
  };
  // det(αΥ∞ + βΥ₀) = α³ detΥ∞ + α²β Θ + αβ² Φ + β³ detΥ₀
  return {detS(y0), mixed(y0, yi), mixed(yi, y0), detS(yi),
          reciprocalProduct<S>(s.col(0), screwBracket<S>(s.col(1), s.col(2)))};
}

template <class S> void table84(Context& c) {
  GF08_SCALAR_NAMES;
  const S p = 0.7, pa = 0.7, pb = -0.3, pc = 1.1;
  struct E { RowS<S> row; Inv3<S> v; };
  const std::vector<E> rows = {
      {{T::IID_3, {}}, {0, 0, 0, 0, 0}},
      {{T::IIC0_3, {}}, {0, 0, 0, 0, 0}},
      {{T::IICp_3, {p}}, {0, 0, 0, 0, 0}},
      {{T::IIB_3, {p}}, {0, 0, 0, 0, 1}},
      {{T::IB3_3, {pa, pb}}, {0, 0, 0, 0, 1}},
      {{T::IB0_3, {pa, pb}}, {-2 * pa, 2, 0, 0, pb}},
      {{T::IIA0_3, {}}, {0, 0, 0, -8, 0}},
      {{T::IIAp_3, {p}}, {8 * p * p * p, -24 * p * p, 24 * p, -8, 3 * p}},
      {{T::IA2_3, {pa, pb}}, {8 * pa * pb * pb, -16 * pa * pb - 8 * pb * pb, 8 * pa + 16 * pb, -8, pa + 2 * pb}},
      {{T::IA1_3, {pa, pb, pc}}, {8 * pa * pb * pc, -8 * (pa * pb + pb * pc + pc * pa), 8 * (pa + pb + pc), -8, pa + pb + pc}}};
  for (const auto& e : rows) {
    const Inv3<S> a = inv3<S>(nfS<S>(e.row));
    c.checkResidual<S>("Table 8.4 " + screwSystemTypeName(e.row.t) + ": det Υ₀, Φ, Θ, det Υ∞, i₀",
                    abs(a.d0 - e.v.d0) + abs(a.phi - e.v.phi) + abs(a.theta - e.v.theta) + abs(a.dinf - e.v.dinf) +
                        abs(a.i0 - e.v.i0), kTol * 8);
  }
  // E8.9: IC rows print Φ = 2; every invariant is 0. Ranks distinguish IC from IIC/IID.
  for (const RowS<S>& r : {RowS<S>{T::ICp_3, {p}}, RowS<S>{T::IC0_3, {}}}) {
    const Inv3<S> a = inv3<S>(nfS<S>(r));
    c.checkResidual<S>(screwSystemTypeName(r.t) + ": all five invariants vanish",
                    abs(a.d0) + abs(a.phi) + abs(a.theta) + abs(a.dinf) + abs(a.i0), kTol);
    c.checkPrintedFails<S>(screwSystemTypeName(r.t) + ": Φ = 2 (Table 8.4)", "E8.9", abs(a.phi - 2), kTol);
  }
  auto ranks = [](const RowS<S>& r) {
    const MX nf = nfS<S>(r);
    return std::to_string(detail::smallNumericalRank<S>(gram(nf, kleinForm<S>()))) + "/" +
           std::to_string(detail::smallNumericalRank<S>(gram(nf, infinityForm<S>())));
  };
  c.checkEqual("rank Υ₀ / rank Υ∞ of IC(p≠0)", "2/1", ranks({T::ICp_3, {p}}));
  c.checkEqual("rank Υ₀ / rank Υ∞ of IC⁰", "2/1", ranks({T::IC0_3, {}}));
  c.checkEqual("rank Υ₀ / rank Υ∞ of IIC(p=0)", "0/1", ranks({T::IIC0_3, {}}));
  c.checkEqual("rank Υ₀ / rank Υ∞ of IIC(p≠0)", "1/1", ranks({T::IICp_3, {p}}));
  c.checkEqual("rank Υ₀ / rank Υ∞ of IID", "0/0", ranks({T::IID_3, {}}));
  // E8.10: normalised triple product of the IC normal form.
  const MX ic = nfS<S>({T::ICp_3, {p}});
  const Vec3d w1 = ic.col(0).template head<3>(), v2 = ic.col(1).template tail<3>(), v3 = ic.col(2).template tail<3>();
  const S cprod = w1.dot(v2.cross(v3)) / (w1.norm() * v2.norm() * v3.norm());
  c.checkNear<S>("IC: ω₁·(v₂×v₃)/(|ω₁||v₂||v₃|) = p/√(1+p²)", p / sqrt(1 + p * p), abs(cprod), kTol);
  c.checkNear<S>("… so p² = c²/(1 − c²)", p * p, cprod * cprod / (1 - cprod * cprod), kTol * 4);
  c.checkPrintedFails<S>("IC: normalised triple product = p√(1+p²)", "E8.10", abs(abs(cprod) - p * sqrt(1 + p * p)), kTol);
  // Moduli of A-systems = roots of the cubic; IB₀ moduli from Φ and i₀.
  const S pb4 = 0.4;
  const Inv3<S> ib0 = inv3<S>(nfS<S>({T::IB0_3, {pa, pb4}}));
  c.checkNear<S>("IB₀: p_a = −det Υ₀ / Φ", pa, -ib0.d0 / ib0.phi, kTol);
  c.checkNear<S>("IB₀: p_b² = 2 i₀² / Φ (p_b = 0.4)", S(pb4 * pb4), 2 * ib0.i0 * ib0.i0 / ib0.phi, kTol);
  auto g = rng(96);
  const MX posed = SE3d::Random(g).adjoint() * nfS<S>({T::IA1_3, {pc, pa, pb}}) * randomGL<S>(3, g);
  const Inv3<S> a = inv3<S>(posed);
  const auto id = identifyScrewSystem<S>(posed);
  S worst = 0;
  for (int i = 0; i < 3; ++i) {
    const S x = id.parameters[i];
    worst = std::max(worst, abs(a.dinf * x * x * x + a.theta * x * x + a.phi * x + a.d0) / abs(a.dinf));
  }
  c.checkResidual<S>("posed IA₁: identified pitches are roots of detΥ∞ x³ + Θx² + Φx + detΥ₀", worst,
                  Tolerance<S>::identity(4096));
  c.checkNear<S>("det Υ∞ = −2(s₁ᵀQ∞[s₂, s₃])²", a.dinf,
              -2 * pow(S(posed.col(0).transpose() * infinityForm<S>() *
                                   screwBracket<S>(posed.col(1), posed.col(2))), 2), kTol * abs(a.dinf));
}

template <class S> void bracketExample(Context& c) {
  GF08_SCALAR_NAMES;
  const S p = 0.35, l = 0.8;
  const V6 sa = scr<S>(1, 0, 0, p, 0, 0), sb = scr<S>(0, 1, 0, -l, 0, 0);
  const V6 s1 = sa, s2 = screwBracket<S>(sb, sa), s3 = screwBracket<S>(sb, s2);
  c.checkResidual<S>("s₂ = [s_b, s_a] = (−k, −p k), s₃ = [s_b, [s_b, s_a]] = (−i, −p i − l j)",
                  (s2 - scr<S>(0, 0, -1, 0, 0, -p)).cwiseAbs().maxCoeff() + (s3 - scr<S>(-1, 0, 0, -p, -l, 0)).cwiseAbs().maxCoeff(), kTol);
  const MX s = cols<S>({s1, s2, s3});
  Mat3<S> yi, y0;
  yi << -2, 0, 2, 0, -2, 0, 2, 0, -2;
  y0 << 2 * p, 0, -2 * p, 0, 2 * p, 0, -2 * p, 0, 2 * p;
  c.checkResidual<S>("Υ∞ and Υ₀ as printed", maxAbs(MX(gram(s, infinityForm<S>()) - yi)) + maxAbs(MX(gram(s, kleinForm<S>()) - y0)), kTol);
  const auto id = identifyScrewSystem<S>(s);
  c.checkEqual("identified type", "IIB", screwSystemTypeName(id.type));
  c.checkNear<S>("… with pitch p", p, id.parameters[0], kTol * 8);
  const auto id0 = identifyScrewSystem<S>(cols<S>({scr<S>(1, 0, 0, p, 0, 0), screwBracket<S>(scr<S>(0, 1, 0, 0, 0, 0), scr<S>(1, 0, 0, p, 0, 0)),
                                                      screwBracket<S>(scr<S>(0, 1, 0, 0, 0, 0), screwBracket<S>(scr<S>(0, 1, 0, 0, 0, 0), scr<S>(1, 0, 0, p, 0, 0)))}));
  c.checkEqual("l = 0: the system collapses to dimension 2", 2, id0.dimension);
}

/// Shuffle (GF §8.5): meet of s₁∧…∧s_j and z₁∧…∧z_k for j + k ≥ 6, as a sum over the
/// (6−k)-subsets σ of the s's: sign · det(s_σ, z) · ∧ of the remaining s's.
template <class S> Eigen::Matrix<S, Eigen::Dynamic, 1> shuffle(const ScrewMatX<S>& s, const ScrewMatX<S>& z) {
  GF08_SCALAR_NAMES;
  const int j = int(s.cols()), k = int(z.cols()), r = 6 - k;
  const int out = j + k - 6;
  VecX sum;
  std::vector<int> idx(r);
  for (int i = 0; i < r; ++i) idx[i] = i;
  bool first = true;
  while (true) {
    std::vector<int> rest;
    for (int i = 0, q = 0; i < j; ++i) {
      if (q < r && idx[q] == i) { ++q; continue; }
      rest.push_back(i);
    }
    // sign of the permutation (idx, rest)
    int inv = 0;
    std::vector<int> perm(idx);
    perm.insert(perm.end(), rest.begin(), rest.end());
    for (int a = 0; a < j; ++a)
      for (int b = a + 1; b < j; ++b) inv += perm[a] > perm[b];
    MX m(6, 6);
    for (int i = 0; i < r; ++i) m.col(i) = s.col(idx[i]);
    m.rightCols(k) = z;
    MX remaining(6, out);
    for (int i = 0; i < out; ++i) remaining.col(i) = s.col(rest[i]);
    const VecX term = ((inv % 2) ? -1.0 : 1.0) * detS(m) *
                                 (out > 0 ? wedge<S>(remaining) : VecX::Ones(1));
    if (first) { sum = term; first = false; } else sum += term;
    int i = r - 1;
    while (i >= 0 && idx[i] == j - r + i) --i;
    if (i < 0) break;
    ++idx[i];
    for (int q = i + 1; q < r; ++q) idx[q] = idx[q - 1] + 1;
  }
  return sum;
}

template <class S> void unionIntersection(Context& c) {
  GF08_SCALAR_NAMES;
  auto g = rng(97);
  const MX a = randomGenerators<S>(4, g), b = randomGenerators<S>(3, g);
  const ScrewSystem<S> da(a), db(b);
  const auto cap = intersectionOf(da, db);
  c.checkEqual("random 4-system ∩ 3-system: dimension i + j − 6 = 1 (E8.11: ∧^{i+j−6}, not ∧^{6−i−j})", 1, cap.dimension());
  const VecX sh = shuffle<S>(a, b);
  c.checkEqual("shuffle of a 4- and a 3-vector has C(6, 1) = 6 components", 6, int(sh.size()));
  const V6 shs = sh;
  c.checkResidual<S>("the shuffle lies in both systems and spans the linear-algebra intersection",
                  std::max({da.residualOf(shs), db.residualOf(shs), cap.residualOf(shs)}), kTol * 64);
  const MX a3 = randomGenerators<S>(4, g), b3 = randomGenerators<S>(4, g);
  const auto cap2 = intersectionOf(ScrewSystem<S>(a3), ScrewSystem<S>(b3));
  const VecX sh2 = shuffle<S>(a3, b3);
  c.checkResidual<S>("4 ∩ 4 = 2-system: shuffle ∝ wedge of the intersection basis",
                  (sh2.normalized() - sh2.normalized().dot(wedge<S>(MX(cap2.basis())).normalized()) *
                                          wedge<S>(MX(cap2.basis())).normalized()).norm(), kTol * 256);
  // de Morgan.
  const ScrewSystem<S> u1(randomGenerators<S>(2, g)), u2(randomGenerators<S>(2, g));
  c.checkResidual<S>("de Morgan: reciprocal of (Δ_a ∪ Δ_b) = Δ̄_a ∩ Δ̄_b (largest principal-angle sine)",
                  unionOf(u1, u2).reciprocal().distanceTo(intersectionOf(u1.reciprocal(), u2.reciprocal())), kTol * 16);
  // Non-transversal: shuffle vanishes while the intersection is bigger than expected.
  MX a4 = randomGenerators<S>(4, g), b4 = randomGenerators<S>(3, g);
  b4.col(0) = a4.col(0) + a4.col(1);
  b4.col(1) = a4.col(2) - a4.col(3);
  const VecX sh4 = shuffle<S>(a4, b4);
  const auto cap4 = intersectionOf(ScrewSystem<S>(a4), ScrewSystem<S>(b4));
  c.checkResidual<S>("non-transversal 4- and 3-system: the shuffle vanishes", sh4.cwiseAbs().maxCoeff(), kTol * 64);
  c.checkEqual("… while the linear-algebra intersection is a 2-system", 2, cap4.dimension());
}

}  // namespace

SOMA_STUDY_SCALAR("GF-8.1-screw-system-and-grassmannian", "n-systems as points of G(n,6): Plücker vectors, ∧ⁿAd, basis change", "GF §8.1", grassmannian);
SOMA_STUDY_SCALAR("GF-8.1-1-systems-moduli", "1-systems: pitch quadrics Q_p, pitch round trip, p = ∞", "GF §8.1", oneSystems);
SOMA_STUDY_SCALAR("GF-8.1-reciprocal-system", "Reciprocal system: dimension 6 − n, involution, Ad-equivariance (E8.1)", "GF §8.1", reciprocal);
SOMA_STUDY_SCALAR("GF-8.1-derived-systems-completion", "Derived systems and the completion group of every normal form", "GF §8.1", completionStudy);
SOMA_STUDY_SCALAR("GF-8.2-isotropy-algebra", "Isotropy algebras of the normal forms; discrete symmetries", "GF §8.2", isotropyStudy);
SOMA_STUDY_SCALAR("GF-8.2-normal-forms-2-systems", "Table 8.1: posed 2-system normal forms identified", "GF §8.2", normalForms2);
SOMA_STUDY_SCALAR("GF-8.2.7-SE3-2-system-reduction", "Reduction of SE(3) 2-systems to (i, p_a i), (j, p_b j) (E8.2)", "GF §8.2.7", reduction2);
SOMA_STUDY_SCALAR("GF-8.2-IA-cylindroid", "IA 2-systems: the two real lines and the cylindroid", "GF §8.2", cylindroid);
SOMA_STUDY_SCALAR("GF-8.3-3-system-generalities", "3-systems: moduli count, type I / II", "GF §8.3", generalities3);
SOMA_STUDY_SCALAR("GF-8.3-normal-forms-3-systems", "Table 8.2: posed 3-system normal forms identified", "GF §8.3", normalForms3);
SOMA_STUDY_SCALAR("GF-8.3-regulus-quadrics", "Lines of type-I 3-systems: hyperboloid, paraboloid (E8.7), plane pair (E8.8)", "GF §8.3", reguli);
SOMA_STUDY_SCALAR("GF-8.3-alpha-beta-planes", "α- and β-planes as IIA(0), IIC(0), IIB(0), IID", "GF §8.3", alphaBeta);
SOMA_STUDY_SCALAR("GF-8.3-reciprocal-3-systems", "Reciprocal 3-systems keep their type; IA₁ moduli negate", "GF §8.3", reciprocal3);
SOMA_STUDY_SCALAR("GF-8.4.1-pitch-of-1-and-5-systems", "Pitch of a 5-system from its Plücker vector (E8.4)", "GF §8.4.1", pitch15);
SOMA_STUDY_SCALAR("GF-8.4.2-2-system-invariants", "2-system invariants i₁, i₂, i₃ and the bracket identities", "GF §8.4.2", invariants2);
SOMA_STUDY_SCALAR("GF-8.4.2-extra-invariants-table-8.3", "Table 8.3; i₄, i₅ not invariant (E8.3)", "GF §8.4.2", table83);
SOMA_STUDY_SCALAR("GF-8.4.2-two-lines-example", "Two skew lines span an IA system (E8.5)", "GF §8.4.2", twoLines);
SOMA_STUDY_SCALAR("GF-8.4.3-4-systems-pluecker", "4-systems via the Plücker coordinates of the reciprocal 2-system (E8.6)", "GF §8.4.3", fourSystems);
SOMA_STUDY_SCALAR("GF-8.4.4-3-system-invariants", "Table 8.4 (E8.9), IC modulus (E8.10), moduli from the cubic", "GF §8.4.4", table84);
SOMA_STUDY_SCALAR("GF-8.4.4-example-bracket-3-system", "The bracket-generated 3-system is IIB with pitch p", "GF §8.4.4", bracketExample);
SOMA_STUDY_SCALAR("GF-8.5-union-intersection", "Union, intersection, shuffle product and de Morgan (E8.11)", "GF §8.5", unionIntersection);

}  // namespace soma::studies::gf08::SOMA_UNITY_ID
