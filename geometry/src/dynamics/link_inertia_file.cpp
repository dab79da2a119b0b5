// The "links" array of a robot JSON file (robot_dynamics.hpp): inertial data for GF ch. 13.
#include "soma/geometry/dynamics/robot_dynamics.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace soma {

std::vector<SpatialInertia<double>> parseLinkInertias(const std::string& text, const std::string& origin) {
  using json = nlohmann::json;
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InvalidInput(origin + ": not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object() || !j.contains("links") || !j["links"].is_array() || j["links"].empty())
    throw InvalidInput(origin + ": no \"links\" array of inertial data");
  std::vector<SpatialInertia<double>> out;
  int k = 0;
  for (const auto& l : j["links"]) {
    ++k;
    const std::string where = origin + ": link " + std::to_string(k);
    auto number = [&](const json& v, const char* what) {
      if (!v.is_number()) throw InvalidInput(where + ": \"" + what + "\" entry is not a number");
      return v.get<double>();
    };
    auto array = [&](const char* key, std::size_t size) {
      if (!l.contains(key) || !l[key].is_array() || l[key].size() != size)
        throw InvalidInput(where + ": \"" + key + "\" must be an array of " + std::to_string(size) + " numbers");
      std::vector<double> v;
      for (const auto& x : l[key]) v.push_back(number(x, key));
      return v;
    };
    if (!l.is_object() || !l.contains("mass")) throw InvalidInput(where + ": missing \"mass\"");
    const double m = number(l["mass"], "mass");
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

std::vector<SpatialInertia<double>> readLinkInertias(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InvalidInput("readLinkInertias: cannot read " + file.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return parseLinkInertias(ss.str(), file.string());
}

}  // namespace soma
