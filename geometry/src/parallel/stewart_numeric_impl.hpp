// Stewart–Gough forward kinematics: the scaled leg residuals and the Newton polish in any scalar
// (see stewart_numeric.hpp; the Ceres and NLopt multi-start methods are in stewart_numeric.cpp). GF §11.5.4
#pragma once
#include "soma/geometry/parallel/stewart_numeric.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/algebra/tolerance.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <string>

namespace soma {
namespace {

template <class S> using Vec6S = Eigen::Matrix<S, 6, 1>;
template <class S> using Mat6S = Eigen::Matrix<S, 6, 6>;

/// The platform centred (base and platform centroids at the origin) and scaled to unit size
/// (stewartScale), so that every length 1e-8 … 1e8 is the same problem.
template <class S> struct ScaledPlatform {
  std::array<Vec3<S>, 6> p, q;
  std::array<S, 6> L2;
  Vec3<S> pbar, qbar;
  S size;

  explicit ScaledPlatform(const StewartPlatform<S>& P) : size(stewartScale<S>(P)) {
    pbar = Vec3<S>::Zero();
    qbar = Vec3<S>::Zero();
    for (int i = 0; i < 6; ++i) {
      pbar += P.base[i];
      qbar += P.platform[i];
    }
    pbar /= S(6);
    qbar /= S(6);
    for (int i = 0; i < 6; ++i) {
      p[i] = (P.base[i] - pbar) / size;
      q[i] = (P.platform[i] - qbar) / size;
      const S l = P.legs[i] / size;
      L2[i] = l * l;
    }
  }
  /// The posture in the user's coordinates of a posture (R, t) of the scaled platform:
  /// R q + t_user − p = size (R q' + t − p') with t_user = p̄ + size t − R q̄.
  SE3<S> user(const SO3<S>& R, const Vec3<S>& t) const { return SE3<S>(R, pbar + size * t - R.act(qbar)); }
  Vec3<S> scaledTranslation(const SE3<S>& g) const {
    return (g.translation() - pbar + g.so3().act(qbar)) / size;
  }
};

/// r_i = (|R q_i + t − p_i|² − L_i²) / 2 and, if J, its derivative in (δ, t) for R ← R exp(δ̂):
/// dr_i = (q_i × Rᵀe_i)·δ + e_i·dt, e_i = R q_i + t − p_i. GF §11.5.4 (leg constraint)
template <class S>
void legResiduals(const ScaledPlatform<S>& W, const SO3<S>& R, const Vec3<S>& t, Vec6S<S>& r, Mat6S<S>* J) {
  const Mat3<S> Rm = R.matrix();
  for (int i = 0; i < 6; ++i) {
    const Vec3<S> e = Rm * W.q[i] + t - W.p[i];
    r(i) = (e.squaredNorm() - W.L2[i]) / S(2);
    if (J) {
      J->template block<1, 3>(i, 0) = W.q[i].cross(Rm.transpose() * e).transpose();
      J->template block<1, 3>(i, 3) = e.transpose();
    }
  }
}

/// Newton on the scaled platform from (R, t); true when the correction reached the rounding floor.
template <class S> bool newtonScaled(const ScaledPlatform<S>& W, SO3<S>& R, Vec3<S>& t, int maxIt) {
  using std::abs;
  const S floor = S(64) * Tolerance<S>::epsilon();
  S last = S(0);
  for (int it = 0; it < maxIt; ++it) {
    Vec6S<S> r;
    Mat6S<S> J;
    legResiduals(W, R, t, r, &J);
    Vec6S<S> dx = -r;
    if (detail::smallSolveInPlace<S, 6>(J, dx) == S(0)) return false;  // singular posture
    S step = S(0);
    for (int k = 0; k < 6; ++k) step = std::max(step, S(abs(dx(k))));
    if (it > 0 && step > last) return step <= Tolerance<S>::sqrtEpsilon();  // stopped decreasing: at the floor
    R = R * SO3Tangent<S>(Vec3<S>(dx.template head<3>())).exp();
    t += dx.template tail<3>();
    last = step;
    if (step <= floor) return true;
  }
  return last <= Tolerance<S>::sqrtEpsilon();
}

}  // namespace

// GF §11.5.4, leg constraint: Newton polish in S
template <class S> SE3<S> polishStewartPosture(const StewartPlatform<S>& P, const SE3<S>& g, bool* converged) {
  validateStewartPlatform<S>(P);
  const ScaledPlatform<S> W(P);
  SO3<S> R = g.so3();
  Vec3<S> t = W.scaledTranslation(g);
  const bool ok = newtonScaled(W, R, t, 40);
  if (converged) *converged = ok;
  return W.user(R, t);
}

#define SOMA_INSTANTIATE_STEWART_NUMERIC(S) \
  template SE3<S> polishStewartPosture<S>(const StewartPlatform<S>&, const SE3<S>&, bool*);

}  // namespace soma
