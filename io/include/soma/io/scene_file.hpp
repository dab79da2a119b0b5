#pragma once
// Reading a scene file (DESIGN §5, issue 19): a researcher's own problem in one JSON file,
//   {"entities": {NAME: {"kind": ..., ...}}, "outputs": {NAME: {"kind": ..., ...}}}
// (the rules are also the JSON Schema io/schema/scene.schema.json). Entity kinds:
//   robot     {"file": ROBOT.json|ROBOT.urdf, "tip"} or inline, exactly a robot file's body;
//   pose      {"file": POSE.json} or inline, a pose file's body;
//   platform  {"file": PLATFORM.json} or inline, a platform file's body;
//   point     {"at": [x, y, z]};
//   line      {"point": [x, y, z], "direction": [x, y, z]} or {"through": [[x,y,z], [x,y,z]]};
//   screw     {"coordinates": [ω; v]} or {"point", "direction", "pitch"} (moment v = q × ω + h ω);
//   planar-mechanism  {"file": SCENE.json} or inline, a planar scene file's body (positions or a
//             4-bar, as `soma planar` reads them; double);
//   linear-complex {"coordinates": [α; b]} or {"point", "direction", "pitch"}: the lines reciprocal
//             to that screw (GF §6.6);
//   regulus   {"lines": [L1, L2, L3]}: the regulus through three pairwise skew line entities (GF §6.5.1);
//   cylindroid {"screws": [A, B]}: the pencil of two screw entities (GF §6.5.2);
//   ruled-surface {"line": L, "screw": A, "range": [t0, t1]}: the line swept by the screw motion
//             exp(t A) (GF §9.4; range default [0, 2π]);
//   screw-system {"screws": [A, ...]}: the span of 1 to 6 screw entities (GF ch. 8);
//   rigid-body {"mass", "com": [x, y, z], "inertia": [Ixx, Iyy, Izz, Ixy, Iyz, Ixz]}: a body's
//             inertia about its centre of mass (kg, m, kg·m²; a payload of a dynamics output).
// Output kinds, each naming the entities it uses and, in "needs", the outputs it needs:
//   ik          {"robot", "pose", "method", "scalar", "bits"}   every posture at the pose;
//   fk          {"robot", "joints": [...], "scalar", "bits"}    the tool pose (joints in the robot's unit);
//   stewart     {"platform", "method", "scalar", "bits"}        every posture for the leg lengths;
//   cuspidal    {"robot", "witness": true|false}                 the 3R/6R cuspidality verdict (double),
//               its cusp points and a witness path (GF §5.2.3);
//   cylindroid  {"screws": [A, B] | "cylindroid": C, "scalar", "bits"}   pitches and principal screws;
//   burmester   {"mechanism"}                                 the Burmester pairs of 5 positions (GF §5.4, double);
//   screw-system {"screws": [A, ...] | "system": S, "scalar", "bits"}         the Gibson–Hunt type of their span,
//               its parameters and canonical frame (GF ch. 8), on 6-vectors;
//   workspace   {"robot", "samples", "grid"}                   the reachability and dexterity maps and, for a
//               3R arm, the singular boundary (analyseWorkspace, GF §5.2.3, double);
//   dynamics    {"robot", "from": [...], "to": [...], "duration", "steps", "gravity", "payload",
//               "form": "vector"|"cl062", "scalar", "bits"}   the joint torques (RNE, GF §13.3) along
//               the quintic rest-to-rest trajectory from → to (joints in the robot's unit), the robot
//               file's "links" inertias and a rigid-body payload on the last link; "cl062" also gives
//               the links' momenta as Cl(0,6,2) co-screws (SB §5), a node built only then;
//   figure      {"png": FILE, "draw": [ENTITY...], "size": [w, h]}   a PNG of the entities drawn
//               (every entity when "draw" is absent): robots at the postures of the ik/fk outputs
//               that use them, platforms at their stewart postures, lines, screws, points, and
//               the cylindroids of the cylindroid outputs whose screws are drawn;
//               {"svg": FILE, "draw": [MECHANISM...]} (or a "png" drawing only planar mechanisms) is
//               a 2-D figure: the positions or 4-bar pivots of each planar mechanism and the Burmester
//               pairs of the burmester outputs using it (every planar mechanism when "draw" is absent);
//   report      {"html": FILE, "outputs": [OUTPUT...]}           an HTML page of those outputs (every
//               other output when absent), their figures shown; "outputs" count as "needs".
// Relative "file" paths resolve against the scene file's folder. Everything is validated before
// anything is computed (validateScene): unknown kinds and keys, duplicate keys, missing or
// wrong-kind references, cycles between outputs, wrong types, a scene asking for nothing, and
// numbers that an output's scalar cannot hold. Each defect is an InvalidInput naming the file and
// the key path ("scene.json: outputs.solve.robot: no entity named "ur5"").
// A scene's JSON stays in io: the scene layer gets the typed entities through the accessors below.
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/se3.hpp"
#include "soma/geometry/dynamics/spatial_inertia.hpp"
#include "soma/geometry/lines/cylindroid.hpp"
#include "soma/geometry/lines/line.hpp"
#include "soma/geometry/lines/linear_complex.hpp"
#include "soma/geometry/lines/ruled_surface.hpp"
#include "soma/geometry/lines/three_line_regulus.hpp"
#include "soma/geometry/parallel/stewart.hpp"
#include "soma/io/planar_scene_file.hpp"
#include "soma/io/robot_file.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace soma::io {

enum class SceneEntityKind {
  Robot, Pose, Platform, Point, Line, Screw, PlanarMechanism,
  LinearComplex, Regulus, Cylindroid, RuledSurface, ScrewSystem, RigidBody
};
enum class SceneOutputKind { Ik, Fk, Stewart, Cuspidal, Cylindroid, ScrewSystem, Burmester, Workspace, Dynamics, Figure, Report };
std::string_view sceneEntityKindName(SceneEntityKind k);
std::string_view sceneOutputKindName(SceneOutputKind k);

/// One named entity. Its numbers are read in the scalar an output asks for (sceneRobot<S>, …).
struct SceneEntity {
  std::string name;
  SceneEntityKind kind = SceneEntityKind::Point;
  std::string where;                         ///< "scene.json: entities.arm", for messages
  std::string origin, path;                  ///< "scene.json" and "entities.arm"
  std::optional<std::filesystem::path> file; ///< a robot/pose/platform given by file (resolved)
  std::string tip;                           ///< URDF only: the chain's tip link
  std::string body;                          ///< the inline definition (JSON text, read only by io)
  /// regulus: its three lines; cylindroid, screw-system: its screws; ruled-surface: {line, screw}.
  std::vector<std::string> uses;
};

/// One named output: what it computes, from which entities, in which scalar.
struct SceneOutput {
  std::string name;
  SceneOutputKind kind = SceneOutputKind::Ik;
  std::string where;                  ///< "scene.json: outputs.solve"
  std::string origin, path;           ///< "scene.json" and "outputs.solve"
  std::string robot, pose, platform, mechanism;  ///< entity names (those the kind uses)
  std::vector<std::string> screws;    ///< cylindroid: two screw entities; screw-system: 1 to 6
  std::string system;                 ///< cylindroid, screw-system: the entity named instead of screws (its screws)
  std::vector<std::string> needs;     ///< outputs evaluated before this one
  std::string method = "auto";        ///< ik, stewart
  ScalarKind scalar = ScalarKind::Double;
  int bits = 256;                     ///< mpfr precision
  std::string joints;                 ///< fk: the joint values (JSON text, read only by io)
  std::filesystem::path png;          ///< figure: the PNG to write (relative: to the working folder)
  std::filesystem::path svg;          ///< figure: the SVG to write instead (2-D figures: planar mechanisms)
  std::filesystem::path html;         ///< report: the HTML page to write (relative: to the working folder)
  std::vector<std::string> reported;  ///< report: the outputs shown (also in needs)
  std::vector<std::string> draw;      ///< figure: the entities drawn (empty: every entity)
  int width = 1200, height = 900;     ///< figure: the image size in pixels
  bool witness = true;                ///< cuspidal: plan a witness path when cuspidal
  bool complex = false;               ///< stewart: also every complex solution (as soma stewart --complex)
  int samples = 200000, grid = 120;   ///< workspace: postures sampled, cells per side of the maps
  std::string from, to;               ///< dynamics: the trajectory's end postures (JSON text, read only by io)
  double duration = 1, gravity = 9.81;  ///< dynamics: seconds from rest to rest, g along −z (m/s²)
  int steps = 20;                     ///< dynamics: intervals of the trajectory (steps + 1 samples)
  std::string payload;                ///< dynamics: a rigid-body entity on the last link (none when empty)
  bool cl062 = false;                 ///< dynamics: "form": "cl062" (the momenta in Cl(0,6,2) too)
};

struct SceneFile {
  std::string origin;  ///< the file's name in messages
  std::vector<SceneEntity> entities;  ///< in the file's order
  std::vector<SceneOutput> outputs;   ///< in the file's order
  [[nodiscard]] const SceneEntity* entity(std::string_view name) const;
  [[nodiscard]] const SceneOutput* output(std::string_view name) const;
};

/// Scene JSON text → the checked scene (structure, kinds, keys, references, cycles; files are not
/// opened). A pure function of the text; relative "file" paths are resolved against `folder`.
SceneFile parseScene(const std::string& text, const std::string& origin, const std::filesystem::path& folder = {});
/// Read, parse and validate a scene file (validateScene included).
SceneFile readScene(const std::filesystem::path& file);
/// Reads every entity an output uses in that output's scalar (the files, the numbers): a number
/// the scalar cannot hold, a missing file or a bad body fails here, before anything is computed.
void validateScene(const SceneFile& scene);

/// The typed entities, in S. Throw InvalidInput (with the entity's key path) on bad content.
template <class S> RobotFile<S> sceneRobot(const SceneEntity& e);
template <class S> SE3<S> scenePose(const SceneEntity& e);
template <class S> StewartPlatform<S> scenePlatform(const SceneEntity& e);
template <class S> Vec3<S> scenePoint(const SceneEntity& e);
template <class S> PluckerLine<S> sceneLine(const SceneEntity& e);
template <class S> Vec6<S> sceneScrew(const SceneEntity& e);
template <class S> LinearComplex<S> sceneLinearComplex(const SceneEntity& e);
/// regulus, cylindroid, ruled-surface, screw-system: built from the entities they name in `scene`.
template <class S> ThreeLineRegulus<S> sceneRegulus(const SceneFile& scene, const SceneEntity& e);
template <class S> Cylindroid<S> sceneCylindroid(const SceneFile& scene, const SceneEntity& e);
/// The ruled surface and its parameter range [t0, t1].
template <class S> struct SceneRuledSurface {
  RuledSurface<S> surface;
  S t0, t1;
};
template <class S> SceneRuledSurface<S> sceneRuledSurface(const SceneFile& scene, const SceneEntity& e);
/// The generators as the columns of a 6 × n matrix.
template <class S> Eigen::Matrix<S, 6, Eigen::Dynamic> sceneScrewSystem(const SceneFile& scene, const SceneEntity& e);
template <class S> SpatialInertia<S> sceneRigidBody(const SceneEntity& e);
/// dynamics: the output's "from" and "to" in S (radians/metres; the robot's angle unit applied).
template <class S> std::pair<JointVector<S>, JointVector<S>> sceneTrajectoryEnds(const SceneOutput& o, const RobotFile<S>& robot);
/// A planar-mechanism entity (double, as the planar scene reader reads it).
PlanarScene scenePlanarMechanism(const SceneEntity& e);
/// fk: the output's "joints" in S (radians/metres; the robot's angle unit applied).
template <class S> JointVector<S> sceneJoints(const SceneOutput& o, const RobotFile<S>& robot);

#define SOMA_SCENE_FILE_EXTERN(S)                                                       \
  extern template RobotFile<S> sceneRobot<S>(const SceneEntity&);                       \
  extern template SE3<S> scenePose<S>(const SceneEntity&);                              \
  extern template StewartPlatform<S> scenePlatform<S>(const SceneEntity&);              \
  extern template Vec3<S> scenePoint<S>(const SceneEntity&);                            \
  extern template PluckerLine<S> sceneLine<S>(const SceneEntity&);                      \
  extern template Vec6<S> sceneScrew<S>(const SceneEntity&);                            \
  extern template JointVector<S> sceneJoints<S>(const SceneOutput&, const RobotFile<S>&);               \
  extern template LinearComplex<S> sceneLinearComplex<S>(const SceneEntity&);                           \
  extern template ThreeLineRegulus<S> sceneRegulus<S>(const SceneFile&, const SceneEntity&);            \
  extern template Cylindroid<S> sceneCylindroid<S>(const SceneFile&, const SceneEntity&);               \
  extern template SceneRuledSurface<S> sceneRuledSurface<S>(const SceneFile&, const SceneEntity&);      \
  extern template Eigen::Matrix<S, 6, Eigen::Dynamic> sceneScrewSystem<S>(const SceneFile&, const SceneEntity&); \
  extern template SpatialInertia<S> sceneRigidBody<S>(const SceneEntity&);                              \
  extern template std::pair<JointVector<S>, JointVector<S>> sceneTrajectoryEnds<S>(const SceneOutput&, const RobotFile<S>&);
SOMA_FOR_EACH_SCALAR(SOMA_SCENE_FILE_EXTERN)
#undef SOMA_SCENE_FILE_EXTERN

}  // namespace soma::io
