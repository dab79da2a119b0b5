// PNG input/output with libpng (simplified API, png_image_*).
#include "soma/render/image.hpp"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace soma::render {

namespace {
struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
}  // namespace

void writePng(const Image& image, const std::filesystem::path& png) {
  if (image.width < 1 || image.height < 1 || image.rgba.size() != std::size_t(image.width) * image.height * 4)
    throw std::invalid_argument("soma::render::writePng: image " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " with " + std::to_string(image.rgba.size()) +
                                " bytes is inconsistent (need width*height*4 > 0)");
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(png.c_str(), "wb"));
  if (!file)
    throw std::runtime_error("soma::render::writePng: cannot open '" + png.string() + "' for writing: " +
                             std::strerror(errno));
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  img.width = png_uint_32(image.width);
  img.height = png_uint_32(image.height);
  img.format = PNG_FORMAT_RGBA;
  const int ok = png_image_write_to_stdio(&img, file.get(), 0, image.rgba.data(), image.width * 4, nullptr);
  if (!ok) {
    const std::string msg = img.message;
    png_image_free(&img);
    throw std::runtime_error("soma::render::writePng: libpng failed writing '" + png.string() + "': " + msg);
  }
  if (std::fflush(file.get()) != 0 || std::ferror(file.get()))
    throw std::runtime_error("soma::render::writePng: error writing '" + png.string() + "': " + std::strerror(errno));
  if (std::fclose(file.release()) != 0)
    throw std::runtime_error("soma::render::writePng: error closing '" + png.string() + "': " + std::strerror(errno));
}

Image readPng(const std::filesystem::path& png) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(png.c_str(), "rb"));
  if (!file)
    throw std::runtime_error("soma::render::readPng: cannot open '" + png.string() + "': " + std::strerror(errno));
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_stdio(&img, file.get()))
    throw std::runtime_error("soma::render::readPng: '" + png.string() + "' is not a readable PNG: " + img.message);
  img.format = PNG_FORMAT_RGBA;
  Image out;
  out.width = int(img.width);
  out.height = int(img.height);
  out.rgba.resize(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, out.rgba.data(), 0, nullptr)) {
    const std::string msg = img.message;
    png_image_free(&img);
    throw std::runtime_error("soma::render::readPng: libpng failed reading '" + png.string() + "': " + msg);
  }
  return out;
}

}  // namespace soma::render
