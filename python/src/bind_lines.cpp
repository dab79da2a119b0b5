// Plücker lines (GF ch. 6), linear complexes (GF §6.6) and the identification of screw systems
// (GF ch. 8), in double with numpy arrays.
#include "common.hpp"

#include "soma/geometry/lines/line.hpp"
#include "soma/geometry/lines/linear_complex.hpp"
#include "soma/geometry/screws/identification.hpp"

#include <fmt/format.h>

namespace soma::python {

namespace {
using Vec3d = Eigen::Vector3d;
using Vec6d = Eigen::Matrix<double, 6, 1>;
using Line = PluckerLine<double>;

std::string v3(const Vec3d& v) { return fmt::format("[{:.6g}, {:.6g}, {:.6g}]", v(0), v(1), v(2)); }
}  // namespace

void bindLines(py::module_& m) {
  py::class_<Line>(m, "PluckerLine", "A line in Plücker coordinates (ω; v), v = q × ω (GF §6.2); Klein condition ω·v = 0 checked.")
      .def(py::init([](const Vec3d& w, const Vec3d& v) { return Line(w, v); }), py::arg("direction"), py::arg("moment"))
      .def(py::init([](const Vec6d& s) { return Line(s); }), py::arg("coordinates"))
      .def_static("through_points", &Line::throughPoints, py::arg("p"), py::arg("q"))
      .def_static("point_direction", &Line::pointDirection, py::arg("point"), py::arg("direction"))
      .def_property_readonly("direction", [](const Line& l) { return Vec3d(l.direction()); })
      .def_property_readonly("moment", [](const Line& l) { return Vec3d(l.moment()); })
      .def_property_readonly("coords", [](const Line& l) { return Vec6d(l.coords()); }, "(ω; v) as a 6-vector.")
      .def_property_readonly("foot", [](const Line& l) { return Vec3d(l.foot()); }, "The point of the line nearest the origin.")
      .def("unit_direction", [](const Line& l) { return Vec3d(l.unitDirection()); })
      .def("normalized", &Line::normalized)
      .def("reversed", &Line::reversed)
      .def("point_at", [](const Line& l, double lambda) { return Vec3d(l.pointAt(lambda)); }, py::arg("lam"))
      .def("closest_point", [](const Line& l, const Vec3d& a) { return Vec3d(l.closestPoint(a)); }, py::arg("point"))
      .def("distance", [](const Line& a, const Line& b) { return distance(a, b); }, py::arg("other"),
           "Distance along the common perpendicular.")
      .def("angle", [](const Line& a, const Line& b) { return angle(a, b); }, py::arg("other"))
      .def("meets", [](const Line& a, const Line& b) { return meet(a, b); }, py::arg("other"))
      .def("__repr__", [](const Line& l) {
        return "PluckerLine(direction " + v3(l.direction()) + ", moment " + v3(l.moment()) + ", through " + v3(l.foot()) + ")";
      });

  py::class_<LinearComplex<double>>(m, "LinearComplex", "The lines reciprocal to a screw s = (α; b) (GF §6.6).")
      .def(py::init([](const Vec6d& s) { return LinearComplex<double>(s); }), py::arg("screw"))
      .def_static("from_axis_pitch", [](const Line& axis, double p) { return LinearComplex<double>::fromAxisPitch(axis, p); },
                  py::arg("axis"), py::arg("pitch"))
      .def_property_readonly("screw", [](const LinearComplex<double>& c) { return Vec6d(c.screw()); })
      .def_property_readonly("pitch", &LinearComplex<double>::pitch)
      .def_property_readonly("axis", &LinearComplex<double>::axis)
      .def("is_singular", [](const LinearComplex<double>& c) { return c.isSingular(); })
      .def("contains", [](const LinearComplex<double>& c, const Line& l) { return c.contains(l); }, py::arg("line"))
      .def("line_through", [](const LinearComplex<double>& c, const Vec3d& y, double theta) { return c.lineThrough(y, theta); },
           py::arg("point"), py::arg("angle"), "A line of the complex through a point (angle in its null plane).")
      .def("__repr__", [](const LinearComplex<double>& c) {
        return fmt::format("LinearComplex(pitch {:.6g}, singular {})", c.pitch(), c.isSingular() ? "yes" : "no");
      });

  m.def(
      "identify_screw_system",
      [](const Eigen::MatrixXd& generators) {
        if (generators.rows() != 6) throw py::value_error("identify_screw_system: generators must be 6 x k (one screw per column)");
        const auto id = identifyScrewSystem<double>(ScrewMatX<double>(generators));
        py::dict d;
        d["name"] = id.name();
        d["dimension"] = id.dimension;
        d["via_reciprocal"] = id.viaReciprocal;
        py::list params;
        for (int i = 0; i < id.parameterCount; ++i) params.append(id.parameters[std::size_t(i)]);
        d["parameters"] = params;
        d["frame"] = id.frame;
        d["normal_form"] = Eigen::MatrixXd(id.normalForm);
        d["frame_residual"] = id.frameResidual;
        d["boundary_distance"] = id.boundaryDistance;
        d["boundary_quantity"] = id.boundaryQuantity;
        return d;
      },
      py::arg("generators"),
      "Type (GF Tables 8.1-8.3), parameters, canonical frame and distance to the nearest other type of span(generators).");
}

}  // namespace soma::python
