// The scene script for the report's 3-D viewer: the primitives with sizes resolved as the renderer
// resolves them, groups by kind or by name, text escaped.
#include "soma/render/render.hpp"
#include "soma/render/scene_js.hpp"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

using namespace soma::render;

namespace {
/// The JSON inside "somaScene(…);".
nlohmann::json payload(const std::string& js) {
  REQUIRE(js.rfind("somaScene(", 0) == 0);
  REQUIRE(js.size() > 13);
  REQUIRE(js.substr(js.size() - 3) == ");\n");
  return nlohmann::json::parse(js.substr(10, js.size() - 13));
}
}  // namespace

TEST_CASE("scene script: groups by kind, automatic sizes resolved, text escaped", "[render][scene_js]") {
  Scene s;
  s.title = "a \"title\" </script>";
  s.add(Tube{{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0)}});
  s.add(Points{{Eigen::Vector3d(0, 1, 0)}, palette::blue, 0.25});
  s.add(Frame{});
  Label l;
  l.text = "θ₁ \\ \"q\"";
  s.add(l);
  const auto j = payload(sceneJs(s));
  CHECK(j["title"] == "a \"title\" </script>");
  std::vector<std::string> names;
  for (const auto& g : j["groups"]) names.push_back(g["name"]);
  CHECK(names == std::vector<std::string>{"tubes", "points", "arrows", "labels"});  // empty kinds left out
  const double L = s.characteristicLength();
  CHECK(j["groups"][0]["tubes"][0]["r"].get<double>() == Approx(autosize::tubeRadius * L).epsilon(1e-5));
  CHECK(j["groups"][1]["points"][0]["r"].get<double>() == Approx(0.25));
  CHECK(j["groups"][2]["arrows"].size() == 3);  // a frame is three arrows
  CHECK(j["groups"][2]["arrows"][0]["to"][0].get<double>() == Approx(autosize::frameScale * L).epsilon(1e-5));
  CHECK(j["groups"][3]["labels"][0]["text"] == "θ₁ \\ \"q\"");
  CHECK(sceneJs(s).find("</script") == std::string::npos);  // safe inside a page
}

TEST_CASE("scene script: named scenes are one group each", "[render][scene_js]") {
  std::vector<std::pair<std::string, Scene>> v;
  for (int k = 0; k < 3; ++k) {
    Scene s;
    s.add(Tube{{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, k, 0)}, 0.1});
    v.emplace_back("posture " + std::to_string(k + 1), s);
  }
  const auto j = payload(sceneJs(v, "three"));
  CHECK(j["title"] == "three");
  REQUIRE(j["groups"].size() == 3);
  CHECK(j["groups"][2]["name"] == "posture 3");
  CHECK(j["bounds"][1][1].get<double>() >= 2.0);
}

}  // namespace SOMA_UNITY_ID
