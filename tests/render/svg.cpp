// SVG of 2-D figures (render/svg.hpp): the plot's PNG layout written as vector elements.
#include "soma/render/svg.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <stdexcept>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

namespace {
using namespace soma::render;
std::string fmt2(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}
std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t k = s.find(what); k != std::string::npos; k = s.find(what, k + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("plotSvg: curves and markers at the PNG's pixel positions, y flipped", "[render][svg]") {
  Plot p;
  p.title = "a <b> & c";
  p.add("line", {0, 1, 2}, {0, 2, 1}, palette::blue);
  PlotSeries& m = p.add("", {1.5}, {0.5}, palette::vermillion);
  m.line = false;
  m.markers = true;
  m.markerRadius = 7;
  const int w = 640, h = 480;
  PlotFrame f{};
  (void)plotScene(p, w, h, nullptr, &f);
  const std::string svg = plotSvg(p, w, h);
  auto X = [&](double x) { return f.left + (x - f.xmin) / (f.xmax - f.xmin) * (f.right - f.left); };
  auto Y = [&](double y) { return h - (f.bottom + (y - f.ymin) / (f.ymax - f.ymin) * (f.top - f.bottom)); };
  // The curve's vertices, by the frame's map written out here.
  const std::string pts = fmt2(X(0)) + "," + fmt2(Y(0)) + " " + fmt2(X(1)) + "," + fmt2(Y(2)) + " " + fmt2(X(2)) + "," + fmt2(Y(1));
  CHECK(svg.find("points=\"" + pts + "\"") != std::string::npos);
  CHECK(svg.find("stroke=\"#0072b2\"") != std::string::npos);  // palette::blue
  // The marker: a circle of its radius at (1.5, 0.5).
  CHECK(svg.find("<circle cx=\"" + fmt2(X(1.5)) + "\" cy=\"" + fmt2(Y(0.5)) + "\" r=\"7.00\"") != std::string::npos);
  CHECK(svg.find("a &lt;b&gt; &amp; c</text>") != std::string::npos);
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(count(svg, "<svg ") == 1);
  CHECK(count(svg, "</svg>") == 1);
  CHECK(svg.find("width=\"640\" height=\"480\"") != std::string::npos);
}

TEST_CASE("sceneSvg: a scene with 3-D primitives has no SVG", "[render][svg]") {
  Scene sc;
  sc.add(Tube{{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0)}, 0.1, palette::blue, false});
  CHECK_THROWS_AS(sceneSvg(sc, 300, 200), std::invalid_argument);
  Plot empty;
  CHECK_THROWS_AS(plotSvg(empty, 300, 200), std::invalid_argument);
}

}  // namespace SOMA_UNITY_ID
