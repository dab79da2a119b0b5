// The general 6R by numerical enumeration with Ceres: multi-start Levenberg–Marquardt on the 12
// pose residuals, converged points polished by Newton and clustered (double only).
#include "soma/geometry/serial/general_6r_impl.hpp"

#include <ceres/ceres.h>

namespace soma {
namespace {

class PoseCost : public ceres::SizedCostFunction<12, 6> {
 public:
  PoseCost(const Robot6R<double>& rb, const Mat3<double>& R, const Vec3<double>& t, double L)
      : rb_(rb), R_(R), t_(t), L_(L) {}
  bool Evaluate(double const* const* x, double* r, double** J) const override {
    detail6r::poseResidual12(rb_, R_, t_, L_, x[0], r, J ? J[0] : nullptr);
    return true;
  }

 private:
  const Robot6R<double>& rb_;
  Mat3<double> R_;
  Vec3<double> t_;
  double L_;
};

}  // namespace

// GF §11.5 (up to 16 postures), numerical enumeration
General6RSolution<double> solveGeneral6RCeres(const Robot6R<double>& robot,
                                              const SE3<double>& target,
                                              const General6RNumericOptions& options) {
  for (const auto& r : robot)
    if (r.type != JointType::Revolute)
      throw InvalidInput("general 6R (ceres): every joint must be revolute");
  const double L = detail6r::lengthScale(robot, target.translation());
  const Mat3<double> R = target.rotation();
  const Vec3<double> t = target.translation();
  return detail6r::multiStart6R(robot, target, options, "ceres", [&](std::array<double, 6>& q) {
    ceres::Problem::Options po;
    po.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(po);
    PoseCost cost(robot, R, t, L);
    problem.AddResidualBlock(&cost, nullptr, q.data());
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

}  // namespace soma
