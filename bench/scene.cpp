// Lazy scenes (DESIGN §5, issue 19): one scene of six outputs — the KUKA-type arm's postures in
// double and float128, its tool pose, a cylindroid, the irregular Stewart platform's 40-solution
// homotopy and the same platform by Ceres — evaluated for one output (`postures`, the double IK)
// and for all of them. Each iteration builds a fresh SceneGraph from the parsed scene (the parse
// and validation are outside the timed loop), so every node is built again. The ratio of the two
// times is what asking for one output saves; papers/benchmarks/scenes.md records it.
#include "soma/io/scene_file.hpp"
#include "soma/scene/scene_graph.hpp"

#include <benchmark/benchmark.h>

#include <string>

namespace {
using namespace soma;

const io::SceneFile& sceneFile() {
  static const io::SceneFile s = [] {
    const std::string text = R"({
      "entities": {
        "kr6": {"kind": "robot", "angles": "degrees", "convention": "dh",
                "joints": [{"a": 0.025, "alpha": -90, "d": 0.400, "theta": 0}, {"a": 0.455, "alpha": 0, "d": 0, "theta": 0},
                           {"a": 0.035, "alpha": -90, "d": 0, "theta": 0}, {"a": 0, "alpha": 90, "d": 0.420, "theta": 0},
                           {"a": 0, "alpha": -90, "d": 0, "theta": 0}, {"a": 0, "alpha": 0, "d": 0.080, "theta": 0}]},
        "goal": {"kind": "pose",
                 "rotation": [[0.6623722251999932, 0.48179774367913564, -0.5737019866353118],
                              [0.5811410268744133, -0.8137084629273265, -0.01239533153248388],
                              [-0.47279820448787874, -0.3251914383038731, -0.8189703207607077]],
                 "translation": [0.4061114331387771, 0.19011411822259439, 0.2229268859167985]},
        "hexapod": {"kind": "platform",
          "base": [[1.0, 0.0, 0.0], [0.766044, 0.642788, 0.0], [-0.5, 0.866025, 0.0], [-0.965926, 0.258819, 0.0], [-0.5, -0.866025, 0.0], [0.34202, -0.939693, 0.0]],
          "platform": [[0.469846, 0.17101, -0.02], [-0.043578, 0.498097, 0.0], [-0.383022, 0.321394, 0.02], [-0.409576, -0.286788, -0.02], [-0.086824, -0.492404, 0.0], [0.433013, -0.25, 0.02]],
          "leg_lengths": [1.0404936810969392, 1.2919553625940272, 1.1816058501919338, 1.3033617492694927, 1.1035988565430412, 1.1787259157636987]},
        "a": {"kind": "screw", "point": [0, 0, 0], "direction": [1, 0, 0], "pitch": 0.2},
        "b": {"kind": "screw", "point": [0, 0, 0.5], "direction": [1, 1, 0], "pitch": -0.1}
      },
      "outputs": {
        "postures": {"kind": "ik", "robot": "kr6", "pose": "goal"},
        "postures_float128": {"kind": "ik", "robot": "kr6", "pose": "goal", "scalar": "float128"},
        "tool": {"kind": "fk", "robot": "kr6", "joints": [20, -40, 30, 10, 50, -30]},
        "pencil": {"kind": "cylindroid", "screws": ["a", "b"]},
        "legs": {"kind": "stewart", "platform": "hexapod"},
        "legs_ceres": {"kind": "stewart", "platform": "hexapod", "method": "ceres"}
      }
    })";
    io::SceneFile f = io::parseScene(text, "bench scene");
    io::validateScene(f);
    return f;
  }();
  return s;
}

void run(benchmark::State& state, const std::vector<std::string>& outputs) {
  // The homotopy's start system is solved once per process: do it before timing.
  { scene::SceneGraph warm(sceneFile()); (void)warm.evaluate(); }
  std::size_t nodes = 0;
  for (auto _ : state) {
    scene::SceneGraph g(sceneFile());
    const scene::SceneResult r = g.evaluate(outputs);
    nodes = r.trace.size();
    benchmark::DoNotOptimize(r.outputs.data());
  }
  state.counters["nodes"] = double(nodes);
}

void BM_SceneOneOutput(benchmark::State& state) { run(state, {"postures"}); }
void BM_SceneAllOutputs(benchmark::State& state) { run(state, {}); }
BENCHMARK(BM_SceneOneOutput)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SceneAllOutputs)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
