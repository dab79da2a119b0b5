#pragma once
// `soma fk ROBOT.json|ROBOT.urdf [--tip LINK] --joints q1,q2,... [--json]` (DESIGN §6): the tool pose T(q), and the
// singularity measures of the configuration, in any scalar type.
#include "soma/algebra/scalar.hpp"

#include <filesystem>
#include <ostream>
#include <string>

namespace soma::studies {

/// Returns 0; throws InvalidInput for a bad robot file or joint list (the caller exits 2).
/// `robot` is a DESIGN §6 JSON file or a .urdf (the chain from the root link to `tip`, by
/// default the only leaf link: io/urdf_file.hpp).
int fkCommand(const std::filesystem::path& robot, const std::string& joints, ScalarKind scalar,
              bool json, std::ostream& out, const std::string& tip = "");

}  // namespace soma::studies
