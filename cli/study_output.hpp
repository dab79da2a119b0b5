#pragma once
// Terminal output shared by `soma study run` and `soma report`.
#include <cstdlib>

#include <unistd.h>

namespace soma::cli {

/// Colour on a terminal unless NO_COLOR is set.
inline bool useColor() { return isatty(STDOUT_FILENO) && std::getenv("NO_COLOR") == nullptr; }

}  // namespace soma::cli
