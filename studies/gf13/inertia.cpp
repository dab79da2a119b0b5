// Studies of GF §13.1 (double): the pairing of momentum and velocity, the 6×6 spatial inertia
// from a point-mass cloud, its transformation (skew-axis theorem), diagonalisation, conjugate
// screws, the coadjoint action of the Lie algebra, co-screws on the same line, the principal screws
// of inertia and their commutators (errata 13, 14, 21, 22).
#include "gf13/common.hpp"

#include "soma/algebra/small_linalg.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

namespace soma::studies::gf13::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

struct Cloud {
  std::vector<double> m;
  std::vector<V3> r;
};
Cloud cloud(std::mt19937_64& g, int n, V3 centre = V3::Zero()) {
  Cloud c;
  for (int k = 0; k < n; ++k) {
    c.m.push_back(uni(g, 0.1, 1));
    c.r.push_back(centre + rv3(g));
  }
  return c;
}
/// N of the cloud from SpatialInertia(m, c, I_c) with I_c = Σ m_k (|ρ|² I − ρρᵀ), ρ = r_k − c.
SpatialInertia<double> bodyOf(const Cloud& c) {
  double M = 0;
  V3 com = V3::Zero();
  for (std::size_t k = 0; k < c.m.size(); ++k) {
    M += c.m[k];
    com += c.m[k] * c.r[k];
  }
  com /= M;
  M3 I = M3::Zero();
  for (std::size_t k = 0; k < c.m.size(); ++k) {
    const V3 p = c.r[k] - com;
    I += c.m[k] * (p.squaredNorm() * M3::Identity() - p * p.transpose());
  }
  return SpatialInertia<double>(M, com, I);
}

void pairing(Context& ctx) {
  auto g = std::mt19937_64(1310);
  double worst = 0;
  for (int t = 0; t < 100; ++t) {
    const Cloud c = cloud(g, 8);
    const V6 s = rv6(g);
    const V3 w = s.head<3>(), v = s.tail<3>();
    V3 j = V3::Zero(), p = V3::Zero();
    double ek = 0;
    for (std::size_t k = 0; k < c.m.size(); ++k) {
      const V3 rd = w.cross(c.r[k]) + v;  // velocity of the particle
      j += c.m[k] * c.r[k].cross(rd);
      p += c.m[k] * rd;
      ek += c.m[k] * rd.squaredNorm() / 2;
    }
    worst = std::max(worst, abs(j.dot(w) + p.dot(v) - 2 * ek) / ek);
  }
  ctx.checkResidual("𝓜ᵀs = j·ω + p·v = 2E_K (100 clouds of 8 particles, relative)", worst, 1e-14);
  ctx.note("Momentum (j, p) and E_K computed particle by particle (ṙ = ω × r + v): the pairing of the co-screw of "
           "momentum with the velocity screw is twice the kinetic energy (GF §13.1 line 7625).");
}

void inertiaMatrix(Context& ctx) {
  auto g = std::mt19937_64(1311);
  double wm = 0, we = 0;
  int pd = 0;
  for (int t = 0; t < 100; ++t) {
    const Cloud c = cloud(g, 8, rv3(g, -2, 2));
    const SpatialInertia<double> b = bodyOf(c);
    const M6 N = b.matrix();
    const V6 s = rv6(g);
    const V3 w = s.head<3>(), v = s.tail<3>();
    V6 mom = V6::Zero();
    double ek = 0;
    for (std::size_t k = 0; k < c.m.size(); ++k) {
      const V3 rd = w.cross(c.r[k]) + v;
      mom.head<3>() += c.m[k] * c.r[k].cross(rd);
      mom.tail<3>() += c.m[k] * rd;
      ek += c.m[k] * rd.squaredNorm() / 2;
    }
    wm = std::max(wm, (N * s - mom).norm() / mom.norm());
    we = std::max(we, abs(s.dot(N * s) / 2 - ek) / ek);
    pd += Eigen::LLT<M6>(N).info() == Eigen::Success;
  }
  ctx.checkResidual("N s = particle momentum (j, p) (100 clouds, relative)", wm, 1e-14);
  ctx.checkResidual("½ sᵀ N s = particle E_K (relative)", we, 1e-14);
  ctx.checkEqual("N positive definite (Cholesky succeeds)", 100, pd);
  // extremes: c.o.m. far from the origin (conditioning), m → 0 (rejected)
  std::string conds;
  for (const double far : {1.0, 1e2, 1e4}) {
    const SpatialInertia<double> b(1.0, V3(far, 0, 0), M3(V3(0.1, 0.2, 0.3).asDiagonal()));
    const Eigen::SelfAdjointEigenSolver<M6> es(b.matrix());
    conds += (conds.empty() ? "" : ", ") + toString(far, 3) + " m: " + toString(es.eigenvalues().maxCoeff() / es.eigenvalues().minCoeff(), 3);
  }
  bool threw = false;
  try {
    SpatialInertia<double>(0.0, V3::Zero(), M3::Identity());
  } catch (const InvalidInput&) {
    threw = true;
  }
  ctx.checkEqual("a massless body is InvalidInput", "thrown", threw ? "thrown" : "accepted");
  ctx.note("Condition number of N for a 1 kg body (moments 0.1, 0.2, 0.3) with its c.o.m. at distance " + conds +
           ": it grows like |c|⁴ (the 3×3 block I_c − mC² grows like |c|²). The 3×3 block is the inertia about the "
           "ORIGIN (erratum 22: the book says 'its 3×3 inertia tensor').");
}

void transformation(Context& ctx) {
  auto g = std::mt19937_64(1312);
  double direct = 0, ke = 0, par = 0;
  for (int t = 0; t < 100; ++t) {
    const SpatialInertia<double> b = randomBody(g);
    const SE3<double> x = SE3<double>::Random(g);
    const M6 Np = coadjointTransform(x, b.matrix());
    direct = std::max(direct, maxAbs(DM(Np - b.transformed(x).matrix())) / maxAbs(DM(Np)));
    const V6 s = rv6(g), s2 = x.adjoint() * s;
    ke = std::max(ke, abs(s2.dot(Np * s2) - s.dot(b.matrix() * s)) / s.dot(b.matrix() * s));
    // pure translation, c.o.m. at the origin: N' = [[I − mT², mT], [−mT, m]]
    const SpatialInertia<double> b0(b.mass(), V3::Zero(), b.inertiaAboutCentre());
    const V3 tv = rv3(g, -2, 2);
    const M3 T = hat(tv);
    M6 want;
    want << b0.inertiaAboutCentre() - b.mass() * T * T, b.mass() * T, -b.mass() * T, b.mass() * M3::Identity();
    const M6 got = coadjointTransform(SE3<double>(SO3<double>(), tv), b0.matrix());
    par = std::max(par, maxAbs(DM(got - want)) / maxAbs(DM(want)));
  }
  ctx.checkResidual("H⁻ᵀNH⁻¹ = the body moved directly (c' = Rc + t, I_c' = R I_c Rᵀ), 100 random", direct, 1e-14);
  ctx.checkResidual("E_K invariant: s'ᵀN's' = sᵀNs", ke, 1e-14);
  ctx.checkResidual("translation: N' = [[I − mT², mT], [−mT, mI₃]] (parallel-axis theorem)", par, 1e-14);
}

void diagonalisation(Context& ctx) {
  auto g = std::mt19937_64(1313);
  double worst = 0, cerr = 0;
  for (int t = 0; t < 100; ++t) {
    const SpatialInertia<double> b = randomBody(g, 2);
    const M6 N = b.matrix();
    const double m = N(3, 3);
    const M3 mC = N.topRightCorner<3, 3>();
    const V3 c(mC(2, 1) / m, mC(0, 2) / m, mC(1, 0) / m);  // vee(N₁₂ / m)
    cerr = std::max(cerr, (c - b.centreOfMass()).norm());
    const M3 Ic = N.topLeftCorner<3, 3>() + m * hat(c) * hat(c);
    std::vector<double> vals;
    detail::SmallMat<double> vecs;
    detail::smallSymEigen<double>(detail::SmallMat<double>(Ic), vals, vecs);
    M3 R = vecs;
    if (R.determinant() < 0) R.col(2) *= -1;
    // frame at the c.o.m. along the principal axes: g = (R, c); N in that frame = Ad(g)ᵀ N Ad(g)
    const SE3<double> frame(SO3<double>::fromMatrix(R), c);
    const M6 D = coadjointTransform(frame.inverse(), N);
    M6 off = D;
    off.diagonal().setZero();
    worst = std::max(worst, maxAbs(DM(off)) / maxAbs(DM(D)));
  }
  ctx.checkResidual("c = vee(N₁₂/m) (100 random bodies)", cerr, 1e-14);
  ctx.checkResidual("H⁻ᵀNH⁻¹ diagonal = diag(d₁, d₂, d₃, m, m, m) in the principal frame (off-diagonal, relative)", worst,
                    1e-14);
}

void conjugate(Context& ctx) {
  auto g = std::mt19937_64(1314);
  double group = 0, conj = 0, gs = 0;
  for (int t = 0; t < 50; ++t) {
    const M6 N = randomBody(g).matrix();
    const Eigen::SelfAdjointEigenSolver<M6> es(N);
    const M6 Nh = es.operatorSqrt(), Nih = es.operatorInverseSqrt();
    M6 X;
    for (int i = 0; i < 36; ++i) X(i) = uni(g);
    M6 O = Eigen::HouseholderQR<M6>(X).householderQ();
    if (O.determinant() < 0) O.col(0) *= -1;  // det −1 in even dimension has eigenvalue +1: I − M singular
    const M6 M = Nih * O * Nh;
    group = std::max(group, maxAbs(DM(M.transpose() * N * M - N)) / maxAbs(DM(N)));
    // (I − M) s₁ = (I + M) s₂: s₁, s₂ conjugate
    const V6 s2 = rv6(g);
    const V6 s1 = (M6::Identity() - M).partialPivLu().solve((M6::Identity() + M) * s2);
    conj = std::max(conj, abs(s1.dot(N * s2)) / (s1.norm() * s2.norm() * maxAbs(DM(N))));
    // Gram–Schmidt in the N inner product: six mutually conjugate screws
    std::vector<V6> b;
    for (int i = 0; i < 6; ++i) {
      V6 s = rv6(g);
      for (const V6& p : b) s -= (p.dot(N * s) / p.dot(N * p)) * p;
      b.push_back(s);
    }
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < i; ++j)
        gs = std::max(gs, abs(b[std::size_t(i)].dot(N * b[std::size_t(j)])) /
                              std::sqrt(b[std::size_t(i)].dot(N * b[std::size_t(i)]) * b[std::size_t(j)].dot(N * b[std::size_t(j)])));
  }
  ctx.checkResidual("M = N^{-1/2} O N^{1/2}, O ∈ O(6): MᵀNM = N (50 random)", group, 1e-13);
  ctx.checkResidual("solutions of (I − M)s₁ = (I + M)s₂ are conjugate: s₁ᵀNs₂ = 0", conj, 1e-12);
  ctx.checkResidual("Gram–Schmidt gives six mutually conjugate screws", gs, 1e-12);
}

void coadjointAction(Context& ctx) {
  auto g = std::mt19937_64(1315);
  double e1 = 0, e2 = 0, e3 = 0, e4 = 0;
  const M6 Q0 = q0();
  for (int t = 0; t < 200; ++t) {
    const V6 s = rv6(g), s1 = rv6(g), s2 = rv6(g), P = rv6(g);
    const V3 w = s.head<3>(), v = s.tail<3>(), j = P.head<3>(), p = P.tail<3>();
    V6 want;
    want << w.cross(j) + v.cross(p), w.cross(p);
    e1 = std::max(e1, (coad(s, P) - want).norm());
    e4 = std::max(e4, (coadjoint(SE3Tangent<double>(s), P) - want).norm());
    e2 = std::max(e2, abs(coad(s2, P).dot(s1) - P.dot(br(s1, s2))));
    e3 = std::max(e3, (coad(s1, Q0 * s2) - Q0 * br(s1, s2)).norm());
  }
  ctx.checkResidual("{s, 𝓜} = −ad(s)ᵀ𝓜 = (ω×j + v×p, ω×p) (200 random)", e1, 1e-14);
  ctx.checkResidual("soma::coadjoint equals it", e4, 1e-14);
  ctx.checkResidual("{s₂, 𝓜}(s₁) = 𝓜([s₁, s₂])", e2, 1e-14);
  ctx.checkResidual("{s₁, Q₀s₂} = Q₀[s₁, s₂] (Q₀ is ad-invariant)", e3, 1e-14);
}

void sameLine(Context& ctx) {
  auto g = std::mt19937_64(1316);
  double worst = 0;
  for (int t = 0; t < 200; ++t) {
    const V3 r = rv3(g, -3, 3), v = rv3(g);
    const double p = uni(g, -2, 2), q = uni(g, -2, 2);
    V6 s, M;
    s << v, r.cross(v) + p * v;
    M << r.cross(v) + q * v, v;
    worst = std::max(worst, coad(s, M).norm());
  }
  ctx.checkResidual("s = (v, r×v + pv), 𝓜 = (r×v + qv, v) on the same line: {s, 𝓜} = 0 (200 random)", worst, 1e-14);
  // converse fails with infinite pitches: a pure translation and a pure torque on unrelated lines
  V6 s, M;
  s << 0, 0, 0, 1, 0, 0;  // translation along x
  M << 0, 1, 0, 0, 0, 0;  // torque about y
  ctx.checkResidual("converse counter-example: translation along x, torque about y: {s, 𝓜} = 0", coad(s, M).norm(), 0.0);
  V6 s2, M2;  // finite pitches on two different lines: the bracket does not vanish
  s2 = lineScrew(V3(1, 0, 0), V3(0, 0, 0), 0.2);
  M2 << V3(0, 1, 0).cross(V3(0, 0, 1)) * 1.0 + 0.3 * V3(0, 0, 1), V3(0, 0, 1);
  ctx.checkEqual("finite pitches on two different lines: {s, 𝓜} ≠ 0", "nonzero", coad(s2, M2).norm() > 0.1 ? "nonzero" : "zero");
  ctx.note("Line 7719 swaps p and q inside the expansion (erratum 14); the result, 0, is unaffected.");
}

/// Principal screws: N s = λ Q₀ s ⟺ Q₀ N s = λ s (Q₀² = I).
void principal(Context& ctx) {
  auto g = std::mt19937_64(1317);
  double pitchErr = 0, axisErr = 0, recip = 0, conj = 0, self = 0, detErr = 0;
  double printedMin = 1e300;
  const M6 Q0 = q0();
  for (int t = 0; t < 50; ++t) {
    const SpatialInertia<double> b = randomBody(g, 1.5);
    const M6 N = b.matrix();
    const double m = b.mass();
    const Eigen::SelfAdjointEigenSolver<M3> ic(b.inertiaAboutCentre());
    const Eigen::EigenSolver<M6> es(Q0 * N);
    std::vector<V6> S;
    std::vector<double> L;
    for (int k = 0; k < 6; ++k) {
      S.push_back(es.eigenvectors().col(k).real());
      L.push_back(es.eigenvalues()(k).real());
    }
    for (int k = 0; k < 6; ++k) {
      const V3 w = S[std::size_t(k)].head<3>(), v = S[std::size_t(k)].tail<3>();
      const double p = w.dot(v) / w.squaredNorm();
      // pitch ±√(d_i/m)
      double best = 1e300;
      for (int i = 0; i < 3; ++i) best = std::min(best, abs(abs(p) - std::sqrt(ic.eigenvalues()(i) / m)));
      pitchErr = std::max(pitchErr, best);
      // axis through c: the moment about c is p ω: v − c × ω ... v = c × ω·(−1)? v = r × ω + p ω with r = c
      axisErr = std::max(axisErr, (v - b.centreOfMass().cross(w) - p * w).norm() / w.norm());
      // λ² = m d_i
      double bl = 1e300;
      for (int i = 0; i < 3; ++i) bl = std::min(bl, abs(L[std::size_t(k)] * L[std::size_t(k)] - m * ic.eigenvalues()(i)));
      detErr = std::max(detErr, bl);
      self = std::max(self, coad(S[std::size_t(k)], N * S[std::size_t(k)]).norm());
      printedMin = std::min(printedMin, abs(S[std::size_t(k)].dot(Q0 * S[std::size_t(k)])));
      for (int j = 0; j < k; ++j) {
        recip = std::max(recip, abs(S[std::size_t(j)].dot(Q0 * S[std::size_t(k)])));
        conj = std::max(conj, abs(S[std::size_t(j)].dot(N * S[std::size_t(k)])));
      }
    }
  }
  ctx.checkResidual("pitches of the 6 principal screws are ±√(d_i/m) (50 random bodies, Q₀N eigenvectors)", pitchErr, 1e-12);
  ctx.checkResidual("axes pass through the c.o.m. (moment about c = pω)", axisErr, 1e-12);
  ctx.checkResidual("λ² = m d_i: det(N − λQ₀) = Π(m d_i − λ²)", detErr, 1e-12);
  ctx.checkResidual("principal screws mutually reciprocal: s_jᵀQ₀s_i = 0 (corrected, erratum 13)", recip, 1e-12);
  ctx.checkResidual("and conjugate: s_jᵀNs_i = 0", conj, 1e-12);
  ctx.checkResidual("{s, Ns} = 0 for a principal screw", self, 1e-12);
  ctx.checkPrintedFails("0 = (λ_i − λ_j) s_iᵀQ₀s_i (line 7737)", "13", printedMin, 1e-6);
  ctx.note("Line 7737 prints s_iᵀQ₀s_i; that is 2p_i|ω|², never zero for a principal screw (the smallest "
           "|s_iᵀQ₀s_i| over 300 unit principal screws is " + toString(printedMin, 3) + "). With s_jᵀQ₀s_i it holds.");
}

void commutators(Context& ctx) {
  auto g = std::mt19937_64(1318);
  double worst = 0, self = 0;
  int cases = 0;
  for (int t = 0; t < 20; ++t) {
    const double m = uni(g, 0.5, 3);
    const V3 d = rv3(g, 0.1, 1);
    auto sp = [&](int i, int rho) {
      V6 s = V6::Zero();
      s(i) = 1;
      s(3 + i) = rho * std::sqrt(d(i) / m);
      return s;
    };
    for (int i = 0; i < 3; ++i) {
      self = std::max(self, br(sp(i, 1), sp(i, -1)).norm());
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      for (const int rho : {1, -1})
        for (const int sig : {1, -1}) {
          const double dk = std::sqrt(d(k)), di = std::sqrt(d(i)), dj = std::sqrt(d(j));
          const V6 want = (dk + rho * di + sig * dj) / (2 * dk) * sp(k, 1) + (dk - rho * di - sig * dj) / (2 * dk) * sp(k, -1);
          worst = std::max(worst, (br(sp(i, rho), sp(j, sig)) - want).norm());
          ++cases;
        }
    }
  }
  ctx.checkResidual("[s_i⁺, s_i⁻] = 0", self, 1e-15);
  ctx.checkResidual("[s_i^ρ, s_j^σ] = ((√d_k + ρ√d_i + σ√d_j)s_k⁺ + (√d_k − ρ√d_i − σ√d_j)s_k⁻)/(2√d_k), all 12 sign/cyclic cases × 20 bodies",
                    worst, 1e-14);
  ctx.checkEqual("cases checked", 240, cases);
  ctx.note("Line 7767 has OCR damage (`\\n ho` for ρ, erratum 21); read as ρ the formula holds.");
}

}  // namespace

SOMA_STUDY_DOUBLE("GF-13.1-kinetic-energy-pairing", "𝓜ᵀs = j·ω + p·v = 2E_K (point-mass clouds)", "GF §13.1", pairing);
SOMA_STUDY_DOUBLE("GF-13.1-spatial-inertia-matrix", "N = [[I, mC], [mCᵀ, mI₃]] from particles; positive definite; extremes", "GF §13.1",
     inertiaMatrix);
SOMA_STUDY_DOUBLE("GF-13.1-inertia-transformation", "N' = H⁻ᵀNH⁻¹, the skew-axis (parallel-axis) theorem", "GF §13.1", transformation);
SOMA_STUDY_DOUBLE("GF-13.1-inertia-diagonalisation", "c.o.m. and principal axes make N = diag(d₁, d₂, d₃, m, m, m)", "GF §13.1",
     diagonalisation);
SOMA_STUDY_DOUBLE("GF-13.1-conjugate-screws", "Conjugate screws s₁ᵀNs₂ = 0 and the group MᵀNM = N", "GF §13.1", conjugate);
SOMA_STUDY_DOUBLE("GF-13.1-coadjoint-lie-algebra-action", "{s, 𝓜} = −ad(s)ᵀ𝓜 and its two identities", "GF §13.1", coadjointAction);
SOMA_STUDY_DOUBLE("GF-13.1-same-line-of-action", "A screw and a co-screw on one line: {s, 𝓜} = 0 (converse needs finite pitch)",
     "GF §13.1", sameLine);
SOMA_STUDY_DOUBLE("GF-13.1-principal-screws-of-inertia", "N s = λQ₀s: pitches ±√(d_i/m), axes through c (erratum 13)", "GF §13.1",
     principal);
SOMA_STUDY_DOUBLE("GF-13.1-principal-screw-commutators", "Commutators of the principal screws of inertia, 12 cases", "GF §13.1",
     commutators);

}  // namespace soma::studies::gf13::SOMA_UNITY_ID
