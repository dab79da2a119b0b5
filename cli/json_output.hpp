#pragma once
// The text of every `--json` answer (docs/cli.md): indented by 2, and a byte sequence that is not
// UTF-8 (a file name from the command line, which JSON cannot carry) written as U+FFFD instead of
// throwing nlohmann's type_error.316 (issue 24).
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace soma::cli {

inline std::string jsonText(const nlohmann::json& j) {
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

/// A double of a JSON answer: the number when finite, else the string "inf", "-inf" or "nan"
/// (JSON has no such number, and nlohmann would write null: an exact singularity's condition
/// number is "inf", not null).
inline nlohmann::json jsonNumber(double v) {
  if (std::isfinite(v)) return v;
  if (std::isnan(v)) return "nan";
  return v > 0 ? "inf" : "-inf";
}

}  // namespace soma::cli
