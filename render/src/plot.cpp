// 2-D plots as Scenes in pixel units: axes, ticks, clipped curves, markers, cells, legend.
#include "soma/render/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace soma::render {

PlotSeries& Plot::add(std::string name, std::vector<double> xs, std::vector<double> ys, Color c) {
  PlotSeries s;
  s.name = std::move(name);
  s.x = std::move(xs);
  s.y = std::move(ys);
  s.c = c;
  series.push_back(std::move(s));
  return series.back();
}

std::vector<double> niceTicks(double lo, double hi, int target) {
  std::vector<double> out;
  if (!(std::isfinite(lo) && std::isfinite(hi)) || !(hi > lo) || target < 1) return out;
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * mag >= raw * 0.999) {
      step = m * mag;
      break;
    }
  const double first = std::ceil(lo / step - 1e-9) * step;
  for (double t = first; t <= hi + step * 1e-9; t += step) out.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  return out;
}

namespace {

const char* const kSuperscript[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};

std::string superscript(int k) {
  std::string s = k < 0 ? "⁻" : "";
  const std::string digits = std::to_string(std::abs(k));
  for (char d : digits) s += kSuperscript[d - '0'];
  return s;
}

[[noreturn]] void invalid(const std::string& what) { throw std::invalid_argument("soma::render::Plot: " + what); }

/// Transformed coordinate of a data value (log10 on a log axis; NaN when not representable).
double fwd(double v, AxisScale s) {
  if (!std::isfinite(v)) return std::numeric_limits<double>::quiet_NaN();
  if (s == AxisScale::Log10) return v > 0 ? std::log10(v) : std::numeric_limits<double>::quiet_NaN();
  return v;
}

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double t) {
    if (!std::isfinite(t)) return;
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  bool empty() const { return !(hi >= lo); }
};

/// The visible transformed range of an axis: the user's limits, or the data's with a margin.
void axisRange(const PlotAxis& a, const Range& data, double& lo, double& hi, const char* name, double margin) {
  const bool fixedLo = !std::isnan(a.min), fixedHi = !std::isnan(a.max);
  if (a.scale == AxisScale::Log10 && ((fixedLo && !(a.min > 0)) || (fixedHi && !(a.max > 0))))
    invalid(std::string(name) + " axis is logarithmic but its limits are not positive");
  lo = fixedLo ? fwd(a.min, a.scale) : data.lo;
  hi = fixedHi ? fwd(a.max, a.scale) : data.hi;
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    if (data.empty()) invalid(std::string(name) + " axis has no finite data and no limits");
    if (!std::isfinite(lo)) lo = data.lo;
    if (!std::isfinite(hi)) hi = data.hi;
  }
  if (hi < lo) invalid(std::string(name) + " axis has min > max");
  if (hi == lo) {  // a single value: show a unit window around it
    const double w = lo == 0 ? 1.0 : std::abs(lo) * 0.1;
    if (!fixedLo) lo -= w;
    if (!fixedHi) hi += w;
    if (hi == lo) hi = lo + 1;
  }
  const double pad = margin * (hi - lo);
  if (!fixedLo) lo -= pad;
  if (!fixedHi) hi += pad;
}

std::vector<double> axisTicks(const PlotAxis& a, double lo, double hi, int target) {
  if (!a.ticks.empty()) {
    std::vector<double> t;
    for (double v : a.ticks) {
      const double f = fwd(v, a.scale);
      if (std::isfinite(f) && f >= lo - 1e-12 * (hi - lo) && f <= hi + 1e-12 * (hi - lo)) t.push_back(f);
    }
    return t;
  }
  if (a.scale == AxisScale::Linear) return niceTicks(lo, hi, target);
  // Decades; thinned to about `target`; with 1–2 decades, add 2 and 5.
  std::vector<double> t;
  const int d0 = int(std::ceil(lo - 1e-9)), d1 = int(std::floor(hi + 1e-9));
  // Every k-th decade with k from 1, 2, 5, 10, 20, 50, …, at multiples of k (10⁻²⁰, 10⁻⁴⁰, …).
  const int raw = std::max(1, (d1 - d0 + target - 1) / std::max(1, target));
  int every = 1;
  for (int m = 1; every < raw; m *= 10)
    for (int f : {1, 2, 5})
      if (every < raw) every = f * m;
  for (int d = d0; d <= d1; ++d)
    if (d % every == 0) t.push_back(d);
  if (t.size() < 3)
    for (int d = d0 - 1; d <= d1; ++d)
      for (double m : {2.0, 5.0}) {
        const double f = d + std::log10(m);
        if (f >= lo && f <= hi) t.push_back(f);
      }
  std::sort(t.begin(), t.end());
  return t;
}

/// Liang–Barsky: clip segment p→q to the rectangle; false when nothing is inside.
bool clip(Eigen::Vector2d& p, Eigen::Vector2d& q, double x0, double x1, double y0, double y1) {
  double t0 = 0, t1 = 1;
  const Eigen::Vector2d d = q - p;
  const double pk[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double qk[4] = {p.x() - x0, x1 - p.x(), p.y() - y0, y1 - p.y()};
  for (int k = 0; k < 4; ++k) {
    if (pk[k] == 0) {
      if (qk[k] < 0) return false;
      continue;
    }
    const double r = qk[k] / pk[k];
    if (pk[k] < 0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
    if (t0 > t1) return false;
  }
  const Eigen::Vector2d a = p + t0 * d, b = p + t1 * d;
  p = a;
  q = b;
  return true;
}

int codepoints(const std::string& s) {
  int n = 0;
  for (unsigned char ch : s) n += (ch & 0xC0) != 0x80;
  return n;
}

}  // namespace

std::string tickLabel(double v, AxisScale scale) {
  if (scale == AxisScale::Log10) {
    const double r = std::round(v);
    if (std::abs(v - r) < 1e-9) {
      if (r == 0) return "1";
      if (r == 1) return "10";
      return "10" + superscript(int(r));
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", std::pow(10.0, v));
    return buf;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", std::abs(v) < 1e-300 ? 0.0 : v);
  std::string s = buf;
  if (!s.empty() && s[0] == '-') s = "−" + s.substr(1);  // a typographic minus
  return s;
}

Color colorMap(double t) {
  // Piecewise-linear through samples of a viridis-like ramp (perceptually ordered, prints in grey).
  static const Color stops[] = {Color::hex(0x440154), Color::hex(0x3B528B), Color::hex(0x21918C),
                                Color::hex(0x5EC962), Color::hex(0xFDE725)};
  if (!std::isfinite(t)) return palette::lightGrey;
  t = std::clamp(t, 0.0, 1.0) * 4;
  const int i = std::min(3, int(t));
  const float f = float(t - i);
  const Color& a = stops[i];
  const Color& b = stops[i + 1];
  return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f, 1};
}

Scene plotScene(const Plot& plot, int width, int height, Camera* camera, PlotFrame* frameOut) {
  if (width < 200 || height < 150) invalid("image " + std::to_string(width) + "×" + std::to_string(height) + " is below 200×150");
  if (plot.series.empty() && plot.cells.empty() && plot.texts.empty()) invalid("nothing to plot");
  Range xr, yr;
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& s = plot.series[i];
    if (s.x.size() != s.y.size())
      invalid("series " + std::to_string(i) + " ('" + s.name + "') has " + std::to_string(s.x.size()) + " x and " +
              std::to_string(s.y.size()) + " y values");
    for (std::size_t k = 0; k < s.x.size(); ++k) {
      const double fx = fwd(s.x[k], plot.x.scale), fy = fwd(s.y[k], plot.y.scale);
      if (std::isfinite(fx) && std::isfinite(fy)) {
        xr.add(fx);
        yr.add(fy);
      }
    }
  }
  for (const PlotCells& c : plot.cells) {
    if (c.nx < 1 || c.ny < 1 || c.cells.size() != std::size_t(c.nx) * std::size_t(c.ny))
      invalid("cells: " + std::to_string(c.cells.size()) + " colours for a " + std::to_string(c.nx) + "×" + std::to_string(c.ny) + " grid");
    xr.add(fwd(c.x0, plot.x.scale));
    xr.add(fwd(c.x1, plot.x.scale));
    yr.add(fwd(c.y0, plot.y.scale));
    yr.add(fwd(c.y1, plot.y.scale));
  }
  for (const PlotText& t : plot.texts) {
    xr.add(fwd(t.x, plot.x.scale));
    yr.add(fwd(t.y, plot.y.scale));
  }
  double x0, x1, y0, y1;
  // A margin around curves; none around a map of cells alone (it fills the axes).
  const double margin = plot.series.empty() ? 0.0 : 0.04;
  axisRange(plot.x, xr, x0, x1, "x", margin);
  axisRange(plot.y, yr, y0, y1, "y", margin);

  // The legend's entries and box size (placed below, once the plot area is known).
  struct Entry {
    std::string name;
    Color c;
    bool swatch, dashed, marker, line;
  };
  std::vector<Entry> entries;
  for (const PlotSeries& s : plot.series)
    if (!s.name.empty()) entries.push_back({s.name, s.c, false, s.dashed, s.markers, s.line});
  for (const auto& [name, c] : plot.legendSwatches) entries.push_back({name, c, true, false, false, false});
  const double legendRow = 28;
  int legendChars = 0;
  for (const Entry& e : entries) legendChars = std::max(legendChars, codepoints(e.name));
  const double legendW = 0.56 * 19 * legendChars + 70, legendH = legendRow * double(entries.size()) + 12;

  // Plot area in pixels (world units; y up); a colour bar takes a column at the right.
  const double colorBarW = plot.colorBar ? 150 : 0;
  const double left = 120;
  double bottom = plot.x.label.empty() ? 60 : 100;
  double right = width - 40 - colorBarW;
  const double fullTop = height - (plot.title.empty() ? 30 : 70) - (plot.y.label.empty() ? 0 : 36);
  double top = fullTop;
  const double rx0 = x0, rx1 = x1, ry0 = y0, ry1 = y1, fullRight = right;
  const bool xFixed = !std::isnan(plot.x.min) && !std::isnan(plot.x.max);
  const bool yFixed = !std::isnan(plot.y.min) && !std::isnan(plot.y.max);
  auto fitArea = [&] {
    x0 = rx0, x1 = rx1, y0 = ry0, y1 = ry1;
    top = fullTop;
    if (!plot.equalAspect) return;
    // Widen the range that has fewer pixels per unit; when the caller fixed both of its limits
    // (a map that fills its axes), narrow the plot area instead, so the axes fit the data.
    const double sx = (right - left) / (x1 - x0), sy = (top - bottom) / (y1 - y0);
    if (sx > sy) {
      if (xFixed) {
        right = left + (x1 - x0) * sy;
      } else {
        const double c = (x0 + x1) / 2, h = (right - left) / sy / 2;
        x0 = c - h, x1 = c + h;
      }
    } else {
      if (yFixed) {
        top = bottom + (y1 - y0) * sx;
      } else {
        const double c = (y0 + y1) / 2, h = (top - bottom) / sx / 2;
        y0 = c - h, y1 = c + h;
      }
    }
  };
  fitArea();
  // The legend goes where no data lies under it: the preferred corner, the other corners, the
  // middles of the edges; when each of those covers data, outside the plot area on the right.
  // xr0: the right end of the sample lines; yTop: the top edge of the box.
  double xr0 = 0, yTop = 0;
  bool legendInside = true;
  if (!entries.empty()) {
    auto covers = [&](double bx0, double by0, double bx1, double by1) {
      auto px = [&](double fx) { return left + (fx - x0) / (x1 - x0) * (right - left); };
      auto py = [&](double fy) { return bottom + (fy - y0) / (y1 - y0) * (top - bottom); };
      auto inside = [&](const Eigen::Vector2d& q) {
        return q.x() >= bx0 && q.x() <= bx1 && q.y() >= by0 && q.y() <= by1;
      };
      for (const PlotSeries& sr : plot.series) {
        Eigen::Vector2d prev;
        bool havePrev = false;
        const std::size_t n = sr.x.size();
        for (std::size_t k = 0; k < n + (sr.closed && sr.line ? 1 : 0); ++k) {
          const std::size_t kk = k % std::max<std::size_t>(n, 1);
          const double fx = fwd(sr.x[kk], plot.x.scale), fy = fwd(sr.y[kk], plot.y.scale);
          if (!std::isfinite(fx) || !std::isfinite(fy)) {
            havePrev = false;
            continue;
          }
          const Eigen::Vector2d q(px(fx), py(fy));
          const bool visible = q.x() >= left && q.x() <= right && q.y() >= bottom && q.y() <= top;
          // A marker covers its radius around the point.
          const double r = sr.markers ? sr.markerRadius : 0;
          if (visible && q.x() >= bx0 - r && q.x() <= bx1 + r && q.y() >= by0 - r && q.y() <= by1 + r) return true;
          if (sr.line && havePrev) {
            Eigen::Vector2d a = prev, b = q;
            if (clip(a, b, left, right, bottom, top) && clip(a, b, bx0, bx1, by0, by1)) return true;
          }
          prev = q;
          havePrev = true;
        }
      }
      for (const PlotText& t : plot.texts) {
        const double fx = fwd(t.x, plot.x.scale), fy = fwd(t.y, plot.y.scale);
        if (std::isfinite(fx) && std::isfinite(fy) && inside({px(fx), py(fy)})) return true;
      }
      // A map's cells are data too, except the white ones (the background: nothing there).
      for (const PlotCells& c : plot.cells) {
        const double cx0 = fwd(c.x0, plot.x.scale), cx1 = fwd(c.x1, plot.x.scale);
        const double cy0 = fwd(c.y0, plot.y.scale), cy1 = fwd(c.y1, plot.y.scale);
        for (int j = 0; j < c.ny; ++j)
          for (int i = 0; i < c.nx; ++i) {
            const Color& col = c.cells[std::size_t(j) * c.nx + i];
            if (col.a <= 0 || (col.r >= 1 && col.g >= 1 && col.b >= 1)) continue;
            const double ax = px(cx0 + (cx1 - cx0) * i / c.nx), bx = px(cx0 + (cx1 - cx0) * (i + 1) / c.nx);
            const double ay = py(cy0 + (cy1 - cy0) * j / c.ny), by = py(cy0 + (cy1 - cy0) * (j + 1) / c.ny);
            if (std::max(ax, bx) >= bx0 && std::min(ax, bx) <= bx1 && std::max(ay, by) >= by0 && std::min(ay, by) <= by1)
              return true;
          }
      }
      return false;
    };
    const LegendCorner corners[4] = {LegendCorner::TopRight, LegendCorner::TopLeft, LegendCorner::BottomRight,
                                     LegendCorner::BottomLeft};
    std::vector<std::pair<double, double>> candidates;  // (xr0, yTop)
    auto cornerAt = [&](LegendCorner c) {
      const bool r = c == LegendCorner::TopRight || c == LegendCorner::BottomRight;
      const bool t = c == LegendCorner::TopRight || c == LegendCorner::TopLeft;
      return std::pair<double, double>(r ? right - 16 : left + 8 + legendW, t ? top - 8 : bottom + 8 + legendH);
    };
    candidates.push_back(cornerAt(plot.legend));
    for (LegendCorner c : corners)
      if (c != plot.legend) candidates.push_back(cornerAt(c));
    const double midX = (left + right + legendW) / 2 - 4, midY = (bottom + top + legendH) / 2;
    candidates.push_back({midX, top - 8});
    candidates.push_back({midX, bottom + 8 + legendH});
    candidates.push_back({right - 16, midY});
    candidates.push_back({left + 8 + legendW, midY});
    bool placed = false;
    if (legendW + 24 < right - left && legendH + 16 < top - bottom)
      for (const auto& [cx, cy] : candidates)
        if (!covers(cx - legendW, cy - legendH, cx + 8, cy)) {
          xr0 = cx, yTop = cy, placed = true;
          break;
        }
    if (!placed && legendW < 0.3 * width) {  // outside on the right: the plot area gives up its width
      right = std::min(right, fullRight - legendW - 24);
      fitArea();
      xr0 = right + 16 + legendW;
      yTop = top;
      legendInside = false;
    } else if (!placed) {  // a wide legend: outside below the x axis label, the area gives up its height
      yTop = legendH + 10;  // at the image's foot; the ticks and the x label move up above it
      bottom += legendH + 16;
      if (top - bottom < 80) invalid("the legend leaves no room for the plot");
      fitArea();
      xr0 = std::min(fullRight - 8, (left + fullRight + legendW) / 2);
      legendInside = false;
    }
  }
  auto X = [&](double fx) { return left + (fx - x0) / (x1 - x0) * (right - left); };
  auto Y = [&](double fy) { return bottom + (fy - y0) / (y1 - y0) * (top - bottom); };
  auto at = [](double px, double py, double z = 0) { return Eigen::Vector3d(px, py, z); };

  Scene sc;
  sc.title = plot.title;
  // A title wider than the image is set smaller (DejaVu Sans advances about 0.6 em per character).
  if (const int n = codepoints(plot.title); n > 0 && 0.6 * sc.titlePixelHeight * n > width - 30)
    sc.titlePixelHeight = std::max(12.0, (width - 30) / (0.6 * n));
  // Cells (under the curves and the axes; grid lines stay visible over them, to read values by).
  for (const PlotCells& c : plot.cells) {
    Fill f;
    const double cx0 = fwd(c.x0, plot.x.scale), cx1 = fwd(c.x1, plot.x.scale);
    const double cy0 = fwd(c.y0, plot.y.scale), cy1 = fwd(c.y1, plot.y.scale);
    for (int j = 0; j < c.ny; ++j)
      for (int i = 0; i < c.nx; ++i) {
        Eigen::Vector2d a(X(cx0 + (cx1 - cx0) * i / c.nx), Y(cy0 + (cy1 - cy0) * j / c.ny));
        Eigen::Vector2d b(X(cx0 + (cx1 - cx0) * (i + 1) / c.nx), Y(cy0 + (cy1 - cy0) * (j + 1) / c.ny));
        a = a.cwiseMax(Eigen::Vector2d(left, bottom)).cwiseMin(Eigen::Vector2d(right, top));
        b = b.cwiseMax(Eigen::Vector2d(left, bottom)).cwiseMin(Eigen::Vector2d(right, top));
        if (a.x() == b.x() || a.y() == b.y()) continue;
        const int v = int(f.v.size());
        f.v.insert(f.v.end(), {at(a.x(), a.y(), -1), at(b.x(), a.y(), -1), at(b.x(), b.y(), -1), at(a.x(), b.y(), -1)});
        const Color col = c.cells[std::size_t(j) * c.nx + i];
        f.vc.insert(f.vc.end(), {col, col, col, col});
        f.tri.push_back({v, v + 1, v + 2});
        f.tri.push_back({v, v + 2, v + 3});
      }
    if (!f.tri.empty()) sc.add(std::move(f));
  }
  // Grid, ticks and tick labels.
  const std::vector<double> xt = axisTicks(plot.x, x0, x1, std::max(3, int((right - left) / 150)));
  const std::vector<double> yt = axisTicks(plot.y, y0, y1, std::max(3, int((top - bottom) / 110)));
  for (double t : xt) {
    const double px = X(t);
    if (plot.grid) sc.add(Polyline{{at(px, bottom, -3), at(px, top, -3)}, palette::lightGrey, 1.2});
    sc.add(Polyline{{at(px, bottom), at(px, bottom - 8)}, palette::darkGrey, 1.5});
    Label l;
    l.at = at(px, bottom - 12);
    l.text = tickLabel(t, plot.x.scale);
    l.hAlign = HAlign::Center;
    l.vAlign = VAlign::Top;
    l.offset = {0, 0};
    l.pixelHeight = 19;
    sc.add(l);
  }
  for (double t : yt) {
    const double py = Y(t);
    if (plot.grid) sc.add(Polyline{{at(left, py, -3), at(right, py, -3)}, palette::lightGrey, 1.2});
    sc.add(Polyline{{at(left, py), at(left - 8, py)}, palette::darkGrey, 1.5});
    Label l;
    l.at = at(left - 12, py);
    l.text = tickLabel(t, plot.y.scale);
    l.hAlign = HAlign::Right;
    l.vAlign = VAlign::Middle;
    l.offset = {0, 0};
    l.pixelHeight = 19;
    sc.add(l);
  }
  Polyline box{{at(left, bottom), at(right, bottom), at(right, top), at(left, top)}, palette::darkGrey, 1.5};
  box.closed = true;
  sc.add(box);
  if (!plot.x.label.empty()) {
    Label l;
    l.at = at((left + right) / 2, bottom - 48);
    l.text = plot.x.label;
    l.hAlign = HAlign::Center;
    l.vAlign = VAlign::Top;
    l.offset = {0, 0};
    l.pixelHeight = 22;
    sc.add(l);
  }
  if (!plot.y.label.empty()) {
    Label l;
    l.at = at(left - 60, top + 14);
    l.text = plot.y.label;
    l.hAlign = HAlign::Left;
    l.vAlign = VAlign::Bottom;
    l.offset = {0, 0};
    l.pixelHeight = 22;
    sc.add(l);
  }
  // Curves and markers, clipped to the plot area.
  for (const PlotSeries& s : plot.series) {
    std::vector<Eigen::Vector2d> pts(s.x.size());
    std::vector<bool> ok(s.x.size());
    for (std::size_t k = 0; k < s.x.size(); ++k) {
      const double fx = fwd(s.x[k], plot.x.scale), fy = fwd(s.y[k], plot.y.scale);
      ok[k] = std::isfinite(fx) && std::isfinite(fy);
      pts[k] = ok[k] ? Eigen::Vector2d(X(fx), Y(fy)) : Eigen::Vector2d::Zero();
    }
    if (s.line && pts.size() >= 2) {
      std::vector<Eigen::Vector3d> cur;
      auto flush = [&] {
        if (cur.size() >= 2) {
          Polyline pl{cur, s.c, s.width};
          pl.dashed = s.dashed;
          sc.add(std::move(pl));
        }
        cur.clear();
      };
      const std::size_t nseg = s.closed ? pts.size() : pts.size() - 1;
      for (std::size_t k = 0; k < nseg; ++k) {
        const std::size_t k1 = (k + 1) % pts.size();
        if (!ok[k] || !ok[k1]) {
          flush();
          continue;
        }
        Eigen::Vector2d p = pts[k], q = pts[k1];
        if (!clip(p, q, left, right, bottom, top)) {
          flush();
          continue;
        }
        if (!cur.empty() && (cur.back().head<2>() - p).norm() > 1e-9) flush();
        if (cur.empty()) cur.push_back(at(p.x(), p.y()));
        cur.push_back(at(q.x(), q.y()));
      }
      flush();
    }
    if (s.markers) {
      Points m;
      m.c = s.c;
      m.radius = s.markerRadius;
      for (std::size_t k = 0; k < pts.size(); ++k)
        if (ok[k] && pts[k].x() >= left && pts[k].x() <= right && pts[k].y() >= bottom && pts[k].y() <= top)
          m.p.push_back(at(pts[k].x(), pts[k].y()));
      if (!m.p.empty()) sc.add(std::move(m));
    }
  }
  for (const PlotText& t : plot.texts) {
    const double fx = fwd(t.x, plot.x.scale), fy = fwd(t.y, plot.y.scale);
    if (!std::isfinite(fx) || !std::isfinite(fy)) continue;
    Label l;
    l.at = at(X(fx), Y(fy), 60);
    l.text = t.text;
    l.c = t.c;
    l.pixelHeight = t.pixelHeight;
    l.hAlign = t.hAlign;
    l.vAlign = t.vAlign;
    l.offset = {t.dx, t.dy};
    sc.add(l);
  }
  // The legend (placed above), on a translucent white box.
  if (!entries.empty()) {
    const double row = legendRow, w = legendW, h = legendH;
    Fill bg;
    bg.c = palette::white.withAlpha(0.88f);
    bg.v = {at(xr0 - w, yTop - h, 50), at(xr0 + 8, yTop - h, 50), at(xr0 + 8, yTop, 50), at(xr0 - w, yTop, 50)};
    bg.tri = {{0, 1, 2}, {0, 2, 3}};
    sc.add(std::move(bg));
    for (std::size_t k = 0; k < entries.size(); ++k) {
      const Entry& e = entries[k];
      const double py = yTop - 6 - row * (double(k) + 0.5);
      if (e.swatch) {
        Fill f;
        f.c = e.c;
        f.v = {at(xr0 - 30, py - 9, 51), at(xr0 - 12, py - 9, 51), at(xr0 - 12, py + 9, 51), at(xr0 - 30, py + 9, 51)};
        f.tri = {{0, 1, 2}, {0, 2, 3}};
        sc.add(std::move(f));
      } else {
        if (e.line || !e.marker) {
          Polyline pl{{at(xr0 - 44, py, 51), at(xr0, py, 51)}, e.c, 3};
          pl.dashed = e.dashed;
          pl.dashLength = 8;
          sc.add(std::move(pl));
        }
        if (e.marker) sc.add(Points{{at(xr0 - 22, py, 51)}, e.c, 5});
      }
      Label l;
      l.at = at(xr0 - 54, py, 52);
      l.text = e.name;
      l.c = palette::black;
      l.hAlign = HAlign::Right;
      l.vAlign = VAlign::Middle;
      l.offset = {0, 0};
      l.pixelHeight = 19;
      l.halo = false;
      sc.add(l);
    }
  }
  // The colour bar: colorMap(t) from min (t = 0, bottom) to max (t = 1, top), with ticks.
  double cbLeft = 0, cbRight = 0;
  if (plot.colorBar) {
    const PlotColorBar& cb = *plot.colorBar;
    if (!(std::isfinite(cb.min) && std::isfinite(cb.max) && cb.max > cb.min))
      invalid("colour bar: min " + std::to_string(cb.min) + " is not below max " + std::to_string(cb.max));
    if (cb.scale == AxisScale::Log10 && !(cb.min > 0)) invalid("colour bar: a log scale needs min > 0");
    cbLeft = (legendInside || entries.empty() ? right : xr0 + 8) + 30;
    cbRight = cbLeft + 26;
    const double barTop = top - 30;
    Fill f;
    const int n = 96;
    for (int k = 0; k < n; ++k) {
      const double ya = bottom + (barTop - bottom) * k / n, yb = bottom + (barTop - bottom) * (k + 1) / n;
      const Color c = colorMap((k + 0.5) / n);
      const int v = int(f.v.size());
      f.v.insert(f.v.end(), {at(cbLeft, ya), at(cbRight, ya), at(cbRight, yb), at(cbLeft, yb)});
      f.vc.insert(f.vc.end(), {c, c, c, c});
      f.tri.push_back({v, v + 1, v + 2});
      f.tri.push_back({v, v + 2, v + 3});
    }
    sc.add(std::move(f));
    Polyline frame{{at(cbLeft, bottom), at(cbRight, bottom), at(cbRight, barTop), at(cbLeft, barTop)}, palette::darkGrey, 1.5};
    frame.closed = true;
    sc.add(frame);
    const double f0 = fwd(cb.min, cb.scale), f1 = fwd(cb.max, cb.scale);
    PlotAxis ax;
    ax.scale = cb.scale;
    for (double t : axisTicks(ax, f0, f1, std::max(3, int((barTop - bottom) / 110)))) {
      const double py = bottom + (t - f0) / (f1 - f0) * (barTop - bottom);
      sc.add(Polyline{{at(cbRight, py), at(cbRight + 7, py)}, palette::darkGrey, 1.5});
      Label l;
      l.at = at(cbRight + 10, py);
      l.text = tickLabel(t, cb.scale);
      l.hAlign = HAlign::Left;
      l.vAlign = VAlign::Middle;
      l.offset = {0, 0};
      l.pixelHeight = 17;
      sc.add(l);
    }
    if (!cb.label.empty()) {
      Label l;
      l.at = at(cbLeft - 12, barTop + 10);
      l.text = cb.label;
      l.hAlign = HAlign::Left;
      l.vAlign = VAlign::Bottom;
      l.offset = {0, 0};
      l.pixelHeight = 18;
      sc.add(l);
    }
  }
  if (camera) {
    const Eigen::Vector3d c(width / 2.0, height / 2.0, 0);
    *camera = Camera::ortho(c + Eigen::Vector3d(0, 0, 500), c, Eigen::Vector3d::UnitY(), double(height));
  }
  if (frameOut) {
    auto back = [](double f, AxisScale s) { return s == AxisScale::Log10 ? std::pow(10.0, f) : f; };
    *frameOut = {back(x0, plot.x.scale), back(x1, plot.x.scale), back(y0, plot.y.scale), back(y1, plot.y.scale),
                 left, right, bottom, top, width, height};
    if (!entries.empty()) {
      frameOut->legend = true;
      frameOut->legendInside = legendInside;
      frameOut->legendLeft = xr0 - legendW;
      frameOut->legendRight = xr0 + 8;
      frameOut->legendBottom = yTop - legendH;
      frameOut->legendTop = yTop;
    }
    frameOut->colorBarLeft = cbLeft;
    frameOut->colorBarRight = cbRight;
  }
  return sc;
}

void renderPlotPng(const Plot& plot, const std::filesystem::path& png, int width, int height) {
  Camera cam;
  const Scene sc = plotScene(plot, width, height, &cam);
  RenderOptions opt;
  opt.width = width;
  opt.height = height;
  opt.camera = cam;
  renderPng(sc, opt, png);
}

}  // namespace soma::render
