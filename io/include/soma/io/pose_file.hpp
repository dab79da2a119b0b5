#pragma once
// Reading a pose file (DESIGN §6): {"rotation": [[3x3]], "translation": [x, y, z]}, or with
// "quaternion": [w, x, y, z] instead of "rotation". Numbers may be JSON numbers (read as double)
// or decimal strings ("0.1"), which are parsed exactly into the scalar type (for mpfr/float128);
// both through the one number reader (number.hpp) and its errors.
// When JSON numbers (doubles) feed a finer scalar, the rotation is judged unit/orthogonal at
// double's input tolerance (the precision of the data) and then taken exactly in the scalar.
// Every defect is an InvalidInput naming the file and the field: never silently renormalised.
#include "soma/algebra/se3.hpp"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>

namespace soma::io {

/// Parse a pose from JSON text; `origin` names the source in messages (a path or "<string>").
template <class S> SE3<S> parsePose(const std::string& text, const std::string& origin);
/// Read and parse a pose file. Throws InvalidInput for a missing/unreadable file or bad content.
template <class S> SE3<S> readPose(const std::filesystem::path& file);
/// A pose given as a JSON value inside another file (a robot's "base", "tool", "home");
/// `origin` names it in messages ("robot.json: home").
template <class S> SE3<S> poseFromJson(const nlohmann::json& j, const std::string& origin);

/// The pose file's JSON of g, in S's digits (json_number.hpp): {"rotation": [[3x3]], "translation":
/// [x, y, z]}, each number a JSON number (float, double) or a decimal string (the wider scalars).
/// readPose/poseFromJson read it back exactly. The one writer of a pose in every command's output.
template <class S> nlohmann::json poseJson(const SE3<S>& g);

#define SOMA_POSE_EXTERN(S)                                                          \
  extern template nlohmann::json poseJson<S>(const SE3<S>&);                         \
  extern template SE3<S> parsePose<S>(const std::string&, const std::string&);       \
  extern template SE3<S> readPose<S>(const std::filesystem::path&);                  \
  extern template SE3<S> poseFromJson<S>(const nlohmann::json&, const std::string&);
SOMA_FOR_EACH_SCALAR(SOMA_POSE_EXTERN)
#undef SOMA_POSE_EXTERN

}  // namespace soma::io
