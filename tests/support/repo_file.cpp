// The one file that knows where the checkout is (tests/support/repo_file.hpp).
#include "support/repo_file.hpp"

std::filesystem::path soma::test::sourceDir() { return std::filesystem::path(SOMA_SOURCE_DIR); }
