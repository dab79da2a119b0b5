// The sweep file reader and the rows' text (sweep_file.hpp, issue 26).
#include "soma/io/sweep_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/json_file.hpp"
#include "soma/io/number.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <set>

namespace soma::io {

namespace {

using json = nlohmann::json;
using ordered = nlohmann::ordered_json;

// The largest sweep soma runs: 10^9 points (a row is ~100 bytes: 100 GB of rows).
constexpr long long kMaxPoints = 1000000000LL;

std::string inQuotes(std::string_view s) { return "\"" + std::string(s) + "\""; }

// The shortest decimal that reads back as x ("0.2", "1e-15").
std::string shortest(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

// The scalar fields of each output kind's JSON (scene_output.hpp), beyond those every output has.
const std::map<std::string, std::vector<std::string>, std::less<>>& kindFields() {
  static const std::map<std::string, std::vector<std::string>, std::less<>> t = {
      {"ik", {"count", "expected_count", "certified", "continuum"}},
      {"stewart", {"count", "expected_count", "complex_count", "certified"}},
      {"cuspidal", {"cuspidal", "six_r", "cusp_count", "aspect_count"}},
      {"workspace", {"samples", "grid", "rho_max", "z_min", "z_max", "reached_cells", "reached_fraction", "mean_dexterity",
                     "boundary_curves", "boundary_points"}},
      {"burmester", {"count", "expected_count", "complex_count"}},
      {"screw-system", {"type", "type_name", "dimension", "boundary_distance"}},
      {"fk", {}},
      {"cylindroid", {}},
      {"dynamics", {}}};
  return t;
}
const std::vector<std::string> kCommonFields = {"seconds", "residual", "ok", "method", "scalar"};

// "entities.arm.joints[1].a" → the JSON pointer /entities/arm/joints/1/a; InvalidInput naming
// `where` for a malformed path.
json::json_pointer pointerOf(const std::string& key, const std::string& where) {
  std::string p;
  std::string token;
  auto flush = [&] {
    if (token.empty()) throw InvalidInput(where + ": " + inQuotes(key) + " is not a key path (an empty name)");
    std::string esc;
    for (char c : token) esc += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
    p += "/" + esc;
    token.clear();
  };
  if (key.empty()) throw InvalidInput(where + ": an empty key path");
  for (std::size_t i = 0; i < key.size(); ++i) {
    const char c = key[i];
    if (c == '.') {
      flush();
    } else if (c == '[') {
      if (!token.empty()) flush();
      const std::size_t close = key.find(']', i);
      const std::string digits = close == std::string::npos ? "" : key.substr(i + 1, close - i - 1);
      if (digits.empty() || !std::all_of(digits.begin(), digits.end(), [](char d) { return d >= '0' && d <= '9'; }))
        throw InvalidInput(where + ": " + inQuotes(key) + " is not a key path (an index is [digits])");
      p += "/" + digits;
      i = close;
      if (i + 1 < key.size() && key[i + 1] != '.' && key[i + 1] != '[')
        throw InvalidInput(where + ": " + inQuotes(key) + " is not a key path (after ] comes . or [)");
      if (i + 1 < key.size() && key[i + 1] == '.') ++i;
    } else {
      token += c;
    }
  }
  if (!token.empty() || key.back() == '.') flush();
  return json::json_pointer(p);
}

// The entities a scene gives by a JSON file, read into it (their keys become key paths of the
// scene): a robot, pose, platform or planar-mechanism {"file": F.json}. A URDF stays a file.
void inlineFiles(json& scene, const std::filesystem::path& folder, const std::string& origin) {
  if (!scene.is_object() || !scene.contains("entities") || !scene["entities"].is_object()) return;
  json& entities = scene["entities"];
  for (auto it = entities.begin(); it != entities.end(); ++it) {
    const std::string name = it.key();
    json& e = it.value();
    if (!e.is_object() || !e.contains("file") || !e["file"].is_string() || !e.contains("kind") || !e["kind"].is_string())
      continue;
    const std::string kind = e["kind"];
    if (kind != "robot" && kind != "pose" && kind != "platform" && kind != "planar-mechanism") continue;
    std::filesystem::path f = e["file"].get<std::string>();
    if (!f.is_absolute() && !folder.empty()) f = folder / f;
    std::string ext = f.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".urdf") {
      e["file"] = f.string();  // resolved: the point scenes are parsed without a folder of their own
      continue;
    }
    json body = parseJson(readTextFile(f, kind), f.string());
    if (!body.is_object())
      throw InvalidInput(origin + ": entities." + name + ".file: " + f.string() + " is not a JSON object");
    if (e.size() != 2)
      throw InvalidInput(origin + ": entities." + name + ": an entity given by a JSON file has only kind and file");
    body["kind"] = kind;
    e = body;
  }
}

json baseScene(const json& base, const KeyPath& where, const std::filesystem::path& folder, std::string& baseOrigin,
               std::filesystem::path& baseFolder) {
  if (!base.is_object()) throw InvalidInput(where.str() + ": expected an object {\"scene\": FILE} or {\"robot\": FILE} or {\"platform\": FILE}");
  checkKeys(base, {"scene", "robot", "pose", "platform"}, where.str(), "(a base is a scene, a robot (and pose) or a platform)");
  const int given = int(base.contains("scene")) + int(base.contains("robot")) + int(base.contains("platform"));
  if (given != 1) throw InvalidInput(where.str() + ": give exactly one of scene, robot, platform");
  if (base.contains("pose") && !base.contains("robot")) throw InvalidInput(where.key("pose").str() + ": a pose goes with a robot base");
  auto file = [&](const char* key) {
    if (!base[key].is_string()) throw InvalidInput(where.key(key).str() + ": expected a file name");
    std::filesystem::path f = base[key].get<std::string>();
    return f.is_absolute() || folder.empty() ? f : folder / f;
  };
  json scene;
  if (base.contains("scene")) {
    const std::filesystem::path f = file("scene");
    scene = parseJson(readTextFile(f, "scene"), f.string());
    baseOrigin = f.string();
    baseFolder = f.parent_path();
  } else if (base.contains("robot")) {
    const std::filesystem::path f = file("robot");
    scene["entities"]["robot"] = {{"kind", "robot"}, {"file", f.string()}};
    scene["outputs"]["cuspidal"] = {{"kind", "cuspidal"}, {"robot", "robot"}, {"witness", false}};
    scene["outputs"]["workspace"] = {{"kind", "workspace"}, {"robot", "robot"}};
    if (base.contains("pose")) {
      scene["entities"]["pose"] = {{"kind", "pose"}, {"file", file("pose").string()}};
      scene["outputs"]["ik"] = {{"kind", "ik"}, {"robot", "robot"}, {"pose", "pose"}};
    }
    baseOrigin = f.string() + " (as a sweep's base scene)";
    baseFolder = folder;
  } else {
    const std::filesystem::path f = file("platform");
    scene["entities"]["platform"] = {{"kind", "platform"}, {"file", f.string()}};
    scene["outputs"]["stewart"] = {{"kind", "stewart"}, {"platform", "platform"}};
    baseOrigin = f.string() + " (as a sweep's base scene)";
    baseFolder = folder;
  }
  // A robot or platform base names its files already resolved.
  inlineFiles(scene, base.contains("scene") ? baseFolder : std::filesystem::path(), baseOrigin);
  return scene;
}

double numberField(const json& j, const char* key, const KeyPath& where) {
  if (!j.contains(key)) throw InvalidInput(where.str() + ": missing ." + key);
  return readNumber<double>(j[key], where.key(key).str());
}

SweepParameter parseParameter(const json& p, const KeyPath& where, const json& base, const std::string& baseOrigin,
                              bool random) {
  SweepParameter s;
  s.where = where.str();
  if (!p.is_object()) throw InvalidInput(where.str() + ": expected an object {\"name\", \"key\", \"range\" | \"values\" | \"uniform\"}");
  checkKeys(p, {"name", "key", "range", "values", "uniform"}, where.str(),
            "(a parameter has name, key and one of range, values, uniform)");
  if (!p.contains("name") || !p["name"].is_string() || p["name"].get<std::string>().empty())
    throw InvalidInput(where.key("name").str() + ": expected a non-empty name (the column)");
  s.name = p["name"];
  if (!p.contains("key") || !p["key"].is_string()) throw InvalidInput(where.key("key").str() + ": expected a key path into the base scene");
  s.key = p["key"];
  const json::json_pointer ptr = pointerOf(s.key, where.key("key").str());
  if (!base.contains(ptr))
    throw InvalidInput(where.key("key").str() + ": " + inQuotes(s.key) + " is not in the base scene " + baseOrigin);
  const json& at = base.at(ptr);
  if (!at.is_number() && !(at.is_string() && detail::isDecimal(at.get<std::string>())))
    throw InvalidInput(where.key("key").str() + ": " + inQuotes(s.key) + " is not a number in the base scene " + baseOrigin +
                       " (it is " + std::string(at.type_name()) + ")");
  const int kinds = int(p.contains("range")) + int(p.contains("values")) + int(p.contains("uniform"));
  if (kinds != 1) throw InvalidInput(where.str() + ": give exactly one of range, values, uniform");
  if (p.contains("uniform")) {
    if (!random) throw InvalidInput(where.key("uniform").str() + ": a uniform parameter needs \"samples\": {\"count\", \"seed\"}");
    const json& u = p["uniform"];
    const KeyPath w = where.key("uniform");
    if (!u.is_object()) throw InvalidInput(w.str() + ": expected {\"from\", \"to\"}");
    checkKeys(u, {"from", "to"}, w.str());
    s.uniform = true;
    s.from = numberField(u, "from", w);
    s.to = numberField(u, "to", w);
    if (!(s.from < s.to)) throw InvalidInput(w.str() + ": an empty interval (from " + shortest(s.from) + " is not below to " + shortest(s.to) + ")");
    return s;
  }
  if (random) throw InvalidInput(where.str() + ": with \"samples\" every parameter is uniform (a grid and random samples do not mix)");
  if (p.contains("values")) {
    const json& v = p["values"];
    if (!v.is_array()) throw InvalidInput(where.key("values").str() + ": expected an array of numbers");
    if (v.empty()) throw InvalidInput(where.key("values").str() + ": an empty list of values");
    for (std::size_t i = 0; i < v.size(); ++i) s.values.push_back(readNumber<double>(v[i], where.key("values").index(i).str()));
    return s;
  }
  const json& r = p["range"];
  const KeyPath w = where.key("range");
  if (!r.is_object()) throw InvalidInput(w.str() + ": expected {\"from\", \"to\", \"count\"}");
  checkKeys(r, {"from", "to", "count"}, w.str(), "(a range has from, to, count)");
  const double from = numberField(r, "from", w), to = numberField(r, "to", w);
  if (!r.contains("count")) throw InvalidInput(w.str() + ": missing .count");
  const long long n = readInteger(r["count"], w.key("count").str(), 0, kMaxPoints);
  if (n == 0) throw InvalidInput(w.key("count").str() + ": an empty range (count 0)");
  if (n == 1 && from != to) throw InvalidInput(w.key("count").str() + ": count 1 needs from = to");
  for (long long i = 0; i < n; ++i)
    s.values.push_back(i == n - 1 ? to : from + (to - from) * double(i) / double(n - 1));
  return s;
}

std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A CSV field: quoted when it holds a comma, a quote or a line break (RFC 4180); line breaks become spaces.
std::string csvField(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  std::replace(s.begin(), s.end(), '\r', ' ');
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

std::size_t SweepFile::points() const {
  if (random) return samples;
  std::size_t n = 1;
  for (const SweepParameter& p : parameters) n *= p.values.size();
  return n;
}

std::vector<double> SweepFile::point(std::size_t i) const {
  std::vector<double> v(parameters.size());
  if (random) {
    std::uint64_t state = seed ^ (std::uint64_t(i) * 0xd1b54a32d192ed03ULL);
    (void)splitmix64(state);
    for (std::size_t k = 0; k < parameters.size(); ++k) {
      const double u = double(splitmix64(state) >> 11) * 0x1.0p-53;  // [0, 1)
      v[k] = parameters[k].from + (parameters[k].to - parameters[k].from) * u;
    }
    return v;
  }
  // The first parameter varies slowest.
  for (std::size_t k = parameters.size(); k-- > 0;) {
    const std::size_t n = parameters[k].values.size();
    v[k] = parameters[k].values[i % n];
    i /= n;
  }
  return v;
}

SweepFile parseSweep(const std::string& text, const std::string& origin, const std::filesystem::path& folder) {
  const json j = parseJson(text, origin);
  const KeyPath root(origin);
  if (!j.is_object()) throw InvalidInput(origin + ": a sweep must be a JSON object");
  checkKeys(j, {"description", "base", "parameters", "samples", "quantities", "rows"}, origin,
            "(a sweep has description, base, parameters, samples, quantities, rows)");
  SweepFile s;
  s.origin = origin;
  if (j.contains("description")) {
    if (!j["description"].is_string()) throw InvalidInput(root.key("description").str() + ": expected a string");
    s.description = j["description"];
  }
  if (!j.contains("base")) throw InvalidInput(root.key("base").str() + ": missing (the scene, robot or platform to vary)");
  const json base = baseScene(j["base"], root.key("base"), folder, s.baseOrigin, s.baseFolder);
  if (j.contains("samples")) {
    const json& n = j["samples"];
    const KeyPath w = root.key("samples");
    if (!n.is_object()) throw InvalidInput(w.str() + ": expected {\"count\", \"seed\"}");
    checkKeys(n, {"count", "seed"}, w.str(), "(samples have count and seed)");
    if (!n.contains("count")) throw InvalidInput(w.str() + ": missing .count");
    if (!n.contains("seed")) throw InvalidInput(w.str() + ": missing .seed (random samples are reproducible)");
    s.random = true;
    s.samples = std::size_t(readInteger(n["count"], w.key("count").str(), 1, kMaxPoints));
    s.seed = std::uint64_t(readInteger(n["seed"], w.key("seed").str(), 0, (1LL << 53)));
  }
  if (!j.contains("parameters") || !j["parameters"].is_array() || j["parameters"].empty())
    throw InvalidInput(root.key("parameters").str() + ": expected a non-empty array of parameters");
  std::set<std::string> names = {"point", "residual", "status", "message", "seconds"}, keys;
  for (std::size_t i = 0; i < j["parameters"].size(); ++i) {
    const KeyPath w = root.key("parameters").index(i);
    s.parameters.push_back(parseParameter(j["parameters"][i], w, base, s.baseOrigin, s.random));
    if (!names.insert(s.parameters.back().name).second)
      throw InvalidInput(w.key("name").str() + ": " + inQuotes(s.parameters.back().name) + " is already a column");
    if (!keys.insert(s.parameters.back().key).second)
      throw InvalidInput(w.key("key").str() + ": " + inQuotes(s.parameters.back().key) + " is varied twice");
  }
  if (!s.random) {
    long double n = 1;
    for (const SweepParameter& p : s.parameters) n *= (long double)p.values.size();
    if (n > (long double)kMaxPoints)
      throw InvalidInput(root.key("parameters").str() + ": the grid has more than 10^9 points");
  }
  if (!j.contains("quantities") || !j["quantities"].is_object() || j["quantities"].empty())
    throw InvalidInput(root.key("quantities").str() + ": expected a non-empty object {NAME: {\"output\", \"field\"}}");
  const json& outputs = base.contains("outputs") && base["outputs"].is_object() ? base["outputs"] : json::object();
  for (const auto& [name, q] : j["quantities"].items()) {
    const KeyPath w = root.key("quantities").key(name);
    if (!q.is_object()) throw InvalidInput(w.str() + ": expected {\"output\", \"field\"}");
    checkKeys(q, {"output", "field"}, w.str(), "(a quantity has output and field)");
    if (!names.insert(name).second) throw InvalidInput(w.str() + ": " + inQuotes(name) + " is already a column");
    SweepQuantity sq;
    sq.name = name;
    sq.where = w.str();
    if (!q.contains("output") || !q["output"].is_string()) throw InvalidInput(w.key("output").str() + ": expected an output's name");
    if (!q.contains("field") || !q["field"].is_string()) throw InvalidInput(w.key("field").str() + ": expected a field's name");
    sq.output = q["output"];
    sq.field = q["field"];
    if (!outputs.contains(sq.output)) {
      std::string list;
      for (auto it = outputs.begin(); it != outputs.end(); ++it) list += (list.empty() ? "" : ", ") + it.key();
      throw InvalidInput(w.key("output").str() + ": the base scene " + s.baseOrigin + " has no output " + inQuotes(sq.output) +
                         " (it has: " + list + ")");
    }
    const json& o = outputs[sq.output];
    const std::string kind = o.is_object() && o.contains("kind") && o["kind"].is_string() ? o["kind"].get<std::string>() : "";
    const auto it = kindFields().find(kind);
    if (it == kindFields().end())
      throw InvalidInput(w.key("output").str() + ": " + inQuotes(sq.output) + " is a " + (kind.empty() ? "malformed" : kind) +
                         " output, which computes no quantity");
    if (std::find(it->second.begin(), it->second.end(), sq.field) == it->second.end() &&
        std::find(kCommonFields.begin(), kCommonFields.end(), sq.field) == kCommonFields.end()) {
      std::string list;
      for (const std::string& f : it->second) list += f + ", ";
      for (const std::string& f : kCommonFields) list += f + (f == kCommonFields.back() ? "" : ", ");
      throw InvalidInput(w.key("field").str() + ": a " + kind + " output has no field " + inQuotes(sq.field) + " (fields: " + list + ")");
    }
    if (std::find(s.outputs.begin(), s.outputs.end(), sq.output) == s.outputs.end()) s.outputs.push_back(sq.output);
    s.quantities.push_back(std::move(sq));
  }
  if (j.contains("rows")) {
    const json& r = j["rows"];
    const KeyPath w = root.key("rows");
    if (!r.is_object()) throw InvalidInput(w.str() + ": expected {\"csv\", \"jsonl\"}");
    checkKeys(r, {"csv", "jsonl"}, w.str(), "(rows have csv and jsonl file names)");
    for (const char* k : {"csv", "jsonl"}) {
      if (!r.contains(k)) continue;
      if (!r[k].is_string()) throw InvalidInput(w.key(k).str() + ": expected a file name");
      const std::string f = r[k];
      if (f.empty() || f.find('/') != std::string::npos || f == "." || f == ".." || f == "sweep.json")
        throw InvalidInput(w.key(k).str() + ": " + inQuotes(f) + " is not a plain file name inside --out");
      (std::string(k) == "csv" ? s.csv : s.jsonl) = f;
    }
    if (s.csv == s.jsonl) throw InvalidInput(w.str() + ": csv and jsonl name the same file");
  }
  s.baseText = base.dump();
  s.fingerprint = json{{"sweep", j}, {"base", base}}.dump();
  return s;
}

SweepFile readSweep(const std::filesystem::path& file) {
  SweepFile s = parseSweep(readTextFile(file, "sweep"), file.string(), file.parent_path());
  (void)sweepPointScene(s, 0);  // the base scene's own defects, before any point runs
  return s;
}

SceneFile sweepPointScene(const SweepFile& sweep, std::size_t i) {
  json scene = json::parse(sweep.baseText);
  const std::vector<double> v = sweep.point(i);
  for (std::size_t k = 0; k < v.size(); ++k) scene[pointerOf(sweep.parameters[k].key, sweep.parameters[k].where)] = v[k];
  SceneFile s = parseScene(scene.dump(), sweep.baseOrigin + " (sweep point " + std::to_string(i) + ")", sweep.baseFolder);
  validateScene(s);
  return s;
}

void sweepRowValues(const SweepFile& sweep, const std::vector<std::string>& outputJson, SweepRow& row) {
  std::vector<json> outs;
  row.residual = 0;
  for (std::size_t k = 0; k < outputJson.size(); ++k) {
    outs.push_back(json::parse(outputJson[k]));
    const json& r = outs.back().contains("residual") ? outs.back()["residual"] : json(0);
    // A residual in a wider scalar's digits may lie below double's range: it is then 0 here.
    const double e = r.is_number() ? r.get<double>() : r.is_string() ? std::strtod(r.get<std::string>().c_str(), nullptr) : 0.0;
    row.residual = std::max(row.residual, e);
  }
  row.values.clear();
  for (const SweepQuantity& q : sweep.quantities) {
    const auto at = std::find(sweep.outputs.begin(), sweep.outputs.end(), q.output) - sweep.outputs.begin();
    const json& o = outs.at(std::size_t(at));
    if (!o.contains(q.field)) throw InvalidInput(q.where + ".field: output " + inQuotes(q.output) + " wrote no " + inQuotes(q.field));
    row.values.push_back(o[q.field].dump());
  }
}

std::string sweepCsvHeader(const SweepFile& sweep) {
  std::string h = "point";
  for (const SweepParameter& p : sweep.parameters) h += "," + csvField(p.name);
  for (const SweepQuantity& q : sweep.quantities) h += "," + csvField(q.name);
  return h + ",residual,status,message,seconds\n";
}

std::string sweepCsvLine(const SweepFile& sweep, const SweepRow& row) {
  std::string l = std::to_string(row.point);
  for (double x : row.parameters) l += "," + shortest(x);
  for (std::size_t k = 0; k < sweep.quantities.size(); ++k) {
    std::string v = k < row.values.size() ? row.values[k] : "";
    if (v.size() >= 2 && v.front() == '"') v = json::parse(v).get<std::string>();  // a decimal string or a name
    l += "," + csvField(v);
  }
  return l + "," + shortest(row.residual) + "," + row.status + "," + csvField(row.message) + "," + shortest(row.seconds) + "\n";
}

std::string sweepJsonLine(const SweepFile& sweep, const SweepRow& row) {
  ordered j;
  j["point"] = row.point;
  ordered p = ordered::object();
  for (std::size_t k = 0; k < sweep.parameters.size(); ++k) p[sweep.parameters[k].name] = row.parameters[k];
  j["parameters"] = p;
  ordered v = ordered::object();
  for (std::size_t k = 0; k < row.values.size() && k < sweep.quantities.size(); ++k)
    v[sweep.quantities[k].name] = ordered::parse(row.values[k]);
  j["values"] = v;
  j["residual"] = row.residual;
  j["status"] = row.status;
  if (!row.message.empty()) j["message"] = row.message;
  j["seconds"] = row.seconds;
  return j.dump() + "\n";
}

std::optional<std::size_t> sweepJsonLinePoint(const std::string& line) {
  if (line.empty() || line.back() != '\n') return std::nullopt;
  const json j = json::parse(line, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("point") || !j["point"].is_number_unsigned() ||
      !j.contains("seconds"))
    return std::nullopt;
  return j["point"].get<std::size_t>();
}

std::vector<SweepRow> readSweepRows(const SweepFile& sweep, const std::filesystem::path& jsonl) {
  std::ifstream in(jsonl, std::ios::binary);
  if (!in) throw InvalidInput(jsonl.string() + ": cannot be read (a sweep's rows: --out DIR/" + sweep.jsonl + ")");
  std::vector<SweepRow> rows;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    const std::string where = jsonl.string() + ": line " + std::to_string(n);
    const bool complete = !in.eof();  // getline stopped at a newline: the line was written whole
    const json j = json::parse(line, nullptr, false);
    if (!complete || j.is_discarded() || !j.is_object())
      throw InvalidInput(where + ": not a complete row (a JSON object on one line)");
    const auto member = [&](const char* key) -> const json& {
      if (!j.contains(key)) throw InvalidInput(where + ": no \"" + std::string(key) + "\"");
      return j.at(key);
    };
    SweepRow r;
    const json& point = member("point");
    if (!point.is_number_unsigned() || point.get<std::size_t>() >= sweep.points())
      throw InvalidInput(where + ": \"point\" is not a point of " + sweep.origin + " (0 .. " +
                         std::to_string(sweep.points()) + " - 1)");
    r.point = point.get<std::size_t>();
    const json& p = member("parameters");
    for (const SweepParameter& sp : sweep.parameters) {
      if (!p.is_object() || !p.contains(sp.name) || !p.at(sp.name).is_number())
        throw InvalidInput(where + ": parameters." + sp.name + " is missing or not a number");
      r.parameters.push_back(p.at(sp.name).get<double>());
    }
    if (!member("status").is_string()) throw InvalidInput(where + ": \"status\" is not a string");
    r.status = j.at("status").get<std::string>();
    const json& v = member("values");
    if (!v.is_object()) throw InvalidInput(where + ": \"values\" is not an object");
    if (!v.empty())
      for (const SweepQuantity& q : sweep.quantities) {
        if (!v.contains(q.name)) throw InvalidInput(where + ": values." + q.name + " is missing");
        r.values.push_back(v.at(q.name).dump());
      }
    // A non-finite residual is written as null (JSON has no NaN).
    if (!(member("residual").is_number() || j.at("residual").is_null()) || !member("seconds").is_number())
      throw InvalidInput(where + ": \"residual\" or \"seconds\" is not a number");
    r.residual = j.at("residual").is_null() ? std::numeric_limits<double>::quiet_NaN() : j.at("residual").get<double>();
    r.seconds = j.at("seconds").get<double>();
    if (j.contains("message") && j.at("message").is_string()) r.message = j.at("message").get<std::string>();
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace soma::io
