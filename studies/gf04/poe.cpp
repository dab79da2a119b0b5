// Studies of GF chapter 4, §4.5.1: product of exponentials, the robot Jacobian and the
// derivatives of joint screws.
#include "gf04/common.hpp"

namespace soma::studies::gf04::SOMA_UNITY_ID {  // this file's own names in a unity batch (studies/CMakeLists.txt)
namespace {

/// A serial arm of joint screws (home position), revolute s = (ω; q × ω) or prismatic (0; d).
template <class S> std::vector<SE3Tangent<S>> randomArm(std::mt19937_64& g, int n = 6) {
  std::vector<SE3Tangent<S>> s;
  for (int i = 0; i < n; ++i) {
    const Vec3<S> w = randomUnit<S>(g), q = randomVec<S, 3>(g);
    s.emplace_back(w, Vec3<S>(q.cross(w)));
  }
  return s;
}
/// K(θ) = e^{θ₁s₁} ⋯ e^{θₙsₙ} (GF §4.5.1, GF-4.5.1-product-of-exponentials), by soma's exp.
template <class S> SE3<S> poe(const std::vector<SE3Tangent<S>>& s, const std::vector<S>& th) {
  SE3<S> k;
  for (std::size_t i = 0; i < s.size(); ++i) k = k * (s[i] * th[i]).exp();
  return k;
}
/// Current joint screws s_k(θ) = Ad(e^{θ₁s₁} ⋯ e^{θ_{k−1}s_{k−1}}) s_k, the Jacobian columns.
// GF §4.5.1, GF-4.5.1-jacobian-and-screw-derivatives
template <class S> std::vector<Vec6<S>> currentScrews(const std::vector<SE3Tangent<S>>& s, const std::vector<S>& th) {
  std::vector<Vec6<S>> out;
  SE3<S> prefix;
  for (std::size_t i = 0; i < s.size(); ++i) {
    out.push_back(prefix.adjoint() * s[i].coeffs());
    prefix = prefix * (s[i] * th[i]).exp();
  }
  return out;
}
template <class S> Mat6<S> jacobian(const std::vector<SE3Tangent<S>>& s, const std::vector<S>& th) {
  const auto cols = currentScrews(s, th);
  Mat6<S> j;
  for (int i = 0; i < 6; ++i) j.col(i) = cols[i];
  return j;
}
template <class S> std::vector<S> randomAngles(std::mt19937_64& g, int n = 6) {
  std::vector<S> th;
  for (int i = 0; i < n; ++i) th.push_back(uniform<S>(g, -2, 2));
  return th;
}

// ---- GF §4.5.1, GF-4.5.1-product-of-exponentials --------------------------------------------
template <class S> void productOfExponentials(Context& c) {
  auto g = rng(57);
  const auto s = randomArm<S>(g);
  const auto th = randomAngles<S>(g);
  const S tol = Tolerance<S>::identity(64);
  Mat4<S> series = Mat4<S>::Identity();
  for (int i = 0; i < 6; ++i) series = series * expSeries(Mat4<S>(th[i] * s[i].hat()));
  c.checkResidual("K(θ) = e^{θ₁S₁}⋯e^{θ₆S₆}: soma exp products = power-series products",
                  maxAbs(Mat4<S>(poe(s, th).matrix() - series)), tol * S(8));
  // At home ∂K/∂θ_i = S_i.
  const std::vector<S> home(6, S(0));
  S atHome(0);
  for (int i = 0; i < 6; ++i) {
    const Mat4<S> d = derivative<S>([&](const S& e) {
      auto t = home;
      t[i] += e;
      return poe(s, t).matrix();
    });
    atHome = maxOf(atHome, maxAbs(Mat4<S>(d - s[i].hat())));
  }
  c.checkResidual("at home ∂K/∂θ_i = S_i (finite differences, 6 joints)", atHome, fdTolerance<S>(S(16)));
  // Point velocity at a general θ with the CURRENT joint screws: (ṗ; 0) = (Σ θ̇_i S_i(θ)) K (p; 1).
  const Vec3<S> p = randomVec<S, 3>(g);
  std::vector<S> rate;
  for (int i = 0; i < 6; ++i) rate.push_back(uniform<S>(g));
  const Vec3<S> fd = derivative<S>([&](const S& e) {
    auto t = th;
    for (int i = 0; i < 6; ++i) t[i] += e * rate[i];
    return poe(s, t).act(p);
  });
  const auto cur = currentScrews(s, th);
  Vec6<S> twist = Vec6<S>::Zero();
  for (int i = 0; i < 6; ++i) twist += rate[i] * cur[i];
  const Vec3<S> pk = poe(s, th).act(p);
  const Vec3<S> vel = twist.template head<3>().cross(pk) + twist.template tail<3>();
  c.checkResidual("ṗ = (Σ θ̇_i S_i(θ)) K p with current screws (finite differences, random θ)",
                  maxAbs(Vec3<S>(fd - vel)), fdTolerance<S>(S(64)));
  // Extremes: θ_i + 2π leaves K unchanged; a prismatic joint with travel 1e3.
  auto t2 = th;
  t2[2] += S(2) * pi<S>();
  t2[4] -= S(4) * pi<S>();
  c.checkResidual("θ₃ + 2π, θ₅ − 4π: K unchanged (revolute joints)", maxAbs(Mat4<S>(poe(s, t2).matrix() - poe(s, th).matrix())),
                  tol * S(16));
  auto sp = s;
  const Vec3<S> d = randomUnit<S>(g);
  sp[1] = SE3Tangent<S>(Vec3<S>::Zero(), d);
  auto tp = th;
  tp[1] = S(1000);
  SE3<S> expect = (s[0] * th[0]).exp() * SE3<S>(SO3<S>(), Vec3<S>(S(1000) * d));
  for (int i = 2; i < 6; ++i) expect = expect * (s[i] * th[i]).exp();
  c.checkResidual("prismatic joint 2 with travel 1000: e^{θ(0; d)} = translation θd (error ≤ 64 eps · 1000)",
                  maxAbs(Mat4<S>(poe(sp, tp).matrix() - expect.matrix())), tol * S(1000));
}
SOMA_STUDY_SCALAR("GF-4.5.1-product-of-exponentials",
           "Product of exponentials K(θ) = Π e^{θ_i s_i}; ∂K/∂θ_i = S_i; point velocity with current screws",
           "GF §4.5.1", productOfExponentials);

// ---- GF §4.5.1, GF-4.5.1-jacobian-and-screw-derivatives ---------------------------------------
template <class S> void jacobianScrewDerivatives(Context& c) {
  auto g = rng(58);
  const auto s = randomArm<S>(g);
  const auto th = randomAngles<S>(g);
  const S tol = Tolerance<S>::identity(64);
  // Ad(e^s) = e^{ad(s)}.
  S adExp(0);
  for (int i = 0; i < 6; ++i)
    adExp = maxOf(adExp, maxAbs(Mat6<S>((s[i] * th[i]).exp().adjoint() - expSeries(Mat6<S>(th[i] * s[i].ad())))));
  c.checkResidual("Ad(e^s) = e^{ad(s)} (SE3::adjoint vs power series, 6 joints)", adExp, tol * S(8));
  // (ω; v) = J θ̇: the end-effector velocity screw vee(K̇K⁻¹) from finite differences.
  std::vector<S> rate;
  for (int i = 0; i < 6; ++i) rate.push_back(uniform<S>(g));
  const Mat4<S> kd = derivative<S>([&](const S& e) {
    auto t = th;
    for (int i = 0; i < 6; ++i) t[i] += e * rate[i];
    return poe(s, t).matrix();
  });
  const Vec6<S> twist = SE3Tangent<S>::vee(Mat4<S>(kd * poe(s, th).inverse().matrix())).coeffs();
  Vec6<S> jrate = Vec6<S>::Zero();
  const Mat6<S> J = jacobian(s, th);
  for (int i = 0; i < 6; ++i) jrate += J.col(i) * rate[i];
  c.checkResidual("velocity screw vee(K̇K⁻¹) = J θ̇, columns = current joint screws", maxAbs(Vec6<S>(twist - jrate)),
                  fdTolerance<S>(S(64)));
  // ∂s_j/∂θ_i = [s_i, s_j] (i < j), 0 (i ≥ j): at home and at a random θ (current screws).
  for (const bool atHome : {true, false}) {
    const std::vector<S> base = atHome ? std::vector<S>(6, S(0)) : th;
    const auto cur = currentScrews(s, base);
    S worst(0);
    for (int i = 0; i < 6; ++i) {
      const auto dcols = derivative<S>([&](const S& e) {
        auto t = base;
        t[i] += e;
        return jacobian(s, t);
      });
      for (int j = 0; j < 6; ++j) {
        const Vec6<S> expect = i < j ? bracket(SE3Tangent<S>(cur[i]), SE3Tangent<S>(cur[j])).coeffs() : Vec6<S>::Zero();
        worst = maxOf(worst, maxAbs(Vec6<S>(dcols.col(j) - expect)));
      }
    }
    c.checkResidual(std::string("∂s_j/∂θ_i = [s_i, s_j] (i < j), 0 (i ≥ j), ") + (atHome ? "at home" : "at a random θ") +
                        " (finite differences, 36 pairs)",
                    worst, fdTolerance<S>(S(64)));
  }
  // det J does not depend on θ₁ and θ₆, but does on θ₃.
  const S d0 = jacobian(s, th).determinant();
  auto t16 = th;
  t16[0] += S(7) / S(10);
  t16[5] -= S(13) / S(10);
  const S d16 = jacobian(s, t16).determinant();
  auto t3 = th;
  t3[2] += S(7) / S(10);
  const S d3 = jacobian(s, t3).determinant();
  c.checkNear("det J unchanged when θ₁ += 0.7, θ₆ −= 1.3 (relative)", S(1), d16 / d0, tol * S(16));
  c.checkEqual("det J when θ₃ += 0.7", "changes", abs(d3 / d0 - S(1)) > S(1) / S(100) ? "changes" : "unchanged");
  c.note("det J = " + str(d0, 8) + " at the random θ; " + str(d16, 8) + " after changing θ₁, θ₆; " + str(d3, 8) +
         " after changing θ₃.");
  // A singular configuration: a spherical wrist with s₄ and s₆ on one line (θ₅ = 0).
  auto sw = s;
  const Vec3<S> w = randomVec<S, 3>(g), z = randomUnit<S>(g);
  Vec3<S> x = randomUnit<S>(g);
  x = (x - x.dot(z) * z).normalized();
  sw[3] = SE3Tangent<S>(z, Vec3<S>(w.cross(z)));
  sw[4] = SE3Tangent<S>(x, Vec3<S>(w.cross(x)));
  sw[5] = SE3Tangent<S>(z, Vec3<S>(w.cross(z)));
  auto tw = th;
  tw[3] = tw[4] = tw[5] = S(0);
  const S scale = jacobian(sw, th).template lpNorm<Eigen::Infinity>();
  c.checkResidual("wrist s₄ = s₆ (θ₅ = 0): det J = 0 (relative to |J|⁶)", abs(jacobian(sw, tw).determinant()) / ipow(scale, 6),
                  tol * S(16));
  tw[4] = S(1) / S(2);
  c.checkEqual("… and θ₅ = 0.5 leaves the singularity", "non-singular",
               abs(jacobian(sw, tw).determinant()) / ipow(scale, 6) > S(1) / S(100000) ? "non-singular" : "singular");
}
SOMA_STUDY_SCALAR("GF-4.5.1-jacobian-and-screw-derivatives",
           "Robot Jacobian = current joint screws; ∂s_j/∂θ_i = [s_i, s_j]; det J independent of θ₁, θ₆",
           "GF §4.5.1", jacobianScrewDerivatives);

}  // namespace
}  // namespace soma::studies::gf04::SOMA_UNITY_ID
