// The scene reader (io/scene_file.hpp): every class of bad input rejected before anything is
// computed, with the file and the key path; entities read in the scalar their outputs ask for.
#include "soma/io/scene_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/pose_file.hpp"
#include "soma/io/robot_file.hpp"

#include "support/repo_file.hpp"
#include "support/scalars.hpp"

#include <catch2/catch.hpp>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using namespace soma::io;
using Catch::Contains;
using soma::test::repoFile;

namespace {
// Every rejected scene file of tests/io/scenes (also rejected by the JSON Schema: tests/io/scene_schema.py).
struct BadFile {
  const char* file;
  const char* message;
};
const BadFile kBadFiles[] = {
    {"bad_entity_kind.json", "entities.arm.kind: unknown entity kind \"robto\" (one of robot, pose, platform, point, line, screw, planar-mechanism, linear-complex, regulus, cylindroid, ruled-surface, screw-system, rigid-body)"},
    {"bad_output_kind.json", "outputs.solve.kind: unknown output kind \"inverse\" (one of ik, fk, stewart, cuspidal, cylindroid, screw-system, burmester, workspace, dynamics, figure, report)"},
    {"bad_unknown_key.json", "outputs.solve: unknown field \"metod\" (an ik output has robot, pose, method, scalar, bits, needs)"},
    {"bad_wrong_type.json", "outputs.solve.scalar: expected a string"},
    {"bad_nothing.json", "outputs: the scene asks for nothing (give at least one output)"},
    {"bad_missing_field.json", "outputs.solve: missing \"pose\" (the name of an entity)"},
    {"bad_screw_count.json", "outputs.c.screws: expected the names of two screw entities"},
    {"bad_entity_key.json", "entities.p: unknown field \"xyz\" (a point has \"at\": [x, y, z])"},
    {"bad_top_key.json", ": unknown field \"output\" (a scene has entities, outputs, description)"},
    {"bad_scalar_name.json", "outputs.solve.scalar: \"quad\" is not one of"},
    {"bad_bits.json", "outputs.solve.bits: \"3\" is outside 16 … 8192"},
    {"bad_regulus_lines.json", "entities.r.lines: expected the names of three line entities"},
    {"bad_rigid_body_key.json", "entities.b: unknown field \"masss\" (a rigid body has mass, com, inertia)"},
    {"bad_ruled_surface_missing.json", "entities.rs: missing \"screw\" (the name of an entity)"},
    {"bad_complex_key.json", "entities.c: unknown field \"pitchh\" (a linear complex has"},
    {"bad_cylindroid_entity.json", "entities.c.screws: expected the names of two screw entities"},
    {"bad_screw_system_entity.json", "entities.s.screws: expected the names of 1 to 6 screw entities"},
    {"bad_workspace_key.json", "outputs.w: unknown field \"sample\" (a workspace output has robot, samples, grid, needs; it works in double)"},
    {"bad_workspace_grid.json", "outputs.w.grid: expected an integer in [8, 2000]"},
    {"bad_dynamics_form.json", "outputs.d.form: \"clifford\" is not one of vector, cl062"},
    {"bad_dynamics_missing.json", "outputs.d: missing \"to\" (the joint values)"},
    {"bad_dynamics_steps.json", "outputs.d.steps: expected an integer in [1, 100000]"},
    {"bad_dynamics_gravity.json", "outputs.d.gravity: "},
    {"bad_figure_png_svg.json", "outputs.f: give \"png\" or \"svg\", not both"},
    {"bad_stewart_complex.json", "outputs.s.complex: expected true or false"},
};

const std::string kRobots = R"("arm": {"kind": "robot", "file": "studies/robots/puma560.json"},
                              "goal": {"kind": "pose", "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "translation": [0.5, 0, 0.3]})";
SceneFile scene(const std::string& outputs, const std::string& entities = kRobots) {
  return parseScene("{\"entities\": {" + entities + "}, \"outputs\": {" + outputs + "}}", "scene.json", soma::test::repoFile(""));
}
}  // namespace

TEST_CASE("scene file: every bad file is rejected with its key path", "[io][scene]") {
  for (const BadFile& b : kBadFiles) {
    INFO(b.file);
    const auto path = repoFile(std::string("tests/io/scenes/") + b.file);
    CHECK_THROWS_AS(readScene(path), InvalidInput);
    CHECK_THROWS_WITH(readScene(path), Contains(path.string() + ": " + std::string(b.message).substr(b.message[0] == ':' ? 2 : 0)) ||
                                           Contains(path.string() + b.message));
  }
}

TEST_CASE("scene file: references, kinds and cycles are checked before anything is computed", "[io][scene]") {
  CHECK_THROWS_WITH(scene(R"("solve": {"kind": "ik", "robot": "ur5", "pose": "goal"})"),
                    "scene.json: outputs.solve.robot: no entity named \"ur5\"");
  CHECK_THROWS_WITH(scene(R"("solve": {"kind": "ik", "robot": "arm", "pose": "arm"})"),
                    "scene.json: outputs.solve.pose: \"arm\" is a robot, expected a pose");
  CHECK_THROWS_WITH(scene(R"("a": {"kind": "fk", "robot": "arm", "joints": [0, 0, 0, 0, 0, 0], "needs": ["b"]},
                             "b": {"kind": "ik", "robot": "arm", "pose": "goal", "needs": ["a"]})"),
                    "scene.json: outputs.b.needs: a cycle between outputs: a → b → a");
  CHECK_THROWS_WITH(scene(R"("a": {"kind": "fk", "robot": "arm", "joints": [0, 0, 0, 0, 0, 0], "needs": ["a"]})"),
                    "scene.json: outputs.a.needs: a cycle between outputs: a → a");
  CHECK_THROWS_WITH(scene(R"("a": {"kind": "fk", "robot": "arm", "joints": [0], "needs": ["zz"]})"),
                    "scene.json: outputs.a.needs[0]: no output named \"zz\"");
  CHECK_THROWS_WITH(scene(R"("c": {"kind": "cylindroid", "screws": ["arm", "goal"]})"),
                    "scene.json: outputs.c.screws[0]: \"arm\" is a robot, expected a screw");
  CHECK_THROWS_WITH(scene(R"("s": {"kind": "stewart", "platform": "p", "method": "ceres", "complex": true})",
                          R"("p": {"kind": "platform", "file": "studies/platforms/general.json"})"),
                    "scene.json: outputs.s.complex: only the homotopy finds the complex solutions (method \"ceres\")");
  // nlohmann would keep the second "arm": a scene rejects the repeat (and a repeated output name).
  CHECK_THROWS_WITH(scene(R"("solve": {"kind": "ik", "robot": "arm", "pose": "goal"})",
                          kRobots + R"(, "arm": {"kind": "point", "at": [0, 0, 0]})"),
                    "scene.json: entities.arm: the key \"arm\" is given twice in one object");
  CHECK_THROWS_WITH(scene(R"("s": {"kind": "ik", "robot": "arm", "pose": "goal"}, "s": {"kind": "ik", "robot": "arm", "pose": "goal"})"),
                    "scene.json: outputs.s: the key \"s\" is given twice in one object");
  CHECK_THROWS_WITH(scene(R"("s": {"kind": "ik", "robot": "arm", "pose": "goal", "kind": "fk"})"),
                    "scene.json: outputs.s.kind: the key \"kind\" is given twice in one object");
  CHECK_THROWS_WITH(scene(R"("solve": {"kind": "ik", "robot": "arm", "pose": "goal", "method": "simplex"})"),
                    Contains("scene.json: outputs.solve.method: \"simplex\" is not one of auto"));
  CHECK_THROWS_WITH(scene(R"("f": {"kind": "figure", "png": "x.png", "draw": ["nobody"]})"),
                    "scene.json: outputs.f.draw[0]: no entity named \"nobody\"");
  CHECK_THROWS_WITH(scene(R"("f": {"kind": "figure", "svg": "x.svg", "draw": ["goal"]})"),
                    "scene.json: outputs.f.draw[0]: an SVG figure is 2-D: \"goal\" is a pose, not a planar-mechanism");
  CHECK_THROWS_WITH(scene(R"("f": {"kind": "figure", "svg": "x.svg"})"),
                    "scene.json: outputs.f.svg: an SVG figure is 2-D and the scene has no planar-mechanism to draw");
  CHECK_THROWS_WITH(scene(R"("f": {"kind": "figure"})"),
                    "scene.json: outputs.f: missing \"png\" (the PNG file to write) or \"svg\"");
  CHECK_THROWS_WITH(scene(R"("f": {"kind": "figure", "png": "x.png", "size": [10, 10]})"),
                    "scene.json: outputs.f.size: expected [width, height], integers in [16, 8192]");
  CHECK_THROWS_WITH(scene(R"("b": {"kind": "burmester", "mechanism": "m"})",
                          R"("m": {"kind": "planar-mechanism", "positions": [{"x": 0, "y": 0, "angle": 0}], "angel": 1})"),
                    "scene.json: entities.m: unknown field \"angel\" (a planar mechanism is a planar scene file's body: positions or fourbar)");
  const SceneFile three = scene(R"("b": {"kind": "burmester", "mechanism": "m"})",
                                R"("m": {"kind": "planar-mechanism", "positions": [{"x": 0, "y": 0, "angle": 0},
                                   {"x": 1, "y": 0, "angle": 0.1}, {"x": 2, "y": 0.5, "angle": 0.3}]})");
  CHECK_THROWS_WITH(validateScene(three), "scene.json: outputs.b.mechanism: a burmester output needs 5 positions, \"m\" has 3");
  // A report needs what it shows: naming itself is a cycle; naming a missing output an error.
  CHECK_THROWS_WITH(scene(R"("r": {"kind": "report", "html": "r.html", "outputs": ["r"]})"),
                    "scene.json: outputs.r.needs: a cycle between outputs: r → r");
  CHECK_THROWS_WITH(scene(R"("r": {"kind": "report", "html": "r.html", "outputs": ["zz"]})"),
                    "scene.json: outputs.r.outputs[0]: no output named \"zz\"");
  CHECK(scene(R"("a": {"kind": "fk", "robot": "arm", "joints": [0, 0, 0, 0, 0, 0]}, "r": {"kind": "report", "html": "r.html"})")
            .output("r")->needs == std::vector<std::string>{"a"});
  CHECK_THROWS_WITH(parseScene("[1, 2]", "scene.json"), "scene.json: a scene must be a JSON object");
  CHECK_THROWS_WITH(parseScene("{\"outputs\": ", "scene.json"), Contains("scene.json: not valid JSON"));
  CHECK_THROWS_WITH(scene(R"("solve": {"kind": "ik", "robot": "arm", "pose": "goal"})",
                          R"("arm": {"kind": "robot", "file": "x.json", "convention": "dh"}, "goal": {"kind": "pose", "file": "p.json"})"),
                    "scene.json: entities.arm: unknown field \"convention\" (a robot by file has file, tip)");
}

TEST_CASE("scene file: numbers are read in the scalar each output asks for", "[io][scene]") {
  const std::string screws = R"("a": {"kind": "screw", "point": [0, 0, 0], "direction": [1, 0, 0], "pitch": "1e-60"},
                                "b": {"kind": "screw", "coordinates": [0, 1, 0, 0, 0, "0.1"]})";
  // double holds 1e-60; float does not (it underflows to 0): validateScene says so, naming the key.
  const SceneFile ok = scene(R"("c": {"kind": "cylindroid", "screws": ["a", "b"]})", screws);
  CHECK_NOTHROW(validateScene(ok));
  const SceneFile bad = scene(R"("c": {"kind": "cylindroid", "screws": ["a", "b"], "scalar": "float"})", screws);
  CHECK_THROWS_WITH(validateScene(bad), Contains("scene.json: entities.a.pitch: \"1e-60\"") && Contains("float"));
  // Decimal strings exact in S: the screw's moment is mpfr's own 0.1.
  setMpfrBits(256);
  CHECK(sceneScrew<mpreal>(*ok.entity("b"))(5) == fromString<mpreal>("0.1"));
  CHECK(sceneScrew<double>(*ok.entity("a"))(3) == 1e-60);  // pitch h along u = x: v = h u
  // An inline robot body is a robot file's body, read by the robot reader (its messages too).
  const SceneFile inl = scene(R"("f": {"kind": "fk", "robot": "r", "joints": [0]})",
                              R"("r": {"kind": "robot", "convention": "dh", "joints": [{"a": 1, "alpha": 0, "d": 0, "theta": "0x1"}]})");
  CHECK_THROWS_WITH(validateScene(inl), "scene.json: entities.r: joints[0].theta: \"0x1\" is not a decimal number (hexadecimal)");
  const SceneFile wrongCount = scene(R"("f": {"kind": "fk", "robot": "arm", "joints": [0, 0]})");
  CHECK_THROWS_WITH(validateScene(wrongCount), "scene.json: outputs.f.joints: 2 values given, the robot has 6 joints");
  // A file entity resolves against the scene's folder; the same robot as the robot reader's.
  const SceneFile fk = scene(R"("f": {"kind": "fk", "robot": "arm", "joints": [90, 0, 0, 0, 0, 0]})");
  const RobotFile<double> rf = sceneRobot<double>(*fk.entity("arm"));
  const RobotFile<double> direct = readRobot<double>(repoFile("studies/robots/puma560.json"));
  CHECK(rf.robot.dof() == direct.robot.dof());
  CHECK(rf.degrees);
  CHECK(sceneJoints<double>(*fk.output("f"), rf)(0) == Approx(pi<double>() / 2).epsilon(1e-15));
  const SE3<double> goal = scenePose<double>(*fk.entity("goal"));
  CHECK(goal.translation()(0) == 0.5);
}

TEST_CASE("scene file: lines and points inline", "[io][scene]") {
  const SceneFile s = scene(R"("c": {"kind": "cylindroid", "screws": ["a", "a"]})",
                            R"("a": {"kind": "screw", "coordinates": [1, 0, 0, 0, 0, 0]},
                               "l": {"kind": "line", "through": [[0, 0, 1], [1, 0, 1]]},
                               "m": {"kind": "line", "point": [0, 0, 1], "direction": [0, 0, 0]},
                               "p": {"kind": "point", "at": [1, 2, "3.5"]})");
  const PluckerLine<double> l = sceneLine<double>(*s.entity("l"));
  // Through (0,0,1) and (1,0,1): direction x, moment q × ω = (0,0,1) × (1,0,0) = (0,1,0).
  CHECK(l.direction() == Vec3<double>(1, 0, 0));
  CHECK(l.moment() == Vec3<double>(0, 1, 0));
  CHECK_THROWS_WITH(sceneLine<double>(*s.entity("m")), "scene.json: entities.m: PluckerLine::pointDirection: direction d is zero");
  CHECK(scenePoint<double>(*s.entity("p"))(2) == 3.5);
}

TEST_CASE("scene file: line-geometry entities, rigid bodies, workspace and dynamics outputs", "[io][scene]") {
  const std::string lines = R"("l1": {"kind": "line", "point": [0, 0, 0], "direction": [1, 0, 0]},
                               "l2": {"kind": "line", "point": [0, 0, 1], "direction": [0, 1, 0]},
                               "l3": {"kind": "line", "point": [0, 0, 2], "direction": [1, 1, 0]},
                               "a": {"kind": "screw", "coordinates": [1, 0, 0, 0, 0, "0.5"]},
                               "b": {"kind": "screw", "point": [0, 0, 1], "direction": [0, 1, 0], "pitch": -1})";
  const std::string fig = R"("f": {"kind": "figure", "png": "x.png"})";
  // References between entities: existence and kind, with the key path.
  CHECK_THROWS_WITH(scene(fig, lines + R"(, "r": {"kind": "regulus", "lines": ["l1", "l2", "zz"]})"),
                    "scene.json: entities.r.lines[2]: no entity named \"zz\"");
  CHECK_THROWS_WITH(scene(fig, lines + R"(, "r": {"kind": "regulus", "lines": ["l1", "l2", "a"]})"),
                    "scene.json: entities.r.lines[2]: \"a\" is a screw, expected a line");
  CHECK_THROWS_WITH(scene(fig, lines + R"(, "c": {"kind": "cylindroid", "screws": ["a", "l1"]})"),
                    "scene.json: entities.c.screws[1]: \"l1\" is a line, expected a screw");
  CHECK_THROWS_WITH(scene(fig, lines + R"(, "rs": {"kind": "ruled-surface", "line": "a", "screw": "b"})"),
                    "scene.json: entities.rs.line: \"a\" is a screw, expected a line");
  CHECK_THROWS_WITH(scene(R"("c": {"kind": "cylindroid", "cylindroid": "l1"})", lines),
                    "scene.json: outputs.c.cylindroid: \"l1\" is a line, expected a cylindroid");
  CHECK_THROWS_WITH(scene(R"("c": {"kind": "cylindroid", "cylindroid": "c", "screws": ["a", "b"]})", lines),
                    "scene.json: outputs.c: give \"screws\" or \"cylindroid\", not both");
  // Meeting lines are no regulus: validateScene says so before anything is computed.
  const SceneFile meet = scene(fig, lines + R"(, "r": {"kind": "regulus", "lines": ["l1", "l1", "l3"]})");
  CHECK_THROWS_WITH(validateScene(meet), Contains("scene.json: entities.r: ThreeLineRegulus: lines 1 and 2 meet or are parallel"));
  // The typed entities.
  const SceneFile s = scene(R"("c": {"kind": "cylindroid", "cylindroid": "cy"}, "s": {"kind": "screw-system", "system": "sys"})",
                            lines + R"(, "r": {"kind": "regulus", "lines": ["l1", "l2", "l3"]},
                                       "cy": {"kind": "cylindroid", "screws": ["a", "b"]},
                                       "sys": {"kind": "screw-system", "screws": ["a", "b", "a"]},
                                       "cx": {"kind": "linear-complex", "point": [0, 1, 0], "direction": [0, 0, 1], "pitch": "0.25"},
                                       "rs": {"kind": "ruled-surface", "line": "l1", "screw": "b", "range": [0, 1]},
                                       "m": {"kind": "rigid-body", "mass": 2, "com": [0, 0, "0.1"], "inertia": [1, 2, 3, 0, 0, 0]})");
  CHECK_NOTHROW(validateScene(s));
  CHECK(s.output("c")->screws == std::vector<std::string>{"a", "b"});
  CHECK(s.output("s")->screws == std::vector<std::string>{"a", "b", "a"});
  const ThreeLineRegulus<double> r = sceneRegulus<double>(s, *s.entity("r"));
  // Every member meets the transversal x = 0 in the plane... checked by the regulus' own test; here:
  // its given lines are members, up to sign.
  for (int i = 0; i < 3; ++i) {
    const Vec6<double> m = r.member(r.givenParameter(i)), g = r.given(i);
    CHECK(std::min((m / m.norm() - g / g.norm()).norm(), (m / m.norm() + g / g.norm()).norm()) <= 1e-12);
  }
  CHECK(sceneLinearComplex<double>(*s.entity("cx")).pitch() == Approx(0.25).epsilon(1e-15));
  // The principal pitches bound the pitches of the pencil's members: a has pitch 0, b pitch −1.
  const Cylindroid<double> cy = sceneCylindroid<double>(s, *s.entity("cy"));
  CHECK(cy.pitchMax() >= 0.0);
  CHECK(cy.pitchMin() <= -1.0 + 1e-12);
  CHECK(sceneScrewSystem<double>(s, *s.entity("sys")).cols() == 3);
  const SceneRuledSurface<double> rs = sceneRuledSurface<double>(s, *s.entity("rs"));
  CHECK(rs.t1 == 1.0);
  CHECK(rs.surface.coords(0.0).isApprox(sceneLine<double>(*s.entity("l1")).coords()));
  const SpatialInertia<double> m = sceneRigidBody<double>(*s.entity("m"));
  CHECK(m.mass() == 2.0);
  CHECK(m.centreOfMass()(2) == 0.1);
  const SceneFile badMass = scene(fig, R"("m": {"kind": "rigid-body", "mass": -1, "com": [0, 0, 0], "inertia": [1, 1, 1, 0, 0, 0]})");
  CHECK_THROWS_WITH(validateScene(badMass), "scene.json: entities.m.mass: the mass must be positive");
  const SceneFile notPd = scene(fig, R"("m": {"kind": "rigid-body", "mass": 1, "com": [0, 0, 0], "inertia": [1, 1, -1, 0, 0, 0]})");
  CHECK_THROWS_WITH(validateScene(notPd), Contains("scene.json: entities.m: "));
  // dynamics: the payload is a rigid body; the robot must carry its links' inertias; joint counts.
  const std::string dyn = R"("arm": {"kind": "robot", "file": "studies/robots/puma560_dynamics.json"},
                             "plain": {"kind": "robot", "file": "studies/robots/puma560.json"},
                             "m": {"kind": "rigid-body", "mass": 2, "com": [0, 0, 0.1], "inertia": [1, 1, 1, 0, 0, 0]},
                             "p": {"kind": "point", "at": [0, 0, 0]})";
  CHECK_THROWS_WITH(scene(R"("d": {"kind": "dynamics", "robot": "arm", "from": [0, 0, 0, 0, 0, 0], "to": [0, 0, 0, 0, 0, 0], "payload": "p"})", dyn),
                    "scene.json: outputs.d.payload: \"p\" is a point, expected a rigid-body");
  CHECK_THROWS_WITH(validateScene(scene(R"("d": {"kind": "dynamics", "robot": "plain", "from": [0, 0, 0, 0, 0, 0], "to": [0, 0, 0, 0, 0, 0]})", dyn)),
                    Contains("scene.json: outputs.d.robot: a dynamics output needs the robot's link inertias"));
  CHECK_THROWS_WITH(validateScene(scene(R"("d": {"kind": "dynamics", "robot": "arm", "from": [0, 0, 0], "to": [0, 0, 0, 0, 0, 0]})", dyn)),
                    "scene.json: outputs.d.from: 3 values given, the robot has 6 joints");
  CHECK_THROWS_WITH(scene(R"("d": {"kind": "dynamics", "robot": "arm", "from": [0, 0, 0, 0, 0, 0], "to": [0, 0, 0, 0, 0, 0], "duration": 0})", dyn),
                    "scene.json: outputs.d.duration: expected a positive number of seconds");
  const SceneFile ok = scene(R"("d": {"kind": "dynamics", "robot": "arm", "from": [0, 0, 0, 0, 0, 0], "to": [90, 0, 0, 0, 0, 0], "payload": "m", "form": "cl062", "steps": 4})", dyn);
  CHECK_NOTHROW(validateScene(ok));
  CHECK(ok.output("d")->cl062);
  CHECK(ok.output("d")->steps == 4);
  const auto ends = sceneTrajectoryEnds<double>(*ok.output("d"), sceneRobot<double>(*ok.entity("arm")));
  CHECK(ends.second(0) == Approx(pi<double>() / 2).epsilon(1e-15));  // degrees in the robot's file
}

}  // namespace SOMA_UNITY_ID
