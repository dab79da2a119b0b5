// `soma fk|ik|stewart --png FILE --svg FILE` (issue 25 item 4; cli/posture_figure.hpp): a panel per
// posture found, one camera for all. Checked against the command's own JSON answer run separately:
// the panel count equals the posture count, each panel title carries that posture's joint values
// (rounded to 0.1°), every panel has drawn pixels, the SVG has the same titles; a figure that cannot
// be written exits 2 and prints no answer.
#include "soma/render/image.hpp"

#include "support/repo_file.hpp"
#include "support/run_soma.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <sys/wait.h>

namespace SOMA_UNITY_ID {

namespace {

std::string run(const std::string& args, int& rc) { return soma::test::runSoma(args, rc); }

std::string slurp(const std::filesystem::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::filesystem::path scratch(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("soma_cli_figures_" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d / name;
}

/// Non-white pixels inside panel k of a grid with `cols` columns (56-pixel banner, 420 × 440 panels).
int inkOfPanel(const soma::render::Image& im, int k, int cols) {
  const int x0 = (k % cols) * 420, y0 = 56 + (k / cols) * 440;
  int ink = 0;
  for (int y = y0 + 30; y < y0 + 440 - 2; ++y)
    for (int x = x0 + 2; x < x0 + 420 - 2; ++x) {
      const std::uint8_t* p = im.pixel(x, y);
      if (p[0] < 200 || p[1] < 200 || p[2] < 200) ++ink;
    }
  return ink;
}

}  // namespace

TEST_CASE("ik --png --svg: the PUMA 560's 8 postures, a panel each, titled with the JSON's joint values", "[cli][figures]") {
  const std::string robot = soma::test::repoFile("studies/robots/puma560_nolimits.json").string();
  const std::string pose = soma::test::repoFile("studies/robots/puma560_pose.json").string();
  int rc = -1;
  const auto answer = nlohmann::json::parse(run("ik " + robot + " --pose " + pose + " --json", rc));
  REQUIRE(rc == 0);
  const auto& sols = answer.at("solutions");
  REQUIRE(sols.size() == 8);
  const auto png = scratch("ik.png"), svg = scratch("ik.svg");
  run("ik " + robot + " --pose " + pose + " --png " + png.string() + " --svg " + svg.string(), rc);
  REQUIRE(rc == 0);
  const soma::render::Image im = soma::render::readPng(png);
  CHECK(im.width == 4 * 420);
  CHECK(im.height == 56 + 2 * 440);
  for (int k = 0; k < 8; ++k) {
    INFO("panel " << k + 1);
    CHECK(inkOfPanel(im, k, 4) > 500);
  }
  const std::string text = slurp(svg);
  for (std::size_t k = 0; k < sols.size(); ++k) {
    std::string joints;
    for (std::size_t i = 0; i < 6; ++i) {
      const auto& v = sols[k].at("joints")[i];
      const double d = v.is_string() ? std::stod(v.get<std::string>()) : v.get<double>();
      joints += fmt::format("{}{:.1f}", i ? ", " : "", d);
    }
    INFO("posture " << k + 1 << ": " << joints);
    CHECK(text.find(fmt::format("{}: ({})°", k + 1, joints)) != std::string::npos);
  }
  CHECK(text.find("<polyline") != std::string::npos);
}

TEST_CASE("stewart --png and fk --svg: a panel per real posture — the robot at its joints", "[cli][figures]") {
  const std::string platform = soma::test::repoFile("studies/platforms/general.json").string();
  int rc = -1;
  const auto answer = nlohmann::json::parse(run("stewart " + platform + " --json", rc));
  REQUIRE(rc == 0);
  const int n = int(answer.at("count").get<int>());
  REQUIRE(n == 8);
  const auto png = scratch("stewart.png");
  run("stewart " + platform + " --png " + png.string(), rc);
  REQUIRE(rc == 0);
  const soma::render::Image im = soma::render::readPng(png);
  CHECK(im.width == 4 * 420);
  CHECK(im.height == 56 + 2 * 440);
  for (int k = 0; k < n; ++k) CHECK(inkOfPanel(im, k, 4) > 500);

  const auto svg = scratch("fk.svg");
  run("fk " + soma::test::repoFile("studies/robots/puma560.json").string() + " --joints 10,20,30,40,50,60 --svg " + svg.string(), rc);
  REQUIRE(rc == 0);
  const std::string text = slurp(svg);
  CHECK(text.find("1: (10.0, 20.0, 30.0, 40.0, 50.0, 60.0)°") != std::string::npos);
  // The chain's links, the three tool-frame axes and the panel: at least 8 line segments.
  std::size_t lines = 0;
  for (std::size_t at = text.find("<polyline"); at != std::string::npos; at = text.find("<polyline", at + 1)) ++lines;
  CHECK(lines >= 8);
}

TEST_CASE("ik --png to a folder that does not exist: exit 2, no answer printed", "[cli][figures]") {
  int rc = -1;
  const std::string out = run("ik " + soma::test::repoFile("studies/robots/puma560.json").string() + " --pose " +
                                  soma::test::repoFile("studies/robots/puma560_pose.json").string() + " --png /nonexistent/dir/ik.png",
                              rc);
  CHECK(rc == 2);
  CHECK(out.empty());
}

}  // namespace SOMA_UNITY_ID
