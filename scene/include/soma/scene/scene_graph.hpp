#pragma once
// A scene as a graph of computations (DESIGN §5, issue 19): each node — an entity read in a scalar
// (`robot:arm[double]`), an output's computation (`ik:solve`) — is built once, on demand, for the
// outputs asked, and the trace says what was built, how long it took and why:
//   SceneGraph graph(io::readScene("scene.json"));
//   SceneResult r = graph.evaluate({"solve"});   // {} asks for every output
// Outputs call the library's entry points (solveIk, SerialRobot::fk, solveStewart, Cylindroid):
// no solver logic here, only wiring. Nothing an asked output does not need is built.
#include "soma/io/scene_file.hpp"

#include <any>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace soma::scene {

/// One node built: its id (`robot:arm[double]`, `pose:goal[double]`, `ik:solve`), the wall-clock
/// seconds of its build (including the nodes it needed that were built for it), and the reason:
/// the output that asked for it and the nodes through which ("output solve via ik:solve").
struct TraceEntry {
  std::string id;
  double seconds = 0;
  std::string reason;
};

/// One output's answer: its JSON (io/scene_output.hpp) and whether its checks passed (every
/// residual within √ε of its scalar).
struct OutputResult {
  std::string name;
  std::string json;
  bool ok = true;
  /// ik, fk: the postures (radians, metres) in double, for figures; stewart: the platform's poses.
  std::vector<std::vector<double>> joints;
  std::vector<SE3<double>> poses;
  /// cuspidal: the witness path's joint states (radians), drawn as the tool's trace.
  std::vector<std::vector<double>> path;
  /// burmester: each real pair's centre (fixed frame), circle point (moving frame) and radius,
  /// drawn by 2-D figures.
  struct Pair2d {
    double cx = 0, cy = 0, px = 0, py = 0, radius = 0;
  };
  std::vector<Pair2d> pairs;
};

struct SceneResult {
  std::vector<OutputResult> outputs;  ///< the asked outputs, in the scene's order
  std::vector<TraceEntry> trace;      ///< the nodes built by this evaluation, each when it was done
  std::vector<std::filesystem::path> written;  ///< the figures and reports written (each renamed into place at the end)
  [[nodiscard]] bool ok() const;
  [[nodiscard]] const OutputResult* output(std::string_view name) const;
  /// Whether a node with this id was built (trace tests).
  [[nodiscard]] bool built(std::string_view id) const;
};

class SceneGraph {
 public:
  /// A scene that parseScene/readScene checked (validateScene: readScene does it).
  explicit SceneGraph(io::SceneFile scene);
  /// Builds what `outputs` need (every output when empty), each node once across evaluations.
  /// InvalidInput for a name that is not an output of the scene.
  /// A figure is written to "<png>.<pid>.partial" and renamed to its name only when every asked output
  /// succeeded: a failing evaluation leaves no figure behind.
  SceneResult evaluate(const std::vector<std::string>& outputs = {});
  /// `soma render`: every entity drawn (as a figure output drawing all of them would), to `png`.
  SceneResult render(const std::filesystem::path& png, int width, int height);
  [[nodiscard]] const io::SceneFile& scene() const { return scene_; }

 private:
  struct Node;
  template <class T, class F> const T& node(const std::string& id, const std::string& reason, F&& build);
  template <class S> const io::RobotFile<S>& robot(const std::string& name, const std::string& reason);
  template <class S> const SE3<S>& pose(const std::string& name, const std::string& reason);
  template <class S> const StewartPlatform<S>& platform(const std::string& name, const std::string& reason);
  template <class S> const Vec6<S>& screw(const std::string& name, const std::string& reason);
  const OutputResult& output(const io::SceneOutput& o, const std::string& reason);
  template <class S> OutputResult compute(const io::SceneOutput& o, const std::string& via);
  OutputResult figure(const io::SceneOutput& o, const std::string& reason);
  /// A figure drawing only planar mechanisms (or asking for SVG): the 2-D plot of them.
  OutputResult figure2d(const io::SceneOutput& o, const std::string& reason);
  OutputResult report(const io::SceneOutput& o, const std::string& reason);
  SceneResult run(const std::vector<const io::SceneOutput*>& outputs);

  io::SceneFile scene_;
  std::map<std::string, std::any> nodes_;
  std::vector<TraceEntry>* trace_ = nullptr;
  struct Pending {
    std::string node;
    std::filesystem::path partial, final;
  };
  std::vector<Pending> pending_;  ///< figures written under their partial names in this evaluation
};

/// The id of an output's node: "<kind>:<name>" (`ik:solve`).
std::string outputNodeId(const io::SceneOutput& o);

}  // namespace soma::scene
