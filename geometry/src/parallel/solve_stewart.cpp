// The non-template part of solve_stewart.hpp (method names); solveStewart itself: solve_stewart_impl.hpp.
#include "soma/geometry/parallel/solve_stewart.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace soma {

std::optional<StewartMethod> parseStewartMethod(std::string_view name) {
  if (name == "auto" || name == "homotopy") return StewartMethod::Homotopy;
  if (name == "ceres") return StewartMethod::Ceres;
  if (name == "nlopt") return StewartMethod::Nlopt;
  return std::nullopt;
}

std::string_view stewartMethodName(StewartMethod m) {
  switch (m) {
    case StewartMethod::Homotopy: return "homotopy";
    case StewartMethod::Ceres: return "ceres";
    case StewartMethod::Nlopt: return "nlopt";
  }
  return "homotopy";
}

std::string stewartMethodNames() { return "auto homotopy ceres nlopt"; }

}  // namespace soma
