// soma::render plots: tick placement, the data -> pixel map, clipping, cells, fills, bad input.
#include "soma/render/render.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

namespace {
using namespace soma::render;

std::array<int, 3> rgb(const Image& img, double x, double yUp) {
  // Plot frames are in pixels with y up; images are stored top row first.
  const std::uint8_t* p = img.pixel(int(x), img.height - 1 - int(yUp));
  return {p[0], p[1], p[2]};
}
std::array<int, 3> rgb8(const Color& c) {
  return {int(std::lround(c.r * 255)), int(std::lround(c.g * 255)), int(std::lround(c.b * 255))};
}
Image renderPlot(const Plot& p, int w, int h, PlotFrame& f) {
  Camera cam;
  const Scene sc = plotScene(p, w, h, &cam, &f);
  RenderOptions o;
  o.width = w;
  o.height = h;
  o.samples = 2;
  o.camera = cam;
  return render(sc, o);
}
double px(const PlotFrame& f, double x) { return f.left + (x - f.xmin) / (f.xmax - f.xmin) * (f.right - f.left); }
double py(const PlotFrame& f, double y) { return f.bottom + (y - f.ymin) / (f.ymax - f.ymin) * (f.top - f.bottom); }
}  // namespace

TEST_CASE("niceTicks: 1-2-5 steps covering the range", "[render][plot]") {
  const auto t = niceTicks(0.0, 1.0, 5);
  REQUIRE(t.size() == 6);
  CHECK(t.front() == 0.0);
  CHECK(t.back() == Approx(1.0));
  CHECK(t[1] - t[0] == Approx(0.2));
  const auto u = niceTicks(-3.7, 12.2, 7);  // raw step 2.27 → 2.5: −2.5, 0, …, 10 (12.5 > 12.2)
  CHECK(u.front() == Approx(-2.5));
  CHECK(u.back() == Approx(10.0));
  for (std::size_t k = 1; k < u.size(); ++k) CHECK(u[k] - u[k - 1] == Approx(2.5));
  CHECK(niceTicks(1.0, 1.0).empty());
  CHECK(niceTicks(0.0, std::nan("")).empty());
  // Far from zero and tiny spans: still inside the range and evenly spaced.
  const auto v = niceTicks(1e8, 1e8 + 3, 3);
  REQUIRE(v.size() >= 3);
  for (double x : v) CHECK((x >= 1e8 && x <= 1e8 + 3));
}

TEST_CASE("tickLabel: decades as powers of ten, typographic minus", "[render][plot]") {
  CHECK(tickLabel(-8, AxisScale::Log10) == "10⁻⁸");
  CHECK(tickLabel(0, AxisScale::Log10) == "1");
  CHECK(tickLabel(12, AxisScale::Log10) == "10¹²");
  CHECK(tickLabel(-0.5, AxisScale::Linear) == "−0.5");
  CHECK(tickLabel(2.5, AxisScale::Linear) == "2.5");
}

TEST_CASE("plot: a curve lands on the pixels its data map to, clipped to the axes", "[render][plot]") {
  Plot p;
  p.x.min = 0, p.x.max = 10, p.y.min = 0, p.y.max = 10;
  p.grid = false;
  // A horizontal line at y = 5 that runs far outside the x range: it must be clipped, not dropped.
  p.add("", {-100, 100}, {5, 5}, palette::vermillion).width = 6;
  // A vertical line x = 2 on a series with a NaN gap between y = 4 and y = 6.
  p.add("", {2, 2, 2, 2}, {1, 4, std::nan(""), 9}, palette::blue).width = 6;
  PlotFrame f;
  const Image img = renderPlot(p, 600, 400, f);
  CHECK(f.xmin == 0);
  CHECK(f.xmax == 10);
  CHECK(rgb(img, px(f, 7), py(f, 5)) == rgb8(palette::vermillion));
  CHECK(rgb(img, px(f, 0.3), py(f, 5)) == rgb8(palette::vermillion));  // clipped at the left edge, still drawn
  CHECK(rgb(img, px(f, 2), py(f, 2.5)) == rgb8(palette::blue));
  CHECK(rgb(img, px(f, 2), py(f, 8.5)) == rgb8(palette::white));  // the gap (NaN) is not bridged
  CHECK(rgb(img, px(f, 7), py(f, 8)) == rgb8(palette::white));
  // Nothing of the curve outside the plot area (left margin at the line's height).
  CHECK(rgb(img, f.left - 30, py(f, 5)) == rgb8(palette::white));
}

TEST_CASE("plot: cells fill their rectangles, flat and unlit — log axes map decades evenly", "[render][plot]") {
  Plot p;
  p.grid = false;
  PlotCells c;
  c.x0 = 1, c.x1 = 1e4, c.y0 = 0, c.y1 = 2, c.nx = 3, c.ny = 2;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) c.cells.push_back(palette::cycle(std::size_t(j * 3 + i)));
  p.cells.push_back(c);
  p.x.scale = AxisScale::Log10;
  p.x.min = 1, p.x.max = 1e4, p.y.min = 0, p.y.max = 2;
  PlotFrame f;
  const Image img = renderPlot(p, 700, 500, f);
  // Cell (i, j) spans decades [10^(4i/3), 10^(4(i+1)/3)] in x: sample at its centre in log space.
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const double lx = 4.0 * (i + 0.5) / 3;
      const double x = f.left + lx / 4 * (f.right - f.left);
      CHECK(rgb(img, x, py(f, j + 0.5)) == rgb8(palette::cycle(std::size_t(j * 3 + i))));
    }
}

TEST_CASE("plot: equal aspect keeps circles round", "[render][plot]") {
  Plot p;
  p.equalAspect = true;
  std::vector<double> x, y;
  for (int k = 0; k < 200; ++k) {
    x.push_back(std::cos(2 * M_PI * k / 200));
    y.push_back(std::sin(2 * M_PI * k / 200));
  }
  p.add("circle", x, y, palette::blue).closed = true;
  PlotFrame f;
  (void)plotScene(p, 900, 500, nullptr, &f);
  const double sx = (f.right - f.left) / (f.xmax - f.xmin), sy = (f.top - f.bottom) / (f.ymax - f.ymin);
  CHECK(sx == Approx(sy).epsilon(1e-12));
  CHECK(f.xmin <= -1.0);
  CHECK(f.ymax >= 1.0);
}

TEST_CASE("plot: bad input is named", "[render][plot]") {
  Plot p;
  CHECK_THROWS_WITH(plotScene(p, 800, 600), Catch::Matchers::Contains("nothing to plot"));
  p.add("bad", {1, 2, 3}, {1, 2}, palette::blue);
  CHECK_THROWS_WITH(plotScene(p, 800, 600), Catch::Matchers::Contains("has 3 x and 2 y values"));
  p.series.clear();
  p.add("ok", {1, 2}, {1, 2}, palette::blue);
  p.y.scale = AxisScale::Log10;
  p.y.min = -1;
  CHECK_THROWS_WITH(plotScene(p, 800, 600), Catch::Matchers::Contains("not positive"));
  p.y.min = std::nan("");
  CHECK_THROWS_WITH(plotScene(p, 100, 600), Catch::Matchers::Contains("below 200"));
  PlotCells c;
  c.nx = 2, c.ny = 2;
  c.cells.resize(3);
  p.cells.push_back(c);
  CHECK_THROWS_WITH(plotScene(p, 800, 600), Catch::Matchers::Contains("3 colours for a 2×2 grid"));
  Fill bad;
  bad.v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  bad.tri = {{0, 1, 3}};
  Scene s;
  s.add(bad);
  CHECK_THROWS_WITH(s.validate(), Catch::Matchers::Contains("Fill[0].tri[0] refers to vertex 3"));
}

TEST_CASE("plot demo: curves, markers, legend, log axis, map", "[.demo][plot]") {
  const std::filesystem::path dir = "out/render-demo";
  std::filesystem::create_directories(dir);
  Plot p;
  p.title = "Demo: error vs angle";
  p.x.label = "θ (rad)";
  p.y.label = "error (ulps)";
  p.x.scale = AxisScale::Log10;
  std::vector<double> x, y1, y2;
  for (int k = 0; k <= 80; ++k) {
    x.push_back(std::pow(10.0, -8 + 8.5 * k / 80));
    y1.push_back(1 + 0.5 * std::sin(k * 0.3));
    y2.push_back(2 + 0.3 * std::cos(k * 0.2));
  }
  p.add("double", x, y1, palette::blue).markers = true;
  p.add("float128", x, y2, palette::vermillion).dashed = true;
  p.texts.push_back({1e-4, 2.6, "a note at (1e-4, 2.6)"});
  renderPlotPng(p, dir / "plot-demo.png", 1000, 650);
  Plot m;
  m.title = "Demo: a map";
  m.x.label = "first parameter";
  m.y.label = "second parameter";
  PlotCells c;
  c.nx = c.ny = 60;
  c.x0 = 0, c.x1 = 3, c.y0 = 0, c.y1 = 2;
  for (int j = 0; j < 60; ++j)
    for (int i = 0; i < 60; ++i) c.cells.push_back(colorMap(0.5 + 0.5 * std::sin(i * 0.1) * std::cos(j * 0.12)));
  m.cells.push_back(c);
  m.legendSwatches.emplace_back("low", colorMap(0));
  m.legendSwatches.emplace_back("high", colorMap(1));
  renderPlotPng(m, dir / "plot-map-demo.png", 900, 700);
  CHECK(std::filesystem::exists(dir / "plot-map-demo.png"));
}

TEST_CASE("plot: log ticks on a wide range fall on round multiples of decades", "[render][plot]") {
  Plot p;
  p.y.scale = AxisScale::Log10;
  p.y.min = 1e-79, p.y.max = 1e1;
  p.add("", {0, 1}, {1e-70, 1}, palette::blue);
  Scene s = plotScene(p, 800, 600);
  std::vector<std::string> labels;
  for (const auto& l : s.labels) labels.push_back(l.text);
  // 80 decades with about 5 ticks: every 20th decade, at 10⁻⁶⁰, 10⁻⁴⁰, 10⁻²⁰, 1.
  for (const char* want : {"10⁻⁶⁰", "10⁻⁴⁰", "10⁻²⁰", "1"})
    CHECK(std::find(labels.begin(), labels.end(), std::string(want)) != labels.end());
  CHECK(std::find(labels.begin(), labels.end(), std::string("10⁻¹⁹")) == labels.end());
}

TEST_CASE("plot: the legend goes to the chosen corner", "[render][plot]") {
  for (const auto corner : {LegendCorner::TopRight, LegendCorner::TopLeft, LegendCorner::BottomRight, LegendCorner::BottomLeft}) {
    Plot p;
    p.legend = corner;
    p.x.min = p.y.min = 0;
    p.x.max = p.y.max = 1;
    p.add("the series", {0.45, 0.55}, {0.5, 0.52}, palette::blue);  // every corner free
    PlotFrame f;
    const Scene s = plotScene(p, 800, 600, nullptr, &f);
    const auto it = std::find_if(s.labels.begin(), s.labels.end(), [](const Label& l) { return l.text == "the series"; });
    REQUIRE(it != s.labels.end());
    const bool right = corner == LegendCorner::TopRight || corner == LegendCorner::BottomRight;
    const bool topSide = corner == LegendCorner::TopRight || corner == LegendCorner::TopLeft;
    const double cx = (f.left + f.right) / 2, cy = (f.bottom + f.top) / 2;
    CHECK((it->at.x() > cx) == right);
    CHECK((it->at.y() > cy) == topSide);
    CHECK(it->at.x() > f.left);
    CHECK(it->at.x() < f.right);
  }
}

namespace {
/// Whether any point of the plot's series (its vertices, and its segments sampled every half pixel)
/// or any text anchor lies inside the legend box: an independent check of the placement.
bool dataUnderLegend(const Plot& p, const PlotFrame& f) {
  auto inBox = [&](double x, double y) {
    return x >= f.legendLeft && x <= f.legendRight && y >= f.legendBottom && y <= f.legendTop && x >= f.left &&
           x <= f.right && y >= f.bottom && y <= f.top;
  };
  for (const PlotSeries& s : p.series)
    for (std::size_t k = 0; k < s.x.size(); ++k) {
      const double x = px(f, s.x[k]), y = py(f, s.y[k]);
      if (inBox(x, y)) return true;
      if (!s.line || k + 1 == s.x.size()) continue;
      const double x1 = px(f, s.x[k + 1]), y1 = py(f, s.y[k + 1]);
      const int n = 2 * int(std::ceil(std::hypot(x1 - x, y1 - y))) + 1;
      for (int j = 0; j <= n; ++j)
        if (inBox(x + (x1 - x) * j / n, y + (y1 - y) * j / n)) return true;
    }
  for (const PlotText& t : p.texts)
    if (inBox(px(f, t.x), py(f, t.y))) return true;
  return false;
}
}  // namespace

TEST_CASE("plot: the legend is placed where no data lies under it", "[render][plot][legend]") {
  SECTION("a curve through the preferred corner moves the legend") {
    Plot p;
    p.legend = LegendCorner::TopRight;
    std::vector<double> xs, ys;
    for (int k = 0; k <= 100; ++k) xs.push_back(k / 100.0), ys.push_back(std::pow(k / 100.0, 3));  // fills top right
    p.add("x³", xs, ys, palette::blue);
    p.add("a point", {0.05}, {0.9}, palette::vermillion).markers = true;  // and one in the top left
    p.series.back().line = false;
    PlotFrame f;
    plotScene(p, 900, 700, nullptr, &f);
    REQUIRE(f.legend);
    CHECK(f.legendInside);
    CHECK_FALSE(dataUnderLegend(p, f));
  }
  SECTION("points in every corner: an edge middle") {
    Plot p;
    p.add("corners", {0, 1, 0, 1, 0.5}, {0, 0, 1, 1, 0.5}, palette::blue).markers = true;
    p.series.back().line = false;
    p.texts.push_back({0.5, 0.5, "centre"});
    PlotFrame f;
    plotScene(p, 900, 700, nullptr, &f);
    REQUIRE(f.legend);
    CHECK(f.legendInside);
    CHECK_FALSE(dataUnderLegend(p, f));
  }
  SECTION("data everywhere: the legend goes right of the plot area") {
    Plot p;
    std::vector<double> xs, ys;
    for (int i = 0; i <= 30; ++i)
      for (int j = 0; j <= 30; ++j) xs.push_back(i / 30.0), ys.push_back(j / 30.0);
    auto& s = p.add("a dense grid", xs, ys, palette::blue);
    s.line = false;
    s.markers = true;
    PlotFrame f;
    plotScene(p, 900, 700, nullptr, &f);
    REQUIRE(f.legend);
    CHECK_FALSE(f.legendInside);
    CHECK(f.legendLeft > f.right);
    CHECK(f.legendRight < 900);
    CHECK_FALSE(dataUnderLegend(p, f));
  }
  SECTION("data everywhere and a wide legend: below the plot area") {
    Plot p;
    std::vector<double> xs, ys;
    for (int i = 0; i <= 30; ++i)
      for (int j = 0; j <= 30; ++j) xs.push_back(i / 30.0), ys.push_back(j / 30.0);
    auto& s = p.add("a dense grid with a name much longer than a third of the image", xs, ys, palette::blue);
    s.line = false;
    s.markers = true;
    p.x.label = "x";
    PlotFrame f;
    plotScene(p, 900, 700, nullptr, &f);
    REQUIRE(f.legend);
    CHECK_FALSE(f.legendInside);
    CHECK(f.legendTop < f.bottom - 60);  // under the ticks and the x label
    CHECK(f.legendBottom >= 0);
    CHECK(f.right - f.left > 600);       // the plot keeps its width
    CHECK_FALSE(dataUnderLegend(p, f));
  }
  SECTION("random scatters never sit under the legend") {
    std::uint32_t seed = 12345;
    auto next = [&] { return (seed = seed * 1664525u + 1013904223u) / 4294967296.0; };
    for (int trial = 0; trial < 40; ++trial) {
      Plot p;
      p.legend = LegendCorner(trial % 4);
      std::vector<double> xs, ys;
      const int n = 5 + trial * 5;
      for (int k = 0; k < n; ++k) xs.push_back(next()), ys.push_back(next());
      p.add("scatter", xs, ys, palette::blue).line = trial % 2 == 0;
      PlotFrame f;
      plotScene(p, 800, 600, nullptr, &f);
      INFO("trial " << trial);
      CHECK_FALSE(dataUnderLegend(p, f));
    }
  }
}

TEST_CASE("plot: a colour bar right of the plot area, labelled from min to max", "[render][plot]") {
  Plot p;
  PlotCells c;
  c.nx = c.ny = 2;
  c.cells = {colorMap(0), colorMap(0.3), colorMap(0.6), colorMap(1)};
  p.cells.push_back(c);
  p.colorBar = PlotColorBar{"σmin/σmax", 0, 0.2};
  PlotFrame f;
  const Scene s = plotScene(p, 900, 700, nullptr, &f);
  CHECK(f.colorBarLeft > f.right);
  CHECK(f.colorBarRight < 900);
  auto has = [&](const std::string& t) {
    return std::any_of(s.labels.begin(), s.labels.end(), [&](const Label& l) { return l.text == t; });
  };
  CHECK(has("σmin/σmax"));
  CHECK(has("0"));
  CHECK(has("0.2"));
  p.colorBar = PlotColorBar{"bad", 1, 1};
  CHECK_THROWS_WITH(plotScene(p, 900, 700), Catch::Contains("colour bar"));
}

TEST_CASE("plot: a title wider than the image is set smaller", "[render][plot]") {
  Plot p;
  p.add("", {0, 1}, {0, 1}, palette::blue);
  p.title = std::string(120, 'x');
  const Scene s = plotScene(p, 1000, 700);
  CHECK(0.6 * s.titlePixelHeight * 120 <= 1000 - 30 + 1e-9);
  p.title = "short";
  CHECK(plotScene(p, 1000, 700).titlePixelHeight == Scene().titlePixelHeight);
}

}  // namespace SOMA_UNITY_ID
