#pragma once
// Definitions of SerialDynamics (serial_dynamics.hpp); included only by its per-scalar
// instantiations (soma_instantiate, cmake/SomaInstantiate.cmake).
#include "soma/geometry/dynamics/serial_dynamics.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <string>

namespace soma {
namespace detail {
/// [a, b] = ad(a) b = (ω_a × ω_b, ω_a × v_b + v_a × ω_b). GF §13.1 (catalogue conventions)
template <class S> Vec6<S> screwBracket(const Vec6<S>& a, const Vec6<S>& b) {
  const Vec3<S> wa = a.template head<3>(), va = a.template tail<3>();
  const Vec3<S> wb = b.template head<3>(), vb = b.template tail<3>();
  Vec6<S> r;
  r.template head<3>() = wa.cross(wb);
  r.template tail<3>() = wa.cross(vb) + va.cross(wb);
  return r;
}
/// {s, P} = −ad(s)ᵀP = (ω × l + v × f, ω × f). GF §13.1 line 7697
template <class S> Vec6<S> screwCoadjoint(const Vec6<S>& s, const Vec6<S>& P) {
  const Vec3<S> w = s.template head<3>(), v = s.template tail<3>();
  const Vec3<S> l = P.template head<3>(), f = P.template tail<3>();
  Vec6<S> r;
  r.template head<3>() = w.cross(l) + v.cross(f);
  r.template tail<3>() = w.cross(f);
  return r;
}
}  // namespace detail

template <class S>
SerialDynamics<S>::SerialDynamics(std::vector<SE3Tangent<S>> homeScrews,
                                  std::vector<SpatialInertia<S>> homeLinks, const S& gravity)
    : screws_(std::move(homeScrews)), links_(std::move(homeLinks)), g_(gravity) {
  using std::abs;
  if (screws_.empty()) throw InvalidInput("SerialDynamics: no joints");
  if (screws_.size() != links_.size())
    throw InvalidInput("SerialDynamics: " + std::to_string(screws_.size()) + " joint screws but " +
                       std::to_string(links_.size()) + " link inertias");
  if (!isFinite(g_) || g_ < S(0))
    throw InvalidInput("SerialDynamics: gravity " + toString(g_) + " is not a finite number ≥ 0");
  const S tol = Tolerance<S>::input();
  for (std::size_t i = 0; i < screws_.size(); ++i) {
    const Vec6<S> s = screws_[i].coeffs();
    const std::string name = "SerialDynamics: joint " + std::to_string(i + 1);
    if (!allFinite(s)) throw InvalidInput(name + " screw has a NaN or infinite entry");
    const S w2 = s.template head<3>().squaredNorm();
    using std::sqrt;
    if (abs(w2 - S(1)) <= tol) {
      revolute_.push_back(true);
      screws_[i] = SE3Tangent<S>(Vec6<S>(s / sqrt(w2)));  // exactly unit in S (RNEA's Rodrigues needs it)
    } else if (w2 <= tol * tol && abs(s.template tail<3>().squaredNorm() - S(1)) <= tol) {
      revolute_.push_back(false);
      Vec6<S> u = Vec6<S>::Zero();
      u.template tail<3>() = s.template tail<3>() / s.template tail<3>().norm();
      screws_[i] = SE3Tangent<S>(u);
    } else {
      throw InvalidInput(name + " screw is neither a unit rotation (|ω| = 1) nor a unit translation "
                                "(ω = 0, |v| = 1)");
    }
    N0_.push_back(links_[i].matrix());
  }
}

template <class S> Vec6<S> SerialDynamics<S>::gravityScrew() const {
  Vec6<S> g = Vec6<S>::Zero();
  g(5) = -g_;
  return g;
}

template <class S> SerialDynamics<S> SerialDynamics<S>::withPayload(const SpatialInertia<S>& p) const {
  std::vector<SpatialInertia<S>> links = links_;
  links.back() = links.back() + p;
  return SerialDynamics(screws_, links, g_);
}
template <class S> SerialDynamics<S> SerialDynamics<S>::withGravity(const S& g) const {
  return SerialDynamics(screws_, links_, g);
}

template <class S> void SerialDynamics<S>::checkState(const DynVector<S>& v, const char* what) const {
  if (v.size() != dof())
    throw InvalidInput(std::string("SerialDynamics: ") + what + " has " + std::to_string(v.size()) +
                       " entries, the robot has " + std::to_string(dof()) + " joints");
  if (!allFinite(v)) throw InvalidInput(std::string("SerialDynamics: ") + what + " has a NaN or infinite entry");
}

// GF §13.3 line 7965: s_i = H₁···H_i s_i⁰, N_i = (H₁ᵀ)⁻¹···(H_iᵀ)⁻¹ N_i⁰ H_i⁻¹···H₁⁻¹
template <class S> ChainConfiguration<S> SerialDynamics<S>::configuration(const DynVector<S>& theta) const {
  checkState(theta, "θ");
  const int n = dof();
  ChainConfiguration<S> c;
  c.placements.reserve(std::size_t(n));
  SE3<S> G;
  for (int i = 0; i < n; ++i) {
    G = G * SE3Tangent<S>(Vec6<S>(screws_[std::size_t(i)].coeffs() * theta(i))).exp();
    c.placements.push_back(G);
    const Mat6<S> Ad = G.adjoint();
    c.screws.push_back(Ad * screws_[std::size_t(i)].coeffs());
    c.inertias.push_back(coadjointTransform(G, N0_[std::size_t(i)]));
  }
  c.tails.resize(std::size_t(n));
  c.tails[std::size_t(n - 1)] = c.inertias[std::size_t(n - 1)];
  for (int i = n - 2; i >= 0; --i) c.tails[std::size_t(i)] = c.tails[std::size_t(i + 1)] + c.inertias[std::size_t(i)];
  return c;
}

template <class S>
std::vector<Vec6<S>> SerialDynamics<S>::linkVelocities(const ChainConfiguration<S>& c,
                                                       const DynVector<S>& thetaDot) const {
  checkState(thetaDot, "θ̇");
  std::vector<Vec6<S>> q(c.screws.size());
  Vec6<S> acc = Vec6<S>::Zero();
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = acc += thetaDot(Eigen::Index(i)) * c.screws[i];
  return q;
}

// GF §13.2.2 line 7873 (erratum 15): q̈_i = q̈_{i−1} + θ̈_i s_i + θ̇_i [q̇_{i−1}, s_i]
template <class S>
std::vector<Vec6<S>> SerialDynamics<S>::linkAccelerations(const ChainConfiguration<S>& c,
                                                          const DynVector<S>& thetaDot,
                                                          const DynVector<S>& thetaDDot) const {
  checkState(thetaDDot, "θ̈");
  const std::vector<Vec6<S>> qd = linkVelocities(c, thetaDot);
  std::vector<Vec6<S>> a(qd.size());
  Vec6<S> acc = Vec6<S>::Zero(), prev = Vec6<S>::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Eigen::Index k = Eigen::Index(i);
    acc += thetaDDot(k) * c.screws[i] + thetaDot(k) * detail::screwBracket(prev, c.screws[i]);
    a[i] = acc;
    prev = qd[i];
  }
  return a;
}

// GF §13.2.2 lines 7877–7887: A_ij = s_iᵀ N̄_max(i,j) s_j
template <class S> DynMatrix<S> SerialDynamics<S>::massMatrix(const ChainConfiguration<S>& c) const {
  const int n = dof();
  DynMatrix<S> A(n, n);
  for (int j = 0; j < n; ++j) {
    for (int i = j; i < n; ++i) {
      A(i, j) = c.screws[std::size_t(i)].dot(c.tails[std::size_t(i)] * c.screws[std::size_t(j)]);
      A(j, i) = A(i, j);
    }
  }
  return A;
}
// The same A_ij = s_iᵀ N̄_max(i,j) s_j without 6×6 algebra (the fast path): the placements G_i by
// Rodrigues, s_i = Ad(G_i)s_i⁰ by 3×3 blocks, and the tail sums N̄_i kept as (mass M, first moment
// h = Σ m c, inertia about the origin Ī), which add; N̄ s = (Ī ω + h × v, M v − h × ω); then
// f_j = N̄_j s_j and A_ij = s_i · f_j (i ≤ j). GF §13.2.2 lines 7877–7887
template <class S> DynMatrix<S> SerialDynamics<S>::massMatrix(const DynVector<S>& theta) const {
  using std::cos;
  using std::sin;
  checkState(theta, "θ");
  const int n = dof();
  const std::size_t nn = static_cast<std::size_t>(n);
  std::vector<Vec3<S>> w(nn), v(nn), h(nn);
  std::vector<Mat3<S>> I(nn);
  std::vector<S> M(nn);
  Mat3<S> R = Mat3<S>::Identity();
  Vec3<S> t = Vec3<S>::Zero();
  for (int i = 0; i < n; ++i) {
    const std::size_t k = std::size_t(i);
    const Vec3<S> sw = screws_[k].ang(), sv = screws_[k].lin();
    // s_i = Ad(G_{i−1}) s_i⁰ (H_i fixes s_i⁰): ω = R ω⁰, v = R v⁰ + t × R ω⁰
    w[k] = R * sw;
    v[k] = R * sv + t.cross(w[k]);
    Mat3<S> Ri;
    Vec3<S> ti;
    const S th = theta(i);
    if (revolute_[k]) {
      const Mat3<S> W = skew(sw);
      Ri = Mat3<S>::Identity() + sin(th) * W + (S(1) - cos(th)) * (W * W);
      const Vec3<S> wxv = sw.cross(sv);
      ti = wxv - Ri * wxv + (th * sw.dot(sv)) * sw;
    } else {
      Ri.setIdentity();
      ti = th * sv;
    }
    t = R * ti + t;
    R = R * Ri;
    const SpatialInertia<S>& L = links_[k];
    const Vec3<S> c = R * L.centreOfMass() + t;
    const Mat3<S> C = skew(c);
    M[k] = L.mass();
    h[k] = L.mass() * c;
    I[k] = R * L.inertiaAboutCentre() * R.transpose() - L.mass() * (C * C);
  }
  for (int i = n - 2; i >= 0; --i) {
    const std::size_t k = std::size_t(i);
    M[k] += M[k + 1];
    h[k] += h[k + 1];
    I[k] += I[k + 1];
  }
  DynMatrix<S> A(n, n);
  for (int j = 0; j < n; ++j) {
    const std::size_t k = std::size_t(j);
    const Vec3<S> fl = I[k] * w[k] + h[k].cross(v[k]), ff = M[k] * v[k] - h[k].cross(w[k]);
    for (int i = 0; i <= j; ++i) {
      A(i, j) = w[std::size_t(i)].dot(fl) + v[std::size_t(i)].dot(ff);
      A(j, i) = A(i, j);
    }
  }
  return A;
}

namespace detail {
// GF §13.2.2 lines 7889–7895 and §13.2.3 lines 7911–7917 (corrected, erratum 2)
template <class S, class TailOf>
std::vector<DynMatrix<S>> coriolisFromTails(const std::vector<Vec6<S>>& s, TailOf&& tailOf) {
  const int n = int(s.size());
  std::vector<DynMatrix<S>> B(std::size_t(n), DynMatrix<S>(n, n));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const int x = std::max(i, std::max(j, k));
        const Mat6<S>& Nb = tailOf(x);
        const Vec6<S>&si = s[std::size_t(i)], &sj = s[std::size_t(j)], &sk = s[std::size_t(k)];
        const S t1 = sj.dot(Nb * screwBracket(si, sk));
        const S t2 = sk.dot(Nb * screwBracket(si, sj));
        const Vec6<S> third = j <= k ? screwBracket(sk, sj) : screwBracket(sj, sk);
        const S t3 = si.dot(Nb * third);
        B[std::size_t(i)](j, k) = (t1 + t2 - t3) / S(2);
      }
    }
  }
  return B;
}
}  // namespace detail

template <class S>
std::vector<DynMatrix<S>> SerialDynamics<S>::coriolisTensor(const ChainConfiguration<S>& c) const {
  return detail::coriolisFromTails<S>(c.screws, [&](int x) -> const Mat6<S>& { return c.tails[std::size_t(x)]; });
}
template <class S>
std::vector<DynMatrix<S>> SerialDynamics<S>::coriolisTensor(const DynVector<S>& theta) const {
  return coriolisTensor(configuration(theta));
}

// GF §13.2.2 line 7899 (corrected, erratum 1): C_i = −s_iᵀ N̄_i g
template <class S>
DynVector<S> SerialDynamics<S>::gravityTorque(const ChainConfiguration<S>& c) const {
  const Vec6<S> g = gravityScrew();
  DynVector<S> C(dof());
  for (int i = 0; i < dof(); ++i) {
    const S v = c.screws[std::size_t(i)].dot(c.tails[std::size_t(i)] * g);
    C(i) = S(-v);
  }
  return C;
}
template <class S> DynVector<S> SerialDynamics<S>::gravityTorque(const DynVector<S>& theta) const {
  return gravityTorque(configuration(theta));
}

// GF §13.2.2: τ_i = A_ij θ̈_j + B_ijk θ̇_j θ̇_k + C_i
template <class S>
DynVector<S> SerialDynamics<S>::inverseDynamicsClosedForm(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                          const DynVector<S>& thetaDDot) const {
  const ChainConfiguration<S> c = configuration(theta);
  checkState(thetaDot, "θ̇");
  checkState(thetaDDot, "θ̈");
  const std::vector<DynMatrix<S>> B = coriolisTensor(c);
  DynVector<S> tau = massMatrix(c) * thetaDDot + gravityTorque(c);
  for (int i = 0; i < dof(); ++i) tau(i) += thetaDot.dot(B[std::size_t(i)] * thetaDot);
  return tau;
}

// GF §13.2.2 line 7861: τ_i = Σ_{j≥i} ((q̈_j − g)ᵀ N_j s_i + q̇_jᵀ N_j [s_i, q̇_j])
template <class S>
DynVector<S> SerialDynamics<S>::inverseDynamicsSpatial(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                       const DynVector<S>& thetaDDot) const {
  const ChainConfiguration<S> c = configuration(theta);
  const std::vector<Vec6<S>> qd = linkVelocities(c, thetaDot);
  const std::vector<Vec6<S>> qdd = linkAccelerations(c, thetaDot, thetaDDot);
  const Vec6<S> g = gravityScrew();
  const int n = dof();
  DynVector<S> tau = DynVector<S>::Zero(n);
  for (int i = 0; i < n; ++i) {
    const Vec6<S>& si = c.screws[std::size_t(i)];
    for (int j = i; j < n; ++j) {
      const Mat6<S>& N = c.inertias[std::size_t(j)];
      tau(i) += Vec6<S>(qdd[std::size_t(j)] - g).dot(N * si) +
                qd[std::size_t(j)].dot(N * detail::screwBracket(si, qd[std::size_t(j)]));
    }
  }
  return tau;
}

template <class S>
DynVector<S> SerialDynamics<S>::inverseDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                const DynVector<S>& thetaDDot) const {
  DynVector<S> tau(dof());
  inverseDynamics(theta, thetaDot, thetaDDot, tau);
  return tau;
}

// GF §13.3, algorithm box lines 8041–8065 (GF-13.3-recursive-newton-euler), home coordinates:
//   q̇_i⁰ = θ̇_i s_i⁰ + H_i⁻¹ q̇_{i−1}⁰,   (q̈_i⁰ − g_i⁰) = θ̈_i s_i⁰ + θ̇_i [q̇_i⁰, s_i⁰] + H_i⁻¹ (q̈_{i−1}⁰ − g_{i−1}⁰),
//   𝒬_i⁰ = N_i⁰ (q̈_i⁰ − g_i⁰) + {q̇_i⁰, N_i⁰ q̇_i⁰},  𝒫_i⁰ = 𝒬_i⁰ + H_{i+1}⁻ᵀ 𝒫_{i+1}⁰,  τ_i = 𝒫_i⁰ᵀ s_i⁰,
// with H_i = exp(θ_i s_i⁰) = (R_i, t_i); H⁻¹ on a twist: (Rᵀω, Rᵀ(v − t × ω)); H⁻ᵀ on a co-screw:
// (R l + t × R f, R f). N_i⁰ is applied from (m, m c, I about the origin), not as a 6×6 product.
template <class S>
void SerialDynamics<S>::inverseDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                        const DynVector<S>& thetaDDot, DynVector<S>& tau) const {
  using std::cos;
  using std::sin;
  checkState(theta, "θ");
  checkState(thetaDot, "θ̇");
  checkState(thetaDDot, "θ̈");
  const int n = dof();
  if (tau.size() != n) tau.resize(n);
  struct Work {
    std::vector<Mat3<S>> R;
    std::vector<Vec3<S>> t, Ql, Qf;
  };
  thread_local Work w;
  if (int(w.R.size()) < n) {
    w.R.resize(std::size_t(n));
    w.t.resize(std::size_t(n));
    w.Ql.resize(std::size_t(n));
    w.Qf.resize(std::size_t(n));
  }
  Vec3<S> wp = Vec3<S>::Zero(), vp = Vec3<S>::Zero();
  Vec3<S> awp = Vec3<S>::Zero(), avp(S(0), S(0), g_);  // q̈₀ − g₀ = −g = (0, +g k)
  for (int i = 0; i < n; ++i) {
    const std::size_t k = std::size_t(i);
    const Vec3<S> sw = screws_[k].ang(), sv = screws_[k].lin();
    Mat3<S>& R = w.R[k];
    Vec3<S>& t = w.t[k];
    const S th = theta(i);
    if (revolute_[k]) {
      const S sn = sin(th), cs = cos(th);
      const Mat3<S> W = skew(sw);
      R = Mat3<S>::Identity() + sn * W + (S(1) - cs) * (W * W);
      const Vec3<S> wxv = sw.cross(sv);
      t = wxv - R * wxv + (th * sw.dot(sv)) * sw;
    } else {
      R.setIdentity();
      t = th * sv;
    }
    const Vec3<S> ww = R.transpose() * wp;
    const Vec3<S> vv = R.transpose() * Vec3<S>(vp - t.cross(wp));
    const Vec3<S> om = ww + thetaDot(i) * sw;
    const Vec3<S> ve = vv + thetaDot(i) * sv;
    const Vec3<S> aw = R.transpose() * awp + thetaDDot(i) * sw + thetaDot(i) * om.cross(sw);
    const Vec3<S> av = R.transpose() * Vec3<S>(avp - t.cross(awp)) + thetaDDot(i) * sv +
                       thetaDot(i) * Vec3<S>(om.cross(sv) + ve.cross(sw));
    // N⁰ x = (I ω + m c × v, m v + m ω × c) with I about the origin, mc = m c
    const SpatialInertia<S>& L = links_[k];
    const S m = L.mass();
    const Vec3<S> mc = m * L.centreOfMass();
    const Mat6<S>& N = N0_[k];
    const Mat3<S> I = N.template topLeftCorner<3, 3>();
    const Vec3<S> hl = I * om + mc.cross(ve), hf = m * ve - mc.cross(om);  // N q̇
    const Vec3<S> al = I * aw + mc.cross(av), af = m * av - mc.cross(aw);  // N (q̈ − g)
    w.Ql[k] = al + om.cross(hl) + ve.cross(hf);
    w.Qf[k] = af + om.cross(hf);
    wp = om;
    vp = ve;
    awp = aw;
    avp = av;
  }
  Vec3<S> Pl = w.Ql[std::size_t(n - 1)], Pf = w.Qf[std::size_t(n - 1)];
  tau(n - 1) = Pl.dot(screws_[std::size_t(n - 1)].ang()) + Pf.dot(screws_[std::size_t(n - 1)].lin());
  for (int i = n - 2; i >= 0; --i) {
    const std::size_t k = std::size_t(i);
    const Mat3<S>& R = w.R[k + 1];
    const Vec3<S> Rf = R * Pf;
    Pl = w.Ql[k] + R * Pl + w.t[k + 1].cross(Rf);
    Pf = w.Qf[k] + Rf;
    tau(i) = Pl.dot(screws_[k].ang()) + Pf.dot(screws_[k].lin());
  }
}

template <class S> S SerialDynamics<S>::kineticEnergy(const DynVector<S>& theta, const DynVector<S>& thetaDot) const {
  const ChainConfiguration<S> c = configuration(theta);
  const std::vector<Vec6<S>> q = linkVelocities(c, thetaDot);
  S e = S(0);
  for (std::size_t i = 0; i < q.size(); ++i) e += q[i].dot(c.inertias[i] * q[i]);
  return e / S(2);
}

// GF §13.4 (corrected, erratum 3): E_P = Σ m_i g z_i
template <class S> S SerialDynamics<S>::potentialEnergy(const DynVector<S>& theta) const {
  checkState(theta, "θ");
  SE3<S> G;
  S e = S(0);
  for (int i = 0; i < dof(); ++i) {
    const std::size_t k = std::size_t(i);
    G = G * SE3Tangent<S>(Vec6<S>(screws_[k].coeffs() * theta(i))).exp();
    e += links_[k].mass() * g_ * G.act(links_[k].centreOfMass())(2);
  }
  return e;
}

// GF §13.4.1 (errata 4, 5): ∂E_K/∂θ_i = −(Σ_{j≥i} N_j q̇_j)ᵀ [s_i, q̇_i]
template <class S>
DynVector<S> SerialDynamics<S>::kineticEnergyGradient(const DynVector<S>& theta, const DynVector<S>& thetaDot) const {
  const ChainConfiguration<S> c = configuration(theta);
  const std::vector<Vec6<S>> q = linkVelocities(c, thetaDot);
  const int n = dof();
  DynVector<S> grad(n);
  Vec6<S> M = Vec6<S>::Zero();
  for (int i = n - 1; i >= 0; --i) {
    const std::size_t k = std::size_t(i);
    M += c.inertias[k] * q[k];
    grad(i) = -M.dot(detail::screwBracket(c.screws[k], q[k]));
  }
  return grad;
}

// GF §13.4.3 lines 8206–8210 (corrected, erratum 8): Q_ij = s_aᵀ N̄_a [s_b, g], a = max, b = min
template <class S> DynMatrix<S> SerialDynamics<S>::potentialHessian(const DynVector<S>& theta) const {
  const ChainConfiguration<S> c = configuration(theta);
  const Vec6<S> g = gravityScrew();
  const int n = dof();
  DynMatrix<S> Q(n, n);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b <= a; ++b) {
      const Vec6<S> br = detail::screwBracket(c.screws[std::size_t(b)], g);
      Q(a, b) = c.screws[std::size_t(a)].dot(c.tails[std::size_t(a)] * br);
      Q(b, a) = Q(a, b);
    }
  }
  return Q;
}

// GF §13.2.3 lines 7901–7921 (C^p corrected, erratum 1)
template <class S>
PayloadTerms<S> SerialDynamics<S>::payloadTerms(const DynVector<S>& theta, const SpatialInertia<S>& payloadHome) const {
  const ChainConfiguration<S> c = configuration(theta);
  const Mat6<S> Np = coadjointTransform(c.placements.back(), payloadHome.matrix());
  const int n = dof();
  PayloadTerms<S> p;
  p.A.resize(n, n);
  p.C.resize(n);
  const Vec6<S> g = gravityScrew();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) p.A(i, j) = c.screws[std::size_t(i)].dot(Np * c.screws[std::size_t(j)]);
    p.C(i) = -c.screws[std::size_t(i)].dot(Np * g);
  }
  p.B = detail::coriolisFromTails<S>(c.screws, [&](int) -> const Mat6<S>& { return Np; });
  return p;
}

template <class S>
DynVector<S> SerialDynamics<S>::forwardDynamics(const DynVector<S>& theta, const DynVector<S>& thetaDot,
                                                const DynVector<S>& tau) const {
  checkState(tau, "τ");
  const DynVector<S> bias = inverseDynamics(theta, thetaDot, DynVector<S>::Zero(dof()));
  const Eigen::LLT<DynMatrix<S>> llt(massMatrix(theta));
  if (llt.info() != Eigen::Success)
    throw InvalidInput("SerialDynamics::forwardDynamics: the generalised inertia A is not positive definite");
  return llt.solve(DynVector<S>(tau - bias));
}

template <class S>
DynVector<S> SerialDynamics<S>::momentum(const DynVector<S>& theta, const DynVector<S>& thetaDot) const {
  checkState(thetaDot, "θ̇");
  return massMatrix(theta) * thetaDot;
}
template <class S>
DynVector<S> SerialDynamics<S>::velocity(const DynVector<S>& theta, const DynVector<S>& pi) const {
  checkState(pi, "π");
  const Eigen::LLT<DynMatrix<S>> llt(massMatrix(theta));
  if (llt.info() != Eigen::Success)
    throw InvalidInput("SerialDynamics::velocity: the generalised inertia A is not positive definite");
  return llt.solve(pi);
}
// GF §13.5 line 8279: h = ½ πᵀ A⁻¹ π + E_P
template <class S> S SerialDynamics<S>::hamiltonian(const DynVector<S>& theta, const DynVector<S>& pi) const {
  return velocity(theta, pi).dot(pi) / S(2) + potentialEnergy(theta);
}
// GF §13.5 lines 8289, 8345 (corrected, erratum 10): π̇_i = B_jik θ̇_j θ̇_k − C_i + τ_i
template <class S>
void SerialDynamics<S>::hamiltonField(const DynVector<S>& theta, const DynVector<S>& pi, const DynVector<S>& tau,
                                      DynVector<S>& thetaDot, DynVector<S>& piDot) const {
  checkState(tau, "τ");
  const ChainConfiguration<S> c = configuration(theta);
  checkState(pi, "π");
  const Eigen::LLT<DynMatrix<S>> llt(massMatrix(c));
  if (llt.info() != Eigen::Success)
    throw InvalidInput("SerialDynamics::hamiltonField: the generalised inertia A is not positive definite");
  thetaDot = llt.solve(pi);
  const std::vector<Vec6<S>> q = linkVelocities(c, thetaDot);
  const int n = dof();
  piDot.resize(n);
  Vec6<S> M = Vec6<S>::Zero();
  for (int i = n - 1; i >= 0; --i) {
    const std::size_t k = std::size_t(i);
    M += c.inertias[k] * q[k];
    piDot(i) = -M.dot(detail::screwBracket(c.screws[k], q[k]));
  }
  piDot += tau - gravityTorque(c);
}

}  // namespace soma

// Explicit instantiation for one scalar (the rule: cmake/SomaInstantiate.cmake).
#define SOMA_INSTANTIATE_SERIAL_DYNAMICS(S) template class SerialDynamics<S>;
