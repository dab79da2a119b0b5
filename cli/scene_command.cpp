// `soma scene SCENE.json [--only OUTPUT...] [--json] [--trace]` (DESIGN §5, issue 19): the scene's
// outputs (or only those named), built lazily by the scene graph; --trace lists every node built,
// its time and which output needed it.
#include "command.hpp"
#include "json_output.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/json_number.hpp"
#include "soma/io/scene_file.hpp"
#include "soma/scene/scene_graph.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <iostream>

namespace soma::cli {

namespace {

// A number of an output's JSON in text: a wider scalar's decimal string as written (its own digits,
// io/json_number.hpp), a JSON number with `digits` significant digits.
std::string numberText(const nlohmann::json& x, int digits) {
  if (x.is_string()) return x.get<std::string>();
  return fmt::format("{:.{}g}", x.get<double>(), digits);
}

// A residual or error measure: a few digits are enough, in whatever scalar it was written.
double measure(const nlohmann::json& x) { return io::readJsonNumber<double>(x, "scene output"); }

// One line per output, from its JSON (io/scene_output.hpp).
std::string summary(const nlohmann::json& j) {
  const std::string kind = j["kind"];
  std::string s = fmt::format("{} ({}, {}): {}", j["output"].get<std::string>(), kind, j["scalar"].get<std::string>(),
                              j["method"].get<std::string>());
  if (j.contains("count"))
    s += fmt::format("   {} found, {} expected in general", j["count"].get<int>(), j["expected_count"].get<int>());
  if (kind == "fk") {
    const auto& t = j["pose"]["translation"];
    s += fmt::format("   translation {} {} {}", numberText(t[0], 9), numberText(t[1], 9), numberText(t[2], 9));
  }
  if (kind == "cylindroid")
    s += fmt::format("   pitches {} {}", numberText(j["pitches"][0], 12), numberText(j["pitches"][1], 12));
  if (kind == "workspace")
    s += fmt::format("   {} cells reached, rho_max {:.6g}, {} boundary curves", j["reached_cells"].get<int>(),
                     j["rho_max"].get<double>(), j["boundary_curves"].get<int>());
  if (kind == "dynamics") {
    std::string m;
    for (const auto& t : j["max_abs_torque"]) m += fmt::format(" {:.6g}", t.get<double>());
    s += fmt::format("   {} samples, max |torque|{}", j["times"].size(), m);
  }
  s += fmt::format("   residual {:.3g}   {:.3g} s{}", measure(j["residual"]), j["seconds"].get<double>(),
                   j["ok"].get<bool>() ? "" : "   CHECK FAILED");
  return s;
}

int sceneCommand(const std::string& file, const std::vector<std::string>& only, bool json, bool trace,
                 std::ostream& out) {
  scene::SceneGraph graph(io::readScene(file));
  const scene::SceneResult r = graph.evaluate(only);
  if (json) {
    nlohmann::json j;
    j["scene"] = file;
    j["ok"] = r.ok();
    nlohmann::json outs = nlohmann::json::object();
    for (const auto& o : r.outputs) outs[o.name] = nlohmann::json::parse(o.json);
    j["outputs"] = outs;
    if (trace) {
      nlohmann::json t = nlohmann::json::array();
      for (const auto& e : r.trace) t.push_back({{"id", e.id}, {"seconds", e.seconds}, {"reason", e.reason}});
      j["trace"] = t;
    }
    out << jsonText(j) << "\n";
    return r.ok() ? 0 : 1;
  }
  out << fmt::format("scene: {}   outputs: {} of {}\n", file, r.outputs.size(), graph.scene().outputs.size());
  for (const auto& o : r.outputs) out << "  " << summary(nlohmann::json::parse(o.json)) << "\n";
  if (trace) {
    out << fmt::format("trace: {} nodes built\n", r.trace.size());
    for (const auto& e : r.trace) out << fmt::format("  {:>10.3f} ms  {:<32} {}\n", e.seconds * 1e3, e.id, e.reason);
  }
  return r.ok() ? 0 : 1;
}

class SceneCommand : public Command {
 public:
  void declare(Spec& spec) override {
    spec.name = "scene";
    spec.help = "a scene file's outputs, each node built once, only for the outputs asked";
    spec.add("scene", file_, "scene JSON: {\"entities\": {...}, \"outputs\": {...}} (docs/cli.md)").mustBeGiven();
    spec.add("--only", only_, "compute only these outputs (names in the scene)");
    spec.flag("--json", json_, "print one JSON object");
    spec.flag("--trace", trace_, "list every node built, its time and the output that needed it");
  }
  int run(const Spec&, const Invocation&) override { return sceneCommand(file_, only_, json_, trace_, std::cout); }

 private:
  std::string file_;
  std::vector<std::string> only_;
  bool json_ = false, trace_ = false;
};

}  // namespace

SOMA_CLI_COMMAND(SceneCommand, 95);

}  // namespace soma::cli
