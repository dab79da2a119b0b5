#include "soma/io/json_file.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/number.hpp"

#include <fstream>
#include <sstream>
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
  std::ifstream in(file);
  if (!in) throw InvalidInput(file.string() + ": cannot open the " + std::string(what) + " file");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

namespace {

using json = nlohmann::json;

// nlohmann's document builder, which also keeps the key path of the value being read: a JSON
// number that a double cannot hold is then reported where it is, instead of as a syntax error
// (overflow) or silently as 0 (underflow).
class DocumentBuilder : public nlohmann::detail::json_sax_dom_parser<json> {
  using Base = nlohmann::detail::json_sax_dom_parser<json>;
  struct Frame {
    bool array = false;
    std::size_t index = 0;
    std::string key;
    std::set<std::string> keys;  // the object's keys so far (uniqueKeys)
  };

 public:
  DocumentBuilder(json& result, std::string origin, bool uniqueKeys)
      : Base(result, true), origin_(std::move(origin)), uniqueKeys_(uniqueKeys) {}

  bool null() { return done(Base::null()); }
  bool boolean(bool v) { return done(Base::boolean(v)); }
  bool number_integer(json::number_integer_t v) { return done(Base::number_integer(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return done(Base::number_unsigned(v)); }
  bool number_float(json::number_float_t v, const json::string_t& text) {
    if (v == 0 && io::detail::decimalIsNonZero(text))
      throw InvalidInput(where() + ": " + text +
                         " is too small for a JSON number (a double: it underflows to 0); write it as the decimal "
                         "string \"" + text + "\"");
    return done(Base::number_float(v, text));
  }
  bool string(json::string_t& v) { return done(Base::string(v)); }
  bool binary(json::binary_t& v) { return done(Base::binary(v)); }
  bool start_object(std::size_t n) {
    frames_.push_back({false, 0, {}, {}});
    return Base::start_object(n);
  }
  bool key(json::string_t& k) {
    // nlohmann keeps the last of two equal keys: a reader that asks has the repeat rejected.
    if (uniqueKeys_ && !frames_.back().keys.insert(k).second) {
      KeyPath at(origin_);  // the object holding the key
      for (std::size_t i = 0; i + 1 < frames_.size(); ++i) at = frames_[i].array ? at.index(frames_[i].index) : at.key(frames_[i].key);
      const std::string s = at.str();
      throw InvalidInput((s.empty() ? "" : s + ": ") + "the key \"" + k + "\" is given twice");
    }
    frames_.back().key = k;
    return Base::key(k);
  }
  bool end_object() {
    frames_.pop_back();
    return done(Base::end_object());
  }
  bool start_array(std::size_t n) {
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
  // After a value: the next one in an array has the next index.
  bool done(bool ok) {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return ok;
  }
  std::string where() const {
    KeyPath k(origin_);
    for (const Frame& f : frames_) k = f.array ? k.index(f.index) : k.key(f.key);
    return k.str();
  }
  std::string origin_;
  bool uniqueKeys_ = false;
  std::vector<Frame> frames_;
};

}  // namespace

json parseJsonText(const std::string& text, const std::string& origin, DuplicateKeys duplicates) {
  json result;
  DocumentBuilder builder(result, origin, duplicates == DuplicateKeys::Reject);
  json::sax_parse(text, &builder);
  return result;
}

json parseJson(const std::string& text, const std::string& origin, DuplicateKeys duplicates) {
  try {
    return parseJsonText(text, origin, duplicates);
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
