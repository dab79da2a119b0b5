#pragma once
// 2-D plots for figures: axes with ticks (linear or log), curves, markers, text in data
// coordinates, colour cells (heat maps, classification maps) and a legend, turned into a Scene
// and rendered off-screen. Used for measurements (error vs angle, time vs scalar type) and for
// planar geometry (coupler curves, inflection circles: `equalAspect`).
#include "soma/render/renderer.hpp"
#include "soma/render/scene.hpp"

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace soma::render {

enum class AxisScale { Linear, Log10 };

struct PlotAxis {
  std::string label;
  AxisScale scale = AxisScale::Linear;
  /// The visible range; NaN = from the data (with a small margin, widened to round ticks).
  double min = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
  /// Tick positions in data units; empty = automatic (1-2-5 steps, or decades on a log axis).
  std::vector<double> ticks;
};

/// A curve and/or markers. Non-finite points (and non-positive ones on a log axis) break the
/// curve into pieces; parts outside the visible range are clipped.
struct PlotSeries {
  std::string name;  ///< legend entry; empty = not in the legend
  std::vector<double> x, y;
  Color c = palette::blue;
  bool line = true;
  double width = 3;  ///< pixels
  bool dashed = false;
  bool markers = false;
  double markerRadius = 5;  ///< pixels
  bool closed = false;      ///< join the last point to the first (a closed curve)
};

/// Text anchored at a point in data coordinates (offset in pixels, x right, y down).
struct PlotText {
  double x = 0, y = 0;
  std::string text;
  Color c = palette::black;
  double pixelHeight = 20;
  HAlign hAlign = HAlign::Left;
  VAlign vAlign = VAlign::Bottom;
  double dx = 6, dy = -6;
};

/// An nx × ny grid of coloured cells covering [x0, x1] × [y0, y1] in data coordinates; cell (i, j)
/// (i along x, j along y) has colour cells[j * nx + i]. Drawn under the curves.
struct PlotCells {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  int nx = 0, ny = 0;
  std::vector<Color> cells;
};

/// The corner of the plot area the legend box prefers. It goes there when no data lies under it,
/// else to the first free place among the other corners and the middles of the edges, else outside
/// the plot area on the right (the area narrows; below it for a legend wider than 30 % of the image): a legend never hides a point, a curve, a text or a
/// cell of a map that is not white.
enum class LegendCorner { TopRight, TopLeft, BottomRight, BottomLeft };

/// A colour bar right of the plot area for cells coloured with colorMap(t): t = 0 is `min`, t = 1
/// is `max` (on a Log10 scale, t runs along log10 of the value), with ticks and a label.
struct PlotColorBar {
  std::string label;
  double min = 0, max = 1;
  AxisScale scale = AxisScale::Linear;
};

struct Plot {
  std::string title;
  PlotAxis x, y;
  bool equalAspect = false;  ///< one data unit is as long on x as on y (geometric figures)
  bool grid = true;          ///< light grid lines at the ticks
  LegendCorner legend = LegendCorner::TopRight;
  std::vector<PlotSeries> series;
  std::vector<PlotText> texts;
  std::vector<PlotCells> cells;
  /// Extra legend entries drawn as a filled square (e.g. the classes of a map).
  std::vector<std::pair<std::string, Color>> legendSwatches;
  /// The scale of a map coloured with colorMap (every continuous map has one).
  std::optional<PlotColorBar> colorBar;

  /// Append a curve; returns it for further styling.
  PlotSeries& add(std::string name, std::vector<double> xs, std::vector<double> ys, Color c);
};

/// Where the plot's axes ended up: the visible data range and the pixel rectangle of the plot area.
struct PlotFrame {
  double xmin, xmax, ymin, ymax;      ///< visible range (data units; log axes in data units too)
  double left, right, bottom, top;    ///< plot area in world units = output pixels (y up)
  int width, height;
  bool legend = false;                ///< a legend was drawn
  bool legendInside = false;          ///< inside the plot area (else right of it)
  double legendLeft = 0, legendRight = 0, legendBottom = 0, legendTop = 0;  ///< its box (pixels, y up)
  double colorBarLeft = 0, colorBarRight = 0;  ///< the colour bar's column (0, 0: none)
};

/// 1-2-5 tick positions covering [lo, hi] with about `target` intervals.
std::vector<double> niceTicks(double lo, double hi, int target = 6);
/// Short label of a tick value ("0.5", "1e-08" → "10⁻⁸" on log axes).
std::string tickLabel(double v, AxisScale scale);
/// A perceptually ordered colour map (dark blue → green → yellow, viridis-like) for t ∈ [0, 1].
Color colorMap(double t);

/// The plot as a Scene in pixel units (x right, y up, z = 0), with the camera that shows it.
/// Throws std::invalid_argument for an empty plot, mismatched x/y sizes, a log axis over
/// non-positive limits, or an image size below 200 × 150.
Scene plotScene(const Plot& plot, int width, int height, Camera* camera = nullptr, PlotFrame* frame = nullptr);
/// Render the plot to a PNG (width × height pixels).
void renderPlotPng(const Plot& plot, const std::filesystem::path& png, int width = 1200, int height = 800);

}  // namespace soma::render
