// Panel grids (panels.hpp): one camera for every panel, PNG by rendering, SVG by projection.
#include "soma/render/panels.hpp"

#include "soma/render/camera.hpp"
#include "soma/render/renderer.hpp"
#include "soma/render/svg.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace soma::render {

namespace {

constexpr int kBanner = 56;

void check(const PanelGrid& g) {
  if (g.panels.empty()) throw std::invalid_argument("soma::render::PanelGrid: no panels");
  if (g.panelWidth < 64 || g.panelHeight < 64 || g.panelWidth > 4096 || g.panelHeight > 4096 || g.columns < 1)
    throw std::invalid_argument("soma::render::PanelGrid: panel size or columns out of range");
}

/// The banner's font size: 22 px, smaller when the title would not fit the grid's width (about
/// 0.55 em per character of DejaVu Sans).
double bannerPixels(const std::string& title, int width) {
  std::size_t chars = 0;
  for (const unsigned char ch : title) chars += (ch & 0xC0) != 0x80;  // UTF-8 code points
  return std::clamp(double(width) / (0.58 * double(std::max<std::size_t>(chars, 1))), 10.0, 22.0);
}

int columnsOf(const PanelGrid& g) { return std::min<int>(g.columns, int(g.panels.size())); }
int rowsOf(const PanelGrid& g) { return (int(g.panels.size()) + columnsOf(g) - 1) / columnsOf(g); }

/// The camera of every panel: fitted to the union of the panels' geometry.
Camera commonCamera(const PanelGrid& g) {
  Scene all;
  for (const Scene& s : g.panels) {
    all.add(s.points);
    all.add(s.polylines);
    all.add(s.tubes);
    all.add(s.meshes);
    all.add(s.frames);
    all.add(s.arrows);
  }
  all.title = "room for the panel titles";  // Camera::fit leaves room at the top for a title
  all.titlePixelHeight = 16;
  FitOptions fo;
  fo.width = g.panelWidth;
  fo.height = g.panelHeight;
  fo.margin = 0.04;
  return Camera::fit(all, g.view, fo);
}

/// A frame's arrow length when the scene leaves it automatic: a tenth of the panels' extent.
double automaticFrameScale(const PanelGrid& g) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  auto grow = [&](const Eigen::Vector3d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  for (const Scene& s : g.panels) {
    for (const Tube& t : s.tubes)
      for (const auto& p : t.p) grow(p);
    for (const Polyline& l : s.polylines)
      for (const auto& p : l.p) grow(p);
  }
  const double d = (hi - lo).norm();
  return d > 0 && d < 1e300 ? 0.1 * d : 0.1;
}

}  // namespace

Image renderPanels(const PanelGrid& g) {
  check(g);
  const int cols = columnsOf(g), rows = rowsOf(g);
  Image grid;
  grid.width = cols * g.panelWidth;
  grid.height = kBanner + rows * g.panelHeight;
  grid.rgba.assign(std::size_t(grid.width) * std::size_t(grid.height) * 4, 255);
  auto blit = [&](const Image& im, int x0, int y0) {
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x < im.width; ++x) std::copy_n(im.pixel(x, y), 4, grid.pixel(x0 + x, y0 + y));
  };
  {
    Scene head;
    head.title = g.title;
    head.titlePixelHeight = bannerPixels(g.title, grid.width);
    RenderOptions o;
    o.width = grid.width;
    o.height = kBanner;
    o.camera = Camera::lookAt({0, -5, 0}, {0, 0, 0});
    blit(render(head, o), 0, 0);
  }
  const Camera cam = commonCamera(g);
  for (std::size_t k = 0; k < g.panels.size(); ++k) {
    Scene s = g.panels[k];
    s.titlePixelHeight = 13;  // a panel title of ~60 characters fits 420 px
    RenderOptions o;
    o.width = g.panelWidth;
    o.height = g.panelHeight;
    o.camera = cam;
    blit(render(s, o), int(k % std::size_t(cols)) * g.panelWidth, kBanner + int(k / std::size_t(cols)) * g.panelHeight);
  }
  // Thin lines between the panels.
  for (int r = 1; r < rows; ++r)
    for (int x = 0; x < grid.width; ++x) std::fill_n(grid.pixel(x, kBanner + r * g.panelHeight), 3, 200);
  for (int c = 1; c < cols; ++c)
    for (int y = kBanner; y < grid.height; ++y) std::fill_n(grid.pixel(c * g.panelWidth, y), 3, 200);
  return grid;
}

std::string panelsSvg(const PanelGrid& g) {
  check(g);
  const int cols = columnsOf(g), rows = rowsOf(g);
  const int W = cols * g.panelWidth, H = kBanner + rows * g.panelHeight;
  const Camera cam = commonCamera(g);
  const double frameScale = automaticFrameScale(g);
  // sceneSvg's pixel scene: x right, y up, z orders the drawing (low first): z = −depth.
  Scene out;
  out.title = g.title;
  out.titlePixelHeight = bannerPixels(g.title, W);
  for (std::size_t k = 0; k < g.panels.size(); ++k) {
    const Scene& s = g.panels[k];
    const double x0 = double(k % std::size_t(cols)) * g.panelWidth;
    const double y0 = kBanner + double(k / std::size_t(cols)) * g.panelHeight;
    auto px = [&](const Eigen::Vector3d& p) {
      const Eigen::Vector2d q = cam.project(p, g.panelWidth, g.panelHeight);
      return Eigen::Vector3d(x0 + q.x(), H - (y0 + q.y()), -cam.depth(p));
    };
    auto segment = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Color& c, double width) {
      Polyline l;
      const Eigen::Vector3d pa = px(a), pb = px(b);
      const double z = 0.5 * (pa.z() + pb.z());
      l.p = {Eigen::Vector3d(pa.x(), pa.y(), z), Eigen::Vector3d(pb.x(), pb.y(), z)};
      l.c = c;
      l.width = width;
      out.add(std::move(l));
    };
    for (const Tube& t : s.tubes) {
      for (std::size_t i = 0; i + 1 < t.p.size(); ++i) segment(t.p[i], t.p[i + 1], t.c, 5);
      if (t.closed && t.p.size() > 2) segment(t.p.back(), t.p.front(), t.c, 5);
    }
    for (const Polyline& l : s.polylines)
      for (std::size_t i = 0; i + 1 < l.p.size(); ++i) segment(l.p[i], l.p[i + 1], l.c, l.width);
    for (const Arrow& a : s.arrows) segment(a.from, a.to, a.c, 3);
    for (const Frame& f : s.frames) {
      const Eigen::Vector3d o = f.pose.block<3, 1>(0, 3);
      const double L = f.scale > 0 ? f.scale : frameScale;
      const Color axes[3] = {palette::vermillion, palette::bluishGreen, palette::blue};
      for (int i = 0; i < 3; ++i) segment(o, o + L * f.pose.block<3, 1>(0, i), axes[i], 2.5);
    }
    for (const Points& p : s.points) {
      Points q;
      q.c = p.c;
      q.radius = 3.5;
      for (const auto& x : p.p) q.p.push_back(px(x));
      out.add(std::move(q));
    }
    for (const Label& l : s.labels) {
      Label m = l;
      m.at = px(l.at);
      m.pixelHeight = std::min(l.pixelHeight, 15.0);
      m.offset = Eigen::Vector2d(l.offset.x(), l.offset.y());
      out.add(std::move(m));
    }
    if (!s.title.empty()) {
      Label t;
      t.text = s.title;
      t.at = Eigen::Vector3d(x0 + 0.5 * g.panelWidth, H - (y0 + 8), 0);
      t.offset = Eigen::Vector2d::Zero();
      t.hAlign = HAlign::Center;
      t.vAlign = VAlign::Top;
      t.pixelHeight = 13;
      out.add(std::move(t));
    }
  }
  for (int r = 1; r < rows; ++r) {
    Polyline l;
    l.c = Color::hex(0xC8C8C8);
    l.width = 1;
    l.p = {Eigen::Vector3d(0, H - (kBanner + r * g.panelHeight), -1e300), Eigen::Vector3d(W, H - (kBanner + r * g.panelHeight), -1e300)};
    out.add(std::move(l));
  }
  for (int c = 1; c < cols; ++c) {
    Polyline l;
    l.c = Color::hex(0xC8C8C8);
    l.width = 1;
    l.p = {Eigen::Vector3d(c * g.panelWidth, 0, -1e300), Eigen::Vector3d(c * g.panelWidth, H - kBanner, -1e300)};
    out.add(std::move(l));
  }
  return sceneSvg(out, W, H);
}

void writePanels(const PanelGrid& g, const std::filesystem::path& file) {
  if (file.extension() == ".svg") {
    const std::string text = panelsSvg(g);
    const std::filesystem::path tmp = file.string() + ".partial";
    {
      std::ofstream out(tmp, std::ios::binary);
      out << text;
      out.close();
      if (!out) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw std::runtime_error("cannot write " + file.string());
      }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
      std::filesystem::remove(tmp, ec);
      throw std::runtime_error("cannot write " + file.string());
    }
    return;
  }
  writePng(renderPanels(g), file);
}

}  // namespace soma::render
