// Stewart–Gough platforms (GF §11.5.4): the platform from a platform JSON text (the Python
// package writes dicts and arrays as one, so io's reader checks it), forward kinematics by every
// method (solveStewart) on the scalar ladder, leg lengths of a pose.
#include "common.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/geometry/parallel/solve_stewart.hpp"
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/io/json_number.hpp"
#include "soma/io/platform_file.hpp"
#include "soma/io/pose_file.hpp"

#include <fmt/format.h>

#include <complex>

namespace soma::python {

namespace {

struct PlatformHandle {
  std::string text, origin;
  StewartPlatform<double> platform;
  template <class S> StewartPlatform<S> in() const {
    if constexpr (std::is_same_v<S, double>) return platform;
    else return io::parsePlatform<S>(text, origin);
  }
};

/// A complex result number: a Python complex for float and double, an mpmath.mpc carrying every
/// digit of S for the other scalars.
template <class S> py::object complexNumber(const std::complex<S>& z) {
  if constexpr (std::is_same_v<S, double> || std::is_same_v<S, float>)
    return py::cast(std::complex<double>(double(z.real()), double(z.imag())));
  else
    return py::module_::import("soma._numbers")
        .attr("mpc")(io::numberText(z.real()), io::numberText(z.imag()), significandBits<S>());
}
template <class S, std::size_t N> py::list complexList(const std::array<std::complex<S>, N>& v) {
  py::list l;
  for (const auto& z : v) l.append(complexNumber<S>(z));
  return l;
}

template <class S>
py::dict solveIn(const PlatformHandle& h, StewartMethod method, int starts, std::uint64_t seed, bool complexOut) {
  StewartOptions o;
  o.method = method;
  o.numeric.starts = starts;
  o.numeric.seed = seed;
  const StewartSolution<S> sol = solveStewart<S>(h.in<S>(), o);
  py::list postures, residuals, multiplicities;
  for (std::size_t k = 0; k < sol.count(); ++k) {
    postures.append(numbers<S>(sol.postures[k].matrix()));
    residuals.append(number<S>(sol.residuals[k]));
    multiplicities.append(k < sol.posture_multiplicity.size() ? sol.posture_multiplicity[k] : 1);
  }
  py::dict d;
  d["postures"] = postures;
  d["residuals"] = residuals;
  d["seconds"] = sol.seconds;
  d["start_seconds"] = sol.start_seconds;
  d["method"] = sol.method;
  d["tracker"] = sol.tracker;
  d["scalar"] = std::string(scalarName<S>());
  d["expected_count"] = sol.expected_count;
  d["complex_count"] = method == StewartMethod::Homotopy ? int(sol.complexCount()) : -1;
  d["distinct_complex_count"] = method == StewartMethod::Homotopy ? sol.distinctCount() : -1;
  d["multiplicities"] = multiplicities;
  d["platform_class"] = sol.platform_class;
  d["pattern"] = sol.pattern;
  if (complexOut) {
    // Every complex solution (as `soma stewart --complex`): translation t and rotation quaternion a
    // (a·a = 1) in the user's frame, whether it is real, its multiplicity.
    py::list cs;
    for (const auto& c : sol.complex_postures) {
      py::dict e;
      e["translation"] = complexList<S>(c.translation);
      e["rotation"] = complexList<S>(c.rotation);
      e["real"] = c.real;
      e["multiplicity"] = c.multiplicity;
      cs.append(e);
    }
    d["complex_solutions"] = cs;
  }
  d["certified"] = sol.certified;
  d["paths_tracked"] = sol.paths_tracked;
  d["paths_failed"] = sol.paths_failed;
  d["notes"] = sol.notes;
  return d;
}

template <class S> py::object legsIn(const PlatformHandle& h, const std::string& poseJson) {
  const std::array<S, 6> l = stewartLegLengths<S>(h.in<S>(), io::parsePose<S>(poseJson, "leg_lengths: pose"));
  Eigen::Matrix<S, 6, 1> v;
  for (int i = 0; i < 6; ++i) v(i) = l[std::size_t(i)];
  return numbers<S>(v);
}

}  // namespace

void bindParallel(py::module_& m) {
  py::class_<PlatformHandle>(m, "Platform",
                             "A Stewart–Gough platform: six base joints, six platform joints (platform frame), six leg lengths.")
      .def_static("_from_json",
                  [](const std::string& text, const std::string& origin) {
                    return PlatformHandle{text, origin, io::parsePlatform<double>(text, origin)};
                  })
      .def_property_readonly("origin", [](const PlatformHandle& h) { return h.origin; })
      .def_property_readonly("base",
                             [](const PlatformHandle& h) {
                               Eigen::Matrix<double, 6, 3, Eigen::RowMajor> b;
                               for (int i = 0; i < 6; ++i) b.row(i) = h.platform.base[std::size_t(i)].transpose();
                               return b;
                             })
      .def_property_readonly("platform",
                             [](const PlatformHandle& h) {
                               Eigen::Matrix<double, 6, 3, Eigen::RowMajor> b;
                               for (int i = 0; i < 6; ++i) b.row(i) = h.platform.platform[std::size_t(i)].transpose();
                               return b;
                             })
      .def_property_readonly("legs",
                             [](const PlatformHandle& h) {
                               Eigen::Matrix<double, 6, 1> l;
                               for (int i = 0; i < 6; ++i) l(i) = h.platform.legs[std::size_t(i)];
                               return l;
                             })
      .def("leg_lengths_of",
           [](const PlatformHandle& h, const SE3<double>& g) {
             const auto l = stewartLegLengths<double>(h.platform, g);
             Eigen::Matrix<double, 6, 1> v;
             for (int i = 0; i < 6; ++i) v(i) = l[std::size_t(i)];
             return v;
           },
           py::arg("pose"), "The six leg lengths |g·p_i − b_i| of a pose of the platform.")
      .def("residual", [](const PlatformHandle& h, const SE3<double>& g) { return stewartResidual<double>(h.platform, g); },
           py::arg("pose"))
      .def("_leg_lengths",
           [](const PlatformHandle& h, const std::string& pose, const std::string& scalar, int bits) {
             return withScalar(scalarArgument(scalar, bits), [&]<class S>() { return legsIn<S>(h, pose); });
           })
      .def("_solve",
           [](const PlatformHandle& h, const std::string& method, const std::string& scalar, int bits, int starts,
              std::uint64_t seed, bool complexOut) {
             const auto mm = parseStewartMethod(method);
             if (!mm) throw InvalidInput("stewart: method \"" + method + "\" is not one of " + stewartMethodNames());
             if (starts < 1) throw InvalidInput("stewart: starts must be at least 1, got " + std::to_string(starts));
             if (complexOut && *mm != StewartMethod::Homotopy)
               throw InvalidInput("stewart: complex=True: only the homotopy finds the complex solutions (method \"homotopy\")");
             return withScalar(scalarArgument(scalar, bits),
                               [&]<class S>() { return solveIn<S>(h, *mm, starts, seed, complexOut); });
           })
      .def("__repr__", [](const PlatformHandle& h) { return "Platform(from " + h.origin + ")"; });
  m.def("stewart_methods", [] { return stewartMethodNames(); });
}

}  // namespace soma::python
