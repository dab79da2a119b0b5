#pragma once
// Definitions of pose_file.hpp's templates, instantiated for the five scalars by soma_instantiate (io/CMakeLists.txt).
#include "soma/io/pose_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/json_file.hpp"
#include "soma/io/json_number.hpp"
#include "soma/io/number.hpp"

namespace soma::io {

namespace {
using json = nlohmann::json;

/// Whether any non-integer JSON number (a double) was read: the data then carry double precision only.
struct Precision {
  bool sawDouble = false;
};

template <class S, int N>
Eigen::Matrix<S, N, 1> vector(const json& j, const KeyPath& where, Precision& p) {
  if (!j.is_array() || j.size() != std::size_t(N))
    throw InvalidInput(where.str() + ": expected an array of " + std::to_string(N) + " numbers");
  Eigen::Matrix<S, N, 1> v;
  for (int i = 0; i < N; ++i) {
    NumberSource source{};
    v(i) = readNumber<S>(j[i], where.index(std::size_t(i)), &source);
    if (source == NumberSource::JsonDouble) p.sawDouble = true;  // integers are exact in every scalar
  }
  return v;
}
/// True when the numbers came (partly) as JSON doubles and S is finer than double: unit and
/// orthogonality defects are then judged at double's input tolerance, the precision of the data.
template <class S> bool inputIsDouble(const Precision& p) {
  return p.sawDouble && digits<S>() > std::numeric_limits<double>::digits;
}
}  // namespace

template <class S> SE3<S> poseFromJson(const json& j, const std::string& origin) {
  if (!j.is_object()) throw InvalidInput(origin + ": a pose must be a JSON object");
  checkKeys(j, {"rotation", "quaternion", "translation"}, origin,
            "(a pose has \"rotation\" or \"quaternion\", and \"translation\")");
  if (!j.contains("translation")) throw InvalidInput(origin + ": missing \"translation\"");
  const KeyPath root(origin);
  Precision prec;
  const Vec3<S> t = vector<S, 3>(j["translation"], root.key("translation"), prec);
  const bool hasR = j.contains("rotation"), hasQ = j.contains("quaternion");
  if (hasR == hasQ)
    throw InvalidInput(origin + ": give exactly one of \"rotation\" (3x3) and \"quaternion\" [w,x,y,z]");
  try {
    if (hasQ) {
      const Vec4<S> qv = vector<S, 4>(j["quaternion"], root.key("quaternion"), prec);
      const Quat<S> q(qv(0), qv(1), qv(2), qv(3));
      if (!inputIsDouble<S>(prec)) return SE3<S>(SO3<S>::fromQuaternion(q), t);
      // Judged at double precision (the data's), then taken exactly unit in S.
      const Vec4<double> qd = castMatrix<double>(qv);
      (void)SO3<double>::fromQuaternion(Quat<double>(qd(0), qd(1), qd(2), qd(3)));
      return SE3<S>(SO3<S>::fromQuaternionUnchecked(q), t);
    }
    const json& r = j["rotation"];
    if (!r.is_array() || r.size() != 3)
      throw InvalidInput(origin + ": rotation: expected 3 rows of 3 numbers");
    Mat3<S> m;
    for (int i = 0; i < 3; ++i)
      m.row(i) = vector<S, 3>(r[std::size_t(i)], root.key("rotation").index(std::size_t(i)), prec).transpose();
    if (!inputIsDouble<S>(prec)) return SE3<S>(SO3<S>::fromMatrix(m), t);
    // Judged at double precision (the data's), then the rotation of m in S (Shepperd's chart,
    // normalised): the data cannot be orthogonal to better than double's rounding.
    (void)SO3<double>::fromMatrix(castMatrix<double>(m));
    return SE3<S>(SO3<S>::fromQuaternionUnchecked(quaternionFromRotation(m)), t);
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
