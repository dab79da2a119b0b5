#pragma once
// Definitions of pose_file.hpp's templates, instantiated for the five scalars by soma_instantiate (io/CMakeLists.txt).
#include "soma/io/pose_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/json_file.hpp"
#include "soma/io/json_number.hpp"
#include "soma/io/number.hpp"
#include "input_precision.hpp"

namespace soma::io {

namespace {
using json = nlohmann::json;
}  // namespace

template <class S> SE3<S> poseFromJson(const json& j, const std::string& origin) {
  if (!j.is_object()) throw InvalidInput(origin + ": a pose must be a JSON object");
  checkKeys(j, {"rotation", "quaternion", "translation"}, origin,
            "(a pose has \"rotation\" or \"quaternion\", and \"translation\")");
  if (!j.contains("translation")) throw InvalidInput(origin + ": missing \"translation\"");
  const KeyPath root(origin);
  const Vec3<S> t = detail::readVector<S, 3>(j["translation"], root.key("translation")).value;
  const bool hasR = j.contains("rotation"), hasQ = j.contains("quaternion");
  if (hasR == hasQ)
    throw InvalidInput(origin + ": give exactly one of \"rotation\" (3x3) and \"quaternion\" [w,x,y,z]");
  try {
    // Unit and orthogonality defects judged at double's tolerance in every scalar, then the rotation
    // taken exactly in S (input_precision.hpp): one file is one pose in all five scalars.
    if (hasQ) {
      const auto q = detail::readVector<S, 4>(j["quaternion"], root.key("quaternion"));
      return SE3<S>(detail::unitQuaternion<S>(q.value, q.inDouble), t);
    }
    const json& r = j["rotation"];
    if (!r.is_array() || r.size() != 3)
      throw InvalidInput(origin + ": rotation: expected 3 rows of 3 numbers");
    Mat3<S> m;
    Mat3<double> md;
    for (int i = 0; i < 3; ++i) {
      const auto row = detail::readVector<S, 3>(r[std::size_t(i)], root.key("rotation").index(std::size_t(i)));
      m.row(i) = row.value.transpose();
      md.row(i) = row.inDouble.transpose();
    }
    return SE3<S>(detail::rotationMatrix<S>(m, md), t);
  } catch (const InvalidInput& e) {
    const std::string msg = e.what();
    if (msg.rfind(origin, 0) == 0) throw;
    throw InvalidInput(origin + ": " + msg);
  }
}

template <class S> SE3<S> parsePose(const std::string& text, const std::string& origin) {
  return poseFromJson<S>(parseJson(text, origin), origin);
}

template <class S> SE3<S> readPose(const std::filesystem::path& file) {
  return parsePose<S>(readTextFile(file, "pose"), file.string());
}

template <class S> json poseJson(const SE3<S>& g) {
  return {{"rotation", jsonNumbers(g.rotation())}, {"translation", jsonNumbers(g.translation())}};
}

#define SOMA_INSTANTIATE_POSE_FILE(S) namespace io {                                              \
  template json poseJson<S>(const SE3<S>&);                                   \
  template SE3<S> parsePose<S>(const std::string&, const std::string&);       \
  template SE3<S> readPose<S>(const std::filesystem::path&);                  \
  template SE3<S> poseFromJson<S>(const json&, const std::string&); }

}  // namespace soma::io
