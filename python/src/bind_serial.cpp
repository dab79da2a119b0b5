// Serial robots (GF ch. 4, 5, 11): a robot from a robot JSON text, a URDF, or a DH/POE table given
// as Python data (the Python package writes it as robot JSON, so io's reader checks it); forward
// kinematics, Jacobians, every inverse-kinematics method (solveIk) on the scalar ladder, and the
// dynamics of GF ch. 13 (serialDynamicsOf with the file's "links").
#include "common.hpp"
#include "robot_handle.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/geometry/dynamics/robot_dynamics.hpp"
#include "soma/geometry/serial/ik.hpp"
#include "soma/io/pose_file.hpp"

#include <fmt/format.h>

namespace soma::python {

namespace {

using Eigen::VectorXd;

VectorXd jointsFrom(const RobotHandle& r, const VectorXd& q, const char* who) {
  if (q.size() != r.robot().dof())
    throw InvalidInput(fmt::format("{}: {} joint values for {} with {} joints", who, q.size(), r.origin, r.robot().dof()));
  return q;
}

const char* conventionName(DHConvention c) {
  switch (c) {
    case DHConvention::Standard: return "dh";
    case DHConvention::Modified: return "mdh";
    case DHConvention::POE: break;
  }
  return "poe";
}

template <class S> py::dict ikIn(const RobotHandle& h, const std::string& poseJson, IkMethod method, bool complete,
                                 int starts) {
  const io::RobotFile<S> rf = h.in<S>();
  const SE3<S> target = io::parsePose<S>(poseJson, "ik: pose");
  IkOptions o;
  o.method = method;
  o.complete = complete;
  o.completionStarts = starts;
  const IkSolution<S> sol = solveIk<S>(rf.robot, target, o);
  py::list postures, residuals;
  for (std::size_t k = 0; k < sol.count(); ++k) {
    postures.append(numbers<S>(sol.postures[k]));
    residuals.append(number<S>(sol.residuals[k]));
  }
  py::dict d;
  d["postures"] = postures;
  d["residuals"] = residuals;
  d["seconds"] = sol.seconds;
  d["method"] = sol.method;
  d["scalar"] = std::string(scalarName<S>());
  d["expected_count"] = sol.expected_count;
  d["certified"] = sol.certified;
  d["continuum"] = sol.continuum;
  d["complex_count"] = sol.complex_count;
  d["solved_in"] = sol.solved_in;
  d["notes"] = sol.notes;
  d["reason"] = sol.reason;
  d["self_motion_dimension"] = sol.self_motion_dimension;
  d["generic_rank"] = sol.generic_rank;
  d["elimination"] = sol.elimination;
  return d;
}

template <class S> py::object fkIn(const RobotHandle& h, py::handle q) {
  const io::RobotFile<S> rf = h.in<S>();
  const auto v = vectorFrom<S>(q, rf.robot.dof(), "fk: joints");
  return numbers<S>(rf.robot.fk(JointVector<S>(v)).matrix());
}

}  // namespace

void bindSerial(py::module_& m) {
  py::class_<RobotHandle>(m, "Robot",
                          "A serial robot (GF ch. 4): joints, DH or POE geometry, limits. Joint values are in radians "
                          "(metres for prismatic joints), whatever unit the file wrote angles in.")
      .def_static(
          "_from_json",
          [](const std::string& text, const std::string& origin) {
            RobotHandle h{text, false, origin, "", io::parseRobot<double>(text, origin)};
            return h;
          },
          py::arg("text"), py::arg("origin"))
      .def_static(
          "_from_urdf",
          [](const std::string& xml, const std::string& origin, const std::string& tip) {
            RobotHandle h{xml, true, origin, tip, io::parseUrdf<double>(xml, origin, tip)};
            return h;
          },
          py::arg("xml"), py::arg("origin"), py::arg("tip") = "")
      .def_property_readonly("name", [](const RobotHandle& h) { return h.robot().name(); })
      .def_property_readonly("dof", [](const RobotHandle& h) { return h.robot().dof(); })
      .def_property_readonly("origin", [](const RobotHandle& h) { return h.origin; })
      .def_property_readonly("convention", [](const RobotHandle& h) { return std::string(conventionName(h.robot().convention())); })
      .def_property_readonly("degrees", [](const RobotHandle& h) { return h.file.degrees; },
                             "Whether the file wrote its angles in degrees (the Python API always uses radians).")
      .def_property_readonly("has_inertias", [](const RobotHandle& h) { return !h.file.links.empty(); })
      .def_property_readonly("length_scale", [](const RobotHandle& h) { return h.robot().lengthScale(); })
      .def_property_readonly(
          "limits",
          [](const RobotHandle& h) {
            Eigen::MatrixXd L(h.robot().dof(), 2);
            for (int i = 0; i < h.robot().dof(); ++i) L.row(i) << h.robot().joints()[std::size_t(i)].lower, h.robot().joints()[std::size_t(i)].upper;
            return L;
          },
          "dof x 2: lower and upper limit of each joint (±inf when unlimited).")
      .def_property_readonly(
          "joint_types",
          [](const RobotHandle& h) {
            std::vector<std::string> t;
            for (const auto& j : h.robot().joints()) t.push_back(j.type == JointType::Revolute ? "R" : "P");
            return t;
          })
      .def("fk", [](const RobotHandle& h, const VectorXd& q) { return h.robot().fk(jointsFrom(h, q, "fk")); }, py::arg("q"),
           "The tool pose (SE3) at joints q.")
      .def("frames", [](const RobotHandle& h, const VectorXd& q) { return h.robot().frames(jointsFrom(h, q, "frames")); },
           py::arg("q"), "The base, each link's frame and the tool (SE3 each).")
      .def("_fk", [](const RobotHandle& h, py::handle q, const std::string& scalar, int bits) {
        return withScalar(scalarArgument(scalar, bits), [&]<class S>() { return fkIn<S>(h, q); });
      })
      .def("jacobian",
           [](const RobotHandle& h, const VectorXd& q, const std::string& frame) -> Eigen::MatrixXd {
             const VectorXd v = jointsFrom(h, q, "jacobian");
             if (frame == "spatial") return h.robot().spatialJacobian(v);
             if (frame == "body") return h.robot().bodyJacobian(v);
             throw InvalidInput("jacobian: frame \"" + frame + "\" is not one of spatial body");
           },
           py::arg("q"), py::arg("frame") = "spatial", "6 x n, columns the joint twists (ω; v).")
      .def("singularity",
           [](const RobotHandle& h, const VectorXd& q) {
             const auto s = singularityMeasures<double>(h.robot(), jointsFrom(h, q, "singularity"));
             py::dict d;
             d["manipulability"] = s.manipulability;
             d["smallest_singular_value"] = s.smallestSingularValue;
             d["largest_singular_value"] = s.largestSingularValue;
             d["condition"] = s.condition;
             return d;
           },
           py::arg("q"))
      .def("within_limits", [](const RobotHandle& h, const VectorXd& q) { return h.robot().withinLimits(jointsFrom(h, q, "within_limits")); })
      .def("ik_class", [](const RobotHandle& h) { return std::string(ikMethodName(classifyRobot<double>(h.robot()))); },
           "The closed form (or general6r) that method=\"auto\" picks.")
      .def("_ik",
           [](const RobotHandle& h, const std::string& pose, const std::string& method, const std::string& scalar, int bits,
              bool complete, int starts) {
             const auto mm = parseIkMethod(method);
             if (!mm) throw InvalidInput("ik: method \"" + method + "\" is not one of " + ikMethodNames());
             if (starts < 1) throw InvalidInput("ik: starts must be at least 1, got " + std::to_string(starts));
             return withScalar(scalarArgument(scalar, bits),
                               [&]<class S>() { return ikIn<S>(h, pose, *mm, complete, starts); });
           })
      .def("_dynamics",
           [](const RobotHandle& h, double gravity) {
             if (h.file.links.empty())
               throw InvalidInput(h.origin + ": has no \"links\" (the links' mass, com and inertia: docs/cli.md)");
             return serialDynamicsOf<double>(h.robot(), h.file.links, gravity);
           })
      .def("_offsets",
           [](const RobotHandle& h) {
             VectorXd o(h.robot().dof());
             for (int i = 0; i < o.size(); ++i) o(i) = h.robot().joints()[std::size_t(i)].offset;
             return o;
           })
      .def("__repr__", [](const RobotHandle& h) {
        std::string types;
        for (const auto& j : h.robot().joints()) types += j.type == JointType::Revolute ? "R" : "P";
        return fmt::format("Robot('{}', {} joints {}, {}, from {})", h.robot().name(), h.robot().dof(), types,
                           conventionName(h.robot().convention()), h.origin);
      });
  m.def("ik_methods", [] { return ikMethodNames(); }, "The names `method=` takes.");

  using Dyn = SerialDynamics<double>;
  py::class_<Dyn>(m, "Dynamics",
                  "The rigid-body dynamics of a serial robot (GF ch. 13), in the dynamics variable θ = q + offset.")
      .def_property_readonly("dof", &Dyn::dof)
      .def_property_readonly("gravity", [](const Dyn& d) { return d.gravity(); })
      .def("mass_matrix", [](const Dyn& d, const VectorXd& t) { return Eigen::MatrixXd(d.massMatrix(t)); }, py::arg("theta"))
      .def("gravity_torque", [](const Dyn& d, const VectorXd& t) { return VectorXd(d.gravityTorque(t)); }, py::arg("theta"))
      .def("inverse_dynamics",
           [](const Dyn& d, const VectorXd& t, const VectorXd& td, const VectorXd& tdd) { return VectorXd(d.inverseDynamics(t, td, tdd)); },
           py::arg("theta"), py::arg("theta_dot"), py::arg("theta_ddot"), "τ by recursive Newton–Euler (GF §13.3).")
      .def("inverse_dynamics_closed_form",
           [](const Dyn& d, const VectorXd& t, const VectorXd& td, const VectorXd& tdd) {
             return VectorXd(d.inverseDynamicsClosedForm(t, td, tdd));
           },
           py::arg("theta"), py::arg("theta_dot"), py::arg("theta_ddot"), "τ = A θ̈ + B θ̇ θ̇ + C (GF §13.2.2).")
      .def("forward_dynamics",
           [](const Dyn& d, const VectorXd& t, const VectorXd& td, const VectorXd& tau) { return VectorXd(d.forwardDynamics(t, td, tau)); },
           py::arg("theta"), py::arg("theta_dot"), py::arg("tau"))
      .def("kinetic_energy", &Dyn::kineticEnergy, py::arg("theta"), py::arg("theta_dot"))
      .def("potential_energy", &Dyn::potentialEnergy, py::arg("theta"))
      .def("momentum", [](const Dyn& d, const VectorXd& t, const VectorXd& td) { return VectorXd(d.momentum(t, td)); })
      .def("hamiltonian", &Dyn::hamiltonian, py::arg("theta"), py::arg("momentum"))
      .def("__repr__", [](const Dyn& d) { return fmt::format("Dynamics({} joints, g = {:.6g})", d.dof(), d.gravity()); });
}

}  // namespace soma::python
