// The names of the Grashof types of the planar 4-bar (GF §5.4; not a template: the 4-bar itself is
// instantiated per scalar from fourbar_impl.hpp).
#include "soma/geometry/planar/fourbar.hpp"

namespace soma::planar {

std::string grashofName(GrashofType t) {
  switch (t) {
    case GrashofType::CrankRocker: return "crank-rocker";
    case GrashofType::DoubleCrank: return "double-crank";
    case GrashofType::RockerCrank: return "rocker-crank";
    case GrashofType::DoubleRocker: return "Grashof double-rocker";
    case GrashofType::TripleRocker: return "triple-rocker (non-Grashof)";
    case GrashofType::ChangePoint: return "change-point";
  }
  return "?";
}

}  // namespace soma::planar
