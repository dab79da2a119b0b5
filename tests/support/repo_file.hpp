#pragma once
// A file of the repository, for tests that read the example robots, platforms and scenes.
// SOMA_SOURCE_DIR is the source tree's root, set by tests/CMakeLists.txt (not __FILE__: ccache's
// base_dir and out-of-tree builds make __FILE__ relative to the build directory).
#include <filesystem>
#include <string>

namespace soma::test {
inline std::filesystem::path repoFile(const std::string& relative) {
  return std::filesystem::path(SOMA_SOURCE_DIR) / relative;
}
}  // namespace soma::test
