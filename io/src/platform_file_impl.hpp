#pragma once
// Definitions of platform_file.hpp's templates, instantiated for the five scalars by soma_instantiate (io/CMakeLists.txt).
#include "soma/io/platform_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/json_file.hpp"
#include "soma/io/number.hpp"

namespace soma::io {

namespace {

using json = nlohmann::json;

// `path` has no origin: the caller prefixes the file's name to every message.
template <class S> std::array<Vec3<S>, 6> points(const json& j, const KeyPath& path) {
  const std::string where = path.str();
  if (!j.is_array() || j.size() != 6)
    throw InvalidInput(where + ": expected an array of 6 points [x, y, z]" +
                       (j.is_array() ? " (got " + std::to_string(j.size()) + ")" : std::string()));
  std::array<Vec3<S>, 6> p;
  for (std::size_t i = 0; i < 6; ++i) {
    const KeyPath w = path.index(i);
    if (!j[i].is_array() || j[i].size() != 3) throw InvalidInput(w.str() + ": expected a point [x, y, z]");
    for (std::size_t k = 0; k < 3; ++k) p[i](Eigen::Index(k)) = readNumber<S>(j[i][k], w.index(k));
  }
  return p;
}

}  // namespace

template <class S> StewartPlatform<S> parsePlatform(const std::string& text, const std::string& origin) {
  const json j = parseJson(text, origin);
  if (!j.is_object()) throw InvalidInput(origin + ": a platform must be a JSON object");
  checkKeys(j, {"base", "platform", "leg_lengths", "name", "comment"}, origin,
            "(expected base, platform, leg_lengths)");
  for (const char* f : {"base", "platform", "leg_lengths"})
    if (!j.contains(f)) throw InvalidInput(origin + ": missing \"" + std::string(f) + "\"");
  StewartPlatform<S> P;
  try {
    const KeyPath root;
    P.base = points<S>(j["base"], root.key("base"));
    P.platform = points<S>(j["platform"], root.key("platform"));
    const json& L = j["leg_lengths"];
    if (!L.is_array() || L.size() != 6) throw InvalidInput("leg_lengths: expected an array of 6 numbers");
    for (std::size_t i = 0; i < 6; ++i) P.legs[i] = readNumber<S>(L[i], root.key("leg_lengths").index(i));
    validateStewartPlatform<S>(P);
  } catch (const InvalidInput& e) {
    throw InvalidInput(origin + ": " + e.what());
  }
  return P;
}

template <class S> StewartPlatform<S> readPlatform(const std::filesystem::path& file) {
  return parsePlatform<S>(readTextFile(file, "platform"), file.string());
}

#define SOMA_INSTANTIATE_PLATFORM_FILE(S) namespace io {                                                \
  template StewartPlatform<S> parsePlatform<S>(const std::string&, const std::string&); \
  template StewartPlatform<S> readPlatform<S>(const std::filesystem::path&); }

}  // namespace soma::io
