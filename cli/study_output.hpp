#pragma once
// Terminal and folder output shared by `soma study run` and `soma report`.
#include "soma/algebra/errors.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace soma::cli {

/// `--out DIR` made and written to once before any study runs: a folder that cannot be created or
/// written is bad input (InvalidInput, exit 2) at once, not a study failing or a report lost
/// minutes later. The probe file is removed again.
inline void requireWritableFolder(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InvalidInput("--out " + dir.string() + ": cannot create the folder (" + (ec ? ec.message() : "not a folder") + ")");
  const fs::path probe = dir / ".soma-write-probe";
  bool written = false;
  {
    std::ofstream f(probe, std::ios::binary | std::ios::trunc);
    written = f && (f << "soma\n") && f.flush();
  }
  fs::remove(probe, ec);
  if (!written) throw InvalidInput("--out " + dir.string() + ": the folder is not writable");
}

/// Colour on a terminal unless NO_COLOR is set.
inline bool useColor() { return isatty(STDOUT_FILENO) && std::getenv("NO_COLOR") == nullptr; }

}  // namespace soma::cli
