#pragma once
// A file of the repository, for tests that read the example robots, platforms and scenes.
// The source tree's root is compiled into one file only (tests/support/repo_file.cpp, in
// soma_test_main, given SOMA_SOURCE_DIR by tests/CMakeLists.txt), so that the test files themselves
// do not depend on where the checkout is and ccache shares them between checkouts. Not __FILE__:
// ccache's base_dir and out-of-tree builds make __FILE__ relative to the build directory.
#include <filesystem>
#include <string>

namespace soma::test {
/// The repository's root.
std::filesystem::path sourceDir();
/// `relative` below the repository's root.
inline std::filesystem::path repoFile(const std::string& relative) { return sourceDir() / relative; }
}  // namespace soma::test
