// The "links" array of a robot JSON file (link_inertia_file.hpp): inertial data for GF ch. 13.
#include "soma/io/link_inertia_file.hpp"

#include "soma/io/json_file.hpp"
#include "soma/io/number.hpp"

namespace soma::io {

std::vector<SpatialInertia<double>> linkInertiasFromJson(const nlohmann::json& j, const std::string& origin) {
  using json = nlohmann::json;
  if (!j.is_object() || !j.contains("links") || !j["links"].is_array() || j["links"].empty())
    throw InvalidInput(origin + ": no \"links\" array of inertial data");
  std::vector<SpatialInertia<double>> out;
  std::size_t k = 0;
  for (const json& l : j["links"]) {
    const std::string where = origin + ": link " + std::to_string(k + 1);
    const KeyPath path = KeyPath(origin).key("links").index(k++);
    auto array = [&](const char* key, std::size_t size) {
      if (!l.contains(key) || !l[key].is_array() || l[key].size() != size)
        throw InvalidInput(where + ": \"" + key + "\" must be an array of " + std::to_string(size) + " numbers");
      std::vector<double> v;
      for (std::size_t i = 0; i < size; ++i) v.push_back(readNumber<double>(l[key][i], path.key(key).index(i)));
      return v;
    };
    if (!l.is_object() || !l.contains("mass")) throw InvalidInput(where + ": missing \"mass\"");
    checkKeys(l, {"mass", "com", "inertia"}, where, "(a link has mass, com, inertia)");
    const double m = readNumber<double>(l["mass"], path.key("mass"));
    if (!(m > 0)) throw InvalidInput(where + ": mass " + toString(m) + " is not positive (a massless link has no inertia)");
    const std::vector<double> c = array("com", 3), I = array("inertia", 6);
    Mat3<double> Ic;
    Ic << I[0], I[3], I[5], I[3], I[1], I[4], I[5], I[4], I[2];
    try {
      out.emplace_back(m, Vec3<double>(c[0], c[1], c[2]), Ic);
    } catch (const InvalidInput& e) {
      throw InvalidInput(where + ": " + e.what());
    }
  }
  return out;
}

std::vector<SpatialInertia<double>> parseLinkInertias(const std::string& text, const std::string& origin) {
  return linkInertiasFromJson(parseJson(text, origin), origin);
}

std::vector<SpatialInertia<double>> readLinkInertias(const std::filesystem::path& file) {
  return parseLinkInertias(readTextFile(file, "robot"), file.string());
}

}  // namespace soma::io
