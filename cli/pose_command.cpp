// `soma pose POSE.json`: one rigid motion in every representation soma has — matrix, unit
// quaternion, dual quaternion, Study parameters, twist (log) and screw (Chasles) — with the
// round-trip residual of each conversion, in any scalar type.
#include "command.hpp"
#include "json_output.hpp"
#include "scalar_options.hpp"

#include "soma/algebra/dual_quaternion.hpp"
#include "soma/algebra/screw.hpp"
#include "soma/algebra/study_parameters.hpp"
#include "soma/io/json_number.hpp"
#include "soma/io/pose_file.hpp"

#include <chrono>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <iostream>

namespace soma::cli {

namespace {

using json = nlohmann::json;

template <class D> std::string toText(const Eigen::MatrixBase<D>& v) {
  std::string s = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) s += (i ? ", " : "") + io::numberText(v(i));
  return s + "]";
}

template <class S> int run(const std::filesystem::path& file, bool asJson, std::ostream& out) {
  using std::abs;
  const auto t0 = std::chrono::steady_clock::now();
  const SE3<S> g = io::readPose<S>(file);
  const DualQuaternion<S> h = DualQuaternion<S>::fromSE3(g);
  const StudyParameters<S> sp = StudyParameters<S>::fromSE3(g);
  const SE3Tangent<S> xi = g.log();
  const Screw<S> sc = screwOf(g);
  // Round trips, each measured as the max-norm distance of the 4x4 matrices.
  const Mat4<S> m = g.matrix();
  auto dist = [&](const SE3<S>& x) { return (x.matrix() - m).template lpNorm<Eigen::Infinity>(); };
  const S scale = S(1) + g.translation().template lpNorm<Eigen::Infinity>();
  const S tol = Tolerance<S>::identity() * scale;
  const S eExp = dist(xi.exp());
  const S eDq = dist(h.toSE3());
  const S eStudy = dist(sp.toSE3());
  const S eScrew = dist(sc.pureTranslation
                            ? SE3<S>(SO3<S>(), sc.translationDirection * sc.translationDistance)
                            : screwMotion(sc.axis, sc.point, sc.pitch, sc.theta));
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const bool ok = eExp <= tol && eDq <= tol && eStudy <= tol && eScrew <= tol;
  const Quat<S>& q = g.quaternion();
  const Vec4<S> qv(q.w(), q.x(), q.y(), q.z());
  if (asJson) {
    json j = {{"input", file.string()},
              {"seconds", secs},
              {"matrix", io::jsonNumbers(m)},
              {"quaternion_wxyz", io::jsonNumbers(qv)},
              {"dual_quaternion", io::jsonNumbers(h.coeffs())},
              {"study_parameters", io::jsonNumbers(sp.coeffs())},
              {"study_condition", io::jsonNumber(sp.studyCondition())},
              {"study_defect", io::jsonNumber(sp.studyDefect())},
              {"twist", io::jsonNumbers(xi.coeffs())},
              {"screw",
               sc.pureTranslation
                   ? json{{"pure_translation", true},
                          {"direction", io::jsonNumbers(sc.translationDirection)},
                          {"distance", io::jsonNumber(sc.translationDistance)}}
                   : json{{"pure_translation", false},
                          {"angle", io::jsonNumber(sc.theta)},
                          {"axis", io::jsonNumbers(sc.axis)},
                          {"point", io::jsonNumbers(sc.point)},
                          {"pitch_per_radian", io::jsonNumber(sc.pitch)}}},
              {"round_trip_residuals",
               {{"exp(log)", io::jsonNumber(eExp)},
                {"dual_quaternion", io::jsonNumber(eDq)},
                {"study_parameters", io::jsonNumber(eStudy)},
                {"screw", io::jsonNumber(eScrew)}}},
              {"tolerance", io::jsonNumber(tol)},
              {"passed", ok}};
    io::addScalar<S>(j);
    out << jsonText(j) << "\n";
    return ok ? 0 : 1;
  }
  out << fmt::format("pose {} ({}, {} significant bits)\n", file.string(), scalarName<S>(),
                     digits<S>());
  out << "  matrix          " << toText(m.row(0)) << "\n";
  for (int i = 1; i < 4; ++i) out << "                  " << toText(m.row(i)) << "\n";
  out << "  quaternion      (w, x, y, z) = " << toText(qv) << "\n";
  out << "  dual quaternion a + εc, c = ½ t a   (GF §9.3)\n"
      << "                  a = " << toText(h.coeffs().template head<4>()) << "\n"
      << "                  c = " << toText(h.coeffs().template tail<4>()) << "\n";
  out << "  Study params    " << toText(sp.coeffs()) << "\n"
      << "                  a·c = " << io::numberText(sp.studyCondition())
      << ", |a·c|/(|a||c|) = " << toString(sp.studyDefect(), 3) << "  (Study quadric)\n";
  out << "  twist log       (ω; v) = " << toText(xi.coeffs()) << "\n";
  if (sc.pureTranslation)
    out << "  screw           pure translation " << io::numberText(sc.translationDistance)
        << " along " << toText(sc.translationDirection) << "\n";
  else
    out << "  screw           θ = " << io::numberText(sc.theta) << " about " << toText(sc.axis)
        << " through " << toText(sc.point) << ", pitch " << io::numberText(sc.pitch)
        << " per radian  (GF §2.5.2)\n";
  out << fmt::format(
      "  round trips     exp(log) {:.3g}, dual quaternion {:.3g}, Study {:.3g}, screw {:.3g}"
      "  (tolerance {:.3g}) {}\n",
      toDouble(eExp), toDouble(eDq), toDouble(eStudy), toDouble(eScrew), toDouble(tol),
      ok ? "PASS" : "FAIL");
  out << fmt::format("  time            {:.3g} ms\n", secs * 1e3);
  return ok ? 0 : 1;
}

int poseCommand(const std::filesystem::path& file, ScalarKind scalar, bool json, std::ostream& out) {
  return withScalar(scalar, [&]<class S>() { return run<S>(file, json, out); });
}

class PoseCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "pose";
    spec.help = "one pose in every representation: matrix, quaternion, dual quaternion, Study "
                "parameters, twist, screw, with round-trip residuals";
    spec.add("file", file_, "pose JSON: {\"rotation\": [[3x3]] or \"quaternion\": "
                            "[w,x,y,z], \"translation\": [x,y,z]}")
        .mustBeGiven();
    scalar_.declare(spec);
    spec.flag("--json", json_, "print one JSON object");
  }
  int run(const Spec&, const Invocation&) override { return poseCommand(file_, scalar_.apply(), json_, std::cout); }

 private:
  std::string file_;
  ScalarOptions scalar_;
  bool json_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(PoseCommand, 30);

}  // namespace soma::cli
