#pragma once
// SVG of a 2-D figure: a Plot (plot.hpp) laid out exactly as its PNG (plotScene's pixel
// coordinates, x right, y up) and written as SVG 1.1 — polylines, filled triangles, markers and
// text, no rasterisation. Only the 2-D primitives are written: a scene with tubes, meshes, frames
// or arrows is 3-D and has no SVG.
#include "soma/render/plot.hpp"

#include <filesystem>
#include <string>

namespace soma::render {

/// The SVG text of a Scene in pixel units (z ignored) in a width × height image (y flipped: SVG's
/// y runs down). std::invalid_argument for a scene with 3-D primitives.
std::string sceneSvg(const Scene& scene, int width, int height);
/// The plot as SVG text (plotScene's layout; its errors).
std::string plotSvg(const Plot& plot, int width = 1200, int height = 800);
/// Writes plotSvg to `svg` (std::runtime_error when the file cannot be written).
void renderPlotSvg(const Plot& plot, const std::filesystem::path& svg, int width = 1200, int height = 800);
/// The plot to `file` by its extension: ".svg" writes SVG, anything else PNG (a CLI's --png/--svg).
void renderPlot(const Plot& plot, const std::filesystem::path& file, int width = 1200, int height = 800);
/// A figure in both forms: the PNG at `png` and the SVG beside it (same stem, ".svg"), the vector
/// file the report links next to the raster one.
void renderPlotPngAndSvg(const Plot& plot, const std::filesystem::path& png, int width = 1200, int height = 800);

}  // namespace soma::render
