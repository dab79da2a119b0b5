#pragma once
// Reading a Stewart–Gough platform file (DESIGN §6, GF §11.5):
//   {"name", "comment", "base": [6 points [x, y, z]], "platform": [6 points], "leg_lengths": [6]}
// Numbers through the one number reader (number.hpp): JSON numbers or decimal strings, exact in S.
// Every defect (an unknown field, a missing one, a wrong count, a bad number, a negative leg, a
// degenerate platform) is an InvalidInput naming the file, the key path and the defect.
#include "soma/algebra/scalar.hpp"
#include "soma/geometry/parallel/stewart.hpp"

#include <filesystem>
#include <string>

namespace soma::io {

/// Parse platform JSON text; `origin` names the source in messages.
template <class S> StewartPlatform<S> parsePlatform(const std::string& text, const std::string& origin);
/// Read and parse a platform file.
template <class S> StewartPlatform<S> readPlatform(const std::filesystem::path& file);

#define SOMA_PLATFORM_FILE_EXTERN(S)                                                         \
  extern template StewartPlatform<S> parsePlatform<S>(const std::string&, const std::string&); \
  extern template StewartPlatform<S> readPlatform<S>(const std::filesystem::path&);
SOMA_FOR_EACH_SCALAR(SOMA_PLATFORM_FILE_EXTERN)
#undef SOMA_PLATFORM_FILE_EXTERN

}  // namespace soma::io
