// SO(3), SE(3) and their tangents (exp, log, the right and left Jacobians, manif's J_out_in
// convention), dual quaternions and Study parameters, in double with numpy arrays; and the same
// maps on the scalar ladder (`scalar=`, `bits=`), results as mpmath numbers (GF ch. 2-4, 9).
#include "common.hpp"

#include "soma/algebra/dual_quaternion.hpp"
#include "soma/algebra/errors.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/algebra/so3.hpp"
#include "soma/algebra/study_parameters.hpp"
#include "soma/io/json_number.hpp"
#include "soma/io/pose_file.hpp"

#include <fmt/format.h>

#include <random>

namespace soma::python {

namespace {

using Vec3d = Eigen::Vector3d;
using Vec6d = Eigen::Matrix<double, 6, 1>;
using Mat3d = Eigen::Matrix3d;
using Mat4d = Eigen::Matrix4d;
using Mat6d = Eigen::Matrix<double, 6, 6>;

std::string vecText(const Eigen::VectorXd& v) {
  std::string s = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) s += (i ? ", " : "") + fmt::format("{:.6g}", v(i));
  return s + "]";
}

Eigen::Vector4d wxyz(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }

std::string so3Repr(const SO3d& r) {
  const Vec3d w = r.log().coeffs();
  return "SO3(rotation vector " + vecText(w) + fmt::format(", angle {:.6g} rad)", w.norm());
}
std::string se3Repr(const SE3d& g) {
  return "SE3(rotation vector " + vecText(g.so3().log().coeffs()) + ", translation " + vecText(g.translation()) + ")";
}

// ---- the ladder: exp and log of SO(3)/SE(3), dual quaternions, Study parameters in any scalar ----
template <class S> py::object se3ExpIn(py::handle xi) {
  const auto v = vectorFrom<S>(xi, 6, "se3_exp: xi");
  return numbers<S>(SE3Tangent<S>(Vec6<S>(v)).exp().matrix());
}
template <class S> py::object se3LogIn(const std::string& poseJson) {
  return numbers<S>(io::parsePose<S>(poseJson, "se3_log: pose").log().coeffs());
}
template <class S> py::object so3ExpIn(py::handle w) {
  const auto v = vectorFrom<S>(w, 3, "so3_exp: w");
  return numbers<S>(SO3Tangent<S>(Vec3<S>(v)).exp().matrix());
}
template <class S> py::object so3LogIn(const std::string& poseJson) {
  return numbers<S>(io::parsePose<S>(poseJson, "so3_log: rotation").so3().log().coeffs());
}
template <class S> py::object dualQuaternionIn(const std::string& poseJson) {
  return numbers<S>(DualQuaternion<S>::fromSE3(io::parsePose<S>(poseJson, "dual_quaternion: pose")).coeffs());
}
template <class S> py::object studyIn(const std::string& poseJson) {
  return numbers<S>(StudyParameters<S>::fromSE3(io::parsePose<S>(poseJson, "study_parameters: pose")).coeffs());
}
template <class S> py::object poseFromStudyIn(py::handle v) {
  const auto c = vectorFrom<S>(v, 8, "pose_from_study: coordinates");
  return numbers<S>(StudyParameters<S>::fromCoordinates(Vec8<S>(c)).matrix());
}

}  // namespace

void bindAlgebra(py::module_& m) {
  // ---------------------------------------------------------------- SO(3)
  py::class_<SO3d>(m, "SO3", "A rotation (unit quaternion inside), GF §2.3. Jacobians follow manif (J_out_in, right).")
      .def(py::init([](const Mat3d& r) { return SO3d::fromMatrix(r); }), py::arg("matrix"),
           "From a 3x3 rotation matrix (orthogonality checked: ValueError).")
      .def(py::init<>())
      .def_static("identity", &SO3d::Identity)
      .def_static("from_quaternion",
                  [](double w, double x, double y, double z) { return SO3d::fromQuaternion(Eigen::Quaterniond(w, x, y, z)); },
                  py::arg("w"), py::arg("x"), py::arg("y"), py::arg("z"), "From a unit quaternion (w, x, y, z).")
      .def_static("from_axis_angle", [](const Vec3d& axis, double theta) { return SO3d::fromAxisAngle(axis, theta); },
                  py::arg("axis"), py::arg("angle"))
      .def_static("random", [](std::uint64_t seed) { std::mt19937_64 g(seed); return SO3d::Random(g); },
                  py::arg("seed") = 1, "A uniformly random rotation (seeded).")
      .def_static(
          "exp",
          [](const Vec3d& w, bool jacobian) -> py::object {
            if (!jacobian) return py::cast(SO3Tangent<double>(w).exp());
            Mat3d J;
            const SO3d r = SO3Tangent<double>(w).exp(&J);
            return py::make_tuple(r, J);
          },
          py::arg("w"), py::arg("jacobian") = false, "exp of a rotation vector ω; with jacobian=True also J_R_ω (the right Jacobian).")
      .def_property_readonly("matrix", &SO3d::matrix, "The 3x3 rotation matrix.")
      .def_property_readonly("quaternion", [](const SO3d& r) { return wxyz(r.quaternion()); }, "(w, x, y, z).")
      .def(
          "log",
          [](const SO3d& r, bool jacobian) -> py::object {
            if (!jacobian) return py::cast(Vec3d(r.log().coeffs()));
            Mat3d J;
            const Vec3d w = r.log(&J).coeffs();
            return py::make_tuple(w, J);
          },
          py::arg("jacobian") = false, "The rotation vector ω (θ ∈ [0, π]); with jacobian=True also J_ω_R.")
      .def(
          "inverse",
          [](const SO3d& r, bool jacobian) -> py::object {
            if (!jacobian) return py::cast(r.inverse());
            Mat3d J;
            const SO3d i = r.inverse(&J);
            return py::make_tuple(i, J);
          },
          py::arg("jacobian") = false)
      .def(
          "compose",
          [](const SO3d& a, const SO3d& b, bool jacobians) -> py::object {
            if (!jacobians) return py::cast(a.compose(b));
            Mat3d Ja, Jb;
            const SO3d c = a.compose(b, &Ja, &Jb);
            return py::make_tuple(c, Ja, Jb);
          },
          py::arg("other"), py::arg("jacobians") = false, "self·other; with jacobians=True also J_c_self, J_c_other.")
      .def(
          "act",
          [](const SO3d& r, const Vec3d& p, bool jacobians) -> py::object {
            if (!jacobians) return py::cast(Vec3d(r.act(p)));
            Mat3d Jr, Jp;
            const Vec3d q = r.act(p, &Jr, &Jp);
            return py::make_tuple(q, Jr, Jp);
          },
          py::arg("point"), py::arg("jacobians") = false, "R p; with jacobians=True also J_q_R, J_q_p.")
      .def("adjoint", &SO3d::adjoint)
      .def("between", &SO3d::between)
      .def_static("interpolate", [](const SO3d& a, const SO3d& b, double t) { return SO3d::interpolate(a, b, t); })
      .def("is_approx", &SO3d::isApprox, py::arg("other"), py::arg("tol") = 1e-12)
      .def("__mul__", [](const SO3d& a, const SO3d& b) { return a * b; })
      .def("__mul__", [](const SO3d& a, const Vec3d& p) { return Vec3d(a * p); })
      .def("__repr__", &so3Repr);
  m.def("so3_rjac", [](const Vec3d& w) { return SO3Tangent<double>(w).rjac(); }, py::arg("w"), "Right Jacobian of SO(3) at ω.");
  m.def("so3_ljac", [](const Vec3d& w) { return SO3Tangent<double>(w).ljac(); }, py::arg("w"), "Left Jacobian of SO(3) at ω.");
  m.def("so3_rjacinv", [](const Vec3d& w) { return SO3Tangent<double>(w).rjacinv(); }, py::arg("w"));
  m.def("so3_ljacinv", [](const Vec3d& w) { return SO3Tangent<double>(w).ljacinv(); }, py::arg("w"));
  m.def("hat3", [](const Vec3d& w) { return skew(w); }, py::arg("w"), "The skew matrix [ω]×.");

  // ---------------------------------------------------------------- SE(3)
  py::class_<SE3d>(m, "SE3", "A rigid motion (R, t), GF §2.5. Twists are 6-vectors (ω; v), moment v = q × ω.")
      .def(py::init([](const Mat4d& g) { return SE3d::fromMatrix(g); }), py::arg("matrix"),
           "From a 4x4 homogeneous matrix (checked: ValueError).")
      .def(py::init([](const Mat3d& r, const Vec3d& t) { return SE3d(SO3d::fromMatrix(r), t); }), py::arg("rotation"),
           py::arg("translation"))
      .def(py::init([](const SO3d& r, const Vec3d& t) { return SE3d(r, t); }), py::arg("rotation"), py::arg("translation"))
      .def(py::init<>())
      .def_static("identity", &SE3d::Identity)
      .def_static("random", [](std::uint64_t seed) { std::mt19937_64 g(seed); return SE3d::Random(g); },
                  py::arg("seed") = 1)
      .def_static(
          "exp",
          [](const Vec6d& xi, bool jacobian) -> py::object {
            if (!jacobian) return py::cast(SE3Tangent<double>(xi).exp());
            Mat6d J;
            const SE3d g = SE3Tangent<double>(xi).exp(&J);
            return py::make_tuple(g, J);
          },
          py::arg("xi"), py::arg("jacobian") = false, "exp of a twist (ω; v); with jacobian=True also the right Jacobian.")
      .def_property_readonly("matrix", &SE3d::matrix, "The 4x4 homogeneous matrix.")
      .def_property_readonly("rotation", &SE3d::rotation)
      .def_property_readonly("translation", [](const SE3d& g) { return Vec3d(g.translation()); })
      .def_property_readonly("so3", [](const SE3d& g) { return g.so3(); })
      .def(
          "log",
          [](const SE3d& g, bool jacobian) -> py::object {
            if (!jacobian) return py::cast(Vec6d(g.log().coeffs()));
            Mat6d J;
            const Vec6d xi = g.log(&J).coeffs();
            return py::make_tuple(xi, J);
          },
          py::arg("jacobian") = false, "The twist (ω; v) with exp(ξ) = self; with jacobian=True also J_ξ_g.")
      .def(
          "inverse",
          [](const SE3d& g, bool jacobian) -> py::object {
            if (!jacobian) return py::cast(g.inverse());
            Mat6d J;
            const SE3d i = g.inverse(&J);
            return py::make_tuple(i, J);
          },
          py::arg("jacobian") = false)
      .def(
          "compose",
          [](const SE3d& a, const SE3d& b, bool jacobians) -> py::object {
            if (!jacobians) return py::cast(a.compose(b));
            Mat6d Ja, Jb;
            const SE3d c = a.compose(b, &Ja, &Jb);
            return py::make_tuple(c, Ja, Jb);
          },
          py::arg("other"), py::arg("jacobians") = false)
      .def(
          "act",
          [](const SE3d& g, const Vec3d& p, bool jacobians) -> py::object {
            if (!jacobians) return py::cast(Vec3d(g.act(p)));
            Eigen::Matrix<double, 3, 6> Jg;
            Mat3d Jp;
            const Vec3d q = g.act(p, &Jg, &Jp);
            return py::make_tuple(q, Jg, Jp);
          },
          py::arg("point"), py::arg("jacobians") = false, "R p + t; with jacobians=True also J_q_g (3x6), J_q_p.")
      .def("adjoint", &SE3d::adjoint, "The 6x6 adjoint acting on twists (ω; v).")
      .def("between", &SE3d::between)
      .def("rplus", [](const SE3d& g, const Vec6d& xi) { return g.rplus(SE3Tangent<double>(xi)); })
      .def("rminus", [](const SE3d& g, const SE3d& h) { return Vec6d(g.rminus(h).coeffs()); })
      .def_static("interpolate", [](const SE3d& a, const SE3d& b, double t) { return SE3d::interpolate(a, b, t); })
      .def("is_approx", &SE3d::isApprox, py::arg("other"), py::arg("tol") = 1e-12)
      .def("__mul__", [](const SE3d& a, const SE3d& b) { return a * b; })
      .def("__mul__", [](const SE3d& a, const Vec3d& p) { return Vec3d(a * p); })
      .def("__repr__", &se3Repr);
  m.def("se3_rjac", [](const Vec6d& xi) { return SE3Tangent<double>(xi).rjac(); }, py::arg("xi"), "Right Jacobian of SE(3) at ξ = (ω; v).");
  m.def("se3_ljac", [](const Vec6d& xi) { return SE3Tangent<double>(xi).ljac(); }, py::arg("xi"));
  m.def("se3_rjacinv", [](const Vec6d& xi) { return SE3Tangent<double>(xi).rjacinv(); }, py::arg("xi"));
  m.def("se3_ljacinv", [](const Vec6d& xi) { return SE3Tangent<double>(xi).ljacinv(); }, py::arg("xi"));
  m.def("se3_ad", [](const Vec6d& xi) { return SE3Tangent<double>(xi).ad(); }, py::arg("xi"), "ad(ξ), the 6x6 Lie bracket [ξ, ·].");
  m.def("hat6", [](const Vec6d& xi) { return SE3Tangent<double>(xi).hat(); }, py::arg("xi"), "The 4x4 matrix of ξ in se(3).");

  // ---------------------------------------------------------------- dual quaternions, Study
  py::class_<DualQuaterniond>(m, "DualQuaternion", "A dual quaternion a + ε c (GF §9.3); coefficients (a0..a3, c0..c3).")
      .def(py::init([](const SE3d& g) { return DualQuaterniond::fromSE3(g); }), py::arg("pose"))
      .def(py::init([](const Eigen::Vector4d& a, const Eigen::Vector4d& c) {
             return DualQuaterniond(Eigen::Quaterniond(a(0), a(1), a(2), a(3)), Eigen::Quaterniond(c(0), c(1), c(2), c(3)));
           }),
           py::arg("real"), py::arg("dual"), "From (w, x, y, z) of the real and the dual part.")
      .def_property_readonly("coeffs", [](const DualQuaterniond& h) { return Eigen::Matrix<double, 8, 1>(h.coeffs()); })
      .def_property_readonly("real", [](const DualQuaterniond& h) { return wxyz(h.real()); })
      .def_property_readonly("dual", [](const DualQuaterniond& h) { return wxyz(h.dual()); })
      .def("to_se3", &DualQuaterniond::toSE3)
      .def("conjugate", &DualQuaterniond::conjugate)
      .def("inverse", &DualQuaterniond::inverse)
      .def("is_unit", [](const DualQuaterniond& h) { return h.isUnit(); })
      .def("study_defect", &DualQuaterniond::studyDefect)
      .def("act", [](const DualQuaterniond& h, const Vec3d& p) { return Vec3d(h.act(p)); })
      .def("__mul__", [](const DualQuaterniond& a, const DualQuaterniond& b) { return a * b; })
      .def("__add__", [](const DualQuaterniond& a, const DualQuaterniond& b) { return a + b; })
      .def("__sub__", [](const DualQuaterniond& a, const DualQuaterniond& b) { return a - b; })
      .def("__repr__", [](const DualQuaterniond& h) {
        return "DualQuaternion(real " + vecText(wxyz(h.real())) + ", dual " + vecText(wxyz(h.dual())) + ")";
      });
  py::class_<StudyParameters<double>>(m, "StudyParameters", "A point (a0:a1:a2:a3:c0:c1:c2:c3) of the Study quadric (GF §9.3).")
      .def(py::init([](const SE3d& g) { return StudyParameters<double>::fromSE3(g); }), py::arg("pose"))
      .def(py::init([](const Eigen::Matrix<double, 8, 1>& v) { return StudyParameters<double>::fromCoordinates(v); }),
           py::arg("coordinates"), "Validated: a rigid motion (on the quadric, a ≠ 0), else ValueError.")
      .def_property_readonly("coeffs", [](const StudyParameters<double>& s) { return Eigen::Matrix<double, 8, 1>(s.coeffs()); })
      .def("study_condition", &StudyParameters<double>::studyCondition, "a·c (zero on the quadric).")
      .def("study_defect", &StudyParameters<double>::studyDefect)
      .def("to_se3", &StudyParameters<double>::toSE3)
      .def("normalized", &StudyParameters<double>::normalized)
      .def("__repr__", [](const StudyParameters<double>& s) {
        return "StudyParameters(" + vecText(s.coeffs()) + fmt::format(", defect {:.3g})", s.studyDefect());
      });

  // ---------------------------------------------------------------- the ladder
  m.def("_se3_exp", [](py::handle xi, const std::string& scalar, int bits) {
    return withScalar(scalarArgument(scalar, bits), [&]<class S>() { return se3ExpIn<S>(xi); });
  });
  m.def("_se3_log", [](const std::string& pose, const std::string& scalar, int bits) {
    return withScalar(scalarArgument(scalar, bits), [&]<class S>() { return se3LogIn<S>(pose); });
  });
  m.def("_so3_exp", [](py::handle w, const std::string& scalar, int bits) {
    return withScalar(scalarArgument(scalar, bits), [&]<class S>() { return so3ExpIn<S>(w); });
  });
  m.def("_so3_log", [](const std::string& pose, const std::string& scalar, int bits) {
    return withScalar(scalarArgument(scalar, bits), [&]<class S>() { return so3LogIn<S>(pose); });
  });
  m.def("_dual_quaternion", [](const std::string& pose, const std::string& scalar, int bits) {
    return withScalar(scalarArgument(scalar, bits), [&]<class S>() { return dualQuaternionIn<S>(pose); });
  });
  m.def("_study_parameters", [](const std::string& pose, const std::string& scalar, int bits) {
    return withScalar(scalarArgument(scalar, bits), [&]<class S>() { return studyIn<S>(pose); });
  });
  m.def("_pose_from_study", [](py::handle v, const std::string& scalar, int bits) {
    return withScalar(scalarArgument(scalar, bits), [&]<class S>() { return poseFromStudyIn<S>(v); });
  });
}

}  // namespace soma::python
