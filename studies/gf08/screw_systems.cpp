// Studies of GF chapter 8 (screw systems), in double (the identification of the normal forms,
// Tables 8.1 and 8.2, in the asked scalar): Grassmannian coordinates, reciprocity,
// completion and isotropy algebras, the Gibson–Hunt normal forms (Tables 8.1, 8.2) and their
// identification, the invariants of §8.4 with errata E8.2–E8.11, union and intersection (§8.5),
// and the regulus figure of an IA₁ 3-system.
#include "soma/geometry/screws/identification.hpp"
#include "soma/render/render.hpp"
#include "soma/studies/study.hpp"

#include <cmath>
#include <random>

namespace soma::studies::gf08::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

constexpr const char* kChapter = "GF 8 — Screw systems";
using T = ScrewSystemType;
using V6 = Vec6<double>;
using M6 = Mat6<double>;
using MX = ScrewMatX<double>;
using Vec3d = Vec3<double>;
using std::abs;
using std::sqrt;

std::mt19937_64 rng(std::uint64_t seed) { return std::mt19937_64(seed); }
double uni(std::mt19937_64& g, double lo = -1, double hi = 1) {
  return std::uniform_real_distribution<double>(lo, hi)(g);
}
V6 randomScrew(std::mt19937_64& g) {
  V6 s;
  for (int i = 0; i < 6; ++i) s(i) = uni(g);
  return s;
}
MX randomGenerators(int n, std::mt19937_64& g) {
  MX m(6, n);
  for (int j = 0; j < n; ++j) m.col(j) = randomScrew(g);
  return m;
}
MX randomGL(int n, std::mt19937_64& g) {
  MX m(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) m(i, j) = uni(g, -0.5, 0.5) + (i == j ? 2.0 : 0.0);
  return m;
}
V6 scr(double wx, double wy, double wz, double vx, double vy, double vz) {
  V6 s;
  s << wx, wy, wz, vx, vy, vz;
  return s;
}
MX cols(std::initializer_list<V6> c) {
  MX m(6, Eigen::Index(c.size()));
  int j = 0;
  for (const auto& s : c) m.col(j++) = s;
  return m;
}
double maxAbs(const MX& m) { return m.size() ? m.cwiseAbs().maxCoeff() : 0.0; }
const double kTol = Tolerance<double>::identity(64);
MX gram(const MX& s, const M6& q) { return s.transpose() * q * s; }
/// The n-th compound (∧ⁿ) of a 6×6 matrix: minors in the lexicographic order of wedge().
MX compound(const M6& a, int n) {
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
  MX c(sets.size(), sets.size());
  for (std::size_t r = 0; r < sets.size(); ++r)
    for (std::size_t k = 0; k < sets.size(); ++k) {
      Eigen::MatrixXd m(n, n);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) m(i, j) = a(sets[r][i], sets[k][j]);
      c(r, k) = m.determinant();
    }
  return c;
}
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
MX normalForm(const Row& r) { return MX(screwSystemNormalForm<double>(r.t, r.p)); }

// ---- GF §8.1 ---------------------------------------------------------------------------------
void grassmannian(Context& c) {
  auto g = rng(81);
  double worstM = 0, worstAd = 0;
  for (int n = 1; n <= 5; ++n) {
    const MX s = randomGenerators(n, g), m = randomGL(n, g);
    const auto w = wedge<double>(s), wm = wedge<double>(MX(s * m));
    worstM = std::max(worstM, (wm - w * m.determinant()).cwiseAbs().maxCoeff() / w.cwiseAbs().maxCoeff());
    const SE3d x = SE3d::Random(g);
    const auto wa = wedge<double>(MX(x.adjoint() * s));
    worstAd = std::max(worstAd, (wa - compound(x.adjoint(), n) * w).cwiseAbs().maxCoeff());
  }
  c.checkResidual("s'_i = Σ m_ij s_j: Plücker vector scales by det M (n = 1…5, relative)", worstM, kTol);
  c.checkResidual("Plücker vector of Ad(g)Δ = ∧ⁿAd(g) applied to that of Δ (Cauchy–Binet, n = 1…5)",
                  worstAd, Tolerance<double>::identity(256));
  // Nearly dependent generators: the rank decision and how far the input was from it.
  MX s = randomGenerators(3, g);
  s.col(2) = s.col(0) - s.col(1) + randomScrew(g) * 1e-14;
  const ScrewSystem<double> d(s);
  c.checkEqual("generators s₁, s₂, s₁ − s₂ + 10⁻¹⁴·r span a 2-system", 2, d.dimension());
  c.note("dropped singular-value ratio " + toString(d.droppedRatio(), 3) + " ≤ Tolerance::rank() = " +
         toString(Tolerance<double>::rank(), 3));
}

void oneSystems(Context& c) {
  auto g = rng(82);
  double worst = 0, worstQ = 0;
  for (int k = 0; k < 20; ++k) {
    const Vec3d w = Vec3d(uni(g), uni(g), uni(g)), q = Vec3d(uni(g), uni(g), uni(g));
    const double p = uni(g, -3, 3);
    const V6 s = scr(w.x(), w.y(), w.z(), 0, 0, 0) + (V6() << Vec3d::Zero(), Vec3d(q.cross(w) + p * w)).finished();
    // Q_p with α = p, β = 1: sᵀQ_p s = 0 iff pitch p.
    M6 qp = M6::Zero();
    qp.topLeftCorner<3, 3>() = -2 * p * Mat3<double>::Identity();
    qp.topRightCorner<3, 3>().setIdentity();
    qp.bottomLeftCorner<3, 3>().setIdentity();
    worstQ = std::max(worstQ, abs(double(s.transpose() * qp * s)) / w.squaredNorm());
    const auto id = identifyScrewSystem<double>(MX(s));
    worst = std::max(worst, id.type == T::Screw ? abs(id.parameters[0] - p) : 1.0);
    // p = −sᵀQ₀s / sᵀQ∞s
    worst = std::max(worst, abs(-double(s.transpose() * kleinForm<double>() * s) /
                                double(s.transpose() * infinityForm<double>() * s) - p));
  }
  c.checkResidual("sᵀQ_p s = 0 for 20 random screws of pitch p (Q_p = [[−2pI, I], [I, 0]])", worstQ, kTol * 16);
  c.checkResidual("pitch round trip: identify(span s) = screw(p) and −sᵀQ₀s/sᵀQ∞s = p", worst, kTol * 16);
  const auto tr = identifyScrewSystem<double>(MX(scr(0, 0, 0, 0.3, -1, 2)));
  c.checkEqual("p = ∞: a pure translation", "translation (p=∞)", screwSystemTypeName(tr.type));
}

void reciprocal(Context& c) {
  auto g = rng(83);
  double worstDual = 0, worstEq = 0, worstProd = 0;
  bool dims = true;
  for (int n = 0; n <= 6; ++n) {
    const ScrewSystem<double> d(randomGenerators(n, g));
    const auto r = d.reciprocal();
    dims = dims && r.dimension() == 6 - n;
    worstDual = std::max(worstDual, r.reciprocal().distanceTo(d));
    const SE3d x = SE3d::Random(g);
    worstEq = std::max(worstEq, d.transformed(x).reciprocal().distanceTo(r.transformed(x)));
    worstProd = std::max(worstProd, maxAbs(MX(d.basis().transpose() * kleinForm<double>() * r.basis())));
  }
  c.checkEqual("dim Δ̄ = 6 − n for n = 0…6", "yes", dims ? "yes" : "no");
  c.checkResidual("s_iᵀQ₀ s̄_j = 0 for bases of Δ and Δ̄", worstProd, kTol);
  c.checkResidual("reciprocal of the reciprocal = Δ (largest principal-angle sine)", worstDual, kTol);
  c.checkResidual("reciprocal of Ad(g)Δ = Ad(g) of the reciprocal", worstEq, kTol * 16);
  // E8.1: the intended invariance (Ad s_i)ᵀQ₀(Ad s_j) = s_iᵀQ₀s_j.
  const SE3d x = SE3d::Random(g);
  const V6 a = randomScrew(g), b = randomScrew(g);
  c.checkNear("(Ad(g)s_i)ᵀQ₀(Ad(g)s_j) = s_iᵀQ₀s_j (E8.1: the printed line has s_i on both sides)",
              reciprocalProduct<double>(a, b), reciprocalProduct<double>(x.adjoint() * a, x.adjoint() * b), kTol * 8);
  // Screws of Δ ∩ Δ̄ are lines: IIA(p=0) (a star of lines) is self-reciprocal.
  const ScrewSystem<double> star(MX(x.adjoint() * normalForm({T::IIA0_3, {}})));
  c.checkResidual("IIA(p=0) star of lines is its own reciprocal (every screw a line)",
                  star.reciprocal().distanceTo(star), kTol * 16);
  // 5-systems ↔ the pitch of the reciprocal 1-system; 4-systems ↔ reciprocal 2-systems.
  const ScrewSystem<double> five(MX(x.adjoint() * ScrewSystem<double>(normalForm({T::Screw, {0.4}})).reciprocal().basis()));
  const auto id5 = identifyScrewSystem(five);
  c.checkNear("5-system reciprocal to a screw of pitch 0.4: identified pitch", 0.4, id5.parameters[0], kTol * 16);
}

void completionStudy(Context& c) {
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
    const ScrewSystem<double> d(MX(SE3d::Random(g).adjoint() * normalForm(row)));
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

void isotropyStudy(Context& c) {
  const std::vector<std::pair<Row, int>> rows = {
      {{T::IIC_2, {}}, 4},   {{T::IB0sup_2, {}}, 2}, {{T::IIA0_2, {}}, 1},     {{T::IIBp_2, {0.7}}, 2},
      {{T::IIB0_2, {}}, 2},  {{T::IBp_2, {0.7}}, 1}, {{T::IIAp_2, {0.7}}, 1},  {{T::IA_2, {0.7, -0.3}}, 0},
      {{T::IID_3, {}}, 6},   {{T::IIA0_3, {}}, 3},   {{T::IIC0_3, {}}, 4},     {{T::IICp_3, {0.7}}, 4},
      {{T::ICp_3, {0.7}}, 2}, {{T::IC0_3, {}}, 2},   {{T::IIB_3, {0.7}}, 3},   {{T::IB3_3, {0.7, -0.3}}, 2},
      {{T::IB0_3, {0.7, -0.3}}, 0}, {{T::IIAp_3, {0.7}}, 3}, {{T::IA2_3, {0.7, -0.3}}, 1},
      {{T::IA1_3, {1.1, 0.7, -0.3}}, 0}};
  auto g = rng(85);
  double worstWedge = 0;
  for (const auto& [row, dim] : rows) {
    const MX nf = normalForm(row);
    const ScrewSystem<double> d(nf);
    const auto iso = isotropyAlgebra(d);
    c.checkEqual("isotropy-algebra dimension of " + screwSystemTypeName(row.t) + " (" +
                     std::to_string(nf.cols()) + "-system)", dim, iso.dimension());
    // The book's form: Σ_k s₁∧…∧[s, s_k]∧…∧s_n = 0 for s in the isotropy algebra.
    for (int k = 0; k < iso.dimension(); ++k) {
      const V6 s = iso.basis().col(k);
      Eigen::VectorXd sum = Eigen::VectorXd::Zero(wedge<double>(nf).size());
      for (int j = 0; j < nf.cols(); ++j) {
        MX m = nf;
        m.col(j) = screwBracket<double>(s, nf.col(j));
        sum += wedge<double>(m);
      }
      worstWedge = std::max(worstWedge, sum.cwiseAbs().maxCoeff());
    }
  }
  c.checkResidual("isotropy algebra satisfies Σ s₁∧…∧[s,s_k]∧…∧s_n = 0 (GF §8.2, §8.3)", worstWedge, kTol);
  // Group isotropy: discrete symmetries π-rotations (IA 2-system: about x, y, z).
  const ScrewSystem<double> ia(normalForm({T::IA_2, {0.7, -0.3}}));
  double worst = 0;
  for (int a = 0; a < 3; ++a) {
    const SE3d rpi(SO3d::fromAxisAngle(Vec3d::Unit(a), M_PI), Vec3d::Zero());
    worst = std::max(worst, ia.transformed(rpi).distanceTo(ia));
  }
  c.checkResidual("IA 2-system: π-rotations about x, y, z map it to itself (Z₂×Z₂)", worst, kTol * 16);
  (void)g;
}

/// Identify posed normal forms of every row of a table.
/// The normal form of a table row in W (its parameters converted exactly from double).
template <class W> ScrewMatX<W> normalFormIn(const Row& r) {
  std::array<W, 3> p;
  for (int i = 0; i < 3; ++i) p[i] = scalarCast<W>(r.p[i]);
  return ScrewMatX<W>(screwSystemNormalForm<W>(r.t, p));
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
void reduction2(Context& c) {
  auto g = rng(87);
  double worst = 0;
  for (int k = 0; k < 50; ++k) {
    const double pa = uni(g, -2, 2), pb = pa - uni(g, 0.1, 2);
    const auto id = identifyScrewSystem<double>(
        MX(SE3d::Random(g).adjoint() * normalForm({T::IA_2, {pa, pb}}) * randomGL(2, g)));
    worst = std::max(worst, id.type == T::IA_2 ? std::max(abs(id.parameters[0] - pa), abs(id.parameters[1] - pb)) : 1.0);
  }
  c.checkResidual("50 random Ad(g)-images of IA(p_a, p_b) with random bases: (p_a, p_b) recovered", worst, 1e-12);
  // E8.2: (M Q' Mᵀ)₁₂ = m11 m21 q11 + (m11 m22 + m12 m21) q12 + m12 m22 q22.
  const double m11 = 0.3, m12 = -1.2, m21 = 0.8, m22 = 0.45, q11 = 1.7, q12 = -0.6, q22 = 0.9;
  Eigen::Matrix2d m, q;
  m << m11, m12, m21, m22;
  q << q11, q12, q12, q22;
  const double exact = (m * q * m.transpose())(0, 1);
  const double printed = m11 * m21 * q11 + (m11 * m22 + m12 * m22) * q12 + m12 * m22 * q22;
  const double fixed = m11 * m21 * q11 + (m11 * m22 + m12 * m21) * q12 + m12 * m22 * q22;
  c.checkNear("off-diagonal of MQ'Mᵀ with (m11 m22 + m12 m21) q'12", exact, fixed, kTol);
  c.checkPrintedFails("off-diagonal with (m11 m22 + m12 m22) q'12", "E8.2", abs(printed - exact), kTol);
}

// GF §8.2 IA cylindroid: real lines, angle and distance; pitch and axis position along the cylindroid.
void cylindroid(Context& c) {
  const double pa = 0.7, pb = -0.3;
  const V6 s1 = scr(sqrt(-pb), sqrt(pa), 0, pa * sqrt(-pb), pb * sqrt(pa), 0);
  const V6 s2 = scr(-sqrt(-pb), sqrt(pa), 0, -pa * sqrt(-pb), pb * sqrt(pa), 0);
  auto pitch = [](const V6& s) { return s.head<3>().dot(s.tail<3>()) / s.head<3>().squaredNorm(); };
  c.checkResidual("s₁' and s₂' (GF §8.2.7) have pitch 0", std::max(abs(pitch(s1)), abs(pitch(s2))), kTol);
  const Vec3d w1 = s1.head<3>(), w2 = s2.head<3>();
  c.checkNear("cos φ = (p_a + p_b)/(p_a − p_b)", (pa + pb) / (pa - pb), w1.dot(w2) / (w1.norm() * w2.norm()), kTol);
  c.checkNear("s₁'ᵀQ₀s₂' = 4 p_a p_b", 4 * pa * pb, reciprocalProduct<double>(s1, s2), kTol);
  // Independent: distance between the two lines along their common perpendicular (the z-axis).
  const Vec3d q1 = w1.cross(Vec3d(s1.tail<3>())) / w1.squaredNorm(), q2 = w2.cross(Vec3d(s2.tail<3>())) / w2.squaredNorm();
  const Vec3d n = w1.cross(w2).normalized();
  const double l = (q2 - q1).dot(n), sinphi = w1.cross(w2).dot(n) / (w1.norm() * w2.norm());
  c.checkNear("−l sin φ = 4 p_a p_b / (p_a − p_b) (l from the common perpendicular)", 4 * pa * pb / (pa - pb),
              -l * sinphi * w1.norm() * w2.norm() / (pa - pb), kTol * 4);
  // Posed IA system: pitch and axis of the screw at angle θ (in the canonical frame).
  auto g = rng(88);
  const SE3d x = SE3d::Random(g);
  const auto id = identifyScrewSystem<double>(MX(x.adjoint() * normalForm({T::IA_2, {pa, pb}}) * randomGL(2, g)));
  double worst = 0;
  for (int k = 0; k < 24; ++k) {
    const double th = M_PI * k / 24;
    const V6 local = std::cos(th) * id.normalForm.col(0) + std::sin(th) * id.normalForm.col(1);
    const V6 world = id.frame.adjoint() * local;
    const V6 back = id.frame.inverse().adjoint() * world;
    const Vec3d w = back.head<3>(), v = back.tail<3>();
    const double p = w.dot(v) / w.squaredNorm();
    const Vec3d foot = w.cross(v) / w.squaredNorm();
    worst = std::max({worst, abs(p - (pa * std::cos(th) * std::cos(th) + pb * std::sin(th) * std::sin(th))),
                      abs(foot.z() - (pb - pa) / 2 * std::sin(2 * th)), abs(foot.x()) + abs(foot.y())});
  }
  c.checkResidual("posed IA: p(θ) = p_a cos²θ + p_b sin²θ, axis meets the z-axis at z = (p_b − p_a)/2 sin 2θ",
                  worst, kTol * 64);
}

void generalities3(Context& c) {
  // G(3,6) has dimension 9 and SE(3) 6: the generic 3-systems (IA₁) have 3 moduli and trivial
  // isotropy algebra; the Segre-type split into I (meets Q₀ in a conic) and II (in a pitch quadric).
  auto g = rng(89);
  const ScrewSystem<double> d(randomGenerators(3, g));
  const auto id = identifyScrewSystem(d);
  c.checkEqual("a random 3-system is of type IA₁ (3 moduli)", "IA₁", screwSystemTypeName(id.type));
  c.checkEqual("… with isotropy algebra of dimension 0", 0, isotropyAlgebra(d).dimension());
  // Type II: contained in one pitch quadric — IIA(p) normal form has Υ_p = Υ₀ + pΥ∞ = 0.
  const MX iia = normalForm({T::IIAp_3, {0.7}});
  M6 qp = kleinForm<double>() + 0.7 * infinityForm<double>();
  c.checkResidual("IIA(p = 0.7) lies in the pitch quadric Q_{0.7}: Sᵀ(Q₀ + 0.7 Q∞)S = 0", maxAbs(gram(iia, qp)), kTol);
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
      s << Vec3d(a.head<3>()).cross(Vec3d(b.head<3>())),
          Vec3d(a.head<3>()).cross(Vec3d(b.tail<3>())) + Vec3d(a.tail<3>()).cross(Vec3d(b.head<3>()));
      return s;
    };
    const M6 Q0 = kleinForm<double>(), Qi = infinityForm<double>();
    auto h = rng(4803);
    std::uniform_real_distribution<double> u(-1, 1);
    auto rv = [&] { return Vec3d(u(h), u(h), u(h)); };
    double printedCond = 0, orthDefect = 1e300, corrOrth = 0, corrFails = 1e300;
    for (int k = 0; k < 20; ++k) {
      const Vec3d r = rv(), w1 = rv(), w2 = rv(), w3 = rv();
      const V6 s1 = line(w1, r), s2 = line(w2, r), s3 = line(w3, r);
      printedCond = std::max(printedCond, abs(double(s1.transpose() * Q0 * bracket(s2, s3))));
      const double orth = std::max({abs(s1.head<3>().dot(s2.head<3>())), abs(s1.head<3>().dot(s3.head<3>())),
                                    abs(s2.head<3>().dot(s3.head<3>()))});
      orthDefect = std::min(orthDefect, orth);
      // the corrected condition: every pair meets (Q₀) and is perpendicular (Q∞)
      double pairs = 0;
      for (const auto& [a, b] : {std::pair{s1, s2}, std::pair{s1, s3}, std::pair{s2, s3}})
        pairs = std::max({pairs, abs(double(a.transpose() * Q0 * b)), abs(double(a.transpose() * Qi * b))});
      corrFails = std::min(corrFails, pairs);
      // an orthogonal concurrent triple (a rotated frame at r) satisfies both
      const Mat3<double> F = Eigen::Quaterniond(u(h), u(h), u(h), u(h)).normalized().toRotationMatrix();
      const V6 o1 = line(F.col(0), r), o2 = line(F.col(1), r), o3 = line(F.col(2), r);
      for (const auto& [a, b] : {std::pair{o1, o2}, std::pair{o1, o3}, std::pair{o2, o3}})
        corrOrth = std::max({corrOrth, abs(double(a.transpose() * Q0 * b)), abs(double(a.transpose() * Qi * b))});
      corrOrth = std::max(corrOrth, abs(double(o1.transpose() * Q0 * bracket(o2, o3))));
    }
    c.checkResidual("20 concurrent triples with random directions satisfy s₁ᵀQ₀[s₂, s₃] = 0", printedCond, kTol);
    c.checkPrintedFails("… yet are not mutually orthogonal (smallest largest |ωᵢ·ωⱼ|): the printed condition is not sufficient",
                        "ch. 8 minor 4803", orthDefect, kTol);  // the corrected condition's rounding bound
    c.checkResidual("orthogonal concurrent triples satisfy sᵢᵀQ₀sⱼ = sᵢᵀQ∞sⱼ = 0 (the corrected condition) and the printed one",
                    corrOrth, kTol);
    c.recordIn("… and the random concurrent triples violate the corrected condition (smallest largest |sᵢᵀQsⱼ|)", "> 1e-3",
               io::numberText(corrFails), corrFails, 1e-3, corrFails > 1e-3);
  }
}

template <class W> void normalForms3(Context& c) {
  tableIdentification<W>(c, threeRows(), 90, 25);
  // GF §8.3.6 block reduction: the infinite-pitch extra screw gives IB₃/IIB when q'13 = q'23 = 0.
  const auto id = identifyScrewSystem<W>(normalFormIn<W>({T::IB0_3, {0.7, 0.0}}));
  c.checkEqual("IB₀ with p_b = 0 (t in the ω-plane) stays IB₀", "IB₀", screwSystemTypeName(id.type));
}

// Lines (pitch-0 screws) of type-I 3-systems and their quadrics; errata E8.7, E8.8.
void reguli(Context& c) {
  const double pa = 0.6, pb = 0.3, pc = -0.4;
  double worst = 0;
  for (int k = 0; k < 16; ++k) {
    const double t = 2 * M_PI * k / 16, c1 = std::cos(t), c2 = std::sin(t);
    const double c3 = sqrt((pa * c1 * c1 + pb * c2 * c2) / -pc);
    const Vec3d w(c1, c2, c3), v(pa * c1, pb * c2, pc * c3);
    const Vec3d q = w.cross(v) / w.squaredNorm();
    for (double lam : {-1.0, 0.5, 2.0}) {
      const Vec3d x = q + lam * w;
      worst = std::max(worst, abs(pa * x.x() * x.x() + pb * x.y() * x.y() + pc * x.z() * x.z() + pa * pb * pc));
    }
  }
  c.checkResidual("IA₁ (0.6, 0.3, −0.4): points of its 16 lines satisfy p_a x² + p_b y² + p_c z² + p_a p_b p_c = 0",
                  worst, kTol * 16);
  // IB₀ paraboloid: lines of (i, p_a i), (j, p_a j), (0, i + p_b k).
  const double qa = 0.5, qb = 0.8;
  double worstFixed = 0;
  for (int k = 0; k < 12; ++k) {
    const double c1 = std::cos(0.4 + k), c2 = std::sin(0.4 + k);
    // pitch 0: ω = (c1, c2, 0), v = (qa c1 + c3, qa c2, qb c3) with ω·v = qa + c1 c3 = 0.
    if (abs(c1) < 0.1) continue;
    const double c3 = -qa / c1;
    const Vec3d w(c1, c2, 0), v(qa * c1 + c3, qa * c2, qb * c3);
    const Vec3d q = w.cross(v) / w.squaredNorm();
    for (double lam : {-1.0, 0.7}) {
      const Vec3d x = q + lam * w;
      const double fixed = qb * x.z() * x.z() + x.x() * x.z() - qa * x.y() + qa * qa * qb;
      worstFixed = std::max(worstFixed, abs(fixed));
    }
  }
  c.checkResidual("IB₀ lines lie on p_b z² + xz − p_a y + p_a² p_b = 0 (v = x × ω)", worstFixed, kTol * 16);
  double printedWorst = 0;
  {
    const double c1 = std::cos(0.4), c2 = std::sin(0.4), c3 = -qa / c1;
    const Vec3d w(c1, c2, 0), v(qa * c1 + c3, qa * c2, qb * c3), q = w.cross(v) / w.squaredNorm();
    printedWorst = abs(qb * q.z() * q.z() + q.x() * q.z() + qa * q.y() + qa * qa * qb);
  }
  c.checkPrintedFails("IB₀ paraboloid p_b z² + xz + p_a y + p_a² p_b = 0", "E8.7", printedWorst, kTol * 16);
  // IB₃ plane pair: lines of (i, p_a i), (j, p_b j), (0, k) with p_a p_b < 0 sit at z = ±√(−p_a p_b).
  const double ra = 0.5, rb = -0.18;
  const double c1 = sqrt(-rb), c2 = sqrt(ra);  // ra c1² + rb c2² = 0
  const Vec3d w(c1, c2, 0), v(ra * c1, rb * c2, 0);
  const Vec3d q = w.cross(v) / w.squaredNorm();
  c.checkResidual("IB₃ (0.5, −0.18) line lies in z² + p_a p_b = 0", abs(q.z() * q.z() + ra * rb), kTol);
  c.checkPrintedFails("IB₃ planes z² − p_a p_b = 0", "E8.8", abs(q.z() * q.z() - ra * rb), kTol);
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

void alphaBeta(Context& c) {
  struct P { Row row; Mat3<double> m; int rank; };
  const std::vector<P> planes = {
      {{T::IIA0_3, {}}, Mat3<double>::Identity(), 3},
      {{T::IIC0_3, {}}, Eigen::Vector3d(1, -1, -1).asDiagonal(), 1},
      {{T::IIB_3, {0.0}}, Eigen::Vector3d(1, 1, -1).asDiagonal(), 2},
      {{T::IID_3, {}}, -Mat3<double>::Identity(), 0}};
  for (const auto& pl : planes) {
    const MX nf = normalForm(pl.row);
    Eigen::Matrix<double, 3, 6> a;
    a << Mat3<double>::Identity() - pl.m, Mat3<double>::Identity() + pl.m;
    c.checkResidual(screwSystemTypeName(pl.row.t) + " satisfies (I − M)ω + (I + M)v = 0", maxAbs(MX(a * nf)), kTol);
    c.checkEqual("… rank(I + M)", pl.rank, Eigen::FullPivLU<Mat3<double>>(Mat3<double>::Identity() + pl.m).rank());
  }
}

void reciprocal3(Context& c) {
  auto g = rng(91);
  for (const auto& row : threeRows()) {
    const SE3d x = SE3d::Random(g);
    const ScrewSystem<double> d(MX(x.adjoint() * normalForm(row)));
    const auto id = identifyScrewSystem(d.reciprocal());
    c.checkEqual("reciprocal of " + screwSystemTypeName(row.t) + " has the same type", screwSystemTypeName(row.t),
                 screwSystemTypeName(id.type));
  }
  const auto id = identifyScrewSystem(ScrewSystem<double>(normalForm({T::IA1_3, {1.1, 0.7, -0.3}})).reciprocal());
  c.checkResidual("reciprocal of IA₁(1.1, 0.7, −0.3) is IA₁(0.3, −0.7, −1.1)",
                  abs(id.parameters[0] - 0.3) + abs(id.parameters[1] + 0.7) + abs(id.parameters[2] + 1.1), kTol * 16);
}

// GF §8.4.1 and erratum E8.4.
void pitch15(Context& c) {
  auto g = rng(92);
  const double p = 0.45;
  const MX five = ScrewSystem<double>(MX(SE3d::Random(g).adjoint() * normalForm({T::Screw, {p}}))).reciprocal().basis();
  const auto w = wedge<double>(MX(five * randomGL(5, g)));
  // W_i = (−1)^i × (minor omitting row i): wedge() lists the minors omitting rows 5, 4, …, 0.
  V6 W;
  for (int i = 0; i < 6; ++i) W(i) = ((i % 2) ? -1.0 : 1.0) * w(5 - i);
  const V6 s = kleinForm<double>() * W;
  c.checkResidual("s = Q₀𝒲 is reciprocal to the five screws", maxAbs(MX(five.transpose() * kleinForm<double>() * s)) / s.norm(), kTol);
  const M6 q0 = kleinForm<double>(), q0s = q0 * q0 * q0, qis = q0 * infinityForm<double>() * q0;
  const double fixed = -double(W.transpose() * q0s * W) / double(W.transpose() * qis * W);
  const double printed = double(W.transpose() * q0s * W) / double(W.transpose() * q0s * W);
  c.checkNear("p = −𝒲ᵀQ₀*𝒲 / 𝒲ᵀQ∞*𝒲", p, fixed, kTol * 16);
  c.checkPrintedFails("p = 𝒲ᵀQ₀*𝒲 / 𝒲ᵀQ₀*𝒲 (= 1 always)", "E8.4", abs(printed - p), kTol * 16);
  const auto id = identifyScrewSystem(ScrewSystem<double>(five));
  c.checkNear("identifyScrewSystem on the 5-system: pitch of the reciprocal screw", p, id.parameters[0], kTol * 16);
  // Extreme: 5-system containing all translations → reciprocal pure translation, denominator 0.
  const auto tr = identifyScrewSystem(ScrewSystem<double>(normalForm({T::Translation, {}})).reciprocal());
  c.checkEqual("5-system with all translations: reciprocal screw has p = ∞", "translation (p=∞)", screwSystemTypeName(tr.type));
}

struct Inv2 { double i1, i2, i3; };
Inv2 inv2(const MX& s) {
  const MX y0 = gram(s, kleinForm<double>()), yi = gram(s, infinityForm<double>());
  // det(αΥ₀ + βΥ∞) = α² i₁ + αβ i₂ + β² i₃
  const double i1 = y0.determinant(), i3 = yi.determinant();
  const double i2 = y0(0, 0) * yi(1, 1) + yi(0, 0) * y0(1, 1) - 2 * y0(0, 1) * yi(0, 1);
  return {i1, i2, i3};
}

void invariants2(Context& c) {
  auto g = rng(93);
  const MX s = randomGenerators(2, g);
  const Inv2 a = inv2(s);
  const V6 b = screwBracket<double>(s.col(0), s.col(1));
  const Vec3d w1 = s.col(0).head<3>(), w2 = s.col(1).head<3>();
  c.checkNear("i₂ = −2[s₁,s₂]ᵀQ₀[s₁,s₂]", a.i2, -2 * double(b.transpose() * kleinForm<double>() * b), kTol * 8);
  c.checkNear("i₃ = −2[s₁,s₂]ᵀQ∞[s₁,s₂] = 4(|ω₁|²|ω₂|² − (ω₁·ω₂)²)", a.i3,
              4 * (w1.squaredNorm() * w2.squaredNorm() - w1.dot(w2) * w1.dot(w2)), kTol * 8);
  const MX m = randomGL(2, g);
  const SE3d x = SE3d::Random(g);
  const Inv2 bm = inv2(MX(x.adjoint() * s * m));
  const double d2 = m.determinant() * m.determinant();
  c.checkResidual("i₁, i₂, i₃ scale by det(M)² under a basis change and are Ad-invariant",
                  std::max({abs(bm.i1 - d2 * a.i1), abs(bm.i2 - d2 * a.i2), abs(bm.i3 - d2 * a.i3)}), kTol * 64);
}

void table83(Context& c) {
  // i₁, i₂, i₃ on the normal forms (Table 8.3) and the E8.3 failure of i₄, i₅.
  const double p = 0.7, pa = 0.7, pb = -0.3;
  struct E { Row row; double i1, i2, i3; };
  const std::vector<E> rows = {
      {{T::IIC_2, {}}, 0, 0, 0},     {{T::IB0sup_2, {}}, -1, 0, 0},       {{T::IIA0_2, {}}, 0, 0, 4},
      {{T::IIBp_2, {p}}, 0, 0, 0},   {{T::IIB0_2, {}}, 0, 0, 0},          {{T::IBp_2, {p}}, -1, 0, 0},
      {{T::IIAp_2, {p}}, 4 * p * p, -8 * p, 4}, {{T::IA_2, {pa, pb}}, 4 * pa * pb, -4 * (pa + pb), 4}};
  for (const auto& e : rows) {
    const Inv2 a = inv2(normalForm(e.row));
    c.checkResidual("Table 8.3 " + screwSystemTypeName(e.row.t) + ": i₁, i₂, i₃",
                    std::max({abs(a.i1 - e.i1), abs(a.i2 - e.i2), abs(a.i3 - e.i3)}), kTol);
  }
  // det(A − λQ₀ − μQ∞) with A = s₁s₂ᵀ − s₂s₁ᵀ: coefficient of λ²μ² (i₅) via a polynomial fit.
  auto i5 = [](const MX& s) {
    const M6 A = s.col(0) * s.col(1).transpose() - s.col(1) * s.col(0).transpose();
    // f(λ, μ) = −λ⁶ − i₁λ⁴ − i₄λ³μ − i₅λ²μ²; at λ = 1: f(1, μ) = −1 − i₁ − i₄μ − i₅μ² (exact quadratic in μ).
    auto f = [&](double mu) { return (A - kleinForm<double>() - mu * infinityForm<double>()).determinant(); };
    return -(f(1) + f(-1) - 2 * f(0)) / 2;  // exact: the printed monomials are all there is
  };
  const MX n0 = normalForm({T::IIA0_2, {}});
  const SE3d shift(SO3d::Identity(), Vec3d(1, -2, 1.0 / 3));
  const double i5n = i5(n0), i5t = i5(MX(shift.adjoint() * n0));
  c.checkNear("i₅ of IIA(p=0) in normal form = 0 (Table 8.3)", 0.0, i5n, kTol * 8);
  c.checkNear("i₅ of IIA(p=0) translated by (1, −2, 1/3) = 184/81 (not invariant)", 184.0 / 81, i5t, kTol * 64);
  c.checkPrintedFails("i₅ is a rigid-motion invariant (IIA(p=0) translated)", "E8.3", abs(i5t - i5n), kTol * 8);
  // A' = det(M) A (not det(M)² A).
  auto g = rng(94);
  const MX s = randomGenerators(2, g), m = randomGL(2, g);
  const MX sm = s * m;
  const M6 A = s.col(0) * s.col(1).transpose() - s.col(1) * s.col(0).transpose();
  const M6 Am = sm.col(0) * sm.col(1).transpose() - sm.col(1) * sm.col(0).transpose();
  c.checkResidual("A' = det(M) A", maxAbs(MX(Am - m.determinant() * A)), kTol * 16);
  c.checkPrintedFails("A' = det(M)² A", "E8.3", maxAbs(MX(Am - m.determinant() * m.determinant() * A)), kTol * 16);
  // IA moduli: roots of i₃x² + i₂x + i₁ = identification's pitches (posed, random basis).
  const MX posed = SE3d::Random(g).adjoint() * normalForm({T::IA_2, {pa, pb}}) * randomGL(2, g);
  const Inv2 a = inv2(posed);
  const double disc = sqrt(a.i2 * a.i2 - 4 * a.i1 * a.i3);
  const auto id = identifyScrewSystem<double>(posed);
  c.checkResidual("posed IA: roots of i₃x² + i₂x + i₁ = identified (p_a, p_b)",
                  abs((-a.i2 + disc) / (2 * a.i3) - id.parameters[0]) + abs((-a.i2 - disc) / (2 * a.i3) - id.parameters[1]),
                  Tolerance<double>::identity(4096));
  // IB: p² = i∞ / 2i₁ with [s₁, s₂] a pure translation.
  const MX ib = normalForm({T::IBp_2, {p}});
  const V6 br = screwBracket<double>(ib.col(0), ib.col(1));
  M6 qis = M6::Zero();
  qis.bottomRightCorner<3, 3>() = -2 * Mat3<double>::Identity();
  c.checkNear("IB: p² = i∞ / 2i₁", p * p, double(br.transpose() * qis * br) / (2 * inv2(ib).i1), kTol);
}

void twoLines(Context& c) {
  const double l = 1, phi = M_PI / 3;
  const MX s = cols({scr(1, 0, 0, 0, 0, 0), scr(std::cos(phi), std::sin(phi), 0, -l * std::sin(phi), l * std::cos(phi), 0)});
  const Inv2 a = inv2(s);
  c.checkResidual("i₁ = −l² sin²φ, i₂ = −4l sinφ cosφ, i₃ = 4 sin²φ",
                  abs(a.i1 + l * l * std::sin(phi) * std::sin(phi)) + abs(a.i2 + 4 * l * std::sin(phi) * std::cos(phi)) +
                      abs(a.i3 - 4 * std::sin(phi) * std::sin(phi)), kTol);
  const auto id = identifyScrewSystem<double>(s);
  c.checkEqual("two skew lines (l = 1, φ = π/3) span an IA system", "IA", screwSystemTypeName(id.type));
  c.checkNear("p_a = (l/2) cot(φ/2) = 0.866025…", l / 2 / std::tan(phi / 2), id.parameters[0], kTol * 16);
  c.checkNear("p_b = −(l/2) tan(φ/2) = −0.288675…", -l / 2 * std::tan(phi / 2), id.parameters[1], kTol * 16);
  c.checkPrintedFails("moduli (l/2) tan(φ/2), −(l/2) cot(φ/2)", "E8.5",
              abs(l / 2 * std::tan(phi / 2) - id.parameters[0]) + abs(-l / 2 / std::tan(phi / 2) - id.parameters[1]), kTol);
  const auto id0 = identifyScrewSystem<double>(cols({scr(1, 0, 0, 0, 0, 0), scr(std::cos(phi), std::sin(phi), 0, 0, 0, 0)}));
  c.checkEqual("l = 0: IIA(p=0)", "IIA(p=0)", screwSystemTypeName(id0.type));
  const auto idp = identifyScrewSystem<double>(cols({scr(1, 0, 0, 0, 0, 0), scr(1, 0, 0, 0, l, 0)}));
  c.checkEqual("φ = 0: IIB(p=0) (parallel lines)", "IIB(p=0)", screwSystemTypeName(idp.type));
}

void fourSystems(Context& c) {
  auto g = rng(95);
  const MX s = randomGenerators(2, g);
  const MX four = ScrewSystem<double>(s).reciprocal().basis();
  // p_ij of the reciprocal 2-system and A = s_a s_bᵀ − s_b s_aᵀ.
  const ScrewSystem<double> two(MX(ScrewSystem<double>(four).reciprocal().basis()));
  const V6 x = two.basis().col(0), y = two.basis().col(1);
  auto P = [&](int i, int j) { return x(i - 1) * y(j - 1) - x(j - 1) * y(i - 1); };
  const M6 A = x * y.transpose() - y * x.transpose();
  c.checkResidual("A Q₀ s_i = 0 for the four screws", maxAbs(MX(A * kleinForm<double>() * four)), kTol);
  const Inv2 a = inv2(cols({x, y}));
  const double i1 = -(P(1, 4) * P(1, 4) + P(2, 5) * P(2, 5) + P(3, 6) * P(3, 6)) +
                    2 * (P(1, 2) * P(4, 5) + P(1, 3) * P(4, 6) + P(2, 3) * P(5, 6) - P(1, 5) * P(2, 4) - P(1, 6) * P(3, 4) - P(2, 6) * P(3, 5));
  const double i2 = 4 * (P(2, 3) * (P(3, 5) - P(2, 6)) + P(1, 3) * (P(3, 4) - P(1, 6)) + P(1, 2) * (P(2, 4) - P(1, 5)));
  const double i3 = 4 * (P(1, 2) * P(1, 2) + P(2, 3) * P(2, 3) + P(1, 3) * P(1, 3));
  c.checkResidual("i₁, i₂, i₃ from the p_ij (GF §8.4.3) = from Υ₀, Υ∞", abs(i1 - a.i1) + abs(i2 - a.i2) + abs(i3 - a.i3), kTol * 16);
  V6 br;
  br << P(2, 3), -P(1, 3), P(1, 2), P(2, 6) - P(3, 5), P(3, 4) - P(1, 6), P(1, 5) - P(2, 4);
  c.checkResidual("[s_a, s_b] = (p23, −p13, p12, p26 − p35, p34 − p16, p15 − p24)", maxAbs(MX(br - screwBracket<double>(x, y))), kTol);
  M6 qis = M6::Zero();
  qis.bottomRightCorner<3, 3>() = -2 * Mat3<double>::Identity();
  const double iinf = double(br.transpose() * qis * br);
  const double printed = -(std::pow(P(1, 5) - P(2, 4), 2) + std::pow(P(2, 6) - P(3, 5), 2) + std::pow(P(3, 4) - P(1, 6), 2));
  c.checkNear("i∞ = −2((p15 − p24)² + (p26 − p35)² + (p34 − p16)²)", iinf, 2 * printed, kTol * 8);
  c.checkPrintedFails("i∞ = −((p15 − p24)² + …)", "E8.6", abs(printed - iinf), kTol * 8);
  const auto id = identifyScrewSystem(ScrewSystem<double>(four));
  c.checkEqual("identifyScrewSystem(4-system) reports the reciprocal 2-system's type", "IA", screwSystemTypeName(id.type));
}

struct Inv3 { double d0, phi, theta, dinf, i0; };
Inv3 inv3(const MX& s) {
  const MX y0 = gram(s, kleinForm<double>()), yi = gram(s, infinityForm<double>());
  auto mixed = [](const MX& a, const MX& b) {  // Σ_k det(a with column k from b)
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
      MX m = a;
      m.col(k) = b.col(k);
      sum += m.determinant();
    }
    return sum;
  };
  // det(αΥ∞ + βΥ₀) = α³ detΥ∞ + α²β Θ + αβ² Φ + β³ detΥ₀
  return {y0.determinant(), mixed(y0, yi), mixed(yi, y0), yi.determinant(),
          reciprocalProduct<double>(s.col(0), screwBracket<double>(s.col(1), s.col(2)))};
}

void table84(Context& c) {
  const double p = 0.7, pa = 0.7, pb = -0.3, pc = 1.1;
  struct E { Row row; Inv3 v; };
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
    const Inv3 a = inv3(normalForm(e.row));
    c.checkResidual("Table 8.4 " + screwSystemTypeName(e.row.t) + ": det Υ₀, Φ, Θ, det Υ∞, i₀",
                    abs(a.d0 - e.v.d0) + abs(a.phi - e.v.phi) + abs(a.theta - e.v.theta) + abs(a.dinf - e.v.dinf) +
                        abs(a.i0 - e.v.i0), kTol * 8);
  }
  // E8.9: IC rows print Φ = 2; every invariant is 0. Ranks distinguish IC from IIC/IID.
  for (const Row& r : {Row{T::ICp_3, {p}}, Row{T::IC0_3, {}}}) {
    const Inv3 a = inv3(normalForm(r));
    c.checkResidual(screwSystemTypeName(r.t) + ": all five invariants vanish",
                    abs(a.d0) + abs(a.phi) + abs(a.theta) + abs(a.dinf) + abs(a.i0), kTol);
    c.checkPrintedFails(screwSystemTypeName(r.t) + ": Φ = 2 (Table 8.4)", "E8.9", abs(a.phi - 2), kTol);
  }
  auto ranks = [](const Row& r) {
    const MX nf = normalForm(r);
    return std::to_string(Eigen::FullPivLU<Eigen::MatrixXd>(gram(nf, kleinForm<double>())).rank()) + "/" +
           std::to_string(Eigen::FullPivLU<Eigen::MatrixXd>(gram(nf, infinityForm<double>())).rank());
  };
  c.checkEqual("rank Υ₀ / rank Υ∞ of IC(p≠0)", "2/1", ranks({T::ICp_3, {p}}));
  c.checkEqual("rank Υ₀ / rank Υ∞ of IC⁰", "2/1", ranks({T::IC0_3, {}}));
  c.checkEqual("rank Υ₀ / rank Υ∞ of IIC(p=0)", "0/1", ranks({T::IIC0_3, {}}));
  c.checkEqual("rank Υ₀ / rank Υ∞ of IIC(p≠0)", "1/1", ranks({T::IICp_3, {p}}));
  c.checkEqual("rank Υ₀ / rank Υ∞ of IID", "0/0", ranks({T::IID_3, {}}));
  // E8.10: normalised triple product of the IC normal form.
  const MX ic = normalForm({T::ICp_3, {p}});
  const Vec3d w1 = ic.col(0).head<3>(), v2 = ic.col(1).tail<3>(), v3 = ic.col(2).tail<3>();
  const double cprod = w1.dot(v2.cross(v3)) / (w1.norm() * v2.norm() * v3.norm());
  c.checkNear("IC: ω₁·(v₂×v₃)/(|ω₁||v₂||v₃|) = p/√(1+p²)", p / sqrt(1 + p * p), abs(cprod), kTol);
  c.checkNear("… so p² = c²/(1 − c²)", p * p, cprod * cprod / (1 - cprod * cprod), kTol * 4);
  c.checkPrintedFails("IC: normalised triple product = p√(1+p²)", "E8.10", abs(abs(cprod) - p * sqrt(1 + p * p)), kTol);
  // Moduli of A-systems = roots of the cubic; IB₀ moduli from Φ and i₀.
  const Inv3 ib0 = inv3(normalForm({T::IB0_3, {pa, 0.4}}));
  c.checkNear("IB₀: p_a = −det Υ₀ / Φ", pa, -ib0.d0 / ib0.phi, kTol);
  c.checkNear("IB₀: p_b² = 2 i₀² / Φ", 0.16, 2 * ib0.i0 * ib0.i0 / ib0.phi, kTol);
  auto g = rng(96);
  const MX posed = SE3d::Random(g).adjoint() * normalForm({T::IA1_3, {pc, pa, pb}}) * randomGL(3, g);
  const Inv3 a = inv3(posed);
  const auto id = identifyScrewSystem<double>(posed);
  double worst = 0;
  for (int i = 0; i < 3; ++i) {
    const double x = id.parameters[i];
    worst = std::max(worst, abs(a.dinf * x * x * x + a.theta * x * x + a.phi * x + a.d0) / abs(a.dinf));
  }
  c.checkResidual("posed IA₁: identified pitches are roots of detΥ∞ x³ + Θx² + Φx + detΥ₀", worst,
                  Tolerance<double>::identity(4096));
  c.checkNear("det Υ∞ = −2(s₁ᵀQ∞[s₂, s₃])²", a.dinf,
              -2 * std::pow(double(posed.col(0).transpose() * infinityForm<double>() *
                                   screwBracket<double>(posed.col(1), posed.col(2))), 2), Tolerance<double>::identity(64) * abs(a.dinf));
}

void bracketExample(Context& c) {
  const double p = 0.35, l = 0.8;
  const V6 sa = scr(1, 0, 0, p, 0, 0), sb = scr(0, 1, 0, -l, 0, 0);
  const V6 s1 = sa, s2 = screwBracket<double>(sb, sa), s3 = screwBracket<double>(sb, s2);
  c.checkResidual("s₂ = [s_b, s_a] = (−k, −p k), s₃ = [s_b, [s_b, s_a]] = (−i, −p i − l j)",
                  (s2 - scr(0, 0, -1, 0, 0, -p)).cwiseAbs().maxCoeff() + (s3 - scr(-1, 0, 0, -p, -l, 0)).cwiseAbs().maxCoeff(), kTol);
  const MX s = cols({s1, s2, s3});
  Mat3<double> yi, y0;
  yi << -2, 0, 2, 0, -2, 0, 2, 0, -2;
  y0 << 2 * p, 0, -2 * p, 0, 2 * p, 0, -2 * p, 0, 2 * p;
  c.checkResidual("Υ∞ and Υ₀ as printed", maxAbs(MX(gram(s, infinityForm<double>()) - yi)) + maxAbs(MX(gram(s, kleinForm<double>()) - y0)), kTol);
  const auto id = identifyScrewSystem<double>(s);
  c.checkEqual("identified type", "IIB", screwSystemTypeName(id.type));
  c.checkNear("… with pitch p", p, id.parameters[0], kTol * 8);
  const auto id0 = identifyScrewSystem<double>(cols({scr(1, 0, 0, p, 0, 0), screwBracket<double>(scr(0, 1, 0, 0, 0, 0), scr(1, 0, 0, p, 0, 0)),
                                                      screwBracket<double>(scr(0, 1, 0, 0, 0, 0), screwBracket<double>(scr(0, 1, 0, 0, 0, 0), scr(1, 0, 0, p, 0, 0)))}));
  c.checkEqual("l = 0: the system collapses to dimension 2", 2, id0.dimension);
}

/// Shuffle (GF §8.5): meet of s₁∧…∧s_j and z₁∧…∧z_k for j + k ≥ 6, as a sum over the
/// (6−k)-subsets σ of the s's: sign · det(s_σ, z) · ∧ of the remaining s's.
Eigen::VectorXd shuffle(const MX& s, const MX& z) {
  const int j = int(s.cols()), k = int(z.cols()), r = 6 - k;
  const int out = j + k - 6;
  Eigen::VectorXd sum;
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
    const Eigen::VectorXd term = ((inv % 2) ? -1.0 : 1.0) * m.determinant() *
                                 (out > 0 ? wedge<double>(remaining) : Eigen::VectorXd::Ones(1));
    if (first) { sum = term; first = false; } else sum += term;
    int i = r - 1;
    while (i >= 0 && idx[i] == j - r + i) --i;
    if (i < 0) break;
    ++idx[i];
    for (int q = i + 1; q < r; ++q) idx[q] = idx[q - 1] + 1;
  }
  return sum;
}

void unionIntersection(Context& c) {
  auto g = rng(97);
  const MX a = randomGenerators(4, g), b = randomGenerators(3, g);
  const ScrewSystem<double> da(a), db(b);
  const auto cap = intersectionOf(da, db);
  c.checkEqual("random 4-system ∩ 3-system: dimension i + j − 6 = 1 (E8.11: ∧^{i+j−6}, not ∧^{6−i−j})", 1, cap.dimension());
  const Eigen::VectorXd sh = shuffle(a, b);
  c.checkEqual("shuffle of a 4- and a 3-vector has C(6, 1) = 6 components", 6, int(sh.size()));
  const V6 shs = sh;
  c.checkResidual("the shuffle lies in both systems and spans the linear-algebra intersection",
                  std::max({da.residualOf(shs), db.residualOf(shs), cap.residualOf(shs)}), kTol * 64);
  const MX a3 = randomGenerators(4, g), b3 = randomGenerators(4, g);
  const auto cap2 = intersectionOf(ScrewSystem<double>(a3), ScrewSystem<double>(b3));
  const Eigen::VectorXd sh2 = shuffle(a3, b3);
  c.checkResidual("4 ∩ 4 = 2-system: shuffle ∝ wedge of the intersection basis",
                  (sh2.normalized() - sh2.normalized().dot(wedge<double>(MX(cap2.basis())).normalized()) *
                                          wedge<double>(MX(cap2.basis())).normalized()).norm(), kTol * 256);
  // de Morgan.
  const ScrewSystem<double> u1(randomGenerators(2, g)), u2(randomGenerators(2, g));
  c.checkResidual("de Morgan: reciprocal of (Δ_a ∪ Δ_b) = Δ̄_a ∩ Δ̄_b (largest principal-angle sine)",
                  unionOf(u1, u2).reciprocal().distanceTo(intersectionOf(u1.reciprocal(), u2.reciprocal())), kTol * 16);
  // Non-transversal: shuffle vanishes while the intersection is bigger than expected.
  MX a4 = randomGenerators(4, g), b4 = randomGenerators(3, g);
  b4.col(0) = a4.col(0) + a4.col(1);
  b4.col(1) = a4.col(2) - a4.col(3);
  const Eigen::VectorXd sh4 = shuffle(a4, b4);
  const auto cap4 = intersectionOf(ScrewSystem<double>(a4), ScrewSystem<double>(b4));
  c.checkResidual("non-transversal 4- and 3-system: the shuffle vanishes", sh4.cwiseAbs().maxCoeff(), kTol * 64);
  c.checkEqual("… while the linear-algebra intersection is a 2-system", 2, cap4.dimension());
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-8.1-screw-system-and-grassmannian", "n-systems as points of G(n,6): Plücker vectors, ∧ⁿAd, basis change", "GF §8.1", grassmannian);
SOMA_STUDY_DOUBLE("GF-8.1-1-systems-moduli", "1-systems: pitch quadrics Q_p, pitch round trip, p = ∞", "GF §8.1", oneSystems);
SOMA_STUDY_DOUBLE("GF-8.1-reciprocal-system", "Reciprocal system: dimension 6 − n, involution, Ad-equivariance (E8.1)", "GF §8.1", reciprocal);
SOMA_STUDY_DOUBLE("GF-8.1-derived-systems-completion", "Derived systems and the completion group of every normal form", "GF §8.1", completionStudy);
SOMA_STUDY_DOUBLE("GF-8.2-isotropy-algebra", "Isotropy algebras of the normal forms; discrete symmetries", "GF §8.2", isotropyStudy);
SOMA_STUDY_SCALAR("GF-8.2-normal-forms-2-systems", "Table 8.1: posed 2-system normal forms identified", "GF §8.2", normalForms2);
SOMA_STUDY_DOUBLE("GF-8.2.7-SE3-2-system-reduction", "Reduction of SE(3) 2-systems to (i, p_a i), (j, p_b j) (E8.2)", "GF §8.2.7", reduction2);
SOMA_STUDY_DOUBLE("GF-8.2-IA-cylindroid", "IA 2-systems: the two real lines and the cylindroid", "GF §8.2", cylindroid);
SOMA_STUDY_DOUBLE("GF-8.3-3-system-generalities", "3-systems: moduli count, type I / II", "GF §8.3", generalities3);
SOMA_STUDY_SCALAR("GF-8.3-normal-forms-3-systems", "Table 8.2: posed 3-system normal forms identified", "GF §8.3", normalForms3);
SOMA_STUDY_DOUBLE("GF-8.3-regulus-quadrics", "Lines of type-I 3-systems: hyperboloid, paraboloid (E8.7), plane pair (E8.8)", "GF §8.3", reguli);
SOMA_STUDY_DOUBLE("GF-8.3-alpha-beta-planes", "α- and β-planes as IIA(0), IIC(0), IIB(0), IID", "GF §8.3", alphaBeta);
SOMA_STUDY_DOUBLE("GF-8.3-reciprocal-3-systems", "Reciprocal 3-systems keep their type; IA₁ moduli negate", "GF §8.3", reciprocal3);
SOMA_STUDY_DOUBLE("GF-8.4.1-pitch-of-1-and-5-systems", "Pitch of a 5-system from its Plücker vector (E8.4)", "GF §8.4.1", pitch15);
SOMA_STUDY_DOUBLE("GF-8.4.2-2-system-invariants", "2-system invariants i₁, i₂, i₃ and the bracket identities", "GF §8.4.2", invariants2);
SOMA_STUDY_DOUBLE("GF-8.4.2-extra-invariants-table-8.3", "Table 8.3; i₄, i₅ not invariant (E8.3)", "GF §8.4.2", table83);
SOMA_STUDY_DOUBLE("GF-8.4.2-two-lines-example", "Two skew lines span an IA system (E8.5)", "GF §8.4.2", twoLines);
SOMA_STUDY_DOUBLE("GF-8.4.3-4-systems-pluecker", "4-systems via the Plücker coordinates of the reciprocal 2-system (E8.6)", "GF §8.4.3", fourSystems);
SOMA_STUDY_DOUBLE("GF-8.4.4-3-system-invariants", "Table 8.4 (E8.9), IC modulus (E8.10), moduli from the cubic", "GF §8.4.4", table84);
SOMA_STUDY_DOUBLE("GF-8.4.4-example-bracket-3-system", "The bracket-generated 3-system is IIB with pitch p", "GF §8.4.4", bracketExample);
SOMA_STUDY_DOUBLE("GF-8.5-union-intersection", "Union, intersection, shuffle product and de Morgan (E8.11)", "GF §8.5", unionIntersection);

}  // namespace soma::studies::gf08::SOMA_UNITY_ID
