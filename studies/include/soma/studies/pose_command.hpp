#pragma once
// `soma pose POSE.json`: one rigid motion in every representation soma has — matrix, unit
// quaternion, dual quaternion, Study parameters, twist (log) and screw (Chasles) — with the
// round-trip residual of each conversion, in any scalar type.
#include "soma/algebra/scalar.hpp"

#include <filesystem>
#include <ostream>

namespace soma::studies {

/// Print the representations of the pose in `file` (text, or one JSON object with `json`).
/// Returns 0, or 1 when a round trip misses Tolerance<S>::identity(); throws InvalidInput for a
/// bad pose file (the caller prints the message and exits 2).
int poseCommand(const std::filesystem::path& file, ScalarKind scalar, bool json, std::ostream& out);

}  // namespace soma::studies
