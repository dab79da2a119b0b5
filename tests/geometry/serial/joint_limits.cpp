// shiftIntoLimits (joint_limits.hpp): a revolute angle is θ + 2πk; limits off (−π, π] still hold
// the posture. Both sides of each branch, and the closed form that used to drop such postures.
#include "soma/geometry/serial/ik.hpp"
#include "soma/geometry/serial/joint_limits.hpp"

#include "support/scalars.hpp"

namespace SOMA_UNITY_ID {

using namespace soma;

namespace {
double deg(double d) { return d * M_PI / 180; }

/// A 3R wrist (axes meeting at the origin) with the given limits in degrees.
SerialRobot<double> wrist(const double (&lo)[3], const double (&hi)[3]) {
  std::vector<DHRow<double>> rows = {{JointType::Revolute, 0, M_PI / 2, 0, 0},
                                     {JointType::Revolute, 0, -M_PI / 2, 0, 0},
                                     {JointType::Revolute, 0, 0, 0.1, 0}};
  std::vector<double> l, u;
  for (int i = 0; i < 3; ++i) l.push_back(deg(lo[i])), u.push_back(deg(hi[i]));
  return SerialRobot<double>::fromDH(rows, DHConvention::Standard, SE3<double>(), SE3<double>(), "wrist").withLimits(l, u);
}
}  // namespace

TEST_CASE("shiftIntoLimits: θ + 2πk into limits off −π < θ ≤ π, refused where no multiple fits", "[serial][limits]") {
  const SerialRobot<double> r = wrist({-190, -1, -170}, {45, 215, 170});
  auto at = [](double a, double b, double c) { return JointVector<double>(Eigen::Vector3d(deg(a), deg(b), deg(c))); };
  // Inside already: unchanged.
  const auto same = shiftIntoLimits(r, at(10, 100, -20));
  REQUIRE(same);
  CHECK(*same == at(10, 100, -20));
  // 175° is outside [−190°, 45°] but −185° is inside; −160° is outside [−1°, 215°] but 200° inside.
  const auto moved = shiftIntoLimits(r, at(175, -160, 0));
  REQUIRE(moved);
  CHECK((*moved)(0) == Approx(deg(-185)).epsilon(1e-15));
  CHECK((*moved)(1) == Approx(deg(200)).epsilon(1e-15));
  // Just beyond the reach of any multiple: 100° (−260° < −190°) and −170° (190° < 215°, but the
  // joint-3 range [−170°, 170°] has no multiple of 175° ± 360°).
  CHECK_FALSE(shiftIntoLimits(r, at(100, 0, 0)));
  CHECK_FALSE(shiftIntoLimits(r, at(0, 0, 175)));
  // The two sides of the lower limit of joint 1: 170.5° → −189.5° inside, 169.5° → −190.5° outside.
  CHECK(shiftIntoLimits(r, at(170.5, 0, 0)));
  CHECK_FALSE(shiftIntoLimits(r, at(169.5, 0, 0)));
}

TEST_CASE("solveIk: the closed form keeps a posture whose angle lies within the limits only as θ − 2π", "[serial][limits]") {
  // Joint 1 limits [−190°, 45°]: the posture at q1 = −185° reads as 175° after the wrist's atan2.
  const SerialRobot<double> r = wrist({-190, -179, -179}, {45, 179, 179});
  const JointVector<double> q = Eigen::Vector3d(deg(-185), deg(30), deg(40));
  IkOptions o;
  o.method = IkMethod::Wrist3R;
  const IkSolution<double> s = solveIk<double>(r, r.fk(q), o);
  bool found = false;
  for (const auto& p : s.postures) found = found || (p - q).cwiseAbs().maxCoeff() <= 1e-9;
  CHECK(found);
  for (const auto& p : s.postures) CHECK(r.withinLimits(p));
}

}  // namespace SOMA_UNITY_ID
