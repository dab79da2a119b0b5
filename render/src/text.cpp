// Text: glyphs rasterised by FreeType, composed into a coverage mask, blended onto the image
// (an optional halo — the mask dilated — first, in the halo colour).
#include "text.hpp"

#include "soma/render/renderer.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace soma::render {

std::filesystem::path fontPath() {
  if (const char* env = std::getenv("SOMA_FONT"); env && *env) {
    if (std::filesystem::is_regular_file(env)) return env;
    throw std::runtime_error(std::string("soma::render: SOMA_FONT='") + env + "' is not a readable font file");
  }
  static const char* const candidates[] = {
      "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",  // Debian, Ubuntu (fonts-dejavu-core)
      "/usr/share/fonts/dejavu/DejaVuSans.ttf",           // Fedora (older)
      "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf",  // Fedora
      "/usr/share/fonts/TTF/DejaVuSans.ttf",              // Arch
      "/usr/share/fonts/truetype/DejaVuSans.ttf",
      "/usr/local/share/fonts/DejaVuSans.ttf",
      "/opt/homebrew/share/fonts/DejaVuSans.ttf",
      "/Library/Fonts/DejaVuSans.ttf",
  };
  std::string searched;
  for (const char* c : candidates) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(c, ec)) return c;
    searched += std::string("\n  ") + c;
  }
  throw std::runtime_error(
      "soma::render: no font for text labels. Install DejaVu Sans (Debian: apt-get install fonts-dejavu-core) "
      "or set SOMA_FONT to a .ttf file. Searched:" + searched);
}

namespace detail {
namespace {

struct FreeType {
  FT_Library lib = nullptr;
  FT_Face face = nullptr;
  std::filesystem::path path;
  explicit FreeType(const std::filesystem::path& p) : path(p) {
    if (FT_Init_FreeType(&lib)) throw std::runtime_error("soma::render: FreeType initialisation failed");
    if (FT_New_Face(lib, path.c_str(), 0, &face)) {
      FT_Done_FreeType(lib);
      throw std::runtime_error("soma::render: FreeType cannot load the font '" + path.string() + "'");
    }
  }
  FreeType(const FreeType&) = delete;
  FreeType& operator=(const FreeType&) = delete;
  ~FreeType() {
    FT_Done_Face(face);
    FT_Done_FreeType(lib);
  }
};

// The face of fontPath(), loaded once and reloaded when fontPath() changes (SOMA_FONT set or
// unset between renders). fontPath() is consulted on every call, so a missing font always throws.
FreeType& freetype() {
  static std::unique_ptr<FreeType> ft;
  const std::filesystem::path path = fontPath();
  if (!ft || ft->path != path) {
    ft.reset();
    ft = std::make_unique<FreeType>(path);
  }
  return *ft;
}

std::u32string decodeUtf8(const std::string& s) {
  std::u32string out;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = s[i];
    int n = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
    char32_t cp = n == 0 ? c : n == 1 ? c & 0x1F : n == 2 ? c & 0x0F : c & 0x07;
    bool ok = n >= 0;
    for (int k = 1; ok && k <= n; ++k) {
      if (i + k >= s.size() || (static_cast<unsigned char>(s[i + k]) >> 6) != 2) ok = false;
      else cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
    }
    if (!ok) {
      out.push_back(0xFFFD);
      ++i;
    } else {
      out.push_back(cp);
      i += std::size_t(n) + 1;
    }
  }
  return out;
}

struct Coverage {  // a coverage mask placed at (x0, y0) in image pixels
  int x0 = 0, y0 = 0, w = 0, h = 0;
  std::vector<float> a;
};

void blend(Image& img, const Coverage& m, const Color& c) {
  for (int j = 0; j < m.h; ++j) {
    const int y = m.y0 + j;
    if (y < 0 || y >= img.height) continue;
    for (int i = 0; i < m.w; ++i) {
      const int x = m.x0 + i;
      if (x < 0 || x >= img.width) continue;
      const float t = m.a[std::size_t(j) * m.w + i] * c.a;
      if (t <= 0) continue;
      std::uint8_t* p = img.pixel(x, y);
      const float src[3] = {c.r, c.g, c.b};
      for (int k = 0; k < 3; ++k) p[k] = std::uint8_t(std::lround(src[k] * 255 * t + p[k] * (1 - t)));
      p[3] = std::uint8_t(std::lround(255 * t + p[3] * (1 - t)));
    }
  }
}

}  // namespace

void drawText(Image& image, const std::string& text, double x, double y, const TextStyle& style) {
  if (text.empty()) return;
  FreeType& ft = freetype();
  FT_Face face = ft.face;
  if (FT_Set_Pixel_Sizes(face, 0, FT_UInt(std::max(1.0, std::round(style.pixelHeight)))))
    throw std::runtime_error("soma::render: FreeType cannot size the font to " + std::to_string(style.pixelHeight) + " px");
  const double ascent = face->size->metrics.ascender / 64.0, descent = -face->size->metrics.descender / 64.0;
  const double lineHeight = face->size->metrics.height / 64.0;
  const bool kerning = FT_HAS_KERNING(face);

  // Lay out: glyph bitmaps copied into a mask in text coordinates (origin at the first baseline).
  struct Glyph { int x, y, w, h; std::vector<float> a; };
  std::vector<Glyph> glyphs;
  std::vector<double> lineWidths(1, 0.0);
  std::vector<std::size_t> lineStart(1, 0);
  double penX = 0;
  int line = 0;
  FT_UInt prev = 0;
  for (char32_t cp : decodeUtf8(text)) {
    if (cp == U'\n') {
      lineWidths.back() = penX;
      lineWidths.push_back(0);
      lineStart.push_back(glyphs.size());
      penX = 0;
      prev = 0;
      ++line;
      continue;
    }
    FT_UInt gi = FT_Get_Char_Index(face, cp);
    if (kerning && prev && gi) {
      FT_Vector k;
      FT_Get_Kerning(face, prev, gi, FT_KERNING_DEFAULT, &k);
      penX += k.x / 64.0;
    }
    if (FT_Load_Glyph(face, gi, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT)) continue;
    const FT_GlyphSlot g = face->glyph;
    const FT_Bitmap& bm = g->bitmap;
    Glyph gl{int(std::lround(penX)) + g->bitmap_left, int(std::lround(line * lineHeight)) - g->bitmap_top, int(bm.width),
             int(bm.rows), {}};
    gl.a.resize(std::size_t(gl.w) * gl.h);
    for (int r = 0; r < gl.h; ++r)
      for (int col = 0; col < gl.w; ++col) {
        const unsigned char v = bm.pixel_mode == FT_PIXEL_MODE_MONO
                                    ? ((bm.buffer[r * bm.pitch + col / 8] >> (7 - col % 8)) & 1) * 255
                                    : bm.buffer[r * bm.pitch + col];
        gl.a[std::size_t(r) * gl.w + col] = v / 255.0f;
      }
    glyphs.push_back(std::move(gl));
    penX += g->advance.x / 64.0;
    prev = gi;
  }
  lineWidths.back() = penX;
  lineStart.push_back(glyphs.size());
  const double boxW = *std::max_element(lineWidths.begin(), lineWidths.end());
  const double boxH = ascent + descent + (lineWidths.size() - 1) * lineHeight;

  // Position of the first baseline's origin in the image.
  const double left = style.hAlign == HAlign::Left ? x : style.hAlign == HAlign::Center ? x - boxW / 2 : x - boxW;
  const double top = style.vAlign == VAlign::Top ? y : style.vAlign == VAlign::Middle ? y - boxH / 2 : y - boxH;
  const int ox = int(std::lround(left)), oy = int(std::lround(top + ascent));

  const int pad = style.halo ? int(std::ceil(std::max(1.5, style.pixelHeight / 10))) + 1 : 0;
  Coverage mask;
  mask.x0 = ox - pad - 2;
  mask.y0 = int(std::floor(top)) - pad - 2;
  mask.w = int(std::ceil(boxW)) + 2 * pad + 8;
  mask.h = int(std::ceil(boxH)) + 2 * pad + 8;
  // Glyph extents can exceed the nominal box (accents, italics): grow the mask to cover them.
  for (const auto& g : glyphs) {
    mask.x0 = std::min(mask.x0, ox + g.x - pad - 1);
    mask.y0 = std::min(mask.y0, oy + g.y - pad - 1);
  }
  int x1 = mask.x0 + mask.w, y1 = mask.y0 + mask.h;
  for (const auto& g : glyphs) x1 = std::max(x1, ox + g.x + g.w + pad + 1), y1 = std::max(y1, oy + g.y + g.h + pad + 1);
  mask.w = x1 - mask.x0;
  mask.h = y1 - mask.y0;
  mask.a.assign(std::size_t(mask.w) * mask.h, 0.0f);
  for (std::size_t l = 0; l + 1 < lineStart.size(); ++l) {
    const double shift = style.hAlign == HAlign::Left ? 0 : style.hAlign == HAlign::Center ? (boxW - lineWidths[l]) / 2 : boxW - lineWidths[l];
    const int sx = int(std::lround(shift));
    for (std::size_t k = lineStart[l]; k < lineStart[l + 1]; ++k) {
      const Glyph& g = glyphs[k];
      for (int r = 0; r < g.h; ++r)
        for (int c = 0; c < g.w; ++c) {
          const int mx = ox + sx + g.x + c - mask.x0, my = oy + g.y + r - mask.y0;
          if (mx < 0 || my < 0 || mx >= mask.w || my >= mask.h) continue;
          float& m = mask.a[std::size_t(my) * mask.w + mx];
          m = std::max(m, g.a[std::size_t(r) * g.w + c]);
        }
    }
  }
  if (style.halo) {
    // Dilate the mask with a disc of radius rad (soft edge of one pixel).
    const double rad = std::max(1.5, style.pixelHeight / 10);
    const int R = int(std::ceil(rad)), K = 2 * R + 1;
    std::vector<float> fall(std::size_t(K) * K);  // the disc's soft-edged weights
    for (int dj = -R; dj <= R; ++dj)
      for (int di = -R; di <= R; ++di)
        fall[std::size_t(dj + R) * K + (di + R)] = float(std::clamp(rad + 0.5 - std::sqrt(double(di * di + dj * dj)), 0.0, 1.0));
    Coverage halo = mask;
    for (int j = 0; j < mask.h; ++j)
      for (int i = 0; i < mask.w; ++i) {
        float best = 0;
        for (int dj = -R; dj <= R && best < 1; ++dj) {
          const int jj = j + dj;
          if (jj < 0 || jj >= mask.h) continue;
          const float* m = mask.a.data() + std::size_t(jj) * mask.w;
          const float* w = fall.data() + std::size_t(dj + R) * K + R;
          for (int di = std::max(-R, -i); di <= R && i + di < mask.w; ++di) best = std::max(best, w[di] * m[i + di]);
        }
        halo.a[std::size_t(j) * mask.w + i] = best;
      }
    blend(image, halo, *style.halo);
  }
  blend(image, mask, style.color);
}

}  // namespace detail
}  // namespace soma::render
