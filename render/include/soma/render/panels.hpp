#pragma once
// A grid of panels, each a 3-D scene seen by one camera fitted to all of them (so that sizes
// compare across panels), under a banner title: the postures a solver found, one per panel.
// Written as PNG (rendered) or as SVG (a line drawing: tubes, polylines, frames and arrows
// projected by the same camera and drawn far to near, points as dots, labels and titles as text).
#include "soma/render/image.hpp"
#include "soma/render/scene.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <vector>

namespace soma::render {

struct PanelGrid {
  std::string title;           ///< the banner above the panels
  std::vector<Scene> panels;   ///< each panel's scene; its `title` is drawn at the panel's top
  int panelWidth = 420, panelHeight = 440, columns = 4;
  Eigen::Vector3d view{-1.0, -0.75, -0.55};  ///< the view direction of the common camera
};

/// The grid rendered (OSMesa); std::invalid_argument for no panels or a bad size.
Image renderPanels(const PanelGrid& grid);
/// The grid as SVG text (the line drawing described above; meshes and fills are not drawn).
std::string panelsSvg(const PanelGrid& grid);
/// The grid to `file` by its extension: ".svg" writes panelsSvg, anything else a PNG. The file is
/// written whole or not at all (std::runtime_error naming it when it cannot be written).
void writePanels(const PanelGrid& grid, const std::filesystem::path& file);

}  // namespace soma::render
