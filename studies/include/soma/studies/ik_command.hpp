#pragma once
// `soma ik ROBOT.json --pose POSE.json [--method M] [--scalar T] [--json]` (DESIGN §6): every
// real posture of the robot for the pose, each with its residual, the method, the expected count
// and the time.
#include "soma/algebra/scalar.hpp"

#include <filesystem>
#include <ostream>
#include <string>

namespace soma::studies {

/// Returns 0 when postures were found (or none exist), 1 when a posture's residual exceeds
/// Tolerance<S>::sqrtEpsilon(); throws InvalidInput for bad input (the caller exits 2).
int ikCommand(const std::filesystem::path& robot, const std::filesystem::path& pose,
              const std::string& method, ScalarKind scalar, bool json, std::ostream& out);

}  // namespace soma::studies
