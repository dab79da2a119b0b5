// Stewart–Gough forward kinematics by multi-start local methods (Ceres, NLopt), in double (see
// stewart_numeric.hpp; the scaled residuals and the Newton polish are in stewart_numeric_impl.hpp). GF §11.5.4
#include "stewart_numeric_impl.hpp"

#include <ceres/ceres.h>
#include <nlopt.hpp>

namespace soma {
namespace {

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

}  // namespace soma
