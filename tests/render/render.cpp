// soma::render: pixels of small rendered scenes, PNG round trip, bad input.
#include "soma/render/render.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <thread>

namespace SOMA_UNITY_ID {  // this file's names stay its own in a unity batch (tests/CMakeLists.txt)

// The expression throws `type` and its message contains `text` (Catch2 v2 checks these separately).
#define CHECK_THROWS_CONTAINING(expr, type, text) \
  do {                                            \
    CHECK_THROWS_AS(expr, type);                  \
    CHECK_THROWS_WITH(expr, Catch::Matchers::Contains(text)); \
  } while (false)

namespace {
using namespace soma::render;

std::array<int, 4> px(const Image& img, int x, int y) {
  const std::uint8_t* p = img.pixel(x, y);
  return {p[0], p[1], p[2], p[3]};
}
std::array<int, 4> rgba8(const Color& c) {
  return {int(std::lround(c.r * 255)), int(std::lround(c.g * 255)), int(std::lround(c.b * 255)), int(std::lround(c.a * 255))};
}
double toLinear(double u8) {
  const double u = u8 / 255;
  return u <= 0.04045 ? u / 12.92 : std::pow((u + 0.055) / 1.055, 2.4);
}
/// A small image with an explicit camera.
RenderOptions small(const Camera& cam, int w = 160, int h = 120, int samples = 2,
                    AntiAliasing aa = AntiAliasing::Supersample) {
  RenderOptions o;
  o.width = w;
  o.height = h;
  o.samples = samples;
  o.antiAliasing = aa;
  o.camera = cam;
  return o;
}
/// Looking down the z axis at the plane z = 0 (x right, y up), window `height` world units tall.
Camera topOrtho(double height = 2) { return Camera::ortho({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, height); }

/// A square in the plane z = 0 (normal +z), rotated by `angle` about z.
Mesh square(double half, const Eigen::Vector3d& centre, Color c, double angle = 0) {
  Mesh m;
  m.c = c;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (auto [x, y] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) m.v.push_back(centre + R * Eigen::Vector3d(x * half, y * half, 0));
  m.tri = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

/// The documented lighting model (render/README.md) for a surface whose eye-space normal points
/// at the viewer: colour * (ambient + key diffuse n.L0 + fill diffuse n.L1) + key specular (n.H0)^shininess.
std::array<double, 3> litFacingViewer(const Color& c) {
  const Eigen::Vector3d n(0, 0, 1), L0 = Eigen::Vector3d(-0.25, 0.35, 1).normalized(),
                        L1 = Eigen::Vector3d(0.4, -0.6, 0.6).normalized();
  const Eigen::Vector3d H0 = (L0 + Eigen::Vector3d::UnitZ()).normalized();
  const double diffuse = 0.32 + 0.55 * n.dot(L0) + 0.30 * n.dot(L1);
  const double spec = 0.15 * std::pow(n.dot(H0), 40.0);
  return {c.r * diffuse + spec, c.g * diffuse + spec, c.b * diffuse + spec};
}

/// Centroid (pixels, centres at +0.5) of the pixels that differ from the background, weighted by
/// how much they differ (in linear light).
Eigen::Vector2d centroid(const Image& img, const std::array<int, 4>& bg) {
  double sw = 0, sx = 0, sy = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const auto p = px(img, x, y);
      double w = 0;
      for (int k = 0; k < 3; ++k) w += std::abs(toLinear(p[k]) - toLinear(bg[k]));
      sw += w, sx += w * (x + 0.5), sy += w * (y + 0.5);
    }
  REQUIRE(sw > 0);
  return {sx / sw, sy / sw};
}

struct EnvGuard {  // sets an environment variable for a scope, restoring the previous value
  std::string name;
  std::optional<std::string> old;
  EnvGuard(const char* n, const char* value) : name(n) {
    if (const char* v = std::getenv(n)) old = v;
    if (value) ::setenv(n, value, 1);
    else ::unsetenv(n);
  }
  ~EnvGuard() {
    if (old) ::setenv(name.c_str(), old->c_str(), 1);
    else ::unsetenv(name.c_str());
  }
};
}  // namespace

TEST_CASE("render: background corners, headless", "[render]") {
  EnvGuard noDisplay("DISPLAY", nullptr);  // OSMesa needs no display server
  Scene s;
  s.background = Color::hex(0x336699);
  s.add(sphere({0, 0, 0}, 0.5, palette::orange));
  const auto bg = rgba8(s.background);
  for (auto aa : {AntiAliasing::Supersample, AntiAliasing::Accumulate})
    for (int samples : {1, 3}) {
      const Image img = render(s, small(Camera::lookAt({4, 0, 0}, {0, 0, 0}), 96, 64, samples, aa));
      REQUIRE(img.width == 96);
      REQUIRE(img.height == 64);
      REQUIRE(img.rgba.size() == 96u * 64u * 4u);
      for (auto [x, y] : {std::pair{0, 0}, {95, 0}, {0, 63}, {95, 63}}) CHECK(px(img, x, y) == bg);
      CHECK(px(img, 48, 32) != bg);  // the sphere is there
    }
}

TEST_CASE("render: a sphere at the centre is lit by the documented model", "[render]") {
  for (const Color c : {palette::orange, palette::skyBlue, Color{0.8f, 0.4f, 0.2f}}) {
    Scene s;
    s.add(sphere({0, 0, 0}, 0.5, c, 96, 48));
    // Odd size: the centre pixel's centre is exactly on the optical axis.
    const Image img = render(s, small(Camera::lookAt({4, 0, 0}, {0, 0, 0}), 81, 61, 2));
    const auto p = px(img, 40, 30);
    const auto want = litFacingViewer(c);
    for (int k = 0; k < 3; ++k) CHECK(std::abs(p[k] - std::clamp(want[k], 0.0, 1.0) * 255) <= 2.0);
    CHECK(p[3] == 255);
  }
}

TEST_CASE("render: depth test, whatever the drawing order", "[render]") {
  const Mesh front = square(0.5, {0, 0, 1}, palette::vermillion), back = square(0.5, {0.3, 0.3, 0}, palette::blue);
  for (bool frontFirst : {true, false}) {
    Scene s;
    if (frontFirst) s.add(front), s.add(back);
    else s.add(back), s.add(front);
    const Image img = render(s, small(topOrtho(), 80, 80, 1));
    // Overlap of the two squares at (0.2, 0.2) -> pixel (48, 31): the front (vermillion) square wins.
    const auto overlap = px(img, 48, 31);
    const auto onlyBack = px(img, 62, 17);  // (0.6, 0.6): only the blue square
    const auto want = litFacingViewer(palette::vermillion);
    for (int k = 0; k < 3; ++k) CHECK(std::abs(overlap[k] - std::clamp(want[k], 0.0, 1.0) * 255) <= 2.0);
    CHECK(onlyBack[2] > onlyBack[0] + 100);  // blue there
  }
}

TEST_CASE("render: transparent meshes blend over opaque ones", "[render]") {
  Scene s;
  s.add(square(0.6, {0, 0, 0}, palette::blue));
  s.add(square(0.3, {0, 0, 1}, palette::vermillion.withAlpha(0.5f)));
  const Image img = render(s, small(topOrtho(), 80, 80, 1));
  const auto mixed = px(img, 40, 40), blue = px(img, 40, 20);
  const auto red = litFacingViewer(palette::vermillion), b = litFacingViewer(palette::blue);
  // Blending happens on the stored (sRGB-encoded) values: half of each.
  for (int k = 0; k < 3; ++k) CHECK(std::abs(mixed[k] - (0.5 * red[k] + 0.5 * b[k]) * 255) <= 2.0);
  CHECK(blue == px(img, 20, 40));
  const auto wantBlue = litFacingViewer(palette::blue);
  for (int k = 0; k < 3; ++k) CHECK(std::abs(blue[k] - std::clamp(wantBlue[k], 0.0, 1.0) * 255) <= 2.0);
}

TEST_CASE("render: a label makes dark pixels near its anchor, and only there", "[render]") {
  Scene s;
  Label l;
  l.at = {-0.5, 0.5, 0};
  l.text = "Hg";
  l.pixelHeight = 24;
  l.halo = false;
  s.add(l);
  const Camera cam = topOrtho();
  const Image img = render(s, small(cam, 160, 160, 1));
  const Eigen::Vector2d a = cam.project(l.at, 160, 160);  // (40, 40); box corner (Left, Bottom) at a + (6, -6)
  int nearDark = 0, farDark = 0;
  for (int y = 0; y < 160; ++y)
    for (int x = 0; x < 160; ++x) {
      const auto p = px(img, x, y);
      if (p[0] + p[1] + p[2] > 3 * 100) continue;
      const bool inBox = x >= a.x() + 6 - 1 && x <= a.x() + 6 + 40 && y >= a.y() - 6 - 32 && y <= a.y() - 6 + 1;
      (inBox ? nearDark : farDark)++;
    }
  CHECK(nearDark > 40);
  CHECK(farDark == 0);
}

TEST_CASE("render: a point lands where Camera::project says", "[render]") {
  const Eigen::Vector3d p(0.31, -0.22, 0.17);
  Scene s;
  s.add(Points{{p}, palette::black, 0.03});
  const Camera persp = Camera::lookAt({3, 2, 1.5}, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 30);
  const Camera ortho = Camera::ortho({3, 2, 1.5}, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 1.5);
  for (const Camera& cam : {persp, ortho})
    for (auto aa : {AntiAliasing::Supersample, AntiAliasing::Accumulate}) {
      const int w = 200, h = 150;
      const Image img = render(s, small(cam, w, h, 4, aa));
      const Eigen::Vector2d want = cam.project(p, w, h);
      const Eigen::Vector2d got = centroid(img, rgba8(s.background));
      INFO("orthographic " << cam.orthographic << ", want " << want.transpose() << ", got " << got.transpose());
      CHECK((got - want).norm() < 1.0);
      CHECK((got - want).norm() < 0.25);  // in fact well within a quarter pixel
    }
}

TEST_CASE("render: anti-aliasing makes intermediate values on an edge", "[render]") {
  Scene s;
  s.background = palette::white;
  s.add(square(0.5, {0, 0, 0}, palette::black, 0.2));  // a slanted black square
  auto levels = [](const Image& img) {
    std::set<int> v;
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) v.insert(img.rgba[i]);
    return v;
  };
  const Image none = render(s, small(topOrtho(), 64, 64, 1));
  const Image ss = render(s, small(topOrtho(), 64, 64, 4, AntiAliasing::Supersample));
  const Image acc = render(s, small(topOrtho(), 64, 64, 4, AntiAliasing::Accumulate));
  const int interior = px(none, 32, 32)[0];
  CHECK(levels(none) == std::set<int>{interior, 255});  // aliased: only the two colours
  CHECK(levels(ss).size() > 8);                          // 16 samples give up to 15 intermediate levels
  CHECK(levels(acc).size() > 8);
  // Both modes sample the same 4 x 4 grid in every pixel: the same image, except where an edge
  // passes within the rasteriser's fixed-point snapping (1/256 of a rasterised pixel) of a sample,
  // which may then flip: at most one sample (1/16 of the coverage) in a few edge pixels.
  int differ = 0;
  double maxCoverageDiff = 0;
  for (std::size_t i = 0; i < ss.rgba.size(); i += 4) {
    if (std::abs(int(ss.rgba[i]) - int(acc.rgba[i])) > 1) ++differ;
    maxCoverageDiff = std::max(maxCoverageDiff, std::abs(toLinear(ss.rgba[i]) - toLinear(acc.rgba[i])));
  }
  CHECK(differ <= 8);  // of about 130 edge pixels
  CHECK(maxCoverageDiff <= 1.0 / 16 + 0.01);
  // Averaging is in linear light: the covered fraction of the image equals the square's area.
  double covered = 0;
  for (std::size_t i = 0; i < ss.rgba.size(); i += 4)
    covered += (1 - toLinear(ss.rgba[i])) / (1 - toLinear(interior));
  CHECK(covered / (64 * 64) == Approx(1.0 / 4).epsilon(0.01));  // side 1 in a window 2 x 2
}

TEST_CASE("render: polylines have their width in pixels, and dashes", "[render]") {
  for (double width : {1.0, 3.0, 6.0}) {
    Scene s;
    Polyline pl;
    pl.p = {{-0.8, 0.0, 0}, {0.8, 0.0, 0}};
    pl.width = width;
    s.add(pl);
    const Image img = render(s, small(topOrtho(), 100, 100, 4));
    // Across the line, the coverage (in linear light) integrates to the width.
    double sum = 0;
    for (int y = 0; y < 100; ++y) sum += 1 - toLinear(px(img, 50, y)[0]);
    CHECK(sum == Approx(width).margin(0.15));
    // Round ends: the line reaches half its width beyond its end points (x = +-0.8 -> 10 and 90 px).
    double along = 0;
    for (int x = 0; x < 100; ++x) along += 1 - toLinear(px(img, x, 50)[0]);
    const double row = [&] { double r = 0; for (int y = 0; y < 100; ++y) r = std::max(r, 1 - toLinear(px(img, 50, y)[0])); return r; }();
    if (width >= 3) CHECK(along / row == Approx(80 + width).margin(0.5));
  }
  Scene s;
  Polyline d;
  d.p = {{-0.8, 0, 0}, {0.8, 0, 0}};  // 80 px long
  d.width = 2;
  d.dashed = true;
  d.dashLength = 10;  // 4 dashes of 10 px with gaps of 10 px
  s.add(d);
  const Image img = render(s, small(topOrtho(), 100, 100, 4));
  int runs = 0;
  bool dark = false;
  for (int x = 0; x < 100; ++x) {
    const bool now = px(img, x, 50)[0] < 128;
    if (now && !dark) ++runs;
    dark = now;
  }
  CHECK(runs == 4);
}

TEST_CASE("render: PNG write/read round trip is exact", "[render]") {
  Scene s;
  s.add(sphere({0, 0, 0}, 0.5, palette::bluishGreen));
  s.add(Label{{0, 0, 0.6}, "ok"});
  s.background = Color::hex(0xF0E0D0, 0.5f);
  const Image img = render(s, small(Camera::lookAt({4, 1, 1}, {0, 0, 0}), 70, 50, 2));
  const auto path = std::filesystem::temp_directory_path() / "soma-render-roundtrip.png";
  writePng(img, path);
  const Image back = readPng(path);
  std::filesystem::remove(path);
  CHECK(back.width == img.width);
  CHECK(back.height == img.height);
  CHECK(back.rgba == img.rgba);
  CHECK(px(img, 0, 0) == rgba8(s.background));  // straight alpha: the background's own alpha
}

TEST_CASE("render: renderRgba, renderPng and effectiveCamera agree with render", "[render]") {
  Scene s;
  s.add(sphere({0, 0, 0}, 0.5, palette::orange));
  s.add(Frame{});
  RenderOptions o;
  o.width = 64;
  o.height = 48;
  o.samples = 2;
  const Image img = render(s, o);
  CHECK(renderRgba(s, o) == img.rgba);
  const auto path = std::filesystem::temp_directory_path() / "soma-render-renderpng.png";
  renderPng(s, o, path);
  CHECK(readPng(path).rgba == img.rgba);
  std::filesystem::remove(path);
  FitOptions f;
  f.width = 64;
  f.height = 48;
  const Camera fit = Camera::fit(s, RenderOptions::defaultViewDirection(), f), eff = effectiveCamera(s, o);
  CHECK((eff.eye - fit.eye).norm() == 0);
  CHECK((eff.target - fit.target).norm() == 0);
  o.camera = Camera::lookAt({3, 3, 3}, {0, 0, 0});
  CHECK((effectiveCamera(s, o).eye - Eigen::Vector3d(3, 3, 3)).norm() == 0);
}

TEST_CASE("render: renderPng along a view direction = render with the fitted camera", "[render]") {
  Scene s;
  s.add(sphere({0, 0, 0}, 0.5, palette::orange));
  s.add(sphere({0.9, 0, 0}, 0.2, palette::blue));  // off-centre: the image depends on the view
  FitOptions f;
  f.width = 72;
  f.height = 40;
  f.orthographic = true;
  const Eigen::Vector3d view(1, -2, 0.5);
  const auto path = std::filesystem::temp_directory_path() / "soma-render-renderpng-view.png";
  renderPng(s, view, f, path);
  const Image got = readPng(path);
  std::filesystem::remove(path);
  RenderOptions o;
  o.width = f.width;
  o.height = f.height;
  o.camera = Camera::fit(s, view, f);
  CHECK(got.width == 72);
  CHECK(got.height == 40);
  CHECK(got.rgba == render(s, o).rgba);
  o.camera = Camera::fit(s, Eigen::Vector3d(-1, 2, 0.5), f);  // the view direction is honoured
  CHECK(got.rgba != render(s, o).rgba);
}

TEST_CASE("render: concurrent calls are serialised and give the same image", "[render]") {
  Scene s;
  s.add(sphere({0, 0, 0}, 0.5, palette::reddishPurple));
  s.add(Polyline{{{-1, 0, 0}, {1, 0, 0}}, palette::black, 2});
  const RenderOptions o = small(Camera::lookAt({4, 1, 1}, {0, 0, 0}), 64, 48, 2);
  const Image ref = render(s, o);
  Image a, b;
  std::thread ta([&] { a = render(s, o); }), tb([&] { b = render(s, o); });
  ta.join();
  tb.join();
  CHECK(a.rgba == ref.rgba);
  CHECK(b.rgba == ref.rgba);
}

TEST_CASE("render: bad input throws with a clear message", "[render]") {
  Scene ok;
  ok.add(sphere({0, 0, 0}, 0.5));
  const RenderOptions o = small(Camera::lookAt({4, 0, 0}, {0, 0, 0}), 32, 24, 1);

  Scene nan = ok;
  nan.meshes[0].v[1].y() = std::nan("");
  CHECK_THROWS_CONTAINING(render(nan, o), std::invalid_argument, "Mesh[0].v[1] has a non-finite coordinate");
  Scene nanLine;
  nanLine.add(Polyline{{{0, 0, 0}, {0, std::numeric_limits<double>::infinity(), 0}}});
  CHECK_THROWS_CONTAINING(render(nanLine, o), std::invalid_argument, "Polyline[0].p[1]");

  RenderOptions zero = o;
  zero.width = 0;
  CHECK_THROWS_CONTAINING(render(ok, zero), std::invalid_argument, "image size 0x24");
  RenderOptions noSamples = o;
  noSamples.samples = 0;
  CHECK_THROWS_CONTAINING(render(ok, noSamples), std::invalid_argument, "samples is 0");

  Camera same;
  same.eye = same.target = {1, 2, 3};
  RenderOptions badCam = o;
  badCam.camera = same;
  CHECK_THROWS_CONTAINING(render(ok, badCam), std::invalid_argument, "coincides with Camera.target");
  CHECK_THROWS_AS(Camera::lookAt({1, 2, 3}, {1, 2, 3}), std::invalid_argument);

  {
    EnvGuard font("SOMA_FONT", "/nonexistent");
    Scene labelled = ok;
    labelled.add(Label{{0, 0, 0}, "text"});
    CHECK_THROWS_CONTAINING(render(labelled, o), std::runtime_error, "SOMA_FONT='/nonexistent'");
    Scene titled = ok;
    titled.title = "title";
    CHECK_THROWS_AS(render(titled, o), std::runtime_error);
    CHECK_NOTHROW(render(ok, o));  // no text: no font needed
  }
  CHECK_NOTHROW(render(Scene{}, o));  // an empty scene is a background
}

TEST_CASE("render: a polyline through the eye plane is clipped at the near plane", "[render]") {
  // Looking along +x from the origin; the line runs from behind the eye to in front of it, 0.2 below.
  const Camera cam = Camera::lookAt({0, 0, 0}, {1, 0, 0}, Eigen::Vector3d::UnitZ(), 60);
  Scene s;
  s.add(Polyline{{{-1, 0, -0.2}, {3, 0, -0.2}}, palette::black, 3});
  s.add(Points{{Eigen::Vector3d(3, 0.5, 0.5)}, palette::blue, 0.05});  // something in front
  const int w = 120, h = 90;
  const Image img = render(s, small(cam, w, h, 2));
  const Eigen::Vector2d far = cam.project({3, 0, -0.2}, w, h), mid = cam.project({1, 0, -0.2}, w, h);
  CHECK(std::abs(far.x() - w / 2.0) < 1e-9);  // straight below the centre
  CHECK(px(img, int(mid.x()), int(mid.y()))[0] < 60);  // the visible part is drawn
  CHECK(px(img, int(far.x()), int(far.y()) + 3)[0] < 60);
  // Above the line's vanishing point nothing of it appears (a wrongly projected point behind the
  // eye would land there, mirrored).
  for (int y = 0; y < int(far.y()) - 3; ++y) CHECK(px(img, w / 2, y)[0] == 255);
}

TEST_CASE("render: two-sided surfaces light and tint their back faces — solids cull them", "[render]") {
  const Camera below = Camera::ortho({0, 0, -5}, {0, 0, 0}, {0, 1, 0}, 2);  // sees the square's back
  const Camera above = topOrtho();
  Mesh m = square(0.5, {0, 0, 0}, palette::vermillion);  // normal +z
  Scene s;
  s.add(m);
  const auto front = px(render(s, small(above, 40, 40, 1)), 20, 20);
  const auto back = px(render(s, small(below, 40, 40, 1)), 20, 20);
  const auto wantFront = litFacingViewer(palette::vermillion), wantBack = litFacingViewer(palette::vermillion.lighter(0.35f));
  for (int k = 0; k < 3; ++k) {
    CHECK(std::abs(front[k] - std::clamp(wantFront[k], 0.0, 1.0) * 255) <= 2.0);
    CHECK(std::abs(back[k] - std::clamp(wantBack[k], 0.0, 1.0) * 255) <= 2.0);
  }
  s.meshes[0].twoSided = false;
  CHECK(px(render(s, small(below, 40, 40, 1)), 20, 20) == rgba8(s.background));
  CHECK(px(render(s, small(above, 40, 40, 1)), 20, 20) == front);
}

TEST_CASE("render: frames draw x, y, z in the axis colours", "[render]") {
  Scene s;
  Frame f;
  f.scale = 0.8;
  s.add(f);
  const Image img = render(s, small(topOrtho(), 80, 80, 2));
  // Looking down z: the x arrow points right, the y arrow up; halfway along each shaft.
  const auto x = px(img, 56, 40), y = px(img, 40, 23);
  CHECK(x[0] > x[1] + 60);  // vermillion: red dominates
  CHECK(x[0] > x[2] + 60);
  CHECK(y[1] > y[0] + 60);  // bluish green: green dominates
  CHECK(y[1] > y[2] + 10);
  const auto origin = px(img, 40, 40);  // the z arrow, seen end on: its head, blue, covers the origin
  CHECK(origin[2] > origin[0] + 60);
  CHECK(origin[2] > origin[1] + 20);
}

TEST_CASE("render: parametricSurface's front is the side of f_u x f_v, whichever way the ranges run", "[render]") {
  // A saddle z = u v over the square: f_u x f_v = (-v, -u, 1).
  const SurfaceMap f = [](double u, double v) { return Eigen::Vector3d(u, v, u * v); };
  for (auto ur : {std::pair{-1.0, 1.0}, std::pair{1.0, -1.0}})
    for (auto vr : {std::pair{-1.0, 1.0}, std::pair{1.0, -1.0}}) {
      const Mesh m = parametricSurface(f, ur, vr, 6, 5);
      REQUIRE(m.n.size() == m.v.size());
      for (std::size_t k = 0; k < m.v.size(); ++k) {
        const Eigen::Vector3d want = Eigen::Vector3d(-m.v[k].y(), -m.v[k].x(), 1).normalized();
        CHECK(m.n[k].dot(want) > 0.99);
      }
      for (const auto& t : m.tri) {  // winding agrees with the normals
        const Eigen::Vector3d g = (m.v[t[1]] - m.v[t[0]]).cross(m.v[t[2]] - m.v[t[0]]);
        CHECK(g.dot(m.n[t[0]] + m.n[t[1]] + m.n[t[2]]) > 0);
      }
    }
}

}  // namespace SOMA_UNITY_ID
