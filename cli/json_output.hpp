#pragma once
// The text of every `--json` answer (docs/cli.md): indented by 2, and a byte sequence that is not
// UTF-8 (a file name from the command line, which JSON cannot carry) written as U+FFFD instead of
// throwing nlohmann's type_error.316 (issue 24).
#include <nlohmann/json.hpp>

#include <string>

namespace soma::cli {

inline std::string jsonText(const nlohmann::json& j) {
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace soma::cli
