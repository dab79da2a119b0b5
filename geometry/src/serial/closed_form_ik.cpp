// The closed-form IK method names (not templates; the solvers are in closed_form_ik_impl.hpp,
// instantiated per scalar by soma_instantiate).
#include "soma/geometry/serial/closed_form_ik.hpp"

namespace soma {

std::optional<IkMethod> parseIkMethod(std::string_view name) {
  if (name == "auto") return IkMethod::Auto;
  if (name == "wrist3r") return IkMethod::Wrist3R;
  if (name == "arm3r") return IkMethod::Arm3R;
  if (name == "pieper") return IkMethod::Pieper;
  if (name == "general6r") return IkMethod::General6R;
  if (name == "ceres") return IkMethod::Ceres;
  if (name == "nlopt") return IkMethod::Nlopt;
  return std::nullopt;
}
std::string_view ikMethodName(IkMethod m) {
  switch (m) {
    case IkMethod::Auto: return "auto";
    case IkMethod::Wrist3R: return "wrist3r";
    case IkMethod::Arm3R: return "arm3r";
    case IkMethod::Pieper: return "pieper";
    case IkMethod::General6R: return "general6r";
    case IkMethod::Ceres: return "ceres";
    case IkMethod::Nlopt: return "nlopt";
  }
  return "auto";
}
std::string ikMethodNames() { return "auto wrist3r arm3r pieper general6r ceres nlopt"; }

}  // namespace soma
