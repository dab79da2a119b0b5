#include "soma/studies/trade.hpp"

#include "soma/render/plot.hpp"
#include "soma/render/svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace soma::studies {

void timeQuantiles(std::vector<double> v, double& median, double& p95) {
  median = p95 = 0;
  if (v.empty()) return;
  std::sort(v.begin(), v.end());
  median = v[v.size() / 2];
  p95 = v[std::min(v.size() - 1, std::size_t(0.95 * double(v.size())))];
}

namespace {

std::string micro(double s) {
  if (s >= 1) return fmt::format("{:.3g} s", s);
  if (s >= 1e-3) return fmt::format("{:.3g} ms", 1e3 * s);
  return fmt::format("{:.3g} µs", 1e6 * s);
}

std::string pad(const std::string& s, std::size_t w) {
  std::size_t cols = 0;  // UTF-8 code points (µ, ×, ε are one column)
  for (unsigned char c : s) cols += (c & 0xC0) != 0x80;
  return cols >= w ? s : s + std::string(w - cols, ' ');
}

}  // namespace

std::string tradeText(const TradeTable& t) {
  std::string out = "speed vs accuracy — " + t.solver + " (per " + t.sample + ")\n";
  std::size_t wS = 6, wE = t.errorLabel.size();
  for (const auto& r : t.rungs) {
    wS = std::max(wS, r.scalar.size());
    wE = std::max(wE, r.worstErrorText.size());
  }
  out += "  " + pad("scalar", wS) + "  " + pad(t.sample + "s", 8) + "  " + pad("median", 10) + "  " +
         pad("p95", 10) + "  " + pad(t.errorLabel, wE) + "  escalated\n";
  for (const auto& r : t.rungs) {
    std::string esc = r.escalated == 0 ? std::string("none")
                                       : fmt::format("{} of {} (to {})", r.escalated, r.samples,
                                                     r.escalatedTo.empty() ? "a higher rung" : r.escalatedTo);
    out += "  " + pad(r.scalar, wS) + "  " + pad(std::to_string(r.samples), 8) + "  " +
           pad(micro(r.medianSeconds), 10) + "  " + pad(micro(r.p95Seconds), 10) + "  " +
           pad(r.worstErrorText, wE) + "  " + esc + (r.comment.empty() ? "" : " · " + r.comment) + "\n";
  }
  return out;
}

int tradeFigure(const TradeTable& t, const std::filesystem::path& png) {
  namespace rd = soma::render;
  struct P {
    const TradeRung* r;
    double lx0, lx1, ly;  // log10 of median, p95, error
  };
  std::vector<P> pts;
  for (const auto& r : t.rungs)
    if (std::isfinite(r.worstError) && r.worstError > 0 && r.medianSeconds > 0)
      pts.push_back({&r, std::log10(r.medianSeconds), std::log10(std::max(r.p95Seconds, r.medianSeconds)),
                     std::log10(r.worstError)});
  if (pts.empty()) return 0;
  // The range the data reach (log10), ticks at the decades inside it.
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const P& p : pts) {
    x0 = std::min(x0, p.lx0);
    x1 = std::max(x1, p.lx1);
    y0 = std::min(y0, p.ly);
    y1 = std::max(y1, p.ly);
  }
  // A margin of 4 % of the span (at least a tenth of a decade) so that no marker is cut by the
  // frame; never a whole empty decade.
  auto widen = [](double& lo, double& hi) {
    const double m = std::max(0.1, 0.04 * (hi - lo));
    lo -= m;
    hi += m;
  };
  widen(x0, x1);
  widen(y0, y1);
  auto decadeTicks = [](double lo, double hi) {
    const int first = int(std::ceil(lo)), last = int(std::floor(hi));
    const int span = last - first;
    const int step = span <= 10 ? 1 : span <= 20 ? 2 : span <= 50 ? 5 : span <= 100 ? 10 : 20;
    std::vector<double> ticks;
    for (int e = first; e <= last; ++e)
      if ((e - first) % step == 0) ticks.push_back(std::pow(10.0, e));
    return ticks;
  };
  rd::Plot plot;
  plot.title = t.solver;  // the axes and the caption say the rest (a long title overflows)
  plot.x.label = "time per " + t.sample + " (s): median (point) to p95 (bar)";
  plot.y.label = t.errorLabel;
  plot.x.scale = plot.y.scale = rd::AxisScale::Log10;
  plot.x.min = std::pow(10.0, x0);
  plot.x.max = std::pow(10.0, x1);
  plot.y.min = std::pow(10.0, y0);
  plot.y.max = std::pow(10.0, y1);
  plot.x.ticks = decadeTicks(x0, x1);
  plot.y.ticks = decadeTicks(y0, y1);
  // The legend prefers the top right; the plot moves it where no point, bar or text lies under it
  // (render/plot.hpp: the other corners, the edges' middles, then outside the plot area).
  plot.legend = rd::LegendCorner::TopRight;
  std::size_t ci = 0;
  for (const P& p : pts) {
    const rd::Color c = rd::palette::cycle(ci++);
    const double e = p.r->worstError;
    auto& bar = plot.add("", {p.r->medianSeconds, std::max(p.r->p95Seconds, p.r->medianSeconds)}, {e, e}, c);
    bar.width = 3;
    auto& dot = plot.add(p.r->scalar, {p.r->medianSeconds}, {e}, c);
    dot.line = false;
    dot.markers = true;
    dot.markerRadius = 7;
  }
  rd::renderPlotPngAndSvg(plot, png, 1100, 750);  // the SVG beside the PNG, as every 2-D study figure
  return int(pts.size());
}

}  // namespace soma::studies
