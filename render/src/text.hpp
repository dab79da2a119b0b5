#pragma once
// Internal: FreeType text rasterised and alpha-blended onto an Image.
#include "soma/render/color.hpp"
#include "soma/render/image.hpp"
#include "soma/render/primitives.hpp"

#include <optional>
#include <string>

namespace soma::render::detail {

struct TextStyle {
  double pixelHeight = 20;
  Color color = palette::black;
  std::optional<Color> halo;  ///< outline colour, if any
  HAlign hAlign = HAlign::Left;
  VAlign vAlign = VAlign::Bottom;
};

/// Draw UTF-8 text (lines separated by '\n') with the box corner (hAlign, vAlign) at (x, y) pixels.
/// Needs the caller to hold the render mutex (the FreeType library and face are shared).
void drawText(Image& image, const std::string& text, double x, double y, const TextStyle& style);

}  // namespace soma::render::detail
