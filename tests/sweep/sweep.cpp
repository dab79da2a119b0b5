// Sweeps (issue 26): the reader's points and errors, each point's row against independent values
// (the cusp count of the literature orthogonal 3R, the traced second method over a grid, the UR5's
// 8 postures verified by forward kinematics written out here), the rows' text, resume's line test.
#include "soma/algebra/errors.hpp"
#include "soma/geometry/cuspidal/singular_set.hpp"
#include "soma/io/sweep_file.hpp"
#include "soma/scene/scene_graph.hpp"
#include "soma/sweep/sweep.hpp"

#include "support/repo_file.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using soma::test::repoFile;

namespace {

io::SweepFile example(const std::string& name) { return io::readSweep(repoFile("examples/sweeps/" + name)); }

// A sweep's text with a robot base (paths from the repository root).
std::string cuspSweep(const std::string& parameters, const std::string& extra = "") {
  return R"({"base": {"robot": "studies/robots/cusp3r_orthogonal_wenger.json"}, "parameters": [)" + parameters +
         R"(], "quantities": {"cusps": {"output": "cuspidal", "field": "cusp_count"}})" + extra + "}";
}

io::SweepFile parse(const std::string& text) { return io::parseSweep(text, "t.json", soma::test::sourceDir()); }

// The standard DH product written out (A_i = Rz(θ) Tz(d) Tx(a) Rx(α)): the tool's translation.
Eigen::Vector3d dhTranslation(const nlohmann::json& joints, const std::vector<double>& q, bool degrees) {
  const double u = degrees ? M_PI / 180 : 1;
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  for (std::size_t i = 0; i < q.size(); ++i) {
    const double th = q[i] * u + joints[i]["theta"].get<double>() * u, al = joints[i]["alpha"].get<double>() * u;
    const double a = joints[i]["a"].get<double>(), d = joints[i]["d"].get<double>();
    Eigen::Matrix4d A;
    A << std::cos(th), -std::sin(th) * std::cos(al), std::sin(th) * std::sin(al), a * std::cos(th), std::sin(th),
        std::cos(th) * std::cos(al), -std::cos(th) * std::sin(al), a * std::sin(th), 0, std::sin(al), std::cos(al), d, 0, 0, 0, 1;
    T = T * A;
  }
  return T.block<3, 1>(0, 3);
}

}  // namespace

TEST_CASE("sweep: a grid's points, the first parameter slowest — random samples reproducible and in range", "[sweep]") {
  const io::SweepFile g = parse(cuspSweep(R"({"name": "a2", "key": "entities.robot.joints[1].a", "values": [1, 2, 3]},
                                            {"name": "a3", "key": "entities.robot.joints[2].a", "range": {"from": 0, "to": 1, "count": 5}})"));
  REQUIRE(g.points() == 15);
  CHECK(g.point(0) == std::vector<double>{1, 0});
  CHECK(g.point(1) == std::vector<double>{1, 0.25});
  CHECK(g.point(4) == std::vector<double>{1, 1});
  CHECK(g.point(5) == std::vector<double>{2, 0});
  CHECK(g.point(14) == std::vector<double>{3, 1});
  const std::string uniform = R"({"name": "a2", "key": "entities.robot.joints[1].a", "uniform": {"from": 0.5, "to": 4}})";
  const io::SweepFile r = parse(cuspSweep(uniform, R"(, "samples": {"count": 1000, "seed": 7})"));
  const io::SweepFile r2 = parse(cuspSweep(uniform, R"(, "samples": {"count": 1000, "seed": 7})"));
  const io::SweepFile r3 = parse(cuspSweep(uniform, R"(, "samples": {"count": 1000, "seed": 8})"));
  REQUIRE(r.points() == 1000);
  double lo = 1e9, hi = -1e9, mean = 0;
  int differs = 0;
  for (std::size_t i = 0; i < 1000; ++i) {
    const double x = r.point(i)[0];
    CHECK(x == r2.point(i)[0]);  // the same seed: the same point, whichever process computes it
    differs += x != r3.point(i)[0];
    lo = std::min(lo, x), hi = std::max(hi, x), mean += x / 1000;
  }
  CHECK(lo >= 0.5);
  CHECK(hi < 4);
  CHECK(differs == 1000);
  // Uniform on [0.5, 4): mean 2.25, standard deviation of the mean 3.5/√12/√1000 = 0.032; 5 σ.
  CHECK(std::abs(mean - 2.25) < 5 * 3.5 / std::sqrt(12.0) / std::sqrt(1000.0));
  CHECK(lo < 0.5 + 0.05);
  CHECK(hi > 4 - 0.05);
}

TEST_CASE("sweep: bad sweeps name the key path", "[sweep]") {
  const std::string a2 = R"({"name": "a2", "key": "entities.robot.joints[1].a", "values": [1]})";
  CHECK_THROWS_WITH(parse(cuspSweep(R"({"name": "a2", "key": "entities.robot.joints[7].a", "values": [1]})")),
                    Catch::Contains("t.json: parameters[0].key: \"entities.robot.joints[7].a\" is not in the base scene"));
  CHECK_THROWS_WITH(parse(cuspSweep(R"({"name": "n", "key": "entities.robot.name", "values": [1]})")),
                    Catch::Contains("parameters[0].key: \"entities.robot.name\" is not a number in the base scene"));
  CHECK_THROWS_WITH(parse(cuspSweep(R"({"name": "a2", "key": "entities.robot.joints[1].a", "range": {"from": 0, "to": 1, "count": 0}})")),
                    Catch::Contains("t.json: parameters[0].range.count: an empty range (count 0)"));
  CHECK_THROWS_WITH(parse(cuspSweep(R"({"name": "a2", "key": "entities.robot.joints[1].a", "values": []})")),
                    Catch::Contains("parameters[0].values: an empty list of values"));
  CHECK_THROWS_WITH(parse(cuspSweep(R"({"name": "a2", "key": "entities.robot.joints[1].a", "uniform": {"from": 1, "to": 1}})",
                                    R"(, "samples": {"count": 3, "seed": 1})")),
                    Catch::Contains("parameters[0].uniform: an empty interval"));
  CHECK_THROWS_WITH(parse(cuspSweep(R"({"name": "a2", "key": "entities.robot.joints[1].a", "uniform": {"from": 1, "to": 2}})")),
                    Catch::Contains("parameters[0].uniform: a uniform parameter needs \"samples\""));
  CHECK_THROWS_WITH(parse(cuspSweep(R"({"name": "a2", "key": "entities.robot.joints[1].a", "valuez": [1]})")),
                    Catch::Contains("parameters[0]: unknown field \"valuez\""));
  CHECK_THROWS_WITH(parse(cuspSweep(a2 + "," + a2)), Catch::Contains("parameters[1].name: \"a2\" is already a column"));
  CHECK_THROWS_WITH(parse(cuspSweep(a2, R"(, "sample": 3)")), Catch::Contains("t.json: unknown field \"sample\""));
  CHECK_THROWS_WITH(parse(R"({"base": {"robot": "studies/robots/cusp3r_orthogonal_wenger.json"}, "parameters": [)" + a2 +
                          R"(], "quantities": {"n": {"output": "ik", "field": "count"}}})"),
                    Catch::Contains("quantities.n.output: the base scene") && Catch::Contains("has no output \"ik\""));
  CHECK_THROWS_WITH(parse(R"({"base": {"robot": "studies/robots/cusp3r_orthogonal_wenger.json"}, "parameters": [)" + a2 +
                          R"(], "quantities": {"n": {"output": "cuspidal", "field": "count"}}})"),
                    Catch::Contains("quantities.n.field: a cuspidal output has no field \"count\""));
  CHECK_THROWS_WITH(parse(R"({"base": {"scene": "examples/scenes/ur5_postures.json"}, "parameters": [{"name": "z", "key": "entities.goal.translation[2]", "values": [0.3]}],
                           "quantities": {"n": {"output": "figure", "field": "seconds"}}})"),
                    Catch::Contains("quantities.n.output: \"figure\" is a figure output, which computes no quantity"));
  CHECK_THROWS_WITH(parse(cuspSweep(R"({"name": "a2", "key": "entities..a", "values": [1]})")),
                    Catch::Contains("parameters[0].key: \"entities..a\" is not a key path"));
}

TEST_CASE("sweep: cusp counts of orthogonal 3R arms = the literature arm's 4 and the traced second method", "[sweep]") {
  const io::SweepFile s = example("cusps_orthogonal_3r.json");
  REQUIRE(s.points() == 42);
  std::set<int> seen;
  for (std::size_t i = 0; i < s.points(); ++i) {
    const io::SweepRow row = sweep::evaluatePoint(s, i);
    INFO("a2 = " << row.parameters[0] << ", a3 = " << row.parameters[1] << ": " << row.message);
    REQUIRE(row.status == "ok");
    // The quantities by name: aspects, cuspidal, cusps.
    // The second method (GF §5.2.3): reversals of the traced singular curves' images.
    DHRow<double> r1, r2, r3;
    r1.a = 1, r1.alpha = -M_PI / 2;
    r2.a = row.parameters[0], r2.alpha = M_PI / 2, r2.d = 1;
    r3.a = row.parameters[1];
    const SerialRobot<double> arm = SerialRobot<double>::fromDH({r1, r2, r3});
    const int traced = int(imageReversals(traceSingularCurves(arm, detJSeries(arm))).size());
    const int cusps = std::stoi(row.values[2]);
    CHECK(cusps == traced);
    CHECK((row.values[1] == "true") == (cusps > 0));  // generic 3R: cuspidal ⇔ a cusp point
    seen.insert(cusps);
  }
  CHECK(seen == std::set<int>{0, 2, 4});  // the three domains of Baili, Wenger and Chablat
  // The grid stays off a2 = a3, where (r3 = 0) a whole line of joint space is singular and the
  // traced method does not apply; Wenger's arm (2, 1.5) is a sweep of its own.
  const io::SweepRow wenger = sweep::evaluatePoint(
      parse(cuspSweep(R"({"name": "a2", "key": "entities.robot.joints[1].a", "values": [2]},
                         {"name": "a3", "key": "entities.robot.joints[2].a", "values": [1.5]})")),
      0);
  REQUIRE(wenger.status == "ok");
  CHECK(wenger.values[0] == "4");  // Wenger; Baili, Wenger, Chablat 2004
}

TEST_CASE("sweep: the UR5's 8 postures at each goal of a sweep, verified by the DH product written out", "[sweep]") {
  const io::SweepFile s = example("ur5_ik_counts.json");
  REQUIRE(s.points() == 4);
  std::ifstream in(repoFile("examples/scenes/ur5_postures.json"));
  const nlohmann::json base = nlohmann::json::parse(in);
  for (std::size_t i = 0; i < s.points(); ++i) {
    const io::SweepRow row = sweep::evaluatePoint(s, i);
    REQUIRE(row.status == "ok");
    CHECK(row.values[0] == "8");  // expected
    CHECK(row.values[1] == "8");  // postures: the UR5's generic count
    // The postures themselves, through the scene graph the sweep used, by an independent FK.
    const io::SceneFile point = io::sweepPointScene(s, i);
    scene::SceneGraph graph(point);
    const scene::SceneResult r = graph.evaluate({"postures"});
    REQUIRE(r.output("postures")->joints.size() == 8);
    Eigen::Vector3d goal(base["entities"]["goal"]["translation"][0].get<double>(),
                         base["entities"]["goal"]["translation"][1].get<double>(), row.parameters[0]);
    for (const auto& q : r.output("postures")->joints) {
      std::vector<double> deg;
      for (double x : q) deg.push_back(x * 180 / M_PI);
      CHECK((dhTranslation(base["entities"]["ur5"]["joints"], deg, true) - goal).norm() < 1e-9);
    }
  }
}

TEST_CASE("sweep: rows as CSV and JSON Lines — a partial line is not a row", "[sweep]") {
  const io::SweepFile s = example("cusps_orthogonal_3r.json");
  io::SweepRow row;
  row.point = 3;
  row.parameters = {0.5, 2};
  row.values = {"3", "true", "2"};
  row.residual = 1e-15;
  row.seconds = 0.25;
  CHECK(io::sweepCsvHeader(s) == "point,a2,a3,aspects,cuspidal,cusps,residual,status,message,seconds\n");
  CHECK(io::sweepCsvLine(s, row) == "3,0.5,2,3,true,2,1e-15,ok,,0.25\n");
  const std::string line = io::sweepJsonLine(s, row);
  CHECK(line == R"({"point":3,"parameters":{"a2":0.5,"a3":2.0},"values":{"aspects":3,"cuspidal":true,"cusps":2},"residual":1e-15,"status":"ok","seconds":0.25})"
                "\n");
  CHECK(io::sweepJsonLinePoint(line) == std::optional<std::size_t>(3));
  for (std::size_t cut = 0; cut < line.size(); ++cut) CHECK_FALSE(io::sweepJsonLinePoint(line.substr(0, cut)).has_value());
  row.status = "error";
  row.message = "a, \"quoted\"\nmessage";
  row.values.clear();
  CHECK(io::sweepCsvLine(s, row) == "3,0.5,2,,,,1e-15,error,\"a, \"\"quoted\"\" message\",0.25\n");
}

TEST_CASE("sweep: rows read back exactly as written — a partial, foreign or out-of-range line is refused with its line", "[sweep]") {
  const io::SweepFile s = example("cusps_orthogonal_3r.json");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "soma-test-sweep-rows";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::vector<io::SweepRow> rows(3);
  // Parameters and residuals that a short decimal would not carry: they must come back bit for bit.
  rows[0] = {.point = 0, .parameters = {0.1 + 0.2, 1.0 / 3}, .values = {"3", "true", "2"}, .residual = 2.2250738585072014e-308,
             .status = "ok", .message = "", .seconds = 0.125};
  rows[1] = {.point = 1, .parameters = {std::nextafter(2.0, 3.0), 2}, .values = {}, .residual = std::nan(""),
             .status = "error", .message = "a \"quoted\" message", .seconds = 1e-6};
  rows[2] = {.point = 41, .parameters = {4, 3}, .values = {"1", "false", "0"}, .residual = 0, .status = "ok", .message = "",
             .seconds = 7};
  const auto write = [&](const std::string& text) {
    std::ofstream(dir / "rows.jsonl", std::ios::binary) << text;
    return dir / "rows.jsonl";
  };
  std::string text;
  for (const auto& r : rows) text += io::sweepJsonLine(s, r);
  const std::vector<io::SweepRow> back = io::readSweepRows(s, write(text));
  REQUIRE(back.size() == 3);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(back[i].point == rows[i].point);
    CHECK(back[i].parameters == rows[i].parameters);
    CHECK(back[i].values == rows[i].values);
    CHECK(back[i].status == rows[i].status);
    CHECK(back[i].message == rows[i].message);
    CHECK(back[i].seconds == rows[i].seconds);
  }
  CHECK(back[0].residual == rows[0].residual);
  CHECK(std::isnan(back[1].residual));  // written as null
  // A partial last line (a killed sweep), a point beyond the sweep's 42, another sweep's columns.
  const auto refused = [&](const std::string& t) {
    try {
      io::readSweepRows(s, write(t));
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(refused(text.substr(0, text.size() - 1)), Catch::Contains("line 3: not a complete row"));
  rows[2].point = 42;
  CHECK_THAT(refused(io::sweepJsonLine(s, rows[2])), Catch::Contains("line 1: \"point\" is not a point of"));
  CHECK_THAT(refused(R"({"point":0,"parameters":{"d3":1},"values":{},"residual":0,"status":"ok","seconds":0})" "\n"),
             Catch::Contains("line 1: parameters.a2 is missing"));
  CHECK_THAT(refused(io::sweepJsonLine(s, rows[0]) + "not json\n"), Catch::Contains("line 2: not a complete row"));
  CHECK(io::readSweepRows(s, write("")).empty());
  CHECK_THROWS_WITH(io::readSweepRows(s, dir / "missing.jsonl"), Catch::Contains("missing.jsonl: cannot be read"));
  std::filesystem::remove_all(dir);
}

}  // namespace SOMA_UNITY_ID
