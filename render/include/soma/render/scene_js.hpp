#pragma once
// A Scene for the report's interactive 3-D viewer (three.js, viewer.html): the same primitives the
// off-screen renderer draws, written as a script `somaScene({...});` that a page loads from disk
// (file:// forbids reading JSON, not running a script). Automatic sizes are resolved as the
// renderer resolves them. Groups are what the viewer toggles: one per named scene, or one per
// primitive kind of a single scene.
#include "soma/render/scene.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace soma::render {

/// The script for one scene, its primitives grouped by kind ("tubes", "meshes", "points", …).
std::string sceneJs(const Scene& scene);
/// The script for named scenes shown together (e.g. "posture 1" … "posture 16"); the title is the
/// first scene's unless `title` is given. Sizes resolve against the scenes' joint extent.
std::string sceneJs(const std::vector<std::pair<std::string, Scene>>& groups, const std::string& title = {});
/// Write sceneJs to `js` (std::runtime_error naming the file when it cannot be written).
void writeSceneJs(const std::string& script, const std::filesystem::path& js);

}  // namespace soma::render
