// The scene graph (scene/scene_graph.hpp): what an evaluation builds and, as much, what it does
// NOT build — each node once, only for the outputs asked, with the reason in the trace.
#include "soma/scene/scene_graph.hpp"

#include "soma/algebra/errors.hpp"

#include "support/repo_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::scene;
using Catch::Contains;

namespace {
// A robot, a platform and two screws, and an output of each kind.
const char* kScene = R"({
  "entities": {
    "arm": {"kind": "robot", "file": "studies/robots/puma560.json"},
    "goal": {"kind": "pose", "file": "studies/robots/puma560_pose.json"},
    "hexapod": {"kind": "platform", "file": "studies/platforms/general.json"},
    "a": {"kind": "screw", "point": [0, 0, 0], "direction": [1, 0, 0], "pitch": 0.2},
    "b": {"kind": "screw", "point": [0, 0, 1], "direction": [0, 1, 0], "pitch": -0.1},
    "unused": {"kind": "robot", "file": "studies/robots/wrist3r.json"}
  },
  "outputs": {
    "postures": {"kind": "ik", "robot": "arm", "pose": "goal"},
    "tool": {"kind": "fk", "robot": "arm", "joints": [0, 0, 0, 0, 0, 0]},
    "tool_q": {"kind": "fk", "robot": "arm", "joints": [0, 0, 0, 0, 0, 0], "scalar": "float128", "needs": ["tool"]},
    "legs": {"kind": "stewart", "platform": "hexapod", "method": "ceres"},
    "pencil": {"kind": "cylindroid", "screws": ["a", "b"]},
    "span": {"kind": "screw-system", "screws": ["a", "b"]}
  }
})";

SceneGraph graph() {
  io::SceneFile s = io::parseScene(kScene, "scene.json", soma::test::repoFile(""));
  io::validateScene(s);
  return SceneGraph(std::move(s));
}

std::vector<std::string> ids(const SceneResult& r) {
  std::vector<std::string> v;
  for (const TraceEntry& t : r.trace) v.push_back(t.id);
  return v;
}
}  // namespace

TEST_CASE("scene graph: postures build the robot, the pose and the solve, nothing else", "[scene][trace]") {
  SceneGraph g = graph();
  const SceneResult r = g.evaluate({"postures"});
  // Dependencies are recorded when they are done: first the robot and the pose, then the solve.
  CHECK(ids(r) == std::vector<std::string>{"robot:arm[double]", "pose:goal[double]", "ik:postures"});
  CHECK(r.trace[0].reason == "output postures via ik:postures");
  CHECK(r.trace[2].reason == "output postures");
  // Not built: the platform, the screws, the other outputs, the unused robot.
  for (const char* id : {"platform:hexapod[double]", "stewart:legs", "screw:a[double]", "cylindroid:pencil", "fk:tool",
                         "robot:unused[double]"})
    CHECK_FALSE(r.built(id));
  REQUIRE(r.outputs.size() == 1);
  CHECK(r.outputs[0].name == "postures");
  CHECK(r.ok());
}

TEST_CASE("scene graph: each node is built once across evaluations", "[scene][trace]") {
  SceneGraph g = graph();
  (void)g.evaluate({"postures"});
  // Again: nothing to build, the answer is the one already computed.
  const SceneResult again = g.evaluate({"postures"});
  CHECK(again.trace.empty());
  REQUIRE(again.outputs.size() == 1);
  // fk of the same robot in the same scalar reuses robot:arm[double].
  const SceneResult fk = g.evaluate({"tool"});
  CHECK(ids(fk) == std::vector<std::string>{"fk:tool"});
}

TEST_CASE("scene graph: a needed output is built first — another scalar is another node", "[scene][trace]") {
  SceneGraph g = graph();
  const SceneResult r = g.evaluate({"tool_q"});
  CHECK(ids(r) == std::vector<std::string>{"robot:arm[double]", "fk:tool", "robot:arm[float128]", "fk:tool_q"});
  CHECK(r.trace[0].reason == "output tool_q via fk:tool_q via fk:tool");
  CHECK(r.trace[1].reason == "output tool_q via fk:tool_q");
  // Only the asked output is reported; the needed one was built for it.
  REQUIRE(r.outputs.size() == 1);
  CHECK(r.outputs[0].name == "tool_q");
}

TEST_CASE("scene graph: a screw-system question builds only its screws", "[scene][trace]") {
  SceneGraph g = graph();
  const SceneResult r = g.evaluate({"pencil"});
  CHECK(ids(r) == std::vector<std::string>{"screw:a[double]", "screw:b[double]", "cylindroid:pencil"});
  CHECK_FALSE(r.built("robot:arm[double]"));
  // The identification reuses the same 6-vectors: one node more, and no Clifford algebra.
  const SceneResult id = g.evaluate({"span"});
  CHECK(ids(id) == std::vector<std::string>{"screw-system:span"});
}

TEST_CASE("scene graph: every output, each entity once per scalar", "[scene][trace]") {
  SceneGraph g = graph();
  const SceneResult r = g.evaluate();
  CHECK(r.outputs.size() == 6);
  CHECK(r.trace.size() == 12);  // 6 outputs + arm[double], arm[float128], goal, hexapod, a, b
  CHECK_FALSE(r.built("robot:unused[double]"));
  CHECK(r.ok());
}

namespace {
// PNG width and height from its IHDR chunk (bytes 16–23, big-endian).
std::pair<int, int> pngSize(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char b[24] = {};
  in.read(reinterpret_cast<char*>(b), 24);
  REQUIRE(in.gcount() == 24);
  CHECK(b[1] == 'P');
  CHECK(b[2] == 'N');
  CHECK(b[3] == 'G');
  return {(b[16] << 24) | (b[17] << 16) | (b[18] << 8) | b[19], (b[20] << 24) | (b[21] << 16) | (b[22] << 8) | b[23]};
}

SceneGraph figureGraph(const std::filesystem::path& png, const std::string& draw) {
  const std::string text = std::string(R"({
  "entities": {
    "arm": {"kind": "robot", "file": "studies/robots/puma560.json"},
    "goal": {"kind": "pose", "file": "studies/robots/puma560_pose.json"},
    "a": {"kind": "screw", "point": [0, 0, 0], "direction": [1, 0, 0], "pitch": 0.2},
    "b": {"kind": "screw", "point": [0, 0, 1], "direction": [0, 1, 0], "pitch": -0.1},
    "l": {"kind": "line", "point": [0, 0, 0.5], "direction": [1, 1, 0]},
    "a2": {"kind": "screw", "point": [0, 1, 0], "direction": [1, 0, 0], "pitch": 0.3}
  },
  "outputs": {
    "postures": {"kind": "ik", "robot": "arm", "pose": "goal"},
    "pencil": {"kind": "cylindroid", "screws": ["a", "b"], "scalar": "float128"},
    "picture": {"kind": "figure", "png": ")") + png.string() + R"(", "size": [320, 240])" + draw + R"(},
    "broken": {"kind": "cylindroid", "screws": ["a", "a2"]}
  }
})";
  io::SceneFile s = io::parseScene(text, "figure.json", soma::test::repoFile(""));
  io::validateScene(s);
  return SceneGraph(std::move(s));
}
}  // namespace

TEST_CASE("scene graph: a figure tessellates only the entities it draws", "[scene][trace][figure]") {
  const auto png = std::filesystem::temp_directory_path() / "soma_scene_graph_screws.png";
  std::filesystem::remove(png);
  SceneGraph g = figureGraph(png, R"(, "draw": ["a", "b"])");
  const SceneResult r = g.evaluate({"picture"});
  // The two screws (in double, for drawing), their tessellations and the cylindroid of the output
  // whose screws are both drawn — not the robot, its postures, the line, or the float128 cylindroid.
  CHECK(ids(r) == std::vector<std::string>{"screw:a[double]", "tessellation:a", "screw:b[double]", "tessellation:b",
                                           "tessellation:pencil", "figure:picture"});
  CHECK(r.trace[0].reason == "output picture via figure:picture via tessellation:a");
  REQUIRE(r.written == std::vector<std::filesystem::path>{png});
  CHECK(pngSize(png) == std::pair<int, int>(320, 240));
  for (const auto& f : std::filesystem::directory_iterator(png.parent_path()))
    CHECK(f.path().string().find("soma_scene_graph_screws.png.") == std::string::npos);  // no partial file left
  std::filesystem::remove(png);
}

TEST_CASE("scene graph: a figure of a robot builds the postures it draws", "[scene][trace][figure]") {
  const auto png = std::filesystem::temp_directory_path() / "soma_scene_graph_arm.png";
  SceneGraph g = figureGraph(png, R"(, "draw": ["arm"])");
  const SceneResult r = g.evaluate({"picture"});
  CHECK(ids(r) == std::vector<std::string>{"robot:arm[double]", "pose:goal[double]", "ik:postures", "tessellation:arm",
                                           "figure:picture"});
  CHECK(r.trace[2].reason == "output picture via figure:picture via tessellation:arm");
  // Postures alone build no tessellation.
  SceneGraph h = figureGraph(png, "");
  CHECK_FALSE(h.evaluate({"postures"}).built("tessellation:arm"));
  std::filesystem::remove(png);
}

TEST_CASE("scene graph: a failing evaluation leaves no figure behind", "[scene][figure]") {
  const auto png = std::filesystem::temp_directory_path() / "soma_scene_graph_broken.png";
  std::filesystem::remove(png);
  SceneGraph g = figureGraph(png, R"(, "draw": ["a"])");
  // "picture" is drawn first, then "broken" fails (two parallel screws span no cylindroid):
  // nothing is written.
  CHECK_THROWS_WITH(g.evaluate({"picture", "broken"}), Contains("outputs.broken.screws: Cylindroid: the screws' directions are parallel"));
  CHECK_FALSE(std::filesystem::exists(png));
  for (const auto& f : std::filesystem::directory_iterator(png.parent_path()))
    CHECK(f.path().string().find("soma_scene_graph_broken.png.") == std::string::npos);  // no partial file left
  // Asked again alone, the figure is drawn (its node was not kept).
  CHECK(g.evaluate({"picture"}).written.size() == 1);
  CHECK(std::filesystem::exists(png));
  std::filesystem::remove(png);
}

TEST_CASE("scene graph: a report builds the outputs it shows, and writes its page at the end", "[scene][trace]") {
  const auto html = std::filesystem::temp_directory_path() / "soma_scene_graph_report.html";
  std::filesystem::remove(html);
  const std::string text = R"({"entities": {"a": {"kind": "screw", "point": [0, 0, 0], "direction": [1, 0, 0], "pitch": 0.2},
                                            "b": {"kind": "screw", "point": [0, 0, 1], "direction": [0, 1, 0], "pitch": -0.1}},
                               "outputs": {"pencil": {"kind": "cylindroid", "screws": ["a", "b"]},
                                           "span": {"kind": "screw-system", "screws": ["a", "b"]},
                                           "page": {"kind": "report", "html": ")" + html.string() + R"(", "outputs": ["pencil"]}}})";
  io::SceneFile s = io::parseScene(text, "report.json");
  io::validateScene(s);
  SceneGraph g(std::move(s));
  const SceneResult r = g.evaluate({"page"});
  CHECK(ids(r) == std::vector<std::string>{"screw:a[double]", "screw:b[double]", "cylindroid:pencil", "report:page"});
  CHECK(r.trace[2].reason == "output page via report:page");
  REQUIRE(r.written == std::vector<std::filesystem::path>{html});
  std::ifstream in(html);
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(page, Contains("<h2 id=\"pencil\">pencil (cylindroid)</h2>"));
  CHECK_THAT(page, !Contains("span"));
  std::filesystem::remove(html);
}

TEST_CASE("scene graph: an output that is not in the scene", "[scene]") {
  SceneGraph g = graph();
  CHECK_THROWS_AS(g.evaluate({"nope"}), InvalidInput);
  CHECK_THROWS_WITH(g.evaluate({"nope"}), Contains("has no output named \"nope\""));
}

TEST_CASE("scene graph: Cl(0,6,2) momenta are built only when a dynamics output asks for that form", "[scene][trace]") {
  const char* text = R"({
    "entities": {
      "arm": {"kind": "robot", "file": "studies/robots/puma560_dynamics.json"},
      "box": {"kind": "rigid-body", "mass": 2, "com": [0, 0, 0.1], "inertia": [0.01, 0.01, 0.01, 0, 0, 0]}
    },
    "outputs": {
      "torques": {"kind": "dynamics", "robot": "arm", "from": [0, 0, 0, 0, 0, 0], "to": [60, -30, 45, 0, 30, 0], "steps": 4},
      "loaded": {"kind": "dynamics", "robot": "arm", "from": [0, 0, 0, 0, 0, 0], "to": [60, -30, 45, 0, 30, 0], "steps": 4,
                 "payload": "box", "form": "cl062"}
    }
  })";
  io::SceneFile s = io::parseScene(text, "scene.json", soma::test::repoFile(""));
  io::validateScene(s);
  SceneGraph g(std::move(s));
  const SceneResult plain = g.evaluate({"torques"});
  CHECK(ids(plain) == std::vector<std::string>{"robot:arm[double]", "dynamics-model:arm[g=9.81][double]", "dynamics:torques"});
  for (const TraceEntry& t : plain.trace) CHECK(t.id.find("cl062") == std::string::npos);
  CHECK(plain.ok());
  const SceneResult loaded = g.evaluate({"loaded"});
  // The robot is not read again; the payload model and the momenta are new nodes.
  CHECK(ids(loaded) == std::vector<std::string>{"rigid-body:box[double]", "dynamics-model:arm+box[g=9.81][double]",
                                                "momenta-cl062:loaded[double]", "dynamics:loaded"});
  CHECK(loaded.ok());
  const std::string& j = loaded.output("loaded")->json;
  CHECK(j.find("\"momenta_cl062\"") != std::string::npos);
  CHECK(plain.output("torques")->json.find("momenta_cl062") == std::string::npos);
}

}  // namespace SOMA_UNITY_ID
