// Rendering a Scene off-screen with OSMesa: legacy fixed-function OpenGL on Mesa llvmpipe.
//
// One render: validate; tessellate the shaded primitives into triangle batches (world coordinates
// relative to the scene's centre); turn every polyline into screen-space triangles of constant pixel
// width (round joints and ends, dashes) in the coordinates of the "virtual" image that is actually
// rasterised; draw opaque geometry, then opaque lines, then transparent meshes and lines without
// depth writes; average the samples in linear light; draw labels and the title with FreeType on the
// final 8-bit image (text is never hidden, and it is anti-aliased by FreeType itself).
#include "soma/render/renderer.hpp"

#include "detail.hpp"
#include "tessellate.hpp"
#include "text.hpp"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <numbers>
#include <unordered_map>
#include <stdexcept>
#include <string>
#include <vector>

namespace soma::render {

Camera effectiveCamera(const Scene& scene, const RenderOptions& options) {
  if (options.camera) {
    options.camera->validate();
    return *options.camera;
  }
  FitOptions fit;
  fit.width = options.width;
  fit.height = options.height;
  return Camera::fit(scene, RenderOptions::defaultViewDirection(), fit);
}

namespace {

using detail::invalid;
constexpr double pi = std::numbers::pi;
constexpr int maxImageSide = 8192;
constexpr int maxSamples = 16;
constexpr int maxTileSide = 2048;  // bounds the OSMesa buffer: 2048^2 x (4 colour + 4 depth/stencil) bytes

std::mutex& renderMutex() {
  static std::mutex m;
  return m;
}

// ---------------------------------------------------------------------------------------------
// sRGB <-> linear light (IEC 61966-2-1) for 8-bit codes. Linear values are 16-bit integers
// (0..65535), so that the samples of a pixel are summed exactly in integers; the 65536-entry table
// `code` maps a linear value back to the nearest code (nearest in the encoded scale), and is the
// exact inverse of `linear` on the 256 codes.
struct Srgb {
  std::array<std::uint16_t, 256> linear{};
  std::vector<std::uint8_t> code;
  Srgb() : code(65536) {
    auto decode = [](double u) { return u <= 0.04045 ? u / 12.92 : std::pow((u + 0.055) / 1.055, 2.4); };
    for (int k = 0; k < 256; ++k) linear[k] = std::uint16_t(std::lround(decode(k / 255.0) * 65535));
    int k = 0;
    for (int v = 0; v < 65536; ++v) {
      // Advance past the midpoint (in the encoded scale) between codes k and k+1.
      while (k < 255 && v >= decode((k + 0.5) / 255.0) * 65535) ++k;
      code[v] = std::uint8_t(k);
    }
  }
};
const Srgb& srgb() {
  static const Srgb s;
  return s;
}

// ---------------------------------------------------------------------------------------------
// The OSMesa context and its colour buffer: created on first use and kept for the life of the
// process (deliberately not destroyed at exit: Mesa's own teardown order is not ours to rely on).
// The buffer keeps its size while renders keep theirs, so repeated figures pay neither context
// creation nor reallocation of Mesa's colour and depth buffers. Used only under renderMutex().
struct GlContext {
  OSMesaContext ctx = nullptr;
  std::vector<std::uint8_t> buffer;  // OSMesa's colour buffer, rows bottom-up, filled by glFinish
  int width = 0, height = 0;         // of the buffer
  int maxWidth = 0, maxHeight = 0;   // limits of OSMesa and of the viewport

  void create() {
    if (ctx) return;
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    if (!ctx) throw std::runtime_error("soma::render: OSMesaCreateContextExt failed (is libOSMesa's llvmpipe usable?)");
    bind(16, 16);
    GLint w = 0, h = 0, dims[2] = {0, 0};
    OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &w);
    OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &h);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, dims);
    maxWidth = std::max(64, std::min({maxTileSide, w > 0 ? int(w) : maxTileSide, dims[0] > 0 ? int(dims[0]) : maxTileSide}));
    maxHeight = std::max(64, std::min({maxTileSide, h > 0 ? int(h) : maxTileSide, dims[1] > 0 ? int(dims[1]) : maxTileSide}));
  }
  void bind(int w, int h) {
    if (w != width || h != height) {
      buffer.assign(std::size_t(w) * h * 4, 0);
      width = w, height = h;
    }
    if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, w, h))
      throw std::runtime_error("soma::render: OSMesaMakeCurrent failed for a " + std::to_string(w) + "x" +
                               std::to_string(h) + " buffer");
  }
  // Leave no context current on this thread: the next render may come from another thread.
  void release() { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }
};
GlContext& glContext() {
  static GlContext* c = new GlContext;  // never destroyed, see above
  return *c;
}

// ---------------------------------------------------------------------------------------------
// Lighting (eye space; the camera looks down -z): a key light from the upper left behind the
// viewer, a fill from the lower right (so that faces turned down are not black), a global ambient
// term, a modest white highlight. Documented in render/README.md; tests/render checks the centre
// of a sphere against it.
constexpr float ambient = 0.32f;
constexpr float keyDiffuse = 0.55f, keySpecular = 0.15f, fillDiffuse = 0.30f, shininess = 40.0f;
constexpr float keyDir[4] = {-0.25f, 0.35f, 1.0f, 0.0f};
constexpr float fillDir[4] = {0.40f, -0.60f, 0.60f, 0.0f};
/// Back faces of two-sided surfaces get this tint towards white, so inside and outside differ.
constexpr float backTint = 0.35f;

/// Line depth bias: lines are moved towards the eye by this many times (half width + 1 px) of
/// world length, so a curve drawn on a surface is not half-buried in it.
constexpr double lineBias = 2.0;

// ---------------------------------------------------------------------------------------------
// Everything a pass draws, prepared once per render.
struct LineMesh {
  // Virtual-window coordinates: x right, y up (pixels), z = NDC depth. float: Mesa's fast path, and
  // its 24-bit mantissa matches the 24-bit depth buffer.
  std::vector<float> xyz;
  std::vector<unsigned> idx;
  Color c;
};

/// Small shaded spheres drawn as screen-space discs ("impostors"): a fan whose vertex colours are
/// the lighting model evaluated at the sphere normals they stand for, at the depth of the sphere's
/// front. A sphere a few pixels across looks the same, at a twentieth of the triangles.
struct DiscMesh {
  std::vector<float> xyz;  // virtual-window coordinates, as LineMesh
  std::vector<float> rgba;
  std::vector<unsigned> idx;
  bool empty() const { return idx.empty(); }
};
/// Spheres smaller than this radius in output pixels are drawn as impostors.
constexpr double impostorPixels = 16;

struct Text {
  std::string text;
  double x, y;
  detail::TextStyle style;
};

struct Prepared {
  Scene const* scene = nullptr;
  Camera cam;
  int W = 0, H = 0, samples = 1;
  bool supersample = true;
  int Wv = 0, Hv = 0;  // size of the rasterised ("virtual") image
  double vscale = 1;   // virtual pixels per output pixel
  Eigen::Matrix4d view, proj;
  double zNear = 0, zFar = 0;
  // Shaded triangles: closed solids (back faces culled) and two-sided surfaces, opaque and transparent.
  detail::Batch solid, surface, solidT, surfaceT;
  detail::Batch flat, flatT;  // unlit filled triangles (Fill)
  std::vector<float> surfaceBack, surfaceTBack;  // back-face colours of the two-sided batches
  std::vector<LineMesh> lines, linesT;
  DiscMesh dots, dotsT;
  std::vector<Text> texts;
};

bool transparent(const Color& c) { return c.a < 1.0f; }

std::vector<float> backColours(const std::vector<float>& col) {
  std::vector<float> out(col.size());
  for (std::size_t i = 0; i < col.size(); i += 4) {
    for (int k = 0; k < 3; ++k) out[i + k] = col[i + k] + (1 - col[i + k]) * backTint;
    out[i + 3] = col[i + 3];
  }
  return out;
}

// Depth bias of a line of half width hwOut output pixels (see lineBias): the relative shrink of its
// depth under perspective, its shift towards the eye in world units under orthographic projection.
double lineShrink(const Prepared& pr, double hwOut) {
  return std::min(0.1, lineBias * (hwOut + 1) * 2 * std::tan(pr.cam.fovYDegrees * pi / 360) / pr.H);
}
double lineShift(const Prepared& pr, double hwOut) { return lineBias * (hwOut + 1) * pr.cam.orthoHeight / pr.H; }

// Near and far planes enclosing the scene's bounding box, and its polylines moved towards the eye.
void depthRange(Prepared& pr) {
  Eigen::AlignedBox3d box = pr.scene->bounds();
  if (box.isEmpty()) box = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Constant(0.5));
  const double ext = std::max(box.diagonal().norm(), 1e-300);
  double dmin = 1e300, dmax = -1e300;
  for (int k = 0; k < 8; ++k) {
    const double d = pr.cam.depth(box.corner(Eigen::AlignedBox3d::CornerType(k)));
    dmin = std::min(dmin, d), dmax = std::max(dmax, d);
  }
  double hw = 0;
  for (const Polyline& p : pr.scene->polylines) hw = std::max(hw, p.width / 2);
  if (pr.cam.orthographic) {
    const double pad = 0.05 * ext + 0.05 * (dmax - dmin);
    pr.zNear = dmin - pad - (pr.scene->polylines.empty() ? 0.0 : lineShift(pr, hw));
    pr.zFar = dmax + pad;
  } else if (dmax <= 0) {  // everything behind the eye: nothing is visible
    pr.zNear = 1e-3 * ext;
    pr.zFar = ext;
  } else {
    pr.zFar = dmax * 1.02;
    pr.zNear = std::max(0.8 * dmin * (1 - lineShrink(pr, hw)), pr.zFar * 1e-4);
  }
}

// Output pixels per world unit at p (for choosing tessellation density).
double pixelsPerUnit(const Prepared& pr, const Eigen::Vector3d& p) {
  if (pr.cam.orthographic) return pr.H / pr.cam.orthoHeight;
  const double d = pr.cam.depth(p);
  if (!(d > pr.zNear)) return pr.H / (2 * std::tan(pr.cam.fovYDegrees * pi / 360) * pr.zNear);
  return pr.H / (2 * std::tan(pr.cam.fovYDegrees * pi / 360) * d);
}

// The fixed-function lighting of drawPass, evaluated on the CPU for a unit eye-space normal n.
Color litColour(const Color& c, const Eigen::Vector3d& n) {
  const Eigen::Vector3d L0 = Eigen::Vector3d(keyDir[0], keyDir[1], keyDir[2]).normalized();
  const Eigen::Vector3d L1 = Eigen::Vector3d(fillDir[0], fillDir[1], fillDir[2]).normalized();
  const double d0 = std::max(0.0, n.dot(L0)), d1 = std::max(0.0, n.dot(L1));
  const double diffuse = ambient + keyDiffuse * d0 + fillDiffuse * d1;
  const double spec = d0 > 0 ? keySpecular * std::pow(std::max(0.0, n.dot((L0 + Eigen::Vector3d::UnitZ()).normalized())), double(shininess)) : 0.0;
  auto ch = [&](float v) { return float(std::clamp(v * diffuse + spec, 0.0, 1.0)); };
  return {ch(c.r), ch(c.g), ch(c.b), c.a};
}

Eigen::Vector3d toWindow(const Prepared& pr, const Eigen::Vector4d& e);

// The layout of an impostor: the unit normals of its vertices (centre first, then rings of n) and
// their lit colours, for one colour. Two layouts: a sphere under 4 output pixels in radius gets a
// centre and a rim of 8; a larger one rings at 0.5, 0.8 and 1 of its radius, 12 around.
struct ImpostorLayout {
  int n = 0, rings = 0;
  std::vector<Eigen::Vector3d> normal;
  std::vector<Color> colour;
  ImpostorLayout(bool tiny, const Color& c) : n(tiny ? 8 : 12), rings(tiny ? 1 : 3) {
    static constexpr double fine[] = {0.5, 0.8, 1.0}, coarse[] = {1.0};
    normal.emplace_back(0, 0, 1);
    for (int ring = 0; ring < rings; ++ring)
      for (int k = 0; k < n; ++k) {
        const double rho = tiny ? coarse[ring] : fine[ring], a = 2 * pi * k / n;
        normal.emplace_back(rho * std::cos(a), rho * std::sin(a), std::sqrt(std::max(0.0, 1 - rho * rho)));
      }
    for (const auto& nrm : normal) colour.push_back(litColour(c, nrm));
  }
};

// A sphere of world radius r at p drawn as an impostor of rv virtual pixels.
void addImpostor(const Prepared& pr, DiscMesh& m, const Eigen::Vector3d& p, double r, double rv, const ImpostorLayout& l) {
  Eigen::Vector4d e = pr.view * p.homogeneous();
  if (pr.cam.orthographic) {
    e.z() += r;
  } else {
    const double d = -e.z();
    if (!(d - r > pr.zNear)) return;  // reaches the near plane: not drawn
    e.head<3>() *= (d - r) / d;
  }
  const Eigen::Vector3d w = toWindow(pr, e);
  const unsigned first = unsigned(m.xyz.size() / 3);
  for (std::size_t v = 0; v < l.normal.size(); ++v) {
    m.xyz.insert(m.xyz.end(), {float(w.x() + rv * l.normal[v].x()), float(w.y() + rv * l.normal[v].y()), float(w.z())});
    m.rgba.insert(m.rgba.end(), {l.colour[v].r, l.colour[v].g, l.colour[v].b, l.colour[v].a});
  }
  const unsigned n = unsigned(l.n);
  for (unsigned k = 0; k < n; ++k) {
    const unsigned k1 = (k + 1) % n;
    m.idx.insert(m.idx.end(), {first, first + 1 + k, first + 1 + k1});
    for (unsigned ring = 0; ring + 1 < unsigned(l.rings); ++ring) {
      const unsigned in = first + 1 + ring * n, out = in + n;
      m.idx.insert(m.idx.end(), {in + k, out + k, out + k1, in + k, out + k1, in + k1});
    }
  }
}

void tessellate(Prepared& pr) {
  const Scene& s = *pr.scene;
  Eigen::AlignedBox3d box = s.bounds();
  const Eigen::Vector3d origin = box.isEmpty() ? Eigen::Vector3d(Eigen::Vector3d::Zero()) : Eigen::Vector3d(box.center());
  for (detail::Batch* b : {&pr.solid, &pr.surface, &pr.solidT, &pr.surfaceT, &pr.flat, &pr.flatT}) b->origin = origin;
  const double L = s.characteristicLength();
  const detail::PixelScale ppu = [&pr](const Eigen::Vector3d& p) { return pixelsPerUnit(pr, p); };
  auto solidFor = [&pr](const Color& c) -> detail::Batch& { return transparent(c) ? pr.solidT : pr.solid; };

  for (const Points& x : s.points) {
    const double r = detail::pointRadius(x, L);
    const ImpostorLayout tiny(true, x.c), fine(false, x.c);
    for (const auto& p : x.p) {
      // Spheres a few pixels across need few facets (a workspace may have 10^5 of them).
      const double rpx = r * ppu(p);
      if (rpx < impostorPixels)
        addImpostor(pr, transparent(x.c) ? pr.dotsT : pr.dots, p, r, rpx * pr.vscale, rpx < 4 ? tiny : fine);
      else detail::addSphere(solidFor(x.c), p, r, x.c, detail::circleSegments(r, p, ppu));
    }
  }
  for (const Tube& x : s.tubes) detail::addTube(solidFor(x.c), x.p, detail::tubeRadius(x, L), x.c, x.closed, ppu);
  for (const Mesh& x : s.meshes) {
    if (x.twoSided) detail::addMesh(transparent(x.c) ? pr.surfaceT : pr.surface, x);
    else detail::addMesh(solidFor(x.c), x);
  }
  for (const Fill& x : s.fills) {
    bool anyTransparent = transparent(x.c) && x.vc.empty();
    for (const Color& c : x.vc) anyTransparent = anyTransparent || transparent(c);
    detail::Batch& b = anyTransparent ? pr.flatT : pr.flat;
    const unsigned first = unsigned(b.pos.size() / 3);
    for (std::size_t k = 0; k < x.v.size(); ++k)
      b.vertex(x.v[k], Eigen::Vector3d::UnitZ(), x.vc.empty() ? x.c : x.vc[k]);
    for (const auto& t : x.tri) b.triangle(first + unsigned(t[0]), first + unsigned(t[1]), first + unsigned(t[2]));
  }
  const Color axis[3] = {palette::axisX, palette::axisY, palette::axisZ};
  for (const Frame& f : s.frames) {
    const double sc = detail::frameScale(f, L), r = detail::frameArrowRadius * sc;
    const Eigen::Vector3d o = f.pose.block<3, 1>(0, 3);
    for (int k = 0; k < 3; ++k)
      detail::addArrow(pr.solid, o, o + sc * Eigen::Vector3d(f.pose.block<3, 1>(0, k)), r, axis[k], ppu);
    detail::addSphere(pr.solid, o, 1.6 * r, palette::darkGrey, detail::circleSegments(1.6 * r, o, ppu));
  }
  for (const Arrow& a : s.arrows) detail::addArrow(solidFor(a.c), a.from, a.to, detail::arrowRadius(a, L), a.c, ppu);
  if (s.axes) {
    const double len = detail::axesLength(s, L);
    for (int k = 0; k < 3; ++k)
      detail::addArrow(pr.solid, Eigen::Vector3d::Zero(), len * Eigen::Vector3d::Unit(k), detail::worldAxisRadius(len, L), axis[k], ppu);
  }
  pr.surfaceBack = backColours(pr.surface.col);
  pr.surfaceTBack = backColours(pr.surfaceT.col);
}

// ---------------------------------------------------------------------------------------------
// Polylines: constant pixel width, round joints and ends, dashes measured along the projected curve.

// Eye-space point (biased towards the eye) -> virtual-window point (x, y up, NDC z).
Eigen::Vector3d toWindow(const Prepared& pr, const Eigen::Vector4d& e) {
  const Eigen::Vector4d c = pr.proj * e;
  return {(c.x() / c.w() + 1) / 2 * pr.Wv, (c.y() / c.w() + 1) / 2 * pr.Hv, c.z() / c.w()};
}

void addDisc(LineMesh& m, const Eigen::Vector3d& c, double r) {
  const int n = r > 0.3 ? std::clamp(int(std::ceil(pi / std::acos(1 - 0.25 / r))), 8, 64) : 8;
  const unsigned centre = unsigned(m.xyz.size() / 3);
  m.xyz.insert(m.xyz.end(), {float(c.x()), float(c.y()), float(c.z())});
  for (int k = 0; k < n; ++k) {
    const double a = 2 * pi * k / n;
    m.xyz.insert(m.xyz.end(), {float(c.x() + r * std::cos(a)), float(c.y() + r * std::sin(a)), float(c.z())});
  }
  for (int k = 0; k < n; ++k) m.idx.insert(m.idx.end(), {centre, centre + 1 + k, centre + 1 + (k + 1) % n});
}

// A piece of a curve (window points) as a strip of quads plus a disc at every point.
void addPiece(LineMesh& m, const std::vector<Eigen::Vector3d>& q, double hw) {
  for (std::size_t i = 0; i + 1 < q.size(); ++i) {
    const Eigen::Vector2d d = (q[i + 1] - q[i]).head<2>();
    const double len = d.norm();
    if (!(len > 1e-9)) continue;
    const Eigen::Vector2d n = Eigen::Vector2d(-d.y(), d.x()) * (hw / len);
    const unsigned b = unsigned(m.xyz.size() / 3);
    for (const auto& [p, s] : {std::pair{q[i], 1.0}, std::pair{q[i], -1.0}, std::pair{q[i + 1], 1.0}, std::pair{q[i + 1], -1.0}})
      m.xyz.insert(m.xyz.end(), {float(p.x() + s * n.x()), float(p.y() + s * n.y()), float(p.z())});
    m.idx.insert(m.idx.end(), {b, b + 1, b + 3, b, b + 3, b + 2});
  }
  // Round ends, and round joints where the turn opens a visible wedge on the outer side
  // (hw * turning angle above 0.05 rasterised pixels); smooth stretches need none.
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (i > 0 && i + 1 < q.size()) {
      const Eigen::Vector2d a = (q[i] - q[i - 1]).head<2>(), b = (q[i + 1] - q[i]).head<2>();
      const double turn = std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b));
      if (a.squaredNorm() > 0 && b.squaredNorm() > 0 && hw * turn < 0.05) continue;
    }
    addDisc(m, q[i], hw);
  }
}

LineMesh polylineMesh(const Prepared& pr, const Polyline& pl) {
  LineMesh m;
  m.c = pl.c;
  if (pl.p.empty()) return m;
  const double hwOut = pl.width / 2;               // output pixels
  const double hw = hwOut * pr.vscale;              // virtual pixels
  // Depth bias towards the eye (see lineBias).
  const double shrink = lineShrink(pr, hwOut), shift = lineShift(pr, hwOut);
  std::vector<Eigen::Vector4d> e;
  e.reserve(pl.p.size() + 1);
  for (const auto& p : pl.p) {
    Eigen::Vector4d x = pr.view * p.homogeneous();
    if (pr.cam.orthographic) {
      x.z() += shift;
    } else {
      const double d = -x.z();
      if (d > pr.zNear) {
        const double dn = std::max(d * (1 - shrink), std::min(d, pr.zNear * (1 + 1e-6)));
        x.head<3>() *= dn / d;
      }
    }
    e.push_back(x);
  }
  // Runs of window points, split where the curve leaves the half-space in front of the near plane.
  std::vector<std::vector<Eigen::Vector3d>> runs;
  const std::size_t n = e.size();
  if (n == 1) {
    if (pr.cam.orthographic || -e[0].z() >= pr.zNear) runs.push_back({toWindow(pr, e[0])});
  } else {
    const bool closed = pl.closed && n > 2;
    const std::size_t nseg = closed ? n : n - 1;
    const double zn = pr.zNear * (1 + 1e-9);
    std::vector<Eigen::Vector3d> cur;
    for (std::size_t i = 0; i < nseg; ++i) {
      const Eigen::Vector4d& a = e[i];
      const Eigen::Vector4d& b = e[(i + 1) % n];
      double t0 = 0, t1 = 1;
      if (!pr.cam.orthographic) {
        const double da = -a.z(), db = -b.z();
        if (da < zn && db < zn) t0 = 1, t1 = 0;
        else if (da < zn) t0 = (zn - da) / (db - da);
        else if (db < zn) t1 = (zn - da) / (db - da);
      }
      if (t0 > t1) {
        if (!cur.empty()) runs.push_back(std::move(cur)), cur.clear();
        continue;
      }
      if (cur.empty() || t0 > 0) {
        if (!cur.empty()) runs.push_back(std::move(cur)), cur.clear();
        cur.push_back(toWindow(pr, a + t0 * (b - a)));
      }
      cur.push_back(toWindow(pr, a + t1 * (b - a)));
      if (t1 < 1) runs.push_back(std::move(cur)), cur.clear();
    }
    if (!cur.empty()) runs.push_back(std::move(cur));
  }
  if (!pl.dashed) {
    for (const auto& r : runs) addPiece(m, r, hw);
    return m;
  }
  // Dashes: on for dashLength output pixels, off for as long, continuing across joints and runs.
  const double L = pl.dashLength * pr.vscale;
  double pos = 0;
  for (const auto& r : runs) {
    std::vector<Eigen::Vector3d> piece;
    bool on = std::fmod(pos, 2 * L) < L;
    if (on) piece.push_back(r[0]);
    for (std::size_t j = 0; j + 1 < r.size(); ++j) {
      const double len = (r[j + 1] - r[j]).head<2>().norm();
      const double start = pos, end = pos + len;
      for (double k = std::floor(pos / L) + 1; k * L < end; k += 1) {
        const Eigen::Vector3d x = r[j] + (k * L - start) / len * (r[j + 1] - r[j]);
        if (on) {
          piece.push_back(x);
          addPiece(m, piece, hw);
          piece.clear();
        } else {
          piece = {x};
        }
        on = !on;
      }
      if (on) piece.push_back(r[j + 1]);
      pos = end;
    }
    if (on && !piece.empty()) addPiece(m, piece, hw);
  }
  return m;
}

void prepareLines(Prepared& pr) {
  for (const Polyline& pl : pr.scene->polylines) {
    LineMesh m = polylineMesh(pr, pl);
    if (m.idx.empty()) continue;
    (transparent(pl.c) ? pr.linesT : pr.lines).push_back(std::move(m));
  }
}

// ---------------------------------------------------------------------------------------------
// Text: labels, world-axis names, the title (output pixels, top-down).
void prepareText(Prepared& pr) {
  const Scene& s = *pr.scene;
  const Color halo = s.background.withAlpha(1.0f);
  auto visible = [&pr](const Eigen::Vector3d& p) { return pr.cam.orthographic || pr.cam.depth(p) > 0; };
  for (const Label& l : s.labels) {
    if (l.text.empty() || !visible(l.at)) continue;
    const Eigen::Vector2d p = pr.cam.project(l.at, pr.W, pr.H) + l.offset;
    detail::TextStyle st;
    st.pixelHeight = l.pixelHeight;
    st.color = l.c;
    if (l.halo) st.halo = halo;
    st.hAlign = l.hAlign;
    st.vAlign = l.vAlign;
    pr.texts.push_back({l.text, p.x(), p.y(), st});
  }
  if (s.axes) {
    const double len = detail::axesLength(s, s.characteristicLength());
    const char* names[3] = {"x", "y", "z"};
    const Color colour[3] = {palette::axisX.darker(0.25f), palette::axisY.darker(0.25f), palette::axisZ.darker(0.25f)};
    const Eigen::Vector3d o = Eigen::Vector3d::Zero();
    if (visible(o)) {
      const Eigen::Vector2d po = pr.cam.project(o, pr.W, pr.H);
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d tip = len * Eigen::Vector3d::Unit(k);
        if (!visible(tip)) continue;
        const Eigen::Vector2d pt = pr.cam.project(tip, pr.W, pr.H);
        Eigen::Vector2d d = pt - po;
        d = d.norm() > 1e-9 ? Eigen::Vector2d(d.normalized()) : Eigen::Vector2d(1, 0);
        detail::TextStyle st;
        st.pixelHeight = 22;
        st.color = colour[k];
        st.halo = halo;
        st.hAlign = HAlign::Center;
        st.vAlign = VAlign::Middle;
        const Eigen::Vector2d at = pt + d * (0.75 * st.pixelHeight);
        pr.texts.push_back({names[k], at.x(), at.y(), st});
      }
    }
  }
  if (!s.title.empty()) {
    detail::TextStyle st;
    st.pixelHeight = s.titlePixelHeight;
    st.color = palette::black;
    st.halo = halo;
    st.hAlign = HAlign::Center;
    st.vAlign = VAlign::Top;
    pr.texts.push_back({s.title, pr.W / 2.0, 0.6 * s.titlePixelHeight, st});
  }
}

// ---------------------------------------------------------------------------------------------
// One rasterisation pass into the current OSMesa buffer (tw x th pixels), with `tile` applied
// after the projection (it selects a sub-window of the virtual image and a sub-pixel jitter).

// Buffer objects for the arrays of one render: uploaded on first use, reused by every tile and
// jitter pass (client-side arrays would be scanned and copied by Mesa at every draw), deleted
// when the render's rasterisation ends. array() and elements() bind the buffer and return the
// offset (0) to pass to gl*Pointer and glDrawElements.
class GpuArrays {
 public:
  GpuArrays() = default;
  GpuArrays(const GpuArrays&) = delete;
  GpuArrays& operator=(const GpuArrays&) = delete;
  ~GpuArrays() {
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    for (const auto& [ptr, id] : ids_) glDeleteBuffers(1, &id);
  }
  template <class T> const void* array(const std::vector<T>& v) { return bind(GL_ARRAY_BUFFER, v); }
  const void* elements(const std::vector<unsigned>& v) { return bind(GL_ELEMENT_ARRAY_BUFFER, v); }

 private:
  template <class T> const void* bind(GLenum target, const std::vector<T>& v) {
    auto [it, fresh] = ids_.try_emplace(v.data(), 0u);
    if (fresh) {
      glGenBuffers(1, &it->second);
      glBindBuffer(target, it->second);
      glBufferData(target, GLsizeiptr(v.size() * sizeof(T)), v.data(), GL_STATIC_DRAW);
    } else {
      glBindBuffer(target, it->second);
    }
    return nullptr;
  }
  std::unordered_map<const void*, GLuint> ids_;
};
GpuArrays* gpu = nullptr;  // the current render's, under renderMutex()

void drawBatch(const detail::Batch& b, const std::vector<float>* colours, const Eigen::Matrix4d& view) {
  if (b.empty()) return;
  Eigen::Matrix4d mv = view;
  mv.block<3, 1>(0, 3) += view.block<3, 3>(0, 0) * b.origin;
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(mv.data());
  glVertexPointer(3, GL_FLOAT, 0, gpu->array(b.pos));
  glNormalPointer(GL_FLOAT, 0, gpu->array(b.nrm));
  glColorPointer(4, GL_FLOAT, 0, gpu->array(colours ? *colours : b.col));
  glDrawElements(GL_TRIANGLES, GLsizei(b.idx.size()), GL_UNSIGNED_INT, gpu->elements(b.idx));
}

// Two-sided surface: back faces (tinted), then front faces; two-sided lighting flips back normals.
void drawSurface(const detail::Batch& b, const std::vector<float>& back, const Eigen::Matrix4d& view) {
  if (b.empty()) return;
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  drawBatch(b, &back, view);
  glCullFace(GL_BACK);
  drawBatch(b, nullptr, view);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
}

// Unlit, both faces: the colours are drawn as given.
void drawFlat(const detail::Batch& b, const Eigen::Matrix4d& view) {
  if (b.empty()) return;
  glDisable(GL_LIGHTING);
  glDisable(GL_CULL_FACE);
  glDisableClientState(GL_NORMAL_ARRAY);
  Eigen::Matrix4d mv = view;
  mv.block<3, 1>(0, 3) += view.block<3, 3>(0, 0) * b.origin;
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(mv.data());
  glVertexPointer(3, GL_FLOAT, 0, gpu->array(b.pos));
  glColorPointer(4, GL_FLOAT, 0, gpu->array(b.col));
  glDrawElements(GL_TRIANGLES, GLsizei(b.idx.size()), GL_UNSIGNED_INT, gpu->elements(b.idx));
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnable(GL_LIGHTING);
}

void drawSolid(const detail::Batch& b, const Eigen::Matrix4d& view) {
  if (b.empty()) return;
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  drawBatch(b, nullptr, view);
}

// Virtual-window coordinates -> virtual NDC, then the tile transform.
Eigen::Matrix4d windowProjection(const Prepared& pr, const Eigen::Matrix4d& tile) {
  Eigen::Matrix4d w = Eigen::Matrix4d::Identity();
  w(0, 0) = 2.0 / pr.Wv, w(0, 3) = -1;
  w(1, 1) = 2.0 / pr.Hv, w(1, 3) = -1;
  return tile * w;
}

void drawDots(const DiscMesh& m, const Eigen::Matrix4d& tile, const Prepared& pr) {
  if (m.empty()) return;
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(windowProjection(pr, tile).data());
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_LIGHTING);
  glDisable(GL_CULL_FACE);
  glDisableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, gpu->array(m.xyz));
  glColorPointer(4, GL_FLOAT, 0, gpu->array(m.rgba));
  glDrawElements(GL_TRIANGLES, GLsizei(m.idx.size()), GL_UNSIGNED_INT, gpu->elements(m.idx));
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnable(GL_LIGHTING);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(Eigen::Matrix4d(tile * pr.proj).data());
}

void drawLines(const std::vector<LineMesh>& lines, const Eigen::Matrix4d& tile, const Prepared& pr, int& stencilRef) {
  if (lines.empty()) return;
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(windowProjection(pr, tile).data());
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_LIGHTING);
  glDisable(GL_CULL_FACE);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  // Each polyline touches a pixel at most once (overlapping quads and discs would otherwise blend
  // twice where the line is transparent): the stencil holds the index of the last line drawn there.
  glEnable(GL_STENCIL_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  for (const LineMesh& m : lines) {
    if (stencilRef == 255) {
      glClear(GL_STENCIL_BUFFER_BIT);
      stencilRef = 0;
    }
    ++stencilRef;
    glStencilFunc(GL_NOTEQUAL, stencilRef, 0xFF);
    glColor4f(m.c.r, m.c.g, m.c.b, m.c.a);
    glVertexPointer(3, GL_FLOAT, 0, gpu->array(m.xyz));
    glDrawElements(GL_TRIANGLES, GLsizei(m.idx.size()), GL_UNSIGNED_INT, gpu->elements(m.idx));
  }
  glDisable(GL_STENCIL_TEST);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnable(GL_LIGHTING);
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(Eigen::Matrix4d(tile * pr.proj).data());
}

void drawPass(const Prepared& pr, const Eigen::Matrix4d& tile, int tw, int th) {
  const Color& bg = pr.scene->background;
  glViewport(0, 0, tw, th);
  glClearColor(bg.r, bg.g, bg.b, bg.a);
  glClearDepth(1.0);
  glClearStencil(0);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_BLEND);
  glDisable(GL_DITHER);
  glShadeModel(GL_SMOOTH);
  glEnable(GL_NORMALIZE);

  // Lights, fixed in eye space.
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const float amb[4] = {ambient, ambient, ambient, 1}, zero[4] = {0, 0, 0, 1};
  const float kd[4] = {keyDiffuse, keyDiffuse, keyDiffuse, 1}, ks[4] = {keySpecular, keySpecular, keySpecular, 1};
  const float fd[4] = {fillDiffuse, fillDiffuse, fillDiffuse, 1}, white[4] = {1, 1, 1, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_FALSE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, keyDir);
  glLightfv(GL_LIGHT0, GL_AMBIENT, zero);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, kd);
  glLightfv(GL_LIGHT0, GL_SPECULAR, ks);
  glEnable(GL_LIGHT1);
  glLightfv(GL_LIGHT1, GL_POSITION, fillDir);
  glLightfv(GL_LIGHT1, GL_AMBIENT, zero);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, fd);
  glLightfv(GL_LIGHT1, GL_SPECULAR, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, zero);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);

  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(Eigen::Matrix4d(tile * pr.proj).data());
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);

  int stencilRef = 0;
  // Opaque: solids, surfaces, lines.
  drawSolid(pr.solid, pr.view);
  drawSurface(pr.surface, pr.surfaceBack, pr.view);
  drawFlat(pr.flat, pr.view);
  drawDots(pr.dots, tile, pr);
  drawLines(pr.lines, tile, pr, stencilRef);
  // Transparent, over everything opaque, without depth writes (no sorting).
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  drawSolid(pr.solidT, pr.view);
  drawSurface(pr.surfaceT, pr.surfaceTBack, pr.view);
  drawFlat(pr.flatT, pr.view);
  drawDots(pr.dotsT, tile, pr);
  drawLines(pr.linesT, tile, pr, stencilRef);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
}

/// Maps the virtual image's NDC to the NDC of the tile [x0, x0+tw) x [y0, y0+th) (virtual pixels,
/// y up), shifted by (jx, jy) virtual pixels so that each tile pixel samples the scene at its
/// centre plus the jitter.
Eigen::Matrix4d tileMatrix(const Prepared& pr, double x0, double y0, int tw, int th, double jx, double jy) {
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t(0, 0) = double(pr.Wv) / tw;
  t(0, 3) = (pr.Wv - 2 * (x0 + jx)) / tw - 1;
  t(1, 1) = double(pr.Hv) / th;
  t(1, 3) = (pr.Hv - 2 * (y0 + jy)) / th - 1;
  return t;
}

void checkGlError() {
  if (const GLenum err = glGetError(); err != GL_NO_ERROR) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%04X", unsigned(err));
    throw std::runtime_error(std::string("soma::render: OpenGL error 0x") + buf + " while rendering");
  }
}

// Rasterise all samples; returns per output pixel the sums of the samples' linear-light values
// (16-bit, see Srgb) of r, g, b and of alpha (scaled to 0..65535).
// The virtual image (Wv x Hv) is cut into tiles whose sides are multiples of vscale; each tile is
// drawn once (Supersample) or samples^2 times with sub-pixel jitter (Accumulate), and every virtual
// pixel adds its value to the output pixel it lies in.
std::vector<std::uint32_t> rasterise(const Prepared& pr) {
  GlContext& gl = glContext();
  gl.create();
  const auto& lin = srgb().linear;
  std::vector<std::uint32_t> acc(std::size_t(pr.W) * pr.H * 4, 0);
  const int vs = int(pr.vscale), s = pr.samples;
  // Equal tiles, as few as the limits allow, sides multiples of vs (the last ones may be smaller).
  auto tileSide = [vs](int total, int limit) {
    const int n = (total + limit - 1) / limit;
    const int side = ((total + n - 1) / n + vs - 1) / vs * vs;
    return side <= limit ? side : std::max(vs, limit / vs * vs);
  };
  const int tileW = tileSide(pr.Wv, gl.maxWidth), tileH = tileSide(pr.Hv, gl.maxHeight);
  gl.bind(tileW, tileH);
  std::vector<Eigen::Vector2d> jitter;
  if (pr.supersample) jitter.emplace_back(0, 0);
  else
    for (int jy = 0; jy < s; ++jy)
      for (int jx = 0; jx < s; ++jx) jitter.emplace_back((jx + 0.5) / s - 0.5, (jy + 0.5) / s - 0.5);
  GpuArrays arrays;
  gpu = &arrays;
  struct Reset {
    ~Reset() { gpu = nullptr; }
  } reset;
  glEnable(GL_SCISSOR_TEST);  // clears stay inside the tile
  for (int ty0 = 0; ty0 < pr.Hv; ty0 += tileH)  // top-down tile origin
    for (int tx0 = 0; tx0 < pr.Wv; tx0 += tileW) {
      const int tw = std::min(tileW, pr.Wv - tx0), th = std::min(tileH, pr.Hv - ty0);
      const int yb = pr.Hv - ty0 - th;  // bottom-up origin
      glScissor(0, 0, tw, th);
      for (const auto& j : jitter) {
        drawPass(pr, tileMatrix(pr, tx0, yb, tw, th, j.x(), j.y()), tw, th);
        glFinish();  // also copies the result into gl.buffer (OSMesa, rows bottom-up)
        checkGlError();
        for (int r = 0; r < th; ++r) {
          const int yv = ty0 + (th - 1 - r);  // top-down virtual row
          std::uint32_t* a = acc.data() + (std::size_t(yv / vs) * pr.W + tx0 / vs) * 4;
          const std::uint8_t* p = gl.buffer.data() + std::size_t(r) * gl.width * 4;
          for (int i = 0; i < tw; i += vs, a += 4)  // output pixel by output pixel
            for (int k = 0; k < vs; ++k, p += 4) {
              a[0] += lin[p[0]];
              a[1] += lin[p[1]];
              a[2] += lin[p[2]];
              a[3] += 257u * p[3];
            }
        }
      }
    }
  glDisable(GL_SCISSOR_TEST);
  return acc;
}

void validateOptions(const RenderOptions& o) {
  if (o.width < 1 || o.height < 1 || o.width > maxImageSide || o.height > maxImageSide)
    invalid("RenderOptions: image size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
            " is out of range; width and height must be in [1, " + std::to_string(maxImageSide) + "]");
  if (o.samples < 1 || o.samples > maxSamples)
    invalid("RenderOptions.samples is " + std::to_string(o.samples) + "; it must be in [1, " + std::to_string(maxSamples) + "]");
  if (o.antiAliasing != AntiAliasing::Supersample && o.antiAliasing != AntiAliasing::Accumulate)
    invalid("RenderOptions.antiAliasing has an unknown value");
}

bool hasText(const Scene& s) {
  if (!s.title.empty() || s.axes) return true;
  for (const Label& l : s.labels)
    if (!l.text.empty()) return true;
  return false;
}

}  // namespace

Image render(const Scene& scene, const RenderOptions& options) {
  validateOptions(options);
  scene.validate();
  Prepared pr;
  pr.scene = &scene;
  pr.cam = effectiveCamera(scene, options);
  pr.W = options.width;
  pr.H = options.height;
  pr.samples = options.samples;
  pr.supersample = options.antiAliasing == AntiAliasing::Supersample;
  pr.vscale = pr.supersample ? pr.samples : 1;
  pr.Wv = pr.W * int(pr.vscale);
  pr.Hv = pr.H * int(pr.vscale);
  pr.view = pr.cam.viewMatrix();
  if (hasText(scene)) (void)fontPath();  // fail before any work when text cannot be drawn

  std::lock_guard<std::mutex> lock(renderMutex());
  depthRange(pr);
  pr.proj = pr.cam.projectionMatrix(double(pr.W) / pr.H, pr.zNear, pr.zFar);
  tessellate(pr);
  prepareLines(pr);
  prepareText(pr);

  GlContext& gl = glContext();
  struct Release {
    GlContext& gl;
    ~Release() { gl.release(); }
  } release{gl};
  const std::vector<std::uint32_t> acc = rasterise(pr);

  Image img;
  img.width = pr.W;
  img.height = pr.H;
  img.rgba.resize(acc.size());
  const Srgb& enc = srgb();
  const std::uint32_t n = std::uint32_t(pr.samples * pr.samples), half = n / 2;  // average, rounded
  for (std::size_t i = 0; i < acc.size(); i += 4) {
    img.rgba[i] = enc.code[(acc[i] + half) / n];
    img.rgba[i + 1] = enc.code[(acc[i + 1] + half) / n];
    img.rgba[i + 2] = enc.code[(acc[i + 2] + half) / n];
    img.rgba[i + 3] = std::uint8_t(((acc[i + 3] + half) / n + 128) / 257);
  }
  for (const Text& t : pr.texts) detail::drawText(img, t.text, t.x, t.y, t.style);
  return img;
}

std::vector<std::uint8_t> renderRgba(const Scene& scene, const RenderOptions& options) {
  return render(scene, options).rgba;
}

void renderPng(const Scene& scene, const RenderOptions& options, const std::filesystem::path& png) {
  writePng(render(scene, options), png);
}

void renderPng(const Scene& scene, const Eigen::Vector3d& viewDir, const FitOptions& fit, const std::filesystem::path& png) {
  RenderOptions options;
  options.width = fit.width;
  options.height = fit.height;
  options.camera = Camera::fit(scene, viewDir, fit);
  renderPng(scene, options, png);
}

}  // namespace soma::render
