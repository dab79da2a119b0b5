#pragma once
// Colours for figures: straight (non-premultiplied) sRGB in [0,1], and a colour-blind-safe palette.
#include <cstdint>
#include <cstddef>

namespace soma::render {

/// An sRGB colour with opacity a (1 = opaque). Components are in [0, 1].
struct Color {
  float r = 0, g = 0, b = 0, a = 1;

  /// From 0xRRGGBB, e.g. Color::hex(0x0072B2).
  static constexpr Color hex(std::uint32_t rgb, float alpha = 1.0f) {
    return {float((rgb >> 16) & 0xFF) / 255.0f, float((rgb >> 8) & 0xFF) / 255.0f,
            float(rgb & 0xFF) / 255.0f, alpha};
  }
  /// The same colour with opacity a.
  constexpr Color withAlpha(float alpha) const { return {r, g, b, alpha}; }
  /// Mix with white (t = 1 gives white): a lighter tint for backgrounds and back faces.
  constexpr Color lighter(float t) const {
    return {r + (1 - r) * t, g + (1 - g) * t, b + (1 - b) * t, a};
  }
  /// Mix with black (t = 1 gives black).
  constexpr Color darker(float t) const { return {r * (1 - t), g * (1 - t), b * (1 - t), a}; }
  friend constexpr bool operator==(const Color&, const Color&) = default;
};

/// The Okabe–Ito palette (Okabe & Ito 2008, "Color Universal Design"): distinguishable under the
/// common colour-vision deficiencies, and it prints well. Plus neutral greys.
namespace palette {
inline constexpr Color black = Color::hex(0x000000);
inline constexpr Color orange = Color::hex(0xE69F00);
inline constexpr Color skyBlue = Color::hex(0x56B4E9);
inline constexpr Color bluishGreen = Color::hex(0x009E73);
inline constexpr Color yellow = Color::hex(0xF0E442);
inline constexpr Color blue = Color::hex(0x0072B2);
inline constexpr Color vermillion = Color::hex(0xD55E00);
inline constexpr Color reddishPurple = Color::hex(0xCC79A7);
inline constexpr Color grey = Color::hex(0x8C8C8C);
inline constexpr Color lightGrey = Color::hex(0xD9D9D9);
inline constexpr Color darkGrey = Color::hex(0x404040);
inline constexpr Color white = Color::hex(0xFFFFFF);

/// Colours of frame axes x, y, z (red, green, blue by convention, in colour-blind-safe shades).
inline constexpr Color axisX = Color::hex(0xD55E00);
inline constexpr Color axisY = Color::hex(0x009E73);
inline constexpr Color axisZ = Color::hex(0x0072B2);

/// The i-th colour of a categorical cycle (blue, vermillion, bluish green, orange, reddish purple,
/// sky blue, yellow, black), for series 0, 1, 2, ...
constexpr Color cycle(std::size_t i) {
  constexpr Color c[] = {blue, vermillion, bluishGreen, orange, reddishPurple, skyBlue, yellow, black};
  return c[i % 8];
}
}  // namespace palette

}  // namespace soma::render
