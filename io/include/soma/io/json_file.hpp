#pragma once
// What the JSON readers share (robot, pose, platform, link inertia and planar scene files): the
// file's text, the parsed document, the key path of a value in messages, and the rule that an
// unknown key is an error (a typo is never silently ignored).
#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

namespace soma::io {

/// The key path of a value, for messages: KeyPath("robot.json").key("joints").index(2).key("alpha")
/// reads "robot.json: joints[2].alpha"; without an origin only the path ("joints[2].alpha").
class KeyPath {
 public:
  explicit KeyPath(std::string origin = "") : origin_(std::move(origin)) {}
  [[nodiscard]] KeyPath key(std::string_view name) const;
  [[nodiscard]] KeyPath index(std::size_t i) const;
  [[nodiscard]] std::string str() const;
  operator std::string() const { return str(); }  // NOLINT: a KeyPath is where a message starts

 private:
  std::string origin_, path_;
};

/// The text of `file`. InvalidInput "<file>: cannot open the <what> file" when it cannot be read.
std::string readTextFile(const std::filesystem::path& file, std::string_view what);

/// JSON text → document. A syntax error is nlohmann::json::parse_error (for a reader with its own
/// message); a JSON number beyond a double (it overflows, or a non-zero value underflows to 0) is an
/// InvalidInput naming `origin`, the key path and the number.
nlohmann::json parseJsonText(const std::string& text, const std::string& origin);
/// As parseJsonText, with a syntax error as InvalidInput "<origin>: not valid JSON (<parser's message>)".
nlohmann::json parseJson(const std::string& text, const std::string& origin);

/// Every key of the object `j` is one of `allowed`; else InvalidInput
/// "<where>: unknown field "<key>"" followed by " <hint>" when a hint is given.
void checkKeys(const nlohmann::json& j, std::initializer_list<std::string_view> allowed, const std::string& where,
               const std::string& hint = "");

}  // namespace soma::io
