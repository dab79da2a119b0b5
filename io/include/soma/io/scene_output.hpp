#pragma once
// The JSON of a scene's outputs (`soma scene --json`, docs/cli.md): one object per output with the
// fields every numeric output has, as the CLI's commands print them —
//   "output" (its name), "kind", "method", "scalar", "seconds", "residual" (the largest residual
//   of what it computed), "ok" (every residual within √ε of the scalar)
// and the kind's own fields (ik: "count", "expected_count", "certified", "solutions"; fk: "pose";
// stewart: "count", "expected_count", "certified", "solutions"; cylindroid: "pitches",
// "principal_screws", "centre", "frame"; screw-system: "type", "type_name", "dimension", "via_reciprocal", "parameters", "frame",
// "nearest_other_type", "boundary_distance"; figure: "png", "width", "height", "drawn"). Angles are radians unless the robot's file says degrees.
#include "soma/geometry/lines/cylindroid.hpp"
#include "soma/geometry/parallel/solve_stewart.hpp"
#include "soma/geometry/screws/identification.hpp"
#include "soma/geometry/serial/ik.hpp"
#include "soma/io/scene_file.hpp"

#include <array>
#include <string>
#include <vector>

namespace soma::io {

template <class S>
std::string ikOutputJson(const SceneOutput& o, const RobotFile<S>& robot, const IkSolution<S>& sol, bool ok);
template <class S>
std::string fkOutputJson(const SceneOutput& o, const RobotFile<S>& robot, const JointVector<S>& q, const SE3<S>& pose,
                         double seconds);
/// complex_solutions too when o.complex (the homotopy's).
template <class S>
std::string stewartOutputJson(const SceneOutput& o, const StewartPlatform<S>& P, const StewartSolution<S>& sol, bool ok);
template <class S>
std::string cylindroidOutputJson(const SceneOutput& o, const Cylindroid<S>& c, const S& residual, double seconds, bool ok);

template <class S>
std::string screwSystemOutputJson(const SceneOutput& o, const ScrewSystemIdentification<S>& id, double seconds, bool ok);
/// cuspidal (GF §5.2.3): what analyseCuspidality found, as plain values (io does not link the
/// cuspidal library). Fields "cuspidal", "six_r", "cusp_count", "aspect_count" and "witness":
/// {"found", "certified", "target", "start", "goal" (radians), "points", "note"}.
struct CuspidalRecord {
  std::string method;
  bool cuspidal = false, sixR = false;
  int cuspCount = 0, aspectCount = 0;
  bool witnessFound = false, witnessCertified = false;
  std::vector<double> witnessTarget, witnessStart, witnessGoal;
  int witnessPoints = 0;
  std::string witnessNote;
  double seconds = 0, residual = 0;
};
std::string cuspidalOutputJson(const SceneOutput& o, const CuspidalRecord& c);
/// burmester (GF §5.4): the real Burmester pairs of 5 positions: "expected_count" 4, "count",
/// "complex_count", "pairs": [{"centre", "circle_point" (moving frame), "radius", "residual"}].
struct BurmesterPairRecord {
  std::array<double, 2> centre{}, circle{};
  double radius = 0, residual = 0;
};
std::string burmesterOutputJson(const SceneOutput& o, const std::vector<BurmesterPairRecord>& pairs, int complexPairs,
                                double residual, double seconds, bool ok);
/// workspace (GF §5.2.3): the maps of analyseWorkspace as plain values (io does not link the
/// cuspidal library): "samples", "grid", "rho_max", "z_min", "z_max", "reached_cells",
/// "reached_fraction", "mean_dexterity", "boundary_curves", "boundary_points".
struct WorkspaceRecord {
  int samples = 0, grid = 0, reachedCells = 0, boundaryCurves = 0, boundaryPoints = 0;
  double rhoMax = 0, zMin = 0, zMax = 0, reachedFraction = 0, meanDexterity = 0, seconds = 0;
};
std::string workspaceOutputJson(const SceneOutput& o, const WorkspaceRecord& w);
/// dynamics (GF §13.3): "times" (s), "joints" (each sample's θ, the robot's unit), "torques"
/// (N·m or N, per sample), "max_abs_torque" (per joint), "payload", "gravity"; "residual" is the
/// largest |τ_RNE − τ_closed-form| relative to max(1, |τ|) (two methods, GF §13.2.2 and §13.3);
/// with "form": "cl062" also "momenta_cl062": each link's momentum at the middle sample as a
/// Cl(0,6,2) co-screw (l, p) and "momenta_cl062_residual" (against N q̇ in 6-vector form).
struct DynamicsRecord {
  std::string scalar;
  int bits = 0;
  std::vector<double> times;
  std::vector<std::vector<double>> joints, torques, momenta;
  std::vector<double> maxAbsTorque;
  double residual = 0, momentaResidual = 0, seconds = 0;
};
std::string dynamicsOutputJson(const SceneOutput& o, const DynamicsRecord& d, bool ok);
/// report: "html", "outputs" (the outputs shown).
std::string reportOutputJson(const SceneOutput& o, double seconds);
/// The report's HTML page: a table of the outputs (name, kind, method, scalar, residual, seconds,
/// ok) and a section per output with its JSON (`outputJson`, in the report's order) and, for a
/// figure, its PNG (linked relative to the page's folder).
std::string sceneReportHtml(const SceneFile& s, const SceneOutput& report, const std::vector<std::string>& outputJson);
/// figure: "png" (or "svg"), "width", "height", "drawn" (the entities drawn), "seconds" (the render).
std::string figureOutputJson(const SceneOutput& o, const std::vector<std::string>& drawn, double seconds);

#define SOMA_SCENE_OUTPUT_EXTERN(S)                                                                          \
  extern template std::string ikOutputJson<S>(const SceneOutput&, const RobotFile<S>&, const IkSolution<S>&, bool); \
  extern template std::string fkOutputJson<S>(const SceneOutput&, const RobotFile<S>&, const JointVector<S>&,    \
                                              const SE3<S>&, double);                                         \
  extern template std::string stewartOutputJson<S>(const SceneOutput&, const StewartPlatform<S>&,                \
                                                  const StewartSolution<S>&, bool);                            \
  extern template std::string cylindroidOutputJson<S>(const SceneOutput&, const Cylindroid<S>&, const S&, double, bool); \
  extern template std::string screwSystemOutputJson<S>(const SceneOutput&, const ScrewSystemIdentification<S>&, double, bool);
SOMA_FOR_EACH_SCALAR(SOMA_SCENE_OUTPUT_EXTERN)
#undef SOMA_SCENE_OUTPUT_EXTERN

}  // namespace soma::io
