#pragma once
// An 8-bit RGBA image (top row first) and PNG input/output through libpng.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace soma::render {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  ///< width*height*4 bytes, row-major, top row first, straight alpha

  std::uint8_t* pixel(int x, int y) { return rgba.data() + (std::size_t(y) * width + x) * 4; }
  const std::uint8_t* pixel(int x, int y) const { return rgba.data() + (std::size_t(y) * width + x) * 4; }
};

/// Write an RGBA PNG. Throws std::invalid_argument for an inconsistent image and std::runtime_error
/// (naming the path and the system's reason) when the file cannot be written.
void writePng(const Image& image, const std::filesystem::path& png);
/// Read any PNG libpng understands, converted to 8-bit RGBA. Throws std::runtime_error on failure.
Image readPng(const std::filesystem::path& png);

}  // namespace soma::render
