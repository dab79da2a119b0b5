// The general 6R by numerical enumeration with NLopt: multi-start L-BFGS on the squared pose
// residual, converged points polished by Newton and clustered (double only).
#include "soma/geometry/serial/general_6r_impl.hpp"

#include <nlopt.hpp>

namespace soma {
namespace {

struct NloptData {
  const Robot6R<double>* robot;
  Mat3<double> R;
  Vec3<double> t;
  double L;
};

double objective(unsigned n, const double* x, double* grad, void* data) {
  const auto* d = static_cast<const NloptData*>(data);
  double r[12], J[72];
  detail6r::poseResidual12(*d->robot, d->R, d->t, d->L, x, r, grad ? J : nullptr);
  double f = 0;
  for (double v : r) f += v * v;
  if (grad)
    for (unsigned i = 0; i < n; ++i) {
      double gi = 0;
      for (int k = 0; k < 12; ++k) gi += 2 * r[k] * J[k * 6 + i];
      grad[i] = gi;
    }
  return f;
}

}  // namespace

// GF §11.5 (up to 16 postures), numerical enumeration
General6RSolution<double> solveGeneral6RNlopt(const Robot6R<double>& robot,
                                              const SE3<double>& target,
                                              const General6RNumericOptions& options) {
  for (const auto& r : robot)
    if (r.type != JointType::Revolute)
      throw InvalidInput("general 6R (nlopt): every joint must be revolute");
  NloptData data{&robot, target.rotation(), target.translation(),
                 detail6r::lengthScale(robot, target.translation())};
  return detail6r::multiStart6R(robot, target, options, "nlopt", [&](std::array<double, 6>& q) {
    nlopt::opt opt(nlopt::LD_LBFGS, 6);
    opt.set_min_objective(objective, &data);
    opt.set_ftol_abs(Tolerance<double>::epsilon() * Tolerance<double>::epsilon());
    opt.set_xtol_rel(Tolerance<double>::epsilon());
    opt.set_maxeval(options.max_iterations);
    std::vector<double> x(q.begin(), q.end());
    double f = 0;
    try {
      opt.optimize(x, f);
    } catch (const std::exception&) {  // nlopt throws on roundoff-limited stops: keep x
    }
    for (int i = 0; i < 6; ++i) q[i] = x[i];
    return std::isfinite(f);
  });
}

}  // namespace soma
