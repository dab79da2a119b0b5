#pragma once
// Rendering a Scene off-screen with OSMesa (Mesa llvmpipe, legacy fixed-function OpenGL).
#include "soma/render/camera.hpp"
#include "soma/render/image.hpp"
#include "soma/render/scene.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace soma::render {

/// How edges are anti-aliased. Both sample the same ordered samples x samples grid per pixel and
/// average in linear light; they differ in cost (see the report in render/README.md).
enum class AntiAliasing {
  Supersample,  ///< one pass at samples x the resolution, then a box downsample (default)
  Accumulate,   ///< samples^2 passes at the output resolution with sub-pixel jitter, summed
};

struct RenderOptions {
  int width = 1200, height = 900;
  int samples = 4;  ///< anti-aliasing factor per axis (samples^2 samples per pixel); 1 = none
  AntiAliasing antiAliasing = AntiAliasing::Supersample;
  /// The camera; when empty, Camera::fit(scene, defaultViewDirection, {width, height}).
  std::optional<Camera> camera;
  /// Seen from +x, +y, +z towards the origin, slightly from above.
  static Eigen::Vector3d defaultViewDirection() { return Eigen::Vector3d(-1.0, -0.75, -0.55); }
};

/// The camera a render with these options uses (options.camera or the automatic fit).
Camera effectiveCamera(const Scene& scene, const RenderOptions& options);

/// Render the scene. Throws std::invalid_argument for bad input (see Scene::validate,
/// Camera::validate; image size or samples out of range) and std::runtime_error when OSMesa or
/// FreeType fails (e.g. no font for labels). Serialised by a mutex: safe to call from any thread,
/// one render at a time.
Image render(const Scene& scene, const RenderOptions& options = {});
/// render(scene, options).rgba: width*height*4 bytes, top row first.
std::vector<std::uint8_t> renderRgba(const Scene& scene, const RenderOptions& options = {});
/// Render and write a PNG (throws like render and writePng).
void renderPng(const Scene& scene, const RenderOptions& options, const std::filesystem::path& png);
/// Render with the camera fitted to the scene along viewDir, the image fit.width × fit.height,
/// and write a PNG (the usual way a study draws a 3-D figure).
void renderPng(const Scene& scene, const Eigen::Vector3d& viewDir, const FitOptions& fit, const std::filesystem::path& png);

/// The TrueType font used for text: $SOMA_FONT if set, else the first DejaVu Sans found in the
/// standard locations (Debian fonts-dejavu-core, Fedora, Arch, macOS, ...). Throws std::runtime_error
/// listing the places searched when there is none.
std::filesystem::path fontPath();

}  // namespace soma::render
