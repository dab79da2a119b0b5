// SVG of 2-D figures (svg.hpp): the primitives of plotScene's pixel-unit scene as SVG elements.
#include "soma/render/svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <utility>
#include <vector>
#include <stdexcept>

namespace soma::render {

namespace {

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

std::string rgb(const Color& c) {
  char b[32];
  auto byte = [](float x) { return int(std::lround(std::clamp(x, 0.0f, 1.0f) * 255)); };
  std::snprintf(b, sizeof b, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  std::string s = b;
  return c.a < 1 ? s + "\" fill-opacity=\"" + num(c.a) : s;
}

std::string escape(const std::string& t) {
  std::string o;
  for (const char ch : t) {
    if (ch == '&') o += "&amp;";
    else if (ch == '<') o += "&lt;";
    else if (ch == '>') o += "&gt;";
    else if (ch == '"') o += "&quot;";
    else o += ch;
  }
  return o;
}

}  // namespace

std::string sceneSvg(const Scene& sc, int width, int height) {
  if (!sc.tubes.empty() || !sc.meshes.empty() || !sc.frames.empty() || !sc.arrows.empty())
    throw std::invalid_argument("soma::render::sceneSvg: the scene has 3-D primitives (tubes, meshes, frames or arrows)");
  const double H = height;
  auto pt = [&](const Eigen::Vector3d& p) { return num(p.x()) + "," + num(H - p.y()); };
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
                  std::to_string(width) + "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) +
                  " " + std::to_string(height) + "\" font-family=\"DejaVu Sans, sans-serif\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"" + rgb(sc.background) + "\"/>\n";
  // The depth order of the PNG (plotScene layers by z: grid, cells, curves, legend), then text on top;
  // within one z, fills, lines, markers.
  std::vector<std::pair<double, std::string>> items;
  auto emit = [&](double z, std::string e) { items.emplace_back(z, std::move(e)); };
  for (const Fill& f : sc.fills)
    for (const Eigen::Vector3i& t : f.tri) {
      const Color c = f.vc.empty() ? f.c : f.vc[std::size_t(t(0))];
      emit(f.v[std::size_t(t(0))].z(), "<polygon points=\"" + pt(f.v[std::size_t(t(0))]) + " " + pt(f.v[std::size_t(t(1))]) + " " + pt(f.v[std::size_t(t(2))]) +
           "\" fill=\"" + rgb(c) + "\"/>\n");
    }
  for (const Polyline& l : sc.polylines) {
    if (l.p.size() < 2) continue;
    std::string e;
    e += std::string("<") + (l.closed ? "polygon" : "polyline") + " fill=\"none\" stroke=\"" + rgb(l.c) +
         "\" stroke-width=\"" + num(l.width) + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
    if (l.dashed) e += " stroke-dasharray=\"" + num(l.dashLength) + "\"";
    e += " points=\"";
    for (std::size_t k = 0; k < l.p.size(); ++k) e += (k ? " " : "") + pt(l.p[k]);
    e += "\"/>\n";
    emit(l.p.front().z(), e);
  }
  for (const Points& p : sc.points)
    for (const Eigen::Vector3d& x : p.p)
      emit(x.z(), "<circle cx=\"" + num(x.x()) + "\" cy=\"" + num(H - x.y()) + "\" r=\"" + num(p.radius > 0 ? p.radius : 4) +
           "\" fill=\"" + rgb(p.c) + "\"/>\n");
  std::stable_sort(items.begin(), items.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& it : items) s += it.second;
  for (const Label& l : sc.labels) {
    const char* anchor = l.hAlign == HAlign::Center ? "middle" : l.hAlign == HAlign::Right ? "end" : "start";
    const char* base = l.vAlign == VAlign::Top ? "hanging" : l.vAlign == VAlign::Middle ? "middle" : "alphabetic";
    s += "<text x=\"" + num(l.at.x() + l.offset.x()) + "\" y=\"" + num(H - l.at.y() + l.offset.y()) + "\" font-size=\"" +
         num(l.pixelHeight) + "\" text-anchor=\"" + anchor + "\" dominant-baseline=\"" + base + "\" fill=\"" + rgb(l.c) + "\">" +
         escape(l.text) + "</text>\n";
  }
  if (!sc.title.empty())
    s += "<text x=\"" + num(width / 2.0) + "\" y=\"" + num(sc.titlePixelHeight + 8) + "\" font-size=\"" + num(sc.titlePixelHeight) +
         "\" text-anchor=\"middle\" fill=\"#000000\">" + escape(sc.title) + "</text>\n";
  return s + "</svg>\n";
}

std::string plotSvg(const Plot& plot, int width, int height) { return sceneSvg(plotScene(plot, width, height), width, height); }

void renderPlotSvg(const Plot& plot, const std::filesystem::path& svg, int width, int height) {
  const std::string text = plotSvg(plot, width, height);
  std::ofstream out(svg, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + svg.string());
}

void renderPlot(const Plot& plot, const std::filesystem::path& file, int width, int height) {
  if (file.extension() == ".svg") renderPlotSvg(plot, file, width, height);
  else renderPlotPng(plot, file, width, height);
}

void renderPlotPngAndSvg(const Plot& plot, const std::filesystem::path& png, int width, int height) {
  renderPlotPng(plot, png, width, height);
  std::filesystem::path svg = png;
  svg.replace_extension(".svg");
  if (svg != png) renderPlotSvg(plot, svg, width, height);
}

}  // namespace soma::render
