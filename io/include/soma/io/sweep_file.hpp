#pragma once
// Reading a sweep file (DESIGN §5, issue 26): a scene plus the parameters to vary, the quantities
// to record at each point and where the rows go.
//   {"description": "...",
//    "base": {"scene": SCENE.json} | {"robot": ROBOT.json, "pose": POSE.json} | {"platform": PLATFORM.json},
//    "parameters": [{"name": "a2", "key": "entities.arm.joints[1].a",
//                    "range": {"from": 0.2, "to": 4, "count": 40}}          (count equally spaced, ends included)
//                 | ... "values": [0.5, 1, 2]                              (the values listed)
//                 | ... "uniform": {"from": 0.2, "to": 4}],                (random: needs "samples")
//    "samples": {"count": 1000, "seed": 7},     (random sampling: every parameter "uniform")
//    "quantities": {NAME: {"output": OUTPUT, "field": FIELD}},
//    "rows": {"csv": "rows.csv", "jsonl": "rows.jsonl"}}                   (names inside --out)
// A grid is the Cartesian product of its parameters' values, the first parameter varying slowest;
// random samples draw each point's values from its own stream (splitmix64 of the seed and the point
// index), so that any process computes any point alone. A key is a key path into the base scene
// (a robot or platform base is the scene {"entities": {"robot", "pose"} | {"platform"}, "outputs":
// {"cuspidal", "workspace", "ik"} | {"stewart"}}); the value there must be a number. Entities the
// base scene gives by a JSON "file" are read into it (their keys are then reachable:
// "entities.arm.joints[1].a"). A quantity is a field of an output's JSON (io/scene_output.hpp):
// only the outputs quantities name are computed at each point.
// Every defect is an InvalidInput naming the file and key path (unknown keys, an empty range, a
// key not in the base scene or not a number there, a field the output kind does not have), found
// before any point runs; the first point's scene is parsed and validated too.
#include "soma/io/scene_file.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace soma::io {

struct SweepParameter {
  std::string name;            ///< its column
  std::string key;             ///< the key path in the base scene ("entities.arm.joints[1].a")
  std::string where;           ///< "sweep.json: parameters[0]", for messages
  std::vector<double> values;  ///< a grid parameter's values
  bool uniform = false;        ///< random: drawn uniformly in [from, to)
  double from = 0, to = 0;
};

struct SweepQuantity {
  std::string name;    ///< its column
  std::string output;  ///< the base scene's output computing it
  std::string field;   ///< the field of that output's JSON
  std::string where;   ///< "sweep.json: quantities.cusps"
};

struct SweepFile {
  std::string origin;                       ///< the file's name in messages
  std::string description;
  std::vector<SweepParameter> parameters;   ///< in the file's order
  std::vector<SweepQuantity> quantities;    ///< ordered by name
  std::vector<std::string> outputs;         ///< the outputs the quantities name, each once
  bool random = false;                      ///< "samples" given
  std::size_t samples = 0;
  std::uint64_t seed = 0;
  std::string csv = "rows.csv", jsonl = "rows.jsonl";  ///< file names inside --out
  std::string baseText;                     ///< the base scene (files read into it), JSON text read only by io
  std::string baseOrigin;                   ///< the base scene's name in messages
  std::filesystem::path baseFolder;         ///< relative paths of the base scene resolve here
  std::string fingerprint;                  ///< the sweep and its base as one canonical text (resume)
  /// The number of points: the grid's size or the samples.
  [[nodiscard]] std::size_t points() const;
  /// The parameter values of point i (i < points()).
  [[nodiscard]] std::vector<double> point(std::size_t i) const;
};

/// Sweep JSON text → the checked sweep. Relative paths resolve against `folder`.
SweepFile parseSweep(const std::string& text, const std::string& origin, const std::filesystem::path& folder = {});
/// Read, parse and check a sweep file (its first point's scene parsed and validated).
SweepFile readSweep(const std::filesystem::path& file);

/// The base scene with point i's values, parsed and validated (origin "<base> (sweep point i)").
SceneFile sweepPointScene(const SweepFile& sweep, std::size_t i);

/// One row: a point's parameters, its quantities (each the JSON text of its field: 4, true,
/// "1.25e-31"), the largest residual of the outputs computed, the status and the wall seconds.
struct SweepRow {
  std::size_t point = 0;
  std::vector<double> parameters;
  std::vector<std::string> values;  ///< empty when the point failed
  double residual = 0;
  std::string status = "ok";        ///< "ok", "check-failed" (an output's check), "error" (message says)
  std::string message;
  double seconds = 0;
};

/// The quantities and the largest residual from the outputs' JSON (one per name in sweep.outputs).
/// InvalidInput when an output's JSON lacks a field (not expected: the fields are checked on reading).
void sweepRowValues(const SweepFile& sweep, const std::vector<std::string>& outputJson, SweepRow& row);

/// The CSV header ("point,a2,a3,cusps,residual,status,message,seconds") and a row's line (with "\n").
std::string sweepCsvHeader(const SweepFile& sweep);
std::string sweepCsvLine(const SweepFile& sweep, const SweepRow& row);
/// A row as one JSON object on one line (with "\n"):
///   {"point":0,"parameters":{"a2":0.2},"values":{"cusps":4},"residual":1e-15,"status":"ok","seconds":0.01}
std::string sweepJsonLine(const SweepFile& sweep, const SweepRow& row);
/// The point of a complete JSON line written by sweepJsonLine; nullopt for anything else (a
/// partial line left by a kill).
std::optional<std::size_t> sweepJsonLinePoint(const std::string& line);
/// The rows of a sweep's JSON Lines file (as runSweep wrote them), in the file's order: parameters
/// in the sweep's order, each quantity as its JSON text. InvalidInput naming the file and line when a
/// line is not a complete row of `sweep` (a partial last line, another sweep's columns, a point
/// beyond the sweep's points).
std::vector<SweepRow> readSweepRows(const SweepFile& sweep, const std::filesystem::path& jsonl);

}  // namespace soma::io
