// The scene reader's structure checks (scene_file.hpp): kinds, keys, references, cycles. The
// typed entities (numbers in a scalar) are scene_file_impl.hpp.
#include "soma/io/scene_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/json_file.hpp"
#include "soma/io/number.hpp"
#include "soma/geometry/parallel/solve_stewart.hpp"
#include "soma/geometry/serial/ik.hpp"
#include "soma/io/pose_file.hpp"
#include "soma/io/scene_output.hpp"
#include "soma/io/urdf_file.hpp"

#include <algorithm>
#include <functional>
#include <map>

namespace soma::io {

namespace {
using json = nlohmann::json;

struct EntityKindInfo {
  SceneEntityKind kind;
  std::string_view name;
};
constexpr EntityKindInfo kEntityKinds[] = {
    {SceneEntityKind::Robot, "robot"}, {SceneEntityKind::Pose, "pose"},   {SceneEntityKind::Platform, "platform"},
    {SceneEntityKind::Point, "point"}, {SceneEntityKind::Line, "line"},   {SceneEntityKind::Screw, "screw"},
    {SceneEntityKind::PlanarMechanism, "planar-mechanism"}, {SceneEntityKind::LinearComplex, "linear-complex"},
    {SceneEntityKind::Regulus, "regulus"}, {SceneEntityKind::Cylindroid, "cylindroid"},
    {SceneEntityKind::RuledSurface, "ruled-surface"}, {SceneEntityKind::ScrewSystem, "screw-system"},
    {SceneEntityKind::RigidBody, "rigid-body"}};
struct OutputKindInfo {
  SceneOutputKind kind;
  std::string_view name;
};
constexpr OutputKindInfo kOutputKinds[] = {{SceneOutputKind::Ik, "ik"},
                                           {SceneOutputKind::Fk, "fk"},
                                           {SceneOutputKind::Stewart, "stewart"},
                                           {SceneOutputKind::Cuspidal, "cuspidal"},
                                           {SceneOutputKind::Cylindroid, "cylindroid"},
                                           {SceneOutputKind::ScrewSystem, "screw-system"},
                                           {SceneOutputKind::Burmester, "burmester"},
                                           {SceneOutputKind::Workspace, "workspace"},
                                           {SceneOutputKind::Dynamics, "dynamics"},
                                           {SceneOutputKind::Figure, "figure"},
                                           {SceneOutputKind::Report, "report"}};

template <class Table> std::string kindList(const Table& t) {
  std::string s;
  for (const auto& k : t) s += (s.empty() ? "" : ", ") + std::string(k.name);
  return s;
}

std::string inQuotes(std::string_view s) { return "\"" + std::string(s) + "\""; }

std::string stringField(const json& j, const char* key, const KeyPath& where) {
  const json& v = j[key];
  if (!v.is_string()) throw InvalidInput(where.key(key).str() + ": expected a string");
  return v.get<std::string>();
}

// An array of entity names: `min` to `max` strings.
std::vector<std::string> nameList(const json& j, const char* key, const KeyPath& where, std::size_t min, std::size_t max,
                                  const std::string& what) {
  if (!j.contains(key)) throw InvalidInput(where.str() + ": missing \"" + key + "\" (" + what + ")");
  const json& s = j[key];
  if (!s.is_array() || s.size() < min || s.size() > max) throw InvalidInput(where.key(key).str() + ": expected " + what);
  std::vector<std::string> out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s[i].is_string()) throw InvalidInput(where.key(key).index(i).str() + ": expected a string");
    out.push_back(s[i].get<std::string>());
  }
  return out;
}

// The "kind" of an entity or output (`what`), one of the table's names.
template <class Table> auto kindOf(const json& j, const KeyPath& where, const Table& table, const std::string& what) {
  if (!j.is_object()) throw InvalidInput(where.str() + ": an " + what + " must be a JSON object");
  if (!j.contains("kind")) throw InvalidInput(where.str() + ": missing \"kind\" (one of " + kindList(table) + ")");
  const std::string kind = stringField(j, "kind", where);
  for (const auto& k : table)
    if (k.name == kind) return k.kind;
  throw InvalidInput(where.key("kind").str() + ": unknown " + what + " kind " + inQuotes(kind) + " (one of " +
                     kindList(table) + ")");
}

std::string entityRef(const json& j, const char* key, const KeyPath& where);

// An entity: "kind" plus a file reference or an inline body (kept as text, read in each scalar).
SceneEntity parseEntity(const std::string& name, const json& j, const std::string& origin, const std::string& path,
                        const std::filesystem::path& folder) {
  const KeyPath where = KeyPath(origin).key(path);
  SceneEntity e;
  e.kind = kindOf(j, where, kEntityKinds, "entity");
  e.name = name;
  e.where = where.str();
  e.origin = origin;
  e.path = path;
  json body = j;
  body.erase("kind");
  const bool byFile = e.kind == SceneEntityKind::Robot || e.kind == SceneEntityKind::Pose ||
                      e.kind == SceneEntityKind::Platform || e.kind == SceneEntityKind::PlanarMechanism;
  if (byFile && body.contains("file")) {
    if (e.kind == SceneEntityKind::Robot) checkKeys(body, {"file", "tip"}, where.str(), "(a robot by file has file, tip)");
    else checkKeys(body, {"file"}, where.str(), "(an entity given by file has only kind and file)");
    const std::filesystem::path f = stringField(body, "file", where);
    e.file = f.is_absolute() || folder.empty() ? f : folder / f;
    if (body.contains("tip")) e.tip = stringField(body, "tip", where);
    return e;
  }
  switch (e.kind) {
    case SceneEntityKind::Robot:
    case SceneEntityKind::Pose:
    case SceneEntityKind::Platform: break;  // the robot, pose and platform readers check the body
    case SceneEntityKind::PlanarMechanism:
      checkKeys(body, {"positions", "circle_points", "angles", "fourbar", "crank_angle", "mode", "crank_rates"}, where.str(),
                "(a planar mechanism is a planar scene file's body: positions or fourbar)");
      break;
    case SceneEntityKind::Point: checkKeys(body, {"at"}, where.str(), "(a point has \"at\": [x, y, z])"); break;
    case SceneEntityKind::Line:
      checkKeys(body, {"point", "direction", "through"}, where.str(),
                "(a line has \"point\" and \"direction\", or \"through\": two points)");
      break;
    case SceneEntityKind::Screw:
      checkKeys(body, {"coordinates", "point", "direction", "pitch"}, where.str(),
                "(a screw has \"coordinates\": [ω; v], or \"point\", \"direction\" and \"pitch\")");
      break;
    case SceneEntityKind::LinearComplex:
      checkKeys(body, {"coordinates", "point", "direction", "pitch"}, where.str(),
                "(a linear complex has \"coordinates\": [α; b], or its axis' \"point\", \"direction\" and \"pitch\")");
      break;
    case SceneEntityKind::Regulus:
      checkKeys(body, {"lines"}, where.str(), "(a regulus has \"lines\": three line entities)");
      e.uses = nameList(body, "lines", where, 3, 3, "the names of three line entities");
      break;
    case SceneEntityKind::Cylindroid:
      checkKeys(body, {"screws"}, where.str(), "(a cylindroid has \"screws\": two screw entities)");
      e.uses = nameList(body, "screws", where, 2, 2, "the names of two screw entities");
      break;
    case SceneEntityKind::ScrewSystem:
      checkKeys(body, {"screws"}, where.str(), "(a screw system has \"screws\": 1 to 6 screw entities)");
      e.uses = nameList(body, "screws", where, 1, 6, "the names of 1 to 6 screw entities");
      break;
    case SceneEntityKind::RuledSurface:
      checkKeys(body, {"line", "screw", "range"}, where.str(), "(a ruled surface has line, screw, range)");
      e.uses = {entityRef(body, "line", where), entityRef(body, "screw", where)};
      if (body.contains("range") && (!body["range"].is_array() || body["range"].size() != 2))
        throw InvalidInput(where.key("range").str() + ": expected [t0, t1]");
      break;
    case SceneEntityKind::RigidBody:
      checkKeys(body, {"mass", "com", "inertia"}, where.str(), "(a rigid body has mass, com, inertia)");
      for (const char* k : {"mass", "com", "inertia"})
        if (!body.contains(k)) throw InvalidInput(where.str() + ": missing \"" + std::string(k) + "\" (a rigid body has mass, com, inertia)");
      break;
  }
  e.body = body.dump();
  return e;
}

std::string entityRef(const json& j, const char* key, const KeyPath& where) {
  if (!j.contains(key)) throw InvalidInput(where.str() + ": missing \"" + key + "\" (the name of an entity)");
  return stringField(j, key, where);
}

// An optional integer field in [lo, hi].
int intField(const json& j, const char* key, const KeyPath& where, long long lo, long long hi, int fallback) {
  if (!j.contains(key)) return fallback;
  const json& v = j[key];
  if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
    throw InvalidInput(where.key(key).str() + ": expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v.get<int>();
}

SceneOutput parseOutput(const std::string& name, const json& j, const std::string& origin, const std::string& path) {
  const KeyPath where = KeyPath(origin).key(path);
  SceneOutput o;
  o.kind = kindOf(j, where, kOutputKinds, "output");
  o.name = name;
  o.where = where.str();
  o.origin = origin;
  o.path = path;
  switch (o.kind) {
    case SceneOutputKind::Ik:
      checkKeys(j, {"kind", "robot", "pose", "method", "scalar", "bits", "needs"}, where.str(),
                "(an ik output has robot, pose, method, scalar, bits, needs)");
      o.robot = entityRef(j, "robot", where);
      o.pose = entityRef(j, "pose", where);
      break;
    case SceneOutputKind::Fk:
      checkKeys(j, {"kind", "robot", "joints", "scalar", "bits", "needs"}, where.str(),
                "(an fk output has robot, joints, scalar, bits, needs)");
      o.robot = entityRef(j, "robot", where);
      if (!j.contains("joints")) throw InvalidInput(where.str() + ": missing \"joints\" (the joint values)");
      if (!j["joints"].is_array() || j["joints"].empty())
        throw InvalidInput(where.key("joints").str() + ": expected a non-empty array of numbers");
      o.joints = j["joints"].dump();
      break;
    case SceneOutputKind::Stewart:
      checkKeys(j, {"kind", "platform", "method", "complex", "scalar", "bits", "needs"}, where.str(),
                "(a stewart output has platform, method, complex, scalar, bits, needs)");
      o.platform = entityRef(j, "platform", where);
      if (j.contains("complex")) {
        if (!j["complex"].is_boolean()) throw InvalidInput(where.key("complex").str() + ": expected true or false");
        o.complex = j["complex"].get<bool>();
      }
      break;
    case SceneOutputKind::Cylindroid: {
      checkKeys(j, {"kind", "screws", "cylindroid", "scalar", "bits", "needs"}, where.str(),
                "(a cylindroid output has screws or cylindroid, scalar, bits, needs)");
      if (j.contains("cylindroid")) {
        if (j.contains("screws")) throw InvalidInput(where.str() + ": give \"screws\" or \"cylindroid\", not both");
        o.system = stringField(j, "cylindroid", where);
        break;
      }
      if (!j.contains("screws")) throw InvalidInput(where.str() + ": missing \"screws\" (two screw entities)");
      const json& s = j["screws"];
      if (!s.is_array() || s.size() != 2)
        throw InvalidInput(where.key("screws").str() + ": expected the names of two screw entities");
      for (std::size_t i = 0; i < 2; ++i) {
        if (!s[i].is_string()) throw InvalidInput(where.key("screws").index(i).str() + ": expected a string");
        o.screws.push_back(s[i].get<std::string>());
      }
      break;
    }
    case SceneOutputKind::Cuspidal:
      checkKeys(j, {"kind", "robot", "witness", "needs"}, where.str(),
                "(a cuspidal output has robot, witness, needs; it works in double)");
      o.robot = entityRef(j, "robot", where);
      if (j.contains("witness")) {
        if (!j["witness"].is_boolean()) throw InvalidInput(where.key("witness").str() + ": expected true or false");
        o.witness = j["witness"].get<bool>();
      }
      break;
    case SceneOutputKind::Burmester:
      checkKeys(j, {"kind", "mechanism", "needs"}, where.str(),
                "(a burmester output has mechanism, needs; it works in double)");
      o.mechanism = entityRef(j, "mechanism", where);
      break;
    case SceneOutputKind::ScrewSystem: {
      checkKeys(j, {"kind", "screws", "system", "scalar", "bits", "needs"}, where.str(),
                "(a screw-system output has screws or system, scalar, bits, needs)");
      if (j.contains("system")) {
        if (j.contains("screws")) throw InvalidInput(where.str() + ": give \"screws\" or \"system\", not both");
        o.system = stringField(j, "system", where);
        break;
      }
      if (!j.contains("screws")) throw InvalidInput(where.str() + ": missing \"screws\" (1 to 6 screw entities)");
      const json& s = j["screws"];
      if (!s.is_array() || s.empty() || s.size() > 6)
        throw InvalidInput(where.key("screws").str() + ": expected the names of 1 to 6 screw entities");
      for (std::size_t i = 0; i < s.size(); ++i) {
        if (!s[i].is_string()) throw InvalidInput(where.key("screws").index(i).str() + ": expected a string");
        o.screws.push_back(s[i].get<std::string>());
      }
      break;
    }
    case SceneOutputKind::Workspace:
      checkKeys(j, {"kind", "robot", "samples", "grid", "needs"}, where.str(),
                "(a workspace output has robot, samples, grid, needs; it works in double)");
      o.robot = entityRef(j, "robot", where);
      o.samples = intField(j, "samples", where, 100, 10000000, o.samples);
      o.grid = intField(j, "grid", where, 8, 2000, o.grid);
      break;
    case SceneOutputKind::Dynamics: {
      checkKeys(j, {"kind", "robot", "from", "to", "duration", "steps", "gravity", "payload", "form", "scalar", "bits", "needs"},
                where.str(), "(a dynamics output has robot, from, to, duration, steps, gravity, payload, form, scalar, bits, needs)");
      o.robot = entityRef(j, "robot", where);
      for (const char* k : {"from", "to"}) {
        if (!j.contains(k)) throw InvalidInput(where.str() + ": missing \"" + std::string(k) + "\" (the joint values)");
        if (!j[k].is_array() || j[k].empty()) throw InvalidInput(where.key(k).str() + ": expected a non-empty array of numbers");
      }
      o.from = j["from"].dump();
      o.to = j["to"].dump();
      o.steps = intField(j, "steps", where, 1, 100000, o.steps);
      if (j.contains("duration")) {
        o.duration = readNumber<double>(j["duration"], where.key("duration"));
        if (!(o.duration > 0)) throw InvalidInput(where.key("duration").str() + ": expected a positive number of seconds");
      }
      if (j.contains("gravity")) {
        o.gravity = readNumber<double>(j["gravity"], where.key("gravity"));
        if (!(o.gravity >= 0)) throw InvalidInput(where.key("gravity").str() + ": expected a number ≥ 0 (m/s² along −z)");
      }
      if (j.contains("payload")) o.payload = stringField(j, "payload", where);
      if (j.contains("form")) {
        const std::string f = stringField(j, "form", where);
        if (f != "vector" && f != "cl062")
          throw InvalidInput(where.key("form").str() + ": " + inQuotes(f) + " is not one of vector, cl062");
        o.cl062 = f == "cl062";
      }
      break;
    }
    case SceneOutputKind::Report: {
      checkKeys(j, {"kind", "html", "outputs", "needs"}, where.str(), "(a report output has html, outputs, needs)");
      if (!j.contains("html")) throw InvalidInput(where.str() + ": missing \"html\" (the HTML file to write)");
      o.html = stringField(j, "html", where);
      if (o.html.empty()) throw InvalidInput(where.key("html").str() + ": an empty file name");
      if (j.contains("outputs")) {
        const json& d = j["outputs"];
        if (!d.is_array() || d.empty()) throw InvalidInput(where.key("outputs").str() + ": expected a non-empty array of output names");
        for (std::size_t i = 0; i < d.size(); ++i) {
          if (!d[i].is_string()) throw InvalidInput(where.key("outputs").index(i).str() + ": expected a string");
          o.reported.push_back(d[i].get<std::string>());
        }
      }
      break;
    }
    case SceneOutputKind::Figure: {
      checkKeys(j, {"kind", "png", "svg", "draw", "size", "needs"}, where.str(),
                "(a figure output has png or svg, draw, size, needs)");
      if (j.contains("png") && j.contains("svg")) throw InvalidInput(where.str() + ": give \"png\" or \"svg\", not both");
      if (j.contains("svg")) {
        o.svg = stringField(j, "svg", where);
        if (o.svg.empty()) throw InvalidInput(where.key("svg").str() + ": an empty file name");
      } else {
        if (!j.contains("png")) throw InvalidInput(where.str() + ": missing \"png\" (the PNG file to write) or \"svg\"");
        o.png = stringField(j, "png", where);
        if (o.png.empty()) throw InvalidInput(where.key("png").str() + ": an empty file name");
      }
      if (j.contains("draw")) {
        const json& d = j["draw"];
        if (!d.is_array() || d.empty()) throw InvalidInput(where.key("draw").str() + ": expected a non-empty array of entity names");
        for (std::size_t i = 0; i < d.size(); ++i) {
          if (!d[i].is_string()) throw InvalidInput(where.key("draw").index(i).str() + ": expected a string");
          o.draw.push_back(d[i].get<std::string>());
        }
      }
      if (j.contains("size")) {
        const json& z = j["size"];
        if (!z.is_array() || z.size() != 2 || !z[0].is_number_integer() || !z[1].is_number_integer() ||
            z[0].get<long long>() < 16 || z[1].get<long long>() < 16 || z[0].get<long long>() > 8192 ||
            z[1].get<long long>() > 8192)
          throw InvalidInput(where.key("size").str() + ": expected [width, height], integers in [16, 8192]");
        o.width = z[0].get<int>();
        o.height = z[1].get<int>();
      }
      break;
    }
  }
  if (j.contains("method")) o.method = stringField(j, "method", where);
  if (o.kind == SceneOutputKind::Ik && !parseIkMethod(o.method))
    throw InvalidInput(where.key("method").str() + ": " + inQuotes(o.method) + " is not one of " + ikMethodNames());
  if (o.kind == SceneOutputKind::Stewart && !parseStewartMethod(o.method))
    throw InvalidInput(where.key("method").str() + ": " + inQuotes(o.method) + " is not one of " + stewartMethodNames());
  if (o.kind == SceneOutputKind::Stewart && o.complex && *parseStewartMethod(o.method) != StewartMethod::Homotopy)
    throw InvalidInput(where.key("complex").str() + ": only the homotopy finds the complex solutions (method " +
                       inQuotes(o.method) + ")");
  if (j.contains("scalar")) {
    const std::string s = stringField(j, "scalar", where);
    const auto k = parseScalarKind(s);
    if (!k) throw InvalidInput(where.key("scalar").str() + ": " + inQuotes(s) + " is not one of " + scalarNames());
    o.scalar = *k;
  }
  if (j.contains("bits"))  // mpfr's precision, the range of --bits (docs/cli.md)
    o.bits = int(readInteger(j["bits"], where.key("bits").str(), 16, 8192));
  if (j.contains("needs")) {
    const json& n = j["needs"];
    if (!n.is_array()) throw InvalidInput(where.key("needs").str() + ": expected an array of output names");
    for (std::size_t i = 0; i < n.size(); ++i) {
      if (!n[i].is_string()) throw InvalidInput(where.key("needs").index(i).str() + ": expected a string");
      o.needs.push_back(n[i].get<std::string>());
    }
  }
  return o;
}

// Each name an output uses exists and is of the kind it is used as.
void checkReference(const SceneFile& s, const SceneOutput& o, const std::string& key, const std::string& name,
                    SceneEntityKind want) {
  const SceneEntity* e = s.entity(name);
  if (!e) throw InvalidInput(o.where + "." + key + ": no entity named " + inQuotes(name));
  if (e->kind != want)
    throw InvalidInput(o.where + "." + key + ": " + inQuotes(name) + " is a " + std::string(sceneEntityKindName(e->kind)) +
                       ", expected a " + std::string(sceneEntityKindName(want)));
}

void checkCycles(const SceneFile& s) {
  std::map<std::string, int> state;  // 0 new, 1 on the path, 2 done
  std::vector<std::string> path;
  std::function<void(const SceneOutput&)> visit = [&](const SceneOutput& o) {
    state[o.name] = 1;
    path.push_back(o.name);
    for (const std::string& n : o.needs) {
      const SceneOutput* d = s.output(n);
      if (state[n] == 1) {
        std::string cycle;
        bool on = false;
        for (const std::string& p : path) {
          if (p == n) on = true;
          if (on) cycle += p + " → ";
        }
        throw InvalidInput(o.where + ".needs: a cycle between outputs: " + cycle + n);
      }
      if (state[n] == 0) visit(*d);
    }
    path.pop_back();
    state[o.name] = 2;
  };
  for (const SceneOutput& o : s.outputs)
    if (state[o.name] == 0) visit(o);
}

}  // namespace

namespace {
// The fields every output's JSON starts with (scene_output.hpp), for the outputs computed in double.
json doubleOutputHead(const SceneOutput& o, const std::string& method, double seconds, double residual, bool ok) {
  json j;
  j["output"] = o.name;
  j["kind"] = std::string(sceneOutputKindName(o.kind));
  j["method"] = method;
  j["scalar"] = "double";
  j["seconds"] = seconds;
  j["residual"] = residual;
  j["ok"] = ok;
  return j;
}
}  // namespace

PlanarScene scenePlanarMechanism(const SceneEntity& e) {
  try {
    if (e.file) return readPlanarScene(*e.file);
    return parsePlanarScene(e.body, e.where);
  } catch (const InvalidInput& x) {
    const std::string m = x.what();
    if (m.find(e.file ? e.file->string() : e.where) != std::string::npos) throw;
    throw InvalidInput(e.where + ": " + m);
  }
}

std::string burmesterOutputJson(const SceneOutput& o, const std::vector<BurmesterPairRecord>& pairs, int complexPairs,
                                double residual, double seconds, bool ok) {
  json j = doubleOutputHead(o, "Burmester synthesis (resultant of two centre-point cubics, Newton polish)", seconds, residual, ok);
  j["mechanism"] = o.mechanism;
  j["expected_count"] = 4;
  j["count"] = pairs.size();
  j["complex_count"] = complexPairs;
  json a = json::array();
  for (const BurmesterPairRecord& p : pairs)
    a.push_back({{"centre", {p.centre[0], p.centre[1]}}, {"circle_point", {p.circle[0], p.circle[1]}}, {"radius", p.radius},
                 {"residual", p.residual}});
  j["pairs"] = a;
  return j.dump();
}

std::string workspaceOutputJson(const SceneOutput& o, const WorkspaceRecord& w) {
  json j = doubleOutputHead(o, "OMPL state sampling and the singular curves (GF §5.2.3)", w.seconds, 0, true);
  j["robot"] = o.robot;
  j["samples"] = w.samples;
  j["grid"] = w.grid;
  j["rho_max"] = w.rhoMax;
  j["z_min"] = w.zMin;
  j["z_max"] = w.zMax;
  j["reached_cells"] = w.reachedCells;
  j["reached_fraction"] = w.reachedFraction;
  j["mean_dexterity"] = w.meanDexterity;
  j["boundary_curves"] = w.boundaryCurves;
  j["boundary_points"] = w.boundaryPoints;
  return j.dump();
}

std::string dynamicsOutputJson(const SceneOutput& o, const DynamicsRecord& d, bool ok) {
  json j = doubleOutputHead(o, "recursive Newton-Euler (GF §13.3) along a quintic", d.seconds, d.residual, ok);
  j["scalar"] = d.scalar;
  if (d.scalar == "mpfr") j["bits"] = d.bits;
  j["robot"] = o.robot;
  j["payload"] = o.payload;
  j["gravity"] = o.gravity;
  j["duration"] = o.duration;
  j["times"] = d.times;
  j["joints"] = d.joints;
  j["torques"] = d.torques;
  j["max_abs_torque"] = d.maxAbsTorque;
  j["form"] = o.cl062 ? "cl062" : "vector";
  if (o.cl062) {
    j["momenta_cl062"] = d.momenta;
    j["momenta_cl062_residual"] = d.momentaResidual;
  }
  return j.dump();
}

std::string reportOutputJson(const SceneOutput& o, double seconds) {
  json j = doubleOutputHead(o, "HTML", seconds, 0, true);
  j["html"] = o.html.string();
  j["outputs"] = o.reported;
  return j.dump();
}

namespace {
std::string escapeHtml(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}
}  // namespace

std::string sceneReportHtml(const SceneFile& s, const SceneOutput& report, const std::vector<std::string>& outputJson) {
  std::string h = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + escapeHtml(s.origin) + ": " +
                  escapeHtml(report.name) + "</title>\n<style>body{font-family:sans-serif;max-width:60em;margin:2em auto}"
                  "pre{background:#f4f4f4;padding:1em;overflow-x:auto}td,th{padding:0.2em 0.8em;text-align:left}</style>"
                  "</head><body>\n<h1>" + escapeHtml(s.origin) + "</h1>\n<table><tr><th>output</th><th>kind</th><th>method</th>"
                  "<th>scalar</th><th>residual</th><th>seconds</th><th>ok</th></tr>\n";
  std::vector<json> outs;
  for (const std::string& t : outputJson) outs.push_back(json::parse(t));
  for (const json& j : outs)
    h += "<tr><td><a href=\"#" + escapeHtml(j["output"]) + "\">" + escapeHtml(j["output"]) + "</a></td><td>" +
         escapeHtml(j["kind"]) + "</td><td>" + escapeHtml(j["method"]) + "</td><td>" + escapeHtml(j["scalar"]) + "</td><td>" +
         escapeHtml(json(j["residual"]).dump()) + "</td><td>" + escapeHtml(json(j["seconds"]).dump()) + "</td><td>" +
         (j["ok"].get<bool>() ? "yes" : "<b>NO</b>") + "</td></tr>\n";
  h += "</table>\n";
  const std::filesystem::path folder = std::filesystem::absolute(report.html).parent_path();
  for (const json& j : outs) {
    h += "<h2 id=\"" + escapeHtml(j["output"]) + "\">" + escapeHtml(j["output"]) + " (" + escapeHtml(j["kind"]) + ")</h2>\n";
    if (j["kind"] == "figure") {
      const std::filesystem::path png = std::filesystem::absolute(j[j.contains("svg") ? "svg" : "png"].get<std::string>());
      h += "<img src=\"" + escapeHtml(png.lexically_relative(folder).string()) + "\" width=\"" +
           json(j["width"]).dump() + "\">\n";
    }
    h += "<pre>" + escapeHtml(j.dump(2)) + "</pre>\n";
  }
  return h + "</body></html>\n";
}

std::string cuspidalOutputJson(const SceneOutput& o, const CuspidalRecord& c) {
  json j = doubleOutputHead(o, c.method, c.seconds, c.residual, true);
  j["robot"] = o.robot;
  j["cuspidal"] = c.cuspidal;
  j["six_r"] = c.sixR;
  j["cusp_count"] = c.cuspCount;
  j["aspect_count"] = c.aspectCount;
  json w;
  w["found"] = c.witnessFound;
  w["certified"] = c.witnessCertified;
  w["target"] = c.witnessTarget;
  w["start"] = c.witnessStart;
  w["goal"] = c.witnessGoal;
  w["points"] = c.witnessPoints;
  w["note"] = c.witnessNote;
  j["witness"] = w;
  return j.dump();
}

std::string figureOutputJson(const SceneOutput& o, const std::vector<std::string>& drawn, double seconds) {
  json j = doubleOutputHead(o, o.svg.empty() ? "OSMesa" : "SVG", seconds, 0, true);
  if (o.svg.empty()) j["png"] = o.png.string();
  else j["svg"] = o.svg.string();
  j["width"] = o.width;
  j["height"] = o.height;
  j["drawn"] = drawn;
  return j.dump();
}

std::string_view sceneEntityKindName(SceneEntityKind k) {
  for (const auto& e : kEntityKinds)
    if (e.kind == k) return e.name;
  return "?";
}
std::string_view sceneOutputKindName(SceneOutputKind k) {
  for (const auto& e : kOutputKinds)
    if (e.kind == k) return e.name;
  return "?";
}

const SceneEntity* SceneFile::entity(std::string_view name) const {
  for (const SceneEntity& e : entities)
    if (e.name == name) return &e;
  return nullptr;
}
const SceneOutput* SceneFile::output(std::string_view name) const {
  for (const SceneOutput& o : outputs)
    if (o.name == name) return &o;
  return nullptr;
}

SceneFile parseScene(const std::string& text, const std::string& origin, const std::filesystem::path& folder) {
  const json j = parseJson(text, origin);
  const KeyPath root(origin);
  if (!j.is_object()) throw InvalidInput(origin + ": a scene must be a JSON object");
  checkKeys(j, {"entities", "outputs", "description"}, origin, "(a scene has entities, outputs, description)");
  SceneFile s;
  s.origin = origin;
  if (j.contains("description") && !j["description"].is_string())
    throw InvalidInput(root.key("description").str() + ": expected a string");
  if (j.contains("entities")) {
    if (!j["entities"].is_object()) throw InvalidInput(root.key("entities").str() + ": expected an object {NAME: entity}");
    // nlohmann's object is ordered by key; the file's order is not kept (the names say what is what).
    for (const auto& [name, e] : j["entities"].items())
      s.entities.push_back(parseEntity(name, e, origin, KeyPath().key("entities").key(name).str(), folder));
  }
  if (!j.contains("outputs") || !j["outputs"].is_object() || j["outputs"].empty())
    throw InvalidInput(root.key("outputs").str() + ": the scene asks for nothing (give at least one output)");
  for (const auto& [name, o] : j["outputs"].items())
    s.outputs.push_back(parseOutput(name, o, origin, KeyPath().key("outputs").key(name).str()));
  // A report shows the outputs it names (every other non-report output when it names none): it
  // needs them, so a report naming itself, or two reports naming each other, is a cycle.
  for (SceneOutput& o : s.outputs) {
    if (o.kind != SceneOutputKind::Report) continue;
    if (o.reported.empty())
      for (const SceneOutput& u : s.outputs)
        if (u.kind != SceneOutputKind::Report) o.reported.push_back(u.name);
    for (std::size_t i = 0; i < o.reported.size(); ++i) {
      if (!s.output(o.reported[i]))
        throw InvalidInput(o.where + ".outputs[" + std::to_string(i) + "]: no output named " + inQuotes(o.reported[i]));
      if (std::find(o.needs.begin(), o.needs.end(), o.reported[i]) == o.needs.end()) o.needs.push_back(o.reported[i]);
    }
  }
  // The entities an entity is built from (a regulus' lines, a cylindroid's screws, ...).
  for (const SceneEntity& e : s.entities)
    for (std::size_t i = 0; i < e.uses.size(); ++i) {
      std::string key;
      SceneEntityKind want = SceneEntityKind::Screw;
      switch (e.kind) {
        case SceneEntityKind::Regulus: key = "lines[" + std::to_string(i) + "]"; want = SceneEntityKind::Line; break;
        case SceneEntityKind::RuledSurface:
          key = i == 0 ? "line" : "screw";
          want = i == 0 ? SceneEntityKind::Line : SceneEntityKind::Screw;
          break;
        default: key = "screws[" + std::to_string(i) + "]"; break;
      }
      const SceneEntity* u = s.entity(e.uses[i]);
      if (!u) throw InvalidInput(e.where + "." + key + ": no entity named " + inQuotes(e.uses[i]));
      if (u->kind != want)
        throw InvalidInput(e.where + "." + key + ": " + inQuotes(e.uses[i]) + " is a " +
                           std::string(sceneEntityKindName(u->kind)) + ", expected a " + std::string(sceneEntityKindName(want)));
    }
  // A cylindroid or screw-system output naming such an entity uses that entity's screws.
  for (SceneOutput& o : s.outputs) {
    if (o.system.empty()) continue;
    const bool cyl = o.kind == SceneOutputKind::Cylindroid;
    checkReference(s, o, cyl ? "cylindroid" : "system", o.system, cyl ? SceneEntityKind::Cylindroid : SceneEntityKind::ScrewSystem);
    o.screws = s.entity(o.system)->uses;
  }
  for (const SceneOutput& o : s.outputs) {
    if (!o.payload.empty()) checkReference(s, o, "payload", o.payload, SceneEntityKind::RigidBody);
    if (!o.robot.empty()) checkReference(s, o, "robot", o.robot, SceneEntityKind::Robot);
    if (!o.pose.empty()) checkReference(s, o, "pose", o.pose, SceneEntityKind::Pose);
    if (!o.platform.empty()) checkReference(s, o, "platform", o.platform, SceneEntityKind::Platform);
    if (!o.mechanism.empty()) checkReference(s, o, "mechanism", o.mechanism, SceneEntityKind::PlanarMechanism);
    for (std::size_t i = 0; i < o.screws.size(); ++i)
      checkReference(s, o, "screws[" + std::to_string(i) + "]", o.screws[i], SceneEntityKind::Screw);
    for (std::size_t i = 0; i < o.draw.size(); ++i) {
      const SceneEntity* e = s.entity(o.draw[i]);
      if (!e) throw InvalidInput(o.where + ".draw[" + std::to_string(i) + "]: no entity named " + inQuotes(o.draw[i]));
      if (!o.svg.empty() && e->kind != SceneEntityKind::PlanarMechanism)
        throw InvalidInput(o.where + ".draw[" + std::to_string(i) + "]: an SVG figure is 2-D: " + inQuotes(o.draw[i]) + " is a " +
                           std::string(sceneEntityKindName(e->kind)) + ", not a planar-mechanism");
    }
    if (!o.svg.empty() && o.draw.empty()) {
      bool any = false;
      for (const SceneEntity& e : s.entities) any = any || e.kind == SceneEntityKind::PlanarMechanism;
      if (!any) throw InvalidInput(o.where + ".svg: an SVG figure is 2-D and the scene has no planar-mechanism to draw");
    }
    for (std::size_t i = 0; i < o.needs.size(); ++i)
      if (!s.output(o.needs[i]))
        throw InvalidInput(o.where + ".needs[" + std::to_string(i) + "]: no output named " + inQuotes(o.needs[i]));
  }
  checkCycles(s);
  return s;
}

void validateScene(const SceneFile& s) {
  // The entities built from others, and rigid bodies, are read once in double here (a defect is
  // found before anything is computed, whichever output draws or uses them).
  for (const SceneEntity& e : s.entities) {
    switch (e.kind) {
      case SceneEntityKind::LinearComplex: (void)sceneLinearComplex<double>(e); break;
      case SceneEntityKind::Regulus: (void)sceneRegulus<double>(s, e); break;
      case SceneEntityKind::Cylindroid: (void)sceneCylindroid<double>(s, e); break;
      case SceneEntityKind::RuledSurface: (void)sceneRuledSurface<double>(s, e); break;
      case SceneEntityKind::ScrewSystem: (void)sceneScrewSystem<double>(s, e); break;
      case SceneEntityKind::RigidBody: (void)sceneRigidBody<double>(e); break;
      default: break;
    }
  }
  // A figure draws its entities in double: each is read once here.
  for (const SceneOutput& o : s.outputs) {
    if (o.kind != SceneOutputKind::Figure) continue;
    for (const SceneEntity& e : s.entities) {
      bool drawn = o.draw.empty();
      for (const std::string& d : o.draw) drawn = drawn || d == e.name;
      if (!drawn) continue;
      switch (e.kind) {
        case SceneEntityKind::Robot: (void)sceneRobot<double>(e); break;
        case SceneEntityKind::Pose: (void)scenePose<double>(e); break;
        case SceneEntityKind::Platform: (void)scenePlatform<double>(e); break;
        case SceneEntityKind::Point: (void)scenePoint<double>(e); break;
        case SceneEntityKind::Line: (void)sceneLine<double>(e); break;
        case SceneEntityKind::Screw: (void)sceneScrew<double>(e); break;
        case SceneEntityKind::PlanarMechanism: (void)scenePlanarMechanism(e); break;
        default: break;  // read above
      }
    }
  }
  for (const SceneOutput& o : s.outputs) {
    setMpfrBits(o.bits);
    withScalar(o.scalar, [&]<class S>() {
      switch (o.kind) {
        case SceneOutputKind::Ik:
          (void)sceneRobot<S>(*s.entity(o.robot));
          (void)scenePose<S>(*s.entity(o.pose));
          break;
        case SceneOutputKind::Fk: (void)sceneJoints<S>(o, sceneRobot<S>(*s.entity(o.robot))); break;
        case SceneOutputKind::Stewart: (void)scenePlatform<S>(*s.entity(o.platform)); break;
        case SceneOutputKind::Cuspidal: (void)sceneRobot<S>(*s.entity(o.robot)); break;
        case SceneOutputKind::Burmester: {
          const PlanarScene m = scenePlanarMechanism(*s.entity(o.mechanism));
          if (m.positions.size() != 5)
            throw InvalidInput(o.where + ".mechanism: a burmester output needs 5 positions, \"" + o.mechanism + "\" has " +
                               std::to_string(m.positions.size()) + (m.fourbar ? " (it is a 4-bar)" : ""));
          break;
        }
        case SceneOutputKind::Cylindroid:
        case SceneOutputKind::ScrewSystem:
          for (const std::string& n : o.screws) (void)sceneScrew<S>(*s.entity(n));
          break;
        case SceneOutputKind::Workspace: (void)sceneRobot<double>(*s.entity(o.robot)); break;
        case SceneOutputKind::Dynamics: {
          const RobotFile<S> rf = sceneRobot<S>(*s.entity(o.robot));
          (void)sceneTrajectoryEnds<S>(o, rf);
          if (int(rf.links.size()) != rf.robot.dof())
            throw InvalidInput(o.where + ".robot: a dynamics output needs the robot's link inertias (a \"links\" array of " +
                               std::to_string(rf.robot.dof()) + " in its file), \"" + o.robot + "\" has " +
                               std::to_string(rf.links.size()));
          if (!o.payload.empty()) (void)sceneRigidBody<S>(*s.entity(o.payload));
          break;
        }
        case SceneOutputKind::Figure:
        case SceneOutputKind::Report: break;  // a figure's entities were read in double above
      }
    });
  }
}

SceneFile readScene(const std::filesystem::path& file) {
  SceneFile s = parseScene(readTextFile(file, "scene"), file.string(), file.parent_path());
  validateScene(s);
  return s;
}

}  // namespace soma::io
