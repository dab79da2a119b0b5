#pragma once
// `soma stewart PLATFORM.json [--method M] [--scalar T] [--json]` (DESIGN §6): every real posture
// of a Stewart–Gough platform for its six leg lengths (forward kinematics), with the expected
// count (40), the complex count found, each posture's residual and the time.
#include "soma/algebra/scalar.hpp"
#include "soma/geometry/parallel/stewart.hpp"

#include <filesystem>
#include <ostream>
#include <string>

namespace soma::studies {

/// Returns 0 when the solve is complete (40 complex solutions, every residual ≤ √eps), 1 when
/// short or a residual is larger; throws InvalidInput for bad input (the caller exits 2).
int stewartCommand(const std::filesystem::path& platform, const std::string& method, ScalarKind scalar,
                   bool json, std::ostream& out);

}  // namespace soma::studies
