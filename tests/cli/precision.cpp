// `soma fk` and `soma ik --json` in long double and mpfr (issue 22): the JSON carries the working
// scalar's digits — decimal strings read back with io's reader (io/json_number.hpp) — and they
// agree with an independent value to far more digits than a double holds: the fk pose with a DH
// product computed here from the robot file, the ik postures with the target pose (the forward
// kinematics of each posture, computed here, reaches it).
#include "soma/algebra/errors.hpp"
#include "soma/io/json_number.hpp"

#include "support/repo_file.hpp"
#include "support/run_soma.hpp"
#include "support/scalars.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <sys/wait.h>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using json = nlohmann::json;

using soma::test::runSoma;

json readJsonFile(const std::filesystem::path& f) {
  std::ifstream in(f);
  return json::parse(in);
}

/// A number of an input file as the readers take it (io/number.hpp): a JSON number is its double.
template <class S> S inputNumber(const json& j) { return scalarCast<S>(j.get<double>()); }

/// The tool pose of a standard-DH robot file (angles in degrees) at joints q (degrees), computed
/// here without soma's robot model: A_i = Rz(θ_i + q_i)·Tz(d_i)·Tx(a_i)·Rx(α_i) (DESIGN §6).
template <class S> Mat4<S> dhPose(const json& robot, const std::vector<S>& qDegrees) {
  using std::cos;
  using std::sin;
  const S deg = pi<S>() / S(180);
  Mat4<S> T = Mat4<S>::Identity();
  const json& rows = robot.at("joints");
  REQUIRE(rows.size() == qDegrees.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const S th = inputNumber<S>(rows[i].at("theta")) * deg + qDegrees[i] * deg;
    const S al = inputNumber<S>(rows[i].at("alpha")) * deg;
    const S a = inputNumber<S>(rows[i].at("a")), d = inputNumber<S>(rows[i].at("d"));
    Mat4<S> A;
    A << cos(th), -sin(th) * cos(al), sin(th) * sin(al), a * cos(th),  //
        sin(th), cos(th) * cos(al), -cos(th) * sin(al), a * sin(th),   //
        S(0), sin(al), cos(al), d,                                    //
        S(0), S(0), S(0), S(1);
    T = (T * A).eval();
  }
  return T;
}

/// The pose of soma's JSON ({"rotation", "translation"}) read back in S.
template <class S> Mat4<S> jsonPose(const json& pose, int& longestDigits) {
  Mat4<S> T = Mat4<S>::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const json& v = pose.at("rotation").at(r).at(c);
      T(r, c) = io::readJsonNumber<S>(v, "rotation");
      if (v.is_string()) longestDigits = std::max<int>(longestDigits, int(v.get<std::string>().size()));
    }
    T(r, 3) = io::readJsonNumber<S>(pose.at("translation").at(r), "translation");
  }
  return T;
}

/// Entries of `a` that a double could not have carried: |x − double(x)| above the bound `tol`.
template <class S> int beyondDouble(const Mat4<S>& a, const S& tol) {
  using std::abs;
  int n = 0;
  for (int i = 0; i < 16; ++i)
    if (abs(a(i) - scalarCast<S>(toDouble(a(i)))) > tol) ++n;
  return n;
}

template <class S> std::string scalarArgs() {
  return "--scalar " + std::string(scalarName<S>()) + (std::is_same_v<S, mpreal> ? " --bits 256" : "");
}

TEMPLATE_TEST_CASE("soma fk --json: the pose in the working scalar's digits", "[cli][precision]", long double, mpfr::mpreal) {
  using S = TestType;
  using std::abs;
  setMpfrBits(256);
  const auto robotFile = test::repoFile("studies/robots/puma560_nolimits.json");
  int rc = -1;
  const std::string out =
      runSoma("fk " + robotFile.string() + " --joints 10,-35.5,20,47,-63,81.25 --json " + scalarArgs<S>(), rc);
  REQUIRE(rc == 0);
  const json j = json::parse(out);
  CHECK(j.at("scalar") == std::string(scalarName<S>()));
  if constexpr (std::is_same_v<S, mpreal>) CHECK(j.at("bits") == 256);  // the precision to read it back in
  int longest = 0;
  const Mat4<S> got = jsonPose<S>(j.at("pose"), longest);
  // The joints echoed, read back exactly (decimal strings: 81.25 is 81.25 in S).
  CHECK(io::readJsonNumber<S>(j.at("joints").at(5), "joints[5]") == S(81.25));
  const std::vector<S> q = {S(10), S(-35.5), S(20), S(47), S(-63), S(81.25)};
  const Mat4<S> want = dhPose<S>(readJsonFile(robotFile), q);
  // Independent product of the same six matrices: within 64 ulps of S (lengths below 1 m).
  const S tol = Tolerance<S>::identity();
  INFO("|got - want| = " << toString(S((got - want).cwiseAbs().maxCoeff()), 6));
  CHECK((got - want).cwiseAbs().maxCoeff() <= tol);
  // More digits than a double holds: 21 (long double) or 79 (mpfr, 256 bits) significant digits,
  // and entries a double would have rounded beyond the tolerance.
  CHECK(longest >= (std::is_same_v<S, mpreal> ? 79 : 21));
  CHECK(beyondDouble(got, tol) >= 6);
}

TEMPLATE_TEST_CASE("soma ik --json: every posture reaches the pose in the working scalar's digits", "[cli][precision]",
                   long double, mpfr::mpreal) {
  using S = TestType;
  using std::abs;
  setMpfrBits(256);
  const auto robotFile = test::repoFile("studies/robots/puma560_nolimits.json");
  const auto poseFile = test::repoFile("studies/robots/puma560_pose.json");
  int rc = -1;
  const std::string out = runSoma("ik " + robotFile.string() + " --pose " + poseFile.string() + " --json " + scalarArgs<S>(), rc);
  REQUIRE(rc == 0);
  const json j = json::parse(out);
  REQUIRE(j.at("count") == 8);  // PUMA 560: 8 postures (GF §4.7, Pieper)
  CHECK_FALSE(j.contains("escalated_to"));  // Pieper's closed form: no escalation
  // The target from the pose file (JSON numbers: doubles, exact in S).
  const json pf = readJsonFile(poseFile);
  Mat4<S> target = Mat4<S>::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) target(r, c) = inputNumber<S>(pf.at("rotation").at(r).at(c));
    target(r, 3) = inputNumber<S>(pf.at("translation").at(r));
  }
  const json robot = readJsonFile(robotFile);
  const S tol = Tolerance<S>::identity(1024);  // a closed-form posture (atan2 of computed values), 6 products
  for (const json& s : j.at("solutions")) {
    std::vector<S> q;
    for (const json& v : s.at("joints")) {
      CHECK(v.is_string());  // a decimal string: a JSON double would round
      q.push_back(io::readJsonNumber<S>(v, "joints"));
    }
    const Mat4<S> reached = dhPose<S>(robot, q);
    const S err = (reached - target).cwiseAbs().maxCoeff();
    INFO("posture error " << toString(err, 6) << ", residual " << s.at("residual").dump());
    CHECK(err <= tol);
    // The residual soma reports is S's too: far below double's epsilon.
    CHECK(io::readJsonNumber<S>(s.at("residual"), "residual") <= tol);
  }
}

}  // namespace SOMA_UNITY_ID
