#pragma once
// `soma ik ROBOT.json|ROBOT.urdf [--tip LINK] --pose POSE.json [--method M] [--scalar T] [--json]` (DESIGN §6): every
// real posture of the robot for the pose, each with its residual, the method, the expected count
// and the time.
#include "soma/algebra/scalar.hpp"

#include <filesystem>
#include <ostream>
#include <string>

namespace soma::studies {

/// Returns 0 when postures were found (or none exist), 1 when a posture's residual exceeds
/// Tolerance<S>::sqrtEpsilon(); throws InvalidInput for bad input (the caller exits 2).
/// `robot` is a DESIGN §6 JSON file or a .urdf (the chain from the root link to `tip`).
/// Methods: auto wrist3r arm3r pieper general6r (every scalar), ceres nlopt (double; in another
/// scalar each posture found in double is Newton-polished in that scalar).
int ikCommand(const std::filesystem::path& robot, const std::filesystem::path& pose,
              const std::string& method, ScalarKind scalar, bool json, std::ostream& out,
              const std::string& tip = "");

}  // namespace soma::studies
