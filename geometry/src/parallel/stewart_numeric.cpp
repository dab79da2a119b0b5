// Stewart–Gough forward kinematics by multi-start local methods (Ceres, NLopt) and the Newton
// polish in any scalar (see stewart_numeric.hpp). GF §11.5.4
#include "soma/geometry/parallel/stewart_numeric.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/algebra/small_linalg.hpp"
#include "soma/algebra/tolerance.hpp"

#include <ceres/ceres.h>
#include <nlopt.hpp>

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

/// Ceres residual block: the six leg residuals in x = (ω, t), R = R0 exp(ω̂).
class LegCost : public ceres::SizedCostFunction<6, 6> {
 public:
  LegCost(const ScaledPlatform<double>& W, const SO3<double>& R0) : W_(W), R0_(R0) {}
  bool Evaluate(double const* const* x, double* r, double** J) const override {
    const SO3Tangent<double> w(Vec3<double>(x[0][0], x[0][1], x[0][2]));
    const SO3<double> R = R0_ * w.exp();
    const Vec3<double> t(x[0][3], x[0][4], x[0][5]);
    Vec6S<double> res;
    Mat6S<double> Jl;
    legResiduals(W_, R, t, res, J ? &Jl : nullptr);
    for (int i = 0; i < 6; ++i) r[i] = res(i);
    if (J && J[0]) {
      Jl.block<6, 3>(0, 0) = (Jl.block<6, 3>(0, 0) * w.rjac()).eval();  // chain rule through exp
      for (int i = 0; i < 6; ++i)
        for (int k = 0; k < 6; ++k) J[0][i * 6 + k] = Jl(i, k);
    }
    return true;
  }

 private:
  const ScaledPlatform<double>& W_;
  SO3<double> R0_;
};

struct NloptData {
  const ScaledPlatform<double>* W;
  SO3<double> R0;
};

double nloptObjective(unsigned n, const double* x, double* grad, void* data) {
  const auto* d = static_cast<const NloptData*>(data);
  const SO3Tangent<double> w(Vec3<double>(x[0], x[1], x[2]));
  Vec6S<double> r;
  Mat6S<double> J;
  legResiduals(*d->W, d->R0 * w.exp(), Vec3<double>(x[3], x[4], x[5]), r, grad ? &J : nullptr);
  if (grad) {
    J.block<6, 3>(0, 0) = (J.block<6, 3>(0, 0) * w.rjac()).eval();
    const Vec6S<double> g = 2.0 * (J.transpose() * r);
    for (unsigned k = 0; k < n; ++k) grad[k] = g(k);
  }
  return r.squaredNorm();
}

/// Random starts → local method → Newton polish → residual test → clustering.
template <class Local>
StewartForwardSolution<double> multiStart(const StewartPlatform<double>& P, const StewartNumericOptions& opt,
                                          const char* method, Local&& local) {
  validateStewartPlatform<double>(P);
  if (opt.starts < 1) throw InvalidInput(std::string("stewart (") + method + "): starts must be at least 1");
  const auto clock0 = std::chrono::steady_clock::now();
  const ScaledPlatform<double> W(P);
  StewartForwardSolution<double> sol;
  sol.method = method;
  std::mt19937_64 g(opt.seed);
  // Translations of the scaled platform: |t| ≤ |p'| + |q'| + L' ≤ 3 (each ≤ 1 by the scale).
  std::uniform_real_distribution<double> box(-3.0, 3.0);
  const double accept = Tolerance<double>::sqrtEpsilon();
  const double same = Tolerance<double>::precision(2);
  int converged = 0, duplicates = 0;
  std::vector<std::pair<Mat3<double>, Vec3<double>>> found;  // scaled postures, for clustering
  for (int s = 0; s < opt.starts; ++s) {
    SO3<double> R0 = SO3<double>::Random(g);
    std::array<double, 6> x{0, 0, 0, box(g), box(g), box(g)};
    if (!local(W, R0, x)) continue;
    SO3<double> R = R0 * SO3Tangent<double>(Vec3<double>(x[0], x[1], x[2])).exp();
    Vec3<double> t(x[3], x[4], x[5]);
    newtonScaled(W, R, t, 12);
    const SE3<double> gu = W.user(R, t);
    const double res = stewartResidual<double>(P, gu);
    if (!(res <= accept)) continue;
    ++converged;
    const Mat3<double> Rm = R.matrix();
    bool dup = false;
    for (const auto& [Rf, tf] : found)
      if ((Rf - Rm).cwiseAbs().maxCoeff() < same && (tf - t).cwiseAbs().maxCoeff() < same) dup = true;
    if (dup) {
      ++duplicates;
      continue;
    }
    found.emplace_back(Rm, t);
    sol.postures.push_back(gu);
    sol.residuals.push_back(res);
  }
  sol.real_count = static_cast<int>(sol.postures.size());
  sol.paths_tracked = opt.starts;
  sol.notes.push_back(std::to_string(opt.starts) + " starts, " + std::to_string(converged) + " converged, " +
                      std::to_string(duplicates) +
                      " duplicates clustered: a multi-start search finds real postures only and cannot "
                      "certify that it found them all (the homotopy can)");
  if (sol.postures.empty())
    sol.notes.push_back("no start converged: the leg lengths may be impossible, or the starts too few");
  sol.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock0).count();
  return sol;
}

}  // namespace

// GF §11.5.4 (at most 40 postures), numerical enumeration
StewartForwardSolution<double> solveStewartForwardCeres(const StewartPlatform<double>& P,
                                                        const StewartNumericOptions& options) {
  return multiStart(P, options, "ceres",
                    [&](const ScaledPlatform<double>& W, const SO3<double>& R0, std::array<double, 6>& x) {
                      ceres::Problem::Options po;
                      po.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
                      ceres::Problem problem(po);
                      LegCost cost(W, R0);
                      problem.AddResidualBlock(&cost, nullptr, x.data());
                      ceres::Solver::Options so;
                      so.linear_solver_type = ceres::DENSE_QR;
                      so.max_num_iterations = options.max_iterations;
                      so.function_tolerance = Tolerance<double>::epsilon();
                      so.gradient_tolerance = Tolerance<double>::epsilon();
                      so.parameter_tolerance = Tolerance<double>::epsilon();
                      so.logging_type = ceres::SILENT;
                      so.num_threads = 1;
                      ceres::Solver::Summary summary;
                      ceres::Solve(so, &problem, &summary);
                      return summary.IsSolutionUsable();
                    });
}

// GF §11.5.4 (at most 40 postures), numerical enumeration
StewartForwardSolution<double> solveStewartForwardNlopt(const StewartPlatform<double>& P,
                                                        const StewartNumericOptions& options) {
  return multiStart(P, options, "nlopt",
                    [&](const ScaledPlatform<double>& W, const SO3<double>& R0, std::array<double, 6>& x) {
                      NloptData data{&W, R0};
                      nlopt::opt o(nlopt::LD_LBFGS, 6);
                      o.set_min_objective(nloptObjective, &data);
                      o.set_ftol_abs(Tolerance<double>::epsilon() * Tolerance<double>::epsilon());
                      o.set_xtol_rel(Tolerance<double>::epsilon());
                      o.set_maxeval(options.max_iterations);
                      std::vector<double> v(x.begin(), x.end());
                      double f = 0;
                      try {
                        o.optimize(v, f);
                      } catch (const std::exception&) {  // NLopt throws on roundoff-limited stops: keep v
                      }
                      std::copy(v.begin(), v.end(), x.begin());
                      return std::isfinite(f);
                    });
}

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

#define SOMA_STEWART_NUMERIC_INSTANTIATE(S) \
  template SE3<S> polishStewartPosture<S>(const StewartPlatform<S>&, const SE3<S>&, bool*);
SOMA_FOR_EACH_SCALAR(SOMA_STEWART_NUMERIC_INSTANTIATE)
#undef SOMA_STEWART_NUMERIC_INSTANTIATE

}  // namespace soma
