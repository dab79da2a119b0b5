#include "soma/io/json_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/input_limits.hpp"
#include "soma/io/number.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <type_traits>
#include <vector>

namespace soma::io {

KeyPath KeyPath::key(std::string_view name) const {
  KeyPath k = *this;
  if (!k.path_.empty()) k.path_ += '.';
  k.path_ += name;
  return k;
}

KeyPath KeyPath::index(std::size_t i) const {
  KeyPath k = *this;
  k.path_ += "[" + std::to_string(i) + "]";
  return k;
}

std::string KeyPath::str() const {
  if (origin_.empty()) return path_;
  return path_.empty() ? origin_ : origin_ + ": " + path_;
}

std::string readTextFile(const std::filesystem::path& file, std::string_view what) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw InvalidInput(file.string() + ": is a directory, not a " + std::string(what) + " file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InvalidInput(file.string() + ": cannot open the " + std::string(what) + " file");
  // In bounded pieces: a file beyond the limit (or /dev/zero, a pipe that never ends) is refused
  // after limits::maxFileBytes + 1 bytes, not read to the end.
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, std::size_t(in.gcount()));
    if (text.size() > limits::maxFileBytes)
      throw InvalidInput(file.string() + ": the " + std::string(what) + " file is larger than " +
                         std::to_string(limits::maxFileBytes >> 20) + " MiB, the largest input soma reads");
  }
  if (in.bad()) throw InvalidInput(file.string() + ": cannot read the " + std::string(what) + " file");
  return text;
}

namespace {

using json = nlohmann::json;

// nlohmann's document builder, which also keeps the key path of the value being read: a JSON
// number that a double cannot hold is then reported where it is, instead of as a syntax error
// (overflow) or silently as 0 (underflow); a key given twice in one object is an error (nlohmann
// keeps the last one: the file would silently mean something else); nesting deeper than
// limits::maxDepth is refused before the document exists (dump() and the readers recurse).
class DocumentBuilder : public nlohmann::detail::json_sax_dom_parser<json> {
  using Base = nlohmann::detail::json_sax_dom_parser<json>;
  struct Frame {
    bool array = false;
    std::size_t index = 0;
    std::string key;
    std::set<std::string> keys;  ///< the object's keys so far
  };

 public:
  DocumentBuilder(json& result, std::string origin) : Base(result, true), origin_(std::move(origin)) {}

  bool null() { return done(Base::null()); }
  bool boolean(bool v) { return done(Base::boolean(v)); }
  bool number_integer(json::number_integer_t v) { return done(Base::number_integer(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return done(Base::number_unsigned(v)); }
  bool number_float(json::number_float_t v, const json::string_t& text) {
    if (v == 0 && io::detail::decimalIsNonZero(text))
      throw InvalidInput(where() + ": " + text +
                         " is too small for a JSON number (a double: it underflows to 0); write it as the decimal "
                         "string \"" + text + "\"");
    // A subnormal double keeps fewer than 53 bits of the number: the file's value would be lost.
    if (v != 0 && std::abs(v) < std::numeric_limits<double>::min())
      throw InvalidInput(where() + ": " + text +
                         " is too small for a JSON number (a double holds magnitudes from 2.2250738585072014e-308, "
                         "its smallest normal number); write it as the decimal string \"" + text +
                         "\" for a scalar that holds it");
    return done(Base::number_float(v, text));
  }
  bool string(json::string_t& v) { return done(Base::string(v)); }
  bool binary(json::binary_t& v) { return done(Base::binary(v)); }
  bool start_object(std::size_t n) {
    enter();
    frames_.push_back({false, 0, {}, {}});
    return Base::start_object(n);
  }
  bool key(json::string_t& k) {
    Frame& f = frames_.back();
    if (!f.keys.insert(k).second) {
      f.key = k;
      throw InvalidInput(where() + ": the key \"" + k + "\" is given twice in one object");
    }
    f.key = k;
    return Base::key(k);
  }
  bool end_object() {
    frames_.pop_back();
    return done(Base::end_object());
  }
  bool start_array(std::size_t n) {
    enter();
    frames_.push_back({true, 0, {}, {}});
    return Base::start_array(n);
  }
  bool end_array() {
    frames_.pop_back();
    return done(Base::end_array());
  }
  template <class Exception> bool parse_error(std::size_t pos, const std::string& token, const Exception& e) {
    // 406: "number overflow parsing '1e400'" (the number is finite in no double).
    if constexpr (std::is_same_v<Exception, json::out_of_range>)
      if (e.id == 406)
        throw InvalidInput(where() + ": " + token +
                           " is outside the range of a JSON number (a double: it overflows to infinity); write it "
                           "as the decimal string \"" + token + "\"");
    return Base::parse_error(pos, token, e);
  }

 private:
  // Before an array or object is opened: the depth limit.
  void enter() const {
    if (frames_.size() >= limits::maxDepth)
      throw InvalidInput(where(4) + ": arrays and objects nested deeper than " + std::to_string(limits::maxDepth) +
                         " levels (the most soma reads)");
  }
  // After a value: the next one in an array has the next index.
  bool done(bool ok) {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return ok;
  }
  /// The key path of the value being read; with `levels`, its first levels and "…".
  std::string where(std::size_t levels = limits::maxDepth) const {
    KeyPath k(origin_);
    for (std::size_t i = 0; i < frames_.size() && i < levels; ++i)
      k = frames_[i].array ? k.index(frames_[i].index) : k.key(frames_[i].key);
    return k.str() + (frames_.size() > levels ? "…" : "");
  }
  std::string origin_;
  std::vector<Frame> frames_;
};

}  // namespace

json parseJsonText(const std::string& text, const std::string& origin) {
  json result;
  DocumentBuilder builder(result, origin);
  json::sax_parse(text, &builder);
  return result;
}

json parseJson(const std::string& text, const std::string& origin) {
  try {
    return parseJsonText(text, origin);
  } catch (const json::parse_error& e) {
    throw InvalidInput(origin + ": not valid JSON (" + e.what() + ")");
  }
}

void checkKeys(const json& j, std::initializer_list<std::string_view> allowed, const std::string& where,
               const std::string& hint) {
  for (const auto& [key, value] : j.items()) {
    (void)value;
    bool known = false;
    for (const std::string_view a : allowed) known = known || key == a;
    if (!known) throw InvalidInput(where + ": unknown field \"" + key + "\"" + (hint.empty() ? "" : " " + hint));
  }
}

}  // namespace soma::io
