// Demonstration figures and timing of soma::render (hidden tags: run with "[.demo]" or "[.bench]").
//   build/<dir>/tests/test_render "[.demo]"   -> out/render-demo/helix.png, hyperboloid.png
//   build/<dir>/tests/test_render "[.bench]"  -> ms per 1200x900 frame, Supersample vs Accumulate
#include "soma/render/render.hpp"

#include <catch2/catch.hpp>

#include "support/repo_file.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <numbers>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

namespace {
using namespace soma::render;
constexpr double pi = std::numbers::pi;

/// A screw motion about the z axis: rotation by angle t and translation pitch * t along z,
/// applied to the point (radius, 0, 0) and to the identity frame placed there.
Eigen::Matrix4d screw(double t, double pitch) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = Eigen::AngleAxisd(t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  m(2, 3) = pitch * t;
  return m;
}

Scene helixScene() {
  const double radius = 1, pitch = 0.25, turns = 2;
  const Eigen::Matrix4d start = [&] {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m(0, 3) = radius;
    return m;
  }();
  Scene s;
  s.title = "Screw motion about z: a helix swept by a frame";
  Tube helix;
  helix.c = palette::reddishPurple;  // apart from the frames' axis colours
  const int n = 400;
  for (int k = 0; k <= n; ++k) {
    const double t = 2 * pi * turns * k / n;
    helix.p.push_back((screw(t, pitch) * start).block<3, 1>(0, 3));
  }
  s.add(helix);
  for (int k = 0; k <= 4; ++k) {
    const double t = 2 * pi * turns * k / 4;
    Frame f;
    f.pose = screw(t, pitch) * start;
    s.add(f);
  }
  Polyline axis;
  axis.p = {{0, 0, -0.3}, {0, 0, 2 * pi * turns * pitch + 0.5}};
  axis.dashed = true;
  axis.c = palette::darkGrey;
  axis.width = 2;
  s.add(axis);
  Label l;
  l.text = "screw axis";
  l.at = axis.p[1];
  l.hAlign = HAlign::Center;
  l.offset = {0, -8};
  s.add(l);
  Label a;
  a.text = "t = 0";
  a.at = start.block<3, 1>(0, 3);
  a.offset = {-12, -8};
  a.hAlign = HAlign::Right;
  s.add(a);
  Label b;
  b.text = "t = 4π";
  b.at = (screw(2 * pi * turns, pitch) * start).block<3, 1>(0, 3);
  b.offset = {10, -10};
  s.add(b);
  s.axes = true;
  s.axesLength = 0.6;  // inside the helix, clear of the first frame
  return s;
}

Scene hyperboloidScene() {
  // Hyperboloid of one sheet x^2 + y^2 - z^2 = 1 through its rulings: u sweeps the waist circle,
  // v runs along the ruling (-sin u, cos u, 1) through it.
  const SurfaceMap f = [](double u, double v) {
    return Eigen::Vector3d(std::cos(u) - v * std::sin(u), std::sin(u) + v * std::cos(u), v);
  };
  Scene s;
  s.title = "Hyperboloid of one sheet and one family of its rulings";
  s.add(parametricSurface(f, {0, 2 * pi}, {-1, 1}, 96, 24, palette::skyBlue));
  s.add(parametricIsolines(f, {0, 2 * pi}, {-1, 1}, 0, 5, 192, palette::darkGrey, 1.5));  // v = const: circles
  s.add(parametricIsolines(f, {0, 2 * pi}, {-1, 1}, 25, 0, 2, palette::vermillion, 1.5));  // u = const: rulings
  Label w;
  w.text = "waist circle";
  w.at = f(-pi / 4, 0);
  w.offset = {8, 6};
  w.vAlign = VAlign::Top;
  s.add(w);
  s.axes = true;
  s.axesLength = 1.8;  // long enough to come out of the surface
  return s;
}

std::filesystem::path demoDir() {
  const char* env = std::getenv("SOMA_RENDER_DEMO_DIR");
  if (env && *env) return env;
  // <source>/tests/render/demo.cpp -> <source>/out/render-demo
  return soma::test::repoFile("out/render-demo");
}
}  // namespace

TEST_CASE("render demo figures", "[.demo]") {
  const auto dir = demoDir();
  std::filesystem::create_directories(dir);
  RenderOptions o;  // 1200 x 900, Supersample x4
  const auto t0 = std::chrono::steady_clock::now();
  renderPng(helixScene(), o, dir / "helix.png");
  const auto t1 = std::chrono::steady_clock::now();
  renderPng(hyperboloidScene(), o, dir / "hyperboloid.png");
  const auto t2 = std::chrono::steady_clock::now();
  std::printf("helix %.0f ms (first render, includes context creation), hyperboloid %.0f ms\n",
              std::chrono::duration<double, std::milli>(t1 - t0).count(),
              std::chrono::duration<double, std::milli>(t2 - t1).count());
  CHECK(readPng(dir / "helix.png").width == 1200);
  CHECK(readPng(dir / "hyperboloid.png").height == 900);
}

TEST_CASE("render cost of a point cloud", "[.bench]") {
  Scene s;
  Points cloud;
  std::uint64_t state = 12345;
  auto uniform = [&state] {  // a fixed-seed linear congruential generator
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) / double(1ull << 53);
  };
  for (int k = 0; k < 100000; ++k) cloud.p.emplace_back(uniform(), uniform(), uniform());
  s.add(cloud);
  for (int samples : {1, 2, 4}) {
    RenderOptions o;
    o.samples = samples;
    render(s, o);
    const std::clock_t c0 = std::clock();
    const auto t0 = std::chrono::steady_clock::now();
    render(s, o);
    const auto t1 = std::chrono::steady_clock::now();
    const std::clock_t c1 = std::clock();
    std::printf("100000 points, Supersample samples=%d: %.0f ms wall, %.0f ms CPU per 1200x900 frame\n", samples,
                std::chrono::duration<double, std::milli>(t1 - t0).count(), 1000.0 * double(c1 - c0) / CLOCKS_PER_SEC);
  }
}

TEST_CASE("render anti-aliasing cost", "[.bench]") {
  const Scene scenes[2] = {helixScene(), hyperboloidScene()};
  render(scenes[0], RenderOptions{});  // warm up: context, shader compilation
  for (auto aa : {AntiAliasing::Supersample, AntiAliasing::Accumulate})
    for (int samples : {1, 2, 4}) {
      RenderOptions o;
      o.antiAliasing = aa;
      o.samples = samples;
      for (int k = 0; k < 2; ++k) {
        render(scenes[k], o);  // warm up this configuration
        const int reps = 3;
        const std::clock_t c0 = std::clock();
        const auto t0 = std::chrono::steady_clock::now();
        for (int r = 0; r < reps; ++r) render(scenes[k], o);
        const auto t1 = std::chrono::steady_clock::now();
        const std::clock_t c1 = std::clock();
        // Wall time, and CPU time of all threads (llvmpipe rasterises on every core).
        std::printf("%-11s samples=%d %-11s %7.1f ms wall %7.1f ms CPU per 1200x900 frame\n",
                    aa == AntiAliasing::Supersample ? "Supersample" : "Accumulate", samples,
                    k == 0 ? "helix" : "hyperboloid",
                    std::chrono::duration<double, std::milli>(t1 - t0).count() / reps,
                    1000.0 * double(c1 - c0) / CLOCKS_PER_SEC / reps);
      }
    }
}

}  // namespace SOMA_UNITY_ID
