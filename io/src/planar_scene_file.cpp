#include "soma/io/planar_scene_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/json_file.hpp"
#include "soma/io/number.hpp"

#include <fstream>
#include <sstream>

namespace soma::io {

namespace {
using json = nlohmann::json;
using V2 = Vec2<double>;

// The messages of this format name the field without the file (the CLI prints the file).
double number(const json& j, const std::string& key, const std::string& where, const KeyPath& path) {
  if (!j.contains(key)) throw InvalidInput(where + ": missing \"" + key + "\"");
  return readNumber<double>(j[key], path.key(key));
}
V2 point(const json& j, const KeyPath& path) {
  if (!j.is_array() || j.size() != 2) throw InvalidInput(path.str() + ": expected a point [x, y]");
  return V2(readNumber<double>(j[0], path.index(0)), readNumber<double>(j[1], path.index(1)));
}

void readPositions(const json& in, PlanarScene& s) {
  const json& P = in["positions"];
  if (!P.is_array()) throw InvalidInput("\"positions\" must be an array of {\"x\", \"y\", \"angle\"}");
  for (std::size_t i = 0; i < P.size(); ++i) {
    const std::string w = "position " + std::to_string(i + 1);
    const KeyPath path = KeyPath().key("positions").index(i);
    if (!P[i].is_object()) throw InvalidInput(w + ": expected an object {\"x\", \"y\", \"angle\"}");
    PlanarPosition p;
    p.angle = number(P[i], "angle", w, path) * s.angleUnit;
    p.x = number(P[i], "x", w, path);
    p.y = number(P[i], "y", w, path);
    s.positions.push_back(p);
  }
  if (in.contains("circle_points")) {
    const json& cp = in["circle_points"];
    if (!cp.is_array()) throw InvalidInput("\"circle_points\" must be an array of [x, y] (moving-frame coordinates)");
    s.hasCirclePoints = true;
    for (std::size_t k = 0; k < cp.size(); ++k) s.circlePoints.push_back(point(cp[k], KeyPath().key("circle_points").index(k)));
  }
}

void readFourBar(const json& in, PlanarScene& s) {
  const json& f = in["fourbar"];
  if (!f.is_object()) throw InvalidInput("\"fourbar\" must be an object {\"ground\", \"crank\", \"coupler\", \"rocker\"}");
  if (!f.contains("ground") || !f["ground"].is_array() || f["ground"].size() != 2)
    throw InvalidInput("fourbar: \"ground\" must be [[x, y], [x, y]] (c1, c4)");
  const KeyPath fp = KeyPath().key("fourbar");
  PlanarFourBarInput fb;
  fb.c1 = point(f["ground"][0], fp.key("ground").index(0));
  fb.c4 = point(f["ground"][1], fp.key("ground").index(1));
  if (f.contains("coupler_point")) fb.couplerPoint = point(f["coupler_point"], fp.key("coupler_point"));
  fb.crank = number(f, "crank", "fourbar", fp);
  fb.coupler = number(f, "coupler", "fourbar", fp);
  fb.rocker = number(f, "rocker", "fourbar", fp);
  if (in.contains("crank_angle")) fb.crankAngle = number(in, "crank_angle", "scene", KeyPath()) * s.angleUnit;
  if (in.contains("mode")) {
    if (!in["mode"].is_number_integer() || (in["mode"].get<int>() != 1 && in["mode"].get<int>() != -1))
      throw InvalidInput("\"mode\" must be 1 or -1 (assembly mode)");
    fb.mode = in["mode"].get<int>();
  }
  if (in.contains("crank_rates")) {
    const json& r = in["crank_rates"];
    if (!r.is_array() || r.empty() || r.size() > 4) throw InvalidInput("\"crank_rates\" must be [ω₁, ω̇₁, ω̈₁, ω⃛₁] (1 to 4 numbers)");
    for (std::size_t k = 0; k < r.size(); ++k)
      fb.crankRates[k] = readNumber<double>(r[k], KeyPath().key("crank_rates").index(k)) * s.angleUnit;
  }
  s.fourbar = fb;
}
}  // namespace

PlanarScene readPlanarScene(const std::filesystem::path& file) {
  std::ifstream is(file);
  if (!is) throw InvalidInput("cannot read scene file '" + file.string() + "'");
  std::stringstream text;
  text << is.rdbuf();
  return parsePlanarScene(text.str(), file.string());
}

PlanarScene parsePlanarScene(const std::string& text, const std::string& origin) {
  json in;
  try {
    in = parseJsonText(text, origin);
  } catch (const json::parse_error& e) {
    throw InvalidInput("scene file '" + origin + "' is not valid JSON: " + e.what());
  }
  if (!in.is_object()) throw InvalidInput("scene file: expected a JSON object with \"positions\" or \"fourbar\"");
  PlanarScene s;
  if (in.contains("angles")) {
    const std::string a = in["angles"].is_string() ? in["angles"].get<std::string>() : "";
    if (a == "degrees") {
      s.degrees = true;
      s.angleUnit = 3.14159265358979323846 / 180;
    } else if (a != "radians") {
      throw InvalidInput("\"angles\" must be \"degrees\" or \"radians\"");
    }
  }
  if (in.contains("positions") && in.contains("fourbar")) throw InvalidInput("scene file: give \"positions\" or \"fourbar\", not both");
  if (in.contains("positions")) readPositions(in, s);
  else if (in.contains("fourbar")) readFourBar(in, s);
  else throw InvalidInput("scene file: expected \"positions\" (3–5 poses {x, y, angle}) or \"fourbar\"");
  return s;
}

}  // namespace soma::io
