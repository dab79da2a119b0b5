// Every scene of examples/scenes, run by the scene graph and checked against values computed here
// independently of soma's solvers: forward kinematics by the DH / MDH / POE products written out,
// the postures a pose was made from, leg lengths |R q_i + t − p_i|, a cylindroid's pitches by
// brute-force extremes of the pencil's pitch, the counts the book gives.
#include "soma/io/json_number.hpp"
#include "soma/io/scene_file.hpp"
#include "soma/geometry/screws/identification.hpp"
#include "soma/scene/scene_graph.hpp"

#include "support/repo_file.hpp"

#include <catch2/catch.hpp>
#include <complex>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma;
using json = nlohmann::json;
using soma::test::repoFile;
using M4 = Eigen::Matrix4d;

namespace {

json runScene(const std::string& name) {
  scene::SceneGraph g(io::readScene(repoFile("examples/scenes/" + name)));
  const scene::SceneResult r = g.evaluate();
  json all = json::object();
  for (const auto& o : r.outputs) all[o.name] = json::parse(o.json);
  CHECK(r.ok());
  return all;
}

// A number of a scene's JSON output: a JSON number (float, double) or the decimal string a wider
// scalar is written as (io/json_number.hpp), read in double for the comparisons here.
double num(const json& j) { return io::readJsonNumber<double>(j, "scene output"); }

json fileJson(const std::string& rel) {
  std::ifstream in(repoFile(rel));
  return json::parse(in);
}

M4 rotX(double t) {
  M4 m = M4::Identity();
  m.block<3, 3>(0, 0) = Eigen::AngleAxisd(t, Eigen::Vector3d::UnitX()).toRotationMatrix();
  return m;
}
M4 rotZ(double t) {
  M4 m = M4::Identity();
  m.block<3, 3>(0, 0) = Eigen::AngleAxisd(t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return m;
}
M4 trans(double x, double y, double z) {
  M4 m = M4::Identity();
  m.block<3, 1>(0, 3) = Eigen::Vector3d(x, y, z);
  return m;
}

// The forward kinematics of a DH / MDH table (a robot file's "joints"), written out: standard
// A_i = Rz(θ_i + q_i)·Tz(d_i)·Tx(a_i)·Rx(α_i); modified A_i = Rx(α_{i−1})·Tx(a_{i−1})·Rz(θ_i + q_i)·Tz(d_i).
M4 tableFk(const json& robot, const std::vector<double>& q) {
  const double u = robot.value("angles", "radians") == "degrees" ? M_PI / 180 : 1.0;
  const bool modified = robot["convention"] == "mdh";
  M4 T = M4::Identity();
  for (std::size_t i = 0; i < q.size(); ++i) {
    const json& r = robot["joints"][i];
    const double a = r["a"], al = double(r["alpha"]) * u, d = r["d"], th = double(r["theta"]) * u + q[i];
    T = T * (modified ? rotX(al) * trans(a, 0, 0) * rotZ(th) * trans(0, 0, d)
                      : rotZ(th) * trans(0, 0, d) * trans(a, 0, 0) * rotX(al));
  }
  return T;
}

M4 poseOf(const json& p) {
  M4 T = M4::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) T(r, c) = num(p["rotation"][r][c]);
    T(r, 3) = num(p["translation"][r]);
  }
  return T;
}

std::vector<double> jointsIn(const json& solution, bool degrees) {
  std::vector<double> q;
  for (const auto& v : solution["joints"]) q.push_back(num(v) * (degrees ? M_PI / 180 : 1.0));
  return q;
}

// Every posture reproduces the pose by the table's own product; returns how many match `seed`.
int checkPostures(const json& out, const json& robot, const M4& goal, const std::vector<double>& seed, double tol) {
  int seen = 0;
  for (const auto& s : out["solutions"]) {
    const std::vector<double> q = jointsIn(s, out["angles"] == "degrees");
    CHECK((tableFk(robot, q) - goal).cwiseAbs().maxCoeff() <= tol);
    bool same = !seed.empty();
    for (std::size_t i = 0; i < seed.size(); ++i)
      same = same && std::abs(std::remainder(q[i] - seed[i], 2 * M_PI)) <= 1e-7;
    seen += same;
  }
  return seen;
}

// Principal pitches by brute force: the pitch ω·v/ω·ω of cos θ a + sin θ b on a fine grid, refined
// by golden sections around the best grid points (independent of Cylindroid's diagonalisation).
std::pair<double, double> pencilPitchExtremes(const Eigen::Matrix<double, 6, 1>& a, const Eigen::Matrix<double, 6, 1>& b) {
  auto h = [&](double t) {
    const Eigen::Matrix<double, 6, 1> s = std::cos(t) * a + std::sin(t) * b;
    return s.head<3>().dot(s.tail<3>()) / s.head<3>().squaredNorm();
  };
  auto refine = [&](double t0, double sign) {
    double lo = t0 - 1e-3, hi = t0 + 1e-3;
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (int k = 0; k < 200; ++k) {
      const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
      if (sign * h(x1) > sign * h(x2)) hi = x2;
      else lo = x1;
    }
    return h((lo + hi) / 2);
  };
  double tMax = 0, tMin = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const double t = M_PI * k / n;
    if (h(t) > h(tMax)) tMax = t;
    if (h(t) < h(tMin)) tMin = t;
  }
  return {refine(tMax, 1), refine(tMin, -1)};
}

Eigen::Matrix<double, 6, 1> screwOf(const Eigen::Vector3d& q, const Eigen::Vector3d& d, double pitch) {
  const Eigen::Vector3d u = d.normalized();
  Eigen::Matrix<double, 6, 1> s;
  s << u, q.cross(u) + pitch * u;
  return s;
}

}  // namespace

TEST_CASE("example scene ur5_postures: every posture reproduces the pose — the pose's own joints among them", "[scene][examples]") {
  const json scene = fileJson("examples/scenes/ur5_postures.json");
  const json out = runScene("ur5_postures.json")["postures"];
  CHECK(out["count"] == 8);  // the UR's 3 parallel axes: 8 postures (its expected count)
  CHECK(checkPostures(out, scene["entities"]["ur5"], poseOf(scene["entities"]["goal"]), {0.3, -1.1, 1.4, -0.6, 0.9, 0.2},
                      1e-9) == 1);
}

TEST_CASE("example scene kuka_postures: 8 postures in double and float128, the pose's joints among them", "[scene][examples]") {
  const json scene = fileJson("examples/scenes/kuka_postures.json");
  const json all = runScene("kuka_postures.json");
  for (const char* o : {"postures", "postures_float128"}) {
    INFO(o);
    CHECK(all[o]["expected_count"] == 8);
    CHECK(checkPostures(all[o], scene["entities"]["kr6"], poseOf(scene["entities"]["goal"]), {0.4, -0.7, 0.5, 0.3, 0.8, -0.5},
                        1e-9) == 1);
  }
  CHECK(all["postures"]["count"] == all["postures_float128"]["count"]);
}

TEST_CASE("example scene puma_urdf: the URDF robot's postures and tool pose by the PUMA's DH product", "[scene][examples]") {
  const json dh = fileJson("studies/robots/puma560.json");
  const json all = runScene("puma_urdf.json");
  const M4 goal = poseOf(fileJson("studies/robots/puma560_pose.json"));
  CHECK(all["postures"]["count"].get<int>() >= 1);
  CHECK(checkPostures(all["postures"], dh, goal, {}, 1e-9) == 0);
  const M4 tool = tableFk(dh, {0.1, -0.4, 0.3, 0.2, 0.5, -0.6});
  CHECK((poseOf(all["tool"]["pose"]) - tool).cwiseAbs().maxCoeff() <= 1e-12);
}

TEST_CASE("example scene wrist_rpy: the 2 postures of an RPY wrist (GF §5.1)", "[scene][examples]") {
  const json out = runScene("wrist_rpy.json")["postures"];
  CHECK(out["count"] == 2);
  const M4 goal = poseOf(fileJson("examples/scenes/wrist_rpy.json")["entities"]["goal"]);
  int seed = 0;
  for (const auto& s : out["solutions"]) {
    const std::vector<double> q = jointsIn(s, false);
    // R = Rz(q1) Ry(q2) Rx(q3), the tool at R·(0.1, 0, 0).
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(q[0], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(q[1], Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(q[2], Eigen::Vector3d::UnitX())).toRotationMatrix();
    CHECK((R - goal.block<3, 3>(0, 0)).cwiseAbs().maxCoeff() <= 1e-12);
    CHECK((R * Eigen::Vector3d(0.1, 0, 0) - goal.block<3, 1>(0, 3)).cwiseAbs().maxCoeff() <= 1e-12);
    seed += std::abs(q[0] - 0.3) < 1e-9 && std::abs(q[1] - 0.4) < 1e-9 && std::abs(q[2] - 0.5) < 1e-9;
  }
  CHECK(seed == 1);
}

TEST_CASE("example scene general6r: postures of a general 6R by its DH product — 16 complex", "[scene][examples]") {
  const json out = runScene("general6r.json")["postures"];
  CHECK(out["expected_count"] == 16);
  CHECK(out["count"].get<int>() % 2 == 0);  // real postures of 16 complex come in an even number
  CHECK(checkPostures(out, fileJson("studies/robots/general6r.json"), poseOf(fileJson("studies/robots/general6r_pose.json")),
                      {}, 1e-8) == 0);
}

TEST_CASE("example scene puma_mpfr: the same postures in mpfr and double, each by the DH product", "[scene][examples]") {
  const json all = runScene("puma_mpfr.json");
  const json dh = fileJson("studies/robots/puma560_nolimits.json");
  const M4 goal = poseOf(fileJson("studies/robots/puma560_pose.json"));
  CHECK(all["postures"]["count"] == 8);
  CHECK(all["postures_mpfr"]["count"] == 8);
  CHECK(all["postures_mpfr"]["bits"] == 160);
  CHECK(checkPostures(all["postures_mpfr"], dh, goal, {}, 1e-12) == 0);
  CHECK(num(all["postures_mpfr"]["residual"]) <= 1e-40);
  // Written in the output's own digits (io/json_number.hpp): floor(160 log10 2) + 2 = 50 significant
  // digits, not a double's 17.
  const json& q0 = all["postures_mpfr"]["solutions"][0]["joints"][0];
  REQUIRE(q0.is_string());
  std::size_t digits = 0;
  for (const char c : q0.get<std::string>().substr(0, q0.get<std::string>().find_first_of("eE"))) digits += c >= '0' && c <= '9';
  CHECK(digits >= 49);
}

TEST_CASE("example scene puma_mdh: modified DH postures by the MDH product, the pose's joints among them", "[scene][examples]") {
  const json scene = fileJson("examples/scenes/puma_mdh.json");
  const json out = runScene("puma_mdh.json")["postures"];
  CHECK(out["count"] == 8);
  CHECK(checkPostures(out, scene["entities"]["puma"], poseOf(scene["entities"]["goal"]), {0.2, -0.5, 0.4, 0.3, -0.6, 0.7},
                      1e-9) == 1);
}

void checkLegs(const json& out, const json& P, const M4& known) {
  int seen = 0;
  for (const auto& s : out["solutions"]) {
    const M4 g = poseOf(s);
    for (int i = 0; i < 6; ++i) {
      Eigen::Vector3d b, p;
      for (int k = 0; k < 3; ++k) b(k) = P["base"][i][k], p(k) = P["platform"][i][k];
      const double L = (g.block<3, 3>(0, 0) * p + g.block<3, 1>(0, 3) - b).norm();
      CHECK(std::abs(L - double(P["leg_lengths"][i])) <= 1e-10);
    }
    seen += (g - known).cwiseAbs().maxCoeff() <= 1e-9;
  }
  CHECK(seen == 1);
}

M4 stewartKnownPosture() {
  M4 g = M4::Identity();
  g.block<3, 3>(0, 0) = Eigen::AngleAxisd(0.25, Eigen::Vector3d(0.2, 0.3, 0.93).normalized()).toRotationMatrix();
  g.block<3, 1>(0, 3) = Eigen::Vector3d(0.05, -0.03, 0.9);
  return g;
}

TEST_CASE("example scene stewart_irregular: leg lengths of every posture — the made-from posture among them", "[scene][examples]") {
  const json out = runScene("stewart_irregular.json")["postures"];
  CHECK(out["certified"] == true);
  CHECK(out["count"].get<int>() % 2 == 0);  // 40 complex solutions: the real ones are even in number
  const json P = fileJson("examples/scenes/stewart_irregular.json")["entities"]["hexapod"];
  checkLegs(out, P, stewartKnownPosture());
  // "complex": true: the 40 complex solutions (GF §11.5.4), each on the six leg quadrics in complex
  // arithmetic — (R(a) qᵢ + t − pᵢ)·(R(a) qᵢ + t − pᵢ) = Lᵢ² (bilinear), R(a) written out here for
  // a = (w, x, y, z), a·a = 1 — to 1024 ε (1 + |t|)² (the terms' size; the conversion's ~100 roundings).
  CHECK(out["class"] == "6-6");
  CHECK(out["complex_count"] == 40);
  REQUIRE(out["complex_solutions"].size() == 40);
  using C = std::complex<double>;
  auto cx = [](const json& v) { return C(double(v[0]), double(v[1])); };
  int real = 0;
  for (const auto& e : out["complex_solutions"]) {
    const C w = cx(e["rotation"][0]), x = cx(e["rotation"][1]), y = cx(e["rotation"][2]), z = cx(e["rotation"][3]);
    Eigen::Matrix3cd R;
    R << 1. - 2. * (y * y + z * z), 2. * (x * y - w * z), 2. * (x * z + w * y), 2. * (x * y + w * z), 1. - 2. * (x * x + z * z),
        2. * (y * z - w * x), 2. * (x * z - w * y), 2. * (y * z + w * x), 1. - 2. * (x * x + y * y);
    const Eigen::Vector3cd t(cx(e["translation"][0]), cx(e["translation"][1]), cx(e["translation"][2]));
    const double size = 1 + t.cwiseAbs().maxCoeff();
    for (int i = 0; i < 6; ++i) {
      Eigen::Vector3d b, p;
      for (int k = 0; k < 3; ++k) b(k) = P["base"][i][k], p(k) = P["platform"][i][k];
      const Eigen::Vector3cd u = R * p.cast<C>() + t - b.cast<C>();
      const double L = P["leg_lengths"][i];
      CHECK(std::abs(u.dot(u.conjugate()) - C(L * L)) <= 1024 * std::numeric_limits<double>::epsilon() * size * size);
    }
    real += e["real"].get<bool>();
  }
  CHECK(real == out["count"].get<int>());
}

TEST_CASE("example scene stewart_numeric: ceres postures polished in long double keep the leg lengths", "[scene][examples]") {
  const json out = runScene("stewart_numeric.json")["postures"];
  CHECK(out["scalar"] == "long-double");
  checkLegs(out, fileJson("examples/scenes/stewart_numeric.json")["entities"]["hexapod"], stewartKnownPosture());
}

TEST_CASE("example scene cylindroid_two_screws: the pitches are the pencil's pitch extremes", "[scene][examples]") {
  const json all = runScene("cylindroid_two_screws.json");
  const auto [hMax, hMin] = pencilPitchExtremes(screwOf({0, 0, 0}, {1, 0, 0}, 0.2), screwOf({0, 0, 0.5}, {1, 1, 0}, -0.1));
  for (const char* o : {"pencil", "pencil_mpfr"}) {
    CHECK(num(all[o]["pitches"][0]) == Approx(hMax).margin(1e-9));
    CHECK(num(all[o]["pitches"][1]) == Approx(hMin).margin(1e-9));
  }
}

TEST_CASE("example scene cylindroid_perpendicular: perpendicular meeting screws are the principal ones", "[scene][examples]") {
  const json out = runScene("cylindroid_perpendicular.json")["pencil"];
  CHECK(num(out["pitches"][0]) == Approx(0.3).margin(1e-15));
  CHECK(num(out["pitches"][1]) == Approx(-0.2).margin(1e-15));
  for (int k = 0; k < 3; ++k) CHECK(std::abs(num(out["centre"][k])) <= 1e-15);
}

TEST_CASE("example scene cylindroid_lines: the cylindroid of two lines", "[scene][examples]") {
  const json out = runScene("cylindroid_lines.json")["pencil"];
  Eigen::Matrix<double, 6, 1> a, b;
  a << 1, 0, 0, 0, 0, 0;
  b = screwOf({0, 0, 0.4}, {0.5, std::sqrt(3.0) / 2, 0}, 0);
  const auto [hMax, hMin] = pencilPitchExtremes(a, b);
  CHECK(num(out["pitches"][0]) == Approx(hMax).margin(1e-9));
  CHECK(num(out["pitches"][1]) == Approx(hMin).margin(1e-9));
  // Two lines at angle α (cos α = ½) with reciprocal product ω₁·v₂ + ω₂·v₁ = 2k: the pitch h of
  // μ l₁ + λ l₂ solves det(K − h G) = 0, K = [[0, k], [k, 0]], G = [[1, c], [c, 1]]:
  // h = k / (1 + c) and h = −k / (1 − c).
  const double k = (a.head<3>().dot(b.tail<3>()) + b.head<3>().dot(a.tail<3>())) / 2, c = 0.5;
  CHECK(num(out["pitches"][0]) == Approx(-k / (1 - c)).margin(1e-12));
  CHECK(num(out["pitches"][1]) == Approx(k / (1 + c)).margin(1e-12));
}

TEST_CASE("example scene arm3r_fk: the finger arm's tool position, GF §5.2.2", "[scene][examples]") {
  const json all = runScene("arm3r_fk.json");
  const double q1 = 0.3, q2 = 0.5, q3 = -0.9;
  // p = Rz(q1)·(0, 0.8 + 1.1 cos q2 + 0.6 cos(q2+q3), 1.1 sin q2 + 0.6 sin(q2+q3))
  const Eigen::Vector3d p = Eigen::AngleAxisd(q1, Eigen::Vector3d::UnitZ()) *
                            Eigen::Vector3d(0, 0.8 + 1.1 * std::cos(q2) + 0.6 * std::cos(q2 + q3),
                                            1.1 * std::sin(q2) + 0.6 * std::sin(q2 + q3));
  for (const char* o : {"tool", "tool_mpfr"})
    for (int k = 0; k < 3; ++k) CHECK(num(all[o]["pose"]["translation"][k]) == Approx(p(k)).margin(1e-14));
}

}  // namespace SOMA_UNITY_ID

namespace SOMA_UNITY_ID {

TEST_CASE("example scene screw_system_ia1: a moved IA1 normal form is identified with its pitches", "[scene][examples]") {
  const json all = runScene("screw_system_ia1.json");
  for (const char* o : {"system", "system_float128"}) {
    INFO(o);
    CHECK(all[o]["dimension"] == 3);
    CHECK(all[o]["type_name"] == soma::screwSystemTypeName(soma::ScrewSystemType::IA1_3));
    // Built from (e_i; p_i e_i) with p = 0.3, 0.1, −0.2: the principal pitches are invariants.
    REQUIRE(all[o]["parameters"].size() == 3);
    CHECK(num(all[o]["parameters"][0]) == Approx(0.3).margin(1e-12));
    CHECK(num(all[o]["parameters"][1]) == Approx(0.1).margin(1e-12));
    CHECK(num(all[o]["parameters"][2]) == Approx(-0.2).margin(1e-12));
  }
}

}  // namespace SOMA_UNITY_ID

namespace SOMA_UNITY_ID {

TEST_CASE("example scene cuspidal_3r_witness: 4 cusps — the witness's two postures reach one point", "[scene][examples]") {
  const json out = runScene("cuspidal_3r_witness.json")["verdict"];
  CHECK(out["cuspidal"] == true);
  CHECK(out["cusp_count"] == 4);  // Wenger's orthogonal 3R (1, 2, 1.5, 1, 0): 4 cusp points
  const json& w = out["witness"];
  REQUIRE(w["found"] == true);
  const json robot = fileJson("studies/robots/cusp3r_orthogonal_wenger.json");
  std::vector<double> start, goal;
  for (int i = 0; i < 3; ++i) start.push_back(w["start"][i]), goal.push_back(w["goal"][i]);
  const Eigen::Vector3d target(num(w["target"][0]), num(w["target"][1]), num(w["target"][2]));
  // Both ends reach the target by the DH product; they are two different postures.
  CHECK((tableFk(robot, start).block<3, 1>(0, 3) - target).norm() <= 1e-6);
  CHECK((tableFk(robot, goal).block<3, 1>(0, 3) - target).norm() <= 1e-6);
  double apart = 0;
  for (int i = 0; i < 3; ++i) apart = std::max(apart, std::abs(std::remainder(start[i] - goal[i], 2 * M_PI)));
  CHECK(apart > 1e-3);
}

}  // namespace SOMA_UNITY_ID

namespace SOMA_UNITY_ID {

TEST_CASE("example scene burmester_five_positions: each circle point's 5 positions lie on its circle", "[scene][examples]") {
  const json out = runScene("burmester_five_positions.json")["pairs"];
  CHECK(out["expected_count"] == 4);
  CHECK((out["count"].get<int>() + out["complex_count"].get<int>()) == 4);  // 4 pairs in all, complex ones in conjugates
  CHECK(out["count"].get<int>() % 2 == 0);
  const json& pos = fileJson("examples/scenes/burmester_five_positions.json")["entities"]["task"]["positions"];
  for (const auto& p : out["pairs"]) {
    const Eigen::Vector2d m(num(p["circle_point"][0]), num(p["circle_point"][1]));
    const Eigen::Vector2d c(num(p["centre"][0]), num(p["centre"][1]));
    for (const auto& q : pos) {
      // The circle point moved by position q: R(angle) m + (x, y).
      const Eigen::Vector2d at = Eigen::Rotation2Dd(double(q["angle"]) * M_PI / 180) * m + Eigen::Vector2d(q["x"], q["y"]);
      CHECK((at - c).norm() == Approx(num(p["radius"])).epsilon(1e-8));
    }
  }
}

}  // namespace SOMA_UNITY_ID

namespace SOMA_UNITY_ID {

namespace {
// Standard DH frames T_0 = I, T_1, …, T_n of a robot file's table at q (radians).
std::vector<M4> tableFrames(const json& robot, const std::vector<double>& q) {
  const double u = robot.value("angles", "radians") == "degrees" ? M_PI / 180 : 1.0;
  std::vector<M4> T{M4::Identity()};
  for (std::size_t i = 0; i < q.size(); ++i) {
    const json& r = robot["joints"][i];
    const double a = r["a"], al = double(r["alpha"]) * u, d = r["d"], th = double(r["theta"]) * u + q[i];
    T.push_back(T.back() * rotZ(th) * trans(0, 0, d) * trans(a, 0, 0) * rotX(al));
  }
  return T;
}
// The torques that hold a standard-DH robot still at q against gravity g along −z, written out:
// τ_i = Σ_b m_b g ((c_b − o_{i−1}) × ẑ)·z_{i−1} over the bodies b beyond joint i (link coms in their
// own DH frames, the payload's in the last one) — the statics of GF §13.2.2's C_i, by hand.
std::vector<double> holdingTorques(const json& robot, const std::vector<double>& q, double g, double payloadMass,
                                   const Eigen::Vector3d& payloadCom) {
  const std::vector<M4> T = tableFrames(robot, q);
  const std::size_t n = q.size();
  std::vector<double> masses;
  std::vector<Eigen::Vector3d> coms;
  for (std::size_t i = 0; i < n; ++i) {
    const json& l = robot["links"][i];
    masses.push_back(l["mass"]);
    const Eigen::Vector4d c(l["com"][0], l["com"][1], l["com"][2], 1.0);
    coms.push_back((T[i + 1] * c).head<3>());
  }
  masses.push_back(payloadMass);
  coms.push_back((T[n] * Eigen::Vector4d(payloadCom(0), payloadCom(1), payloadCom(2), 1.0)).head<3>());
  std::vector<double> tau(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d o = T[i].block<3, 1>(0, 3), z = T[i].block<3, 1>(0, 2);
    for (std::size_t b = i; b < masses.size(); ++b)
      tau[i] += masses[b] * g * (coms[b] - o).cross(Eigen::Vector3d::UnitZ()).dot(z);
  }
  return tau;
}
}  // namespace

TEST_CASE("example scene workspace_3r: the map's extent is the arm's reach by brute force", "[scene][examples]") {
  const json out = runScene("workspace_3r.json")["reach"];
  const json robot = fileJson("studies/robots/cusp3r_orthogonal_wenger.json");
  // ρ = distance from axis 1 (the base z axis); q1 does not change it.
  // Joints 2 and 3 on a 400 × 400 grid (the grid's error in ρ is O(h²) ≈ 1e-4 of the reach).
  // The table's A_1 at q1 = 0 and A_3 do not depend on the grid's row: the row's A_2 is formed once.
  double rmax = 0, zmin = 1e9, zmax = -1e9;
  const int n = 400;
  const M4 A1 = tableFk(robot, {0});
  const json& j2 = robot["joints"][1];
  const json& j3 = robot["joints"][2];
  const double u = M_PI / 180;  // the file is in degrees
  auto dh = [&](const json& r, double q) {
    return M4(rotZ(double(r["theta"]) * u + q) * trans(0, 0, r["d"]) * trans(r["a"], 0, 0) * rotX(double(r["alpha"]) * u));
  };
  REQUIRE(robot["angles"] == "degrees");
  for (int i = 0; i < n; ++i) {
    const M4 A12 = A1 * dh(j2, 2 * M_PI * i / n);
    for (int j = 0; j < n; ++j) {
      const M4 T = A12 * dh(j3, 2 * M_PI * j / n);
      rmax = std::max(rmax, std::hypot(T(0, 3), T(1, 3)));
      zmin = std::min(zmin, T(2, 3));
      zmax = std::max(zmax, T(2, 3));
    }
  }
  CHECK((tableFk(robot, {0, 0.4, -1.1}) - A1 * dh(j2, 0.4) * dh(j3, -1.1)).cwiseAbs().maxCoeff() <= 1e-14);
  // rho_max is the sampled extent plus a 2% pad (workspace.hpp): within [0.99 rmax, rmax + pad].
  // The grid misses the true extremes by at most (link lengths 4.5) × h²/2 ≈ 6e-4: slack 2e-3.
  const double pad = 0.02 * std::max(rmax, zmax - zmin), slack = 2e-3;
  CHECK(num(out["rho_max"]) >= 0.99 * rmax);
  CHECK(num(out["rho_max"]) <= rmax + pad + slack);
  CHECK(num(out["z_max"]) <= zmax + pad + slack);
  CHECK(num(out["z_min"]) >= zmin - pad - slack);
  CHECK(out["samples"] == 40000);
  CHECK(out["reached_cells"].get<int>() > 0);
  CHECK(out["boundary_curves"].get<int>() > 0);  // a 3R arm: the singular curves' images
}

TEST_CASE("example scene dynamics_puma_payload: at rest the torques hold the arm and its box against gravity", "[scene][examples]") {
  const json all = runScene("dynamics_puma_payload.json");
  const json robot = fileJson("studies/robots/puma560_dynamics.json");
  const std::vector<double> from(6, 0.0);
  std::vector<double> to;
  for (const double d : {45.0, -60.0, 30.0, 20.0, 40.0, 10.0}) to.push_back(d * M_PI / 180);
  for (const char* o : {"unloaded", "loaded"}) {
    INFO(o);
    const json& out = all[o];
    REQUIRE(out["torques"].size() == 21);
    const double m = std::string(o) == "loaded" ? 2.0 : 0.0;
    // The quintic starts and ends at rest: the torques are the holding torques there.
    const std::vector<double> t0 = holdingTorques(robot, from, 9.81, m, {0, 0, 0.05});
    const std::vector<double> t1 = holdingTorques(robot, to, 9.81, m, {0, 0, 0.05});
    for (std::size_t i = 0; i < 6; ++i) {
      CHECK(num(out["torques"][0][i]) == Approx(t0[i]).margin(1e-9));
      CHECK(num(out["torques"][20][i]) == Approx(t1[i]).margin(1e-9));
    }
    CHECK(num(out["times"][20]) == 2.0);
    CHECK(num(out["joints"][20][1]) == Approx(-60).margin(1e-12));
  }
  CHECK_FALSE(all["unloaded"].contains("momenta_cl062"));
  REQUIRE(all["loaded"]["momenta_cl062"].size() == 6);
  CHECK(num(all["loaded"]["momenta_cl062_residual"]) <= 1e-12);
}

TEST_CASE("example scene line_geometry: the regulus lies on x²+y²−z²=1 — the pencil's pitches by brute force", "[scene][examples]") {
  const json all = runScene("line_geometry.json");
  const io::SceneFile s = io::readScene(repoFile("examples/scenes/line_geometry.json"));
  const ThreeLineRegulus<double> r = io::sceneRegulus<double>(s, *s.entity("hyperboloid"));
  const io::SceneRuledSurface<double> swept = io::sceneRuledSurface<double>(s, *s.entity("swept"));
  for (int k = 0; k < 24; ++k) {
    for (const Eigen::Matrix<double, 6, 1>& m : {r.member(M_PI * k / 24), swept.surface.coords(2 * M_PI * k / 24)}) {
      const PluckerLine<double> l(m);
      for (const double mu : {-1.0, 0.5, 2.0}) {
        const Eigen::Vector3d p = l.pointAt(mu);
        CHECK(std::abs(p(0) * p(0) + p(1) * p(1) - p(2) * p(2) - 1) <= 1e-12);
      }
    }
  }
  const auto [hMax, hMin] = pencilPitchExtremes(screwOf({0, 0, 0}, {1, 0, 0}, 0.4), screwOf({0, 0, 0.3}, {1, 2, 0}, -0.1));
  CHECK(num(all["pitches"]["pitches"][0]) == Approx(hMax).margin(1e-9));
  CHECK(num(all["pitches"]["pitches"][1]) == Approx(hMin).margin(1e-9));
  CHECK(all["system"]["dimension"] == 2);
  // The complex (α; b) = (ẑ; 0.5 ẑ) holds the line through (1, 0, 0) along (0, 0.5, −1), by hand:
  // b·ω + α·v = (0,0,0.5)·(0,0.5,−1) + ẑ·((1,0,0) × (0,0.5,−1)) = −0.5 + 0.5 = 0; not the one along z.
  const LinearComplex<double> c = io::sceneLinearComplex<double>(*s.entity("complex"));
  CHECK(c.pitch() == Approx(0.5).margin(1e-15));
  CHECK(c.contains(PluckerLine<double>::pointDirection({1, 0, 0}, {0, 0.5, -1})));
  CHECK_FALSE(c.contains(PluckerLine<double>::pointDirection({1, 0, 0}, {0, 0, 1})));
  CHECK(all["figure"]["drawn"].size() == 4);
}

TEST_CASE("example scene burmester_svg: the SVG shows each pair's circle point at the five positions on its circle", "[scene][examples]") {
  const json all = runScene("burmester_svg.json");
  const json& out = all["pairs"];
  CHECK((out["count"].get<int>() + out["complex_count"].get<int>()) == 4);
  const json& pos = fileJson("examples/scenes/burmester_svg.json")["entities"]["task"]["positions"];
  for (const auto& p : out["pairs"]) {
    const Eigen::Vector2d m(num(p["circle_point"][0]), num(p["circle_point"][1]));
    const Eigen::Vector2d c(num(p["centre"][0]), num(p["centre"][1]));
    for (const auto& q : pos) {
      const Eigen::Vector2d at = Eigen::Rotation2Dd(double(q["angle"])) * m + Eigen::Vector2d(q["x"], q["y"]);
      CHECK((at - c).norm() == Approx(num(p["radius"])).epsilon(1e-8));
    }
  }
  const json& fig = all["drawing"];
  CHECK(fig["svg"] == "burmester_svg.svg");
  CHECK(fig["drawn"] == json::array({"linkage", "task"}));
  std::ifstream in("burmester_svg.svg");
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(svg.rfind("<?xml", 0) == 0);
  CHECK(svg.find("</svg>") != std::string::npos);
  // A marker per position, per pair its centre and the circle point at each position, the two
  // ground pivots (the legend adds its own).
  std::size_t circles = 0;
  for (std::size_t k = svg.find("<circle"); k != std::string::npos; k = svg.find("<circle", k + 1)) ++circles;
  CHECK(circles >= 5 + 6 * out["count"].get<std::size_t>() + 2);
}

}  // namespace SOMA_UNITY_ID
