// The URDF text checked before TinyXML and urdfdom see it (urdf_scan.hpp).
#include "urdf_scan.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/input_limits.hpp"
#include "soma/io/number.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <string_view>
#include <vector>

namespace soma::io::detail {

namespace {

/// The numeric attributes of URDF (ROS wiki, urdf/XML): element, attribute, count of numbers.
struct NumericAttribute {
  std::string_view element, attribute;
  int count;
};
constexpr NumericAttribute numericAttributes[] = {
    {"origin", "xyz", 3},          {"origin", "rpy", 3},          {"axis", "xyz", 3},
    {"limit", "lower", 1},         {"limit", "upper", 1},         {"limit", "effort", 1},
    {"limit", "velocity", 1},      {"dynamics", "damping", 1},    {"dynamics", "friction", 1},
    {"safety_controller", "soft_lower_limit", 1},                 {"safety_controller", "soft_upper_limit", 1},
    {"safety_controller", "k_position", 1},                       {"safety_controller", "k_velocity", 1},
    {"calibration", "rising", 1},  {"calibration", "falling", 1}, {"calibration", "reference_position", 1},
    {"mimic", "multiplier", 1},    {"mimic", "offset", 1},        {"mass", "value", 1},
    {"inertia", "ixx", 1},         {"inertia", "ixy", 1},         {"inertia", "ixz", 1},
    {"inertia", "iyy", 1},         {"inertia", "iyz", 1},         {"inertia", "izz", 1},
    {"box", "size", 3},            {"cylinder", "radius", 1},     {"cylinder", "length", 1},
    {"capsule", "radius", 1},      {"capsule", "length", 1},      {"sphere", "radius", 1},
    {"mesh", "scale", 3},          {"color", "rgba", 4},
};

struct Attribute {
  std::string name, value;
};

struct Element {
  std::string name;
  std::string label;  ///< how a message names it: `joint "j1"`, `limit`
};

struct JointRecord {
  std::string name;
  std::string parent, child;
  bool hasParent = false, hasChild = false;
};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool isNameStart(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':' || c >= 0x80;
}
bool isNameChar(unsigned char c) { return isNameStart(c) || (c >= '0' && c <= '9') || c == '-' || c == '.'; }

/// A code point XML allows in a document (XML 1.0 §2.2 Char).
bool isXmlChar(std::uint32_t c) {
  return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD) ||
         (c >= 0x10000 && c <= 0x10FFFF);
}

std::string quoted(std::string_view s) { return "\"" + std::string(s) + "\""; }

class Scanner {
 public:
  Scanner(const std::string& text, const std::string& origin) : t_(text), origin_(origin) {}

  void run() {
    if (t_.size() > limits::maxFileBytes)
      throw InvalidInput(origin_ + ": the URDF text is larger than " + std::to_string(limits::maxFileBytes >> 20) +
                         " MiB, the largest input soma reads");
    checkCharacters();
    scan();
    checkJointGraph();
  }

 private:
  [[noreturn]] void fail(std::size_t at, const std::string& what) const {
    const std::size_t line = 1 + std::size_t(std::count(t_.begin(), t_.begin() + std::ptrdiff_t(std::min(at, t_.size())), '\n'));
    throw InvalidInput(origin_ + ": not a valid URDF: line " + std::to_string(line) + ": " + what);
  }
  [[noreturn]] void failGraph(const std::string& what) const {
    throw InvalidInput(origin_ + ": not a valid URDF robot: " + what);
  }

  // ---- characters: strict UTF-8 (no overlong form, no surrogate) of XML characters ---------------
  void checkCharacters() const {
    std::size_t i = 0;
    const std::size_t n = t_.size();
    if (n >= 3 && static_cast<unsigned char>(t_[0]) == 0xEF && static_cast<unsigned char>(t_[1]) == 0xBB &&
        static_cast<unsigned char>(t_[2]) == 0xBF)
      i = 3;  // a byte-order mark
    while (i < n) {
      const auto b = static_cast<unsigned char>(t_[i]);
      std::uint32_t c = 0;
      std::size_t len = 0;
      if (b < 0x80) c = b, len = 1;
      else if (b >= 0xC2 && b <= 0xDF) c = b & 0x1Fu, len = 2;
      else if (b >= 0xE0 && b <= 0xEF) c = b & 0x0Fu, len = 3;
      else if (b >= 0xF0 && b <= 0xF4) c = b & 0x07u, len = 4;
      else fail(i, "byte 0x" + hex(b) + " at offset " + std::to_string(i) + " is not UTF-8");
      if (i + len > n) fail(i, "a UTF-8 sequence cut short at the end of the text (offset " + std::to_string(i) + ")");
      for (std::size_t k = 1; k < len; ++k) {
        const auto cb = static_cast<unsigned char>(t_[i + k]);
        if ((cb & 0xC0u) != 0x80u)
          fail(i, "a UTF-8 sequence cut short at offset " + std::to_string(i) + " (byte 0x" + hex(cb) + ")");
        c = (c << 6) | (cb & 0x3Fu);
      }
      const bool overlong = (len == 3 && c < 0x800) || (len == 4 && c < 0x10000);
      if (overlong || (c >= 0xD800 && c <= 0xDFFF) || c > 0x10FFFF)
        fail(i, "an invalid UTF-8 sequence at offset " + std::to_string(i));
      if (!isXmlChar(c))
        fail(i, (c == 0 ? std::string("a NUL byte") : "the character U+" + hex(c)) + " at offset " + std::to_string(i) +
                    " is not allowed in XML");
      i += len;
    }
  }
  static std::string hex(std::uint32_t v) {
    const char* digits = "0123456789ABCDEF";
    std::string s;
    do s.insert(s.begin(), digits[v & 0xFu]), v >>= 4;
    while (v);
    if (s.size() < 2) s.insert(s.begin(), '0');
    return s;
  }

  // ---- the tags --------------------------------------------------------------------------------
  bool at(std::size_t i, std::string_view s) const { return t_.compare(i, s.size(), s) == 0; }

  std::size_t find(std::size_t from, std::string_view s, std::size_t start, const char* what) const {
    const std::size_t k = t_.find(s, from);
    if (k == std::string::npos) fail(start, std::string("an unterminated ") + what);
    return k;
  }

  std::string readName(std::size_t& i) const {
    const std::size_t b = i;
    if (i < t_.size() && isNameStart(static_cast<unsigned char>(t_[i])))
      while (i < t_.size() && isNameChar(static_cast<unsigned char>(t_[i]))) ++i;
    return t_.substr(b, i - b);
  }
  void skipSpace(std::size_t& i) const {
    while (i < t_.size() && isSpace(t_[i])) ++i;
  }

  /// An entity reference at t_[i] == '&': the five of XML or a numeric one of an XML character.
  /// Returns its length and appends its text to `out` (when given).
  std::size_t entity(std::size_t i, std::string* out) const {
    const std::size_t semi = t_.find(';', i);
    constexpr std::size_t longest = 10;  // "&#x10FFFF;"
    if (semi == std::string::npos || semi - i > longest)
      fail(i, "a '&' that starts no entity reference (write &amp;)");
    const std::string_view name(t_.data() + i + 1, semi - i - 1);
    static const std::pair<std::string_view, char> named[] = {
        {"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
    for (const auto& [n, c] : named)
      if (name == n) {
        if (out) *out += c;
        return semi - i + 1;
      }
    std::uint32_t code = 0;
    bool ok = name.size() >= 2 && name[0] == '#';
    if (ok) {
      const bool hexadecimal = name[1] == 'x';
      const std::string_view digits = name.substr(hexadecimal ? 2 : 1);
      ok = !digits.empty() && digits.size() <= 7;
      for (const char c : digits) {
        int d = -1;
        if (c >= '0' && c <= '9') d = c - '0';
        else if (hexadecimal && c >= 'a' && c <= 'f') d = c - 'a' + 10;
        else if (hexadecimal && c >= 'A' && c <= 'F') d = c - 'A' + 10;
        if (d < 0) ok = false;
        else code = code * (hexadecimal ? 16u : 10u) + std::uint32_t(d);
      }
      ok = ok && isXmlChar(code);
    }
    if (!ok) fail(i, "the entity reference " + quoted(std::string("&") + std::string(name) + ";") +
                         " is not one of XML's (&amp; &lt; &gt; &quot; &apos; &#N; &#xH;)");
    if (out) appendUtf8(*out, code);
    return semi - i + 1;
  }
  static void appendUtf8(std::string& s, std::uint32_t c) {
    if (c < 0x80) s += char(c);
    else if (c < 0x800) s += char(0xC0 | (c >> 6)), s += char(0x80 | (c & 0x3F));
    else if (c < 0x10000) s += char(0xE0 | (c >> 12)), s += char(0x80 | ((c >> 6) & 0x3F)), s += char(0x80 | (c & 0x3F));
    else
      s += char(0xF0 | (c >> 18)), s += char(0x80 | ((c >> 12) & 0x3F)), s += char(0x80 | ((c >> 6) & 0x3F)),
          s += char(0x80 | (c & 0x3F));
  }

  void scan() {
    const std::size_t n = t_.size();
    std::size_t i = 0;
    bool rootSeen = false;
    while (i < n) {
      const char c = t_[i];
      if (c == '&') {
        if (stack_.empty()) fail(i, "text outside the root element");
        i += entity(i, nullptr);
        continue;
      }
      if (c != '<') {
        if (stack_.empty() && !isSpace(c) && !(i < 3 && static_cast<unsigned char>(c) >= 0x80))
          fail(i, "text outside the root element");
        ++i;
        continue;
      }
      if (at(i, "<?")) {
        i = find(i + 2, "?>", i, "processing instruction (<? … ?>)") + 2;
      } else if (at(i, "<!--")) {
        i = find(i + 4, "-->", i, "comment (<!-- … -->)") + 3;
      } else if (at(i, "<![CDATA[")) {
        if (stack_.empty()) fail(i, "a CDATA section outside the root element");
        i = find(i + 9, "]]>", i, "CDATA section") + 3;
      } else if (at(i, "<!")) {
        fail(i, "a <!DOCTYPE> or other declaration (not part of URDF)");
      } else if (at(i, "</")) {
        const std::size_t start = i;
        i += 2;
        const std::string name = readName(i);
        skipSpace(i);
        if (i >= n || t_[i] != '>') fail(start, "a malformed end tag </" + name);
        if (stack_.empty() || stack_.back().name != name)
          fail(start, "</" + name + "> closes " + (stack_.empty() ? std::string("no element") : "<" + stack_.back().name + ">"));
        close();
        ++i;
      } else {
        if (stack_.empty() && rootSeen) fail(i, "a second root element");
        i = startTag(i);
        rootSeen = true;
      }
    }
    if (!stack_.empty()) fail(n, "<" + stack_.back().name + "> is not closed");
    if (!rootSeen) fail(n, "no root element (<robot>)");
  }

  /// A start tag at t_[i] == '<'; returns the index after it.
  std::size_t startTag(std::size_t i) {
    const std::size_t start = i, n = t_.size();
    ++i;
    const std::string name = readName(i);
    if (name.empty()) fail(start, "a '<' that starts no tag (write &lt;)");
    std::vector<Attribute> attributes;
    bool selfClosing = false;
    for (;;) {
      const std::size_t before = i;
      skipSpace(i);
      if (i >= n) fail(start, "the tag <" + name + " is not closed by '>'");
      if (t_[i] == '>') {
        ++i;
        break;
      }
      if (t_[i] == '/') {
        if (i + 1 >= n || t_[i + 1] != '>') fail(i, "a '/' inside the tag <" + name);
        i += 2;
        selfClosing = true;
        break;
      }
      if (i == before) fail(i, "the attributes of <" + name + "> need spaces between them");
      const std::size_t attrStart = i;
      Attribute a;
      a.name = readName(i);
      if (a.name.empty()) fail(i, "a malformed attribute in <" + name + ">");
      skipSpace(i);
      if (i >= n || t_[i] != '=') fail(attrStart, "attribute " + a.name + " of <" + name + "> has no value");
      ++i;
      skipSpace(i);
      if (i >= n || (t_[i] != '"' && t_[i] != '\'')) fail(attrStart, "attribute " + a.name + " of <" + name + "> is not quoted");
      const char q = t_[i++];
      const std::size_t end = t_.find(q, i);
      if (end == std::string::npos) fail(attrStart, "attribute " + a.name + " of <" + name + "> has no closing quote");
      while (i < end) {
        if (t_[i] == '<') fail(i, "a '<' in attribute " + a.name + " of <" + name + "> (write &lt;)");
        if (t_[i] == '&') i += entity(i, &a.value);
        else a.value += t_[i++];
      }
      if (i != end) fail(attrStart, "an entity reference across the end of attribute " + a.name);
      ++i;
      for (const Attribute& b : attributes)
        if (b.name == a.name) fail(attrStart, "attribute " + a.name + " given twice in <" + name + ">");
      attributes.push_back(std::move(a));
    }
    open(start, name, attributes);
    if (selfClosing) close();
    return i;
  }

  static const std::string* attribute(const std::vector<Attribute>& as, std::string_view name) {
    for (const Attribute& a : as)
      if (a.name == name) return &a.value;
    return nullptr;
  }

  /// The element's place for messages: `joint "j1" > limit`.
  std::string path(const std::string& last) const {
    std::string p;
    for (std::size_t k = 1; k < stack_.size(); ++k) p += stack_[k].label + " > ";
    return p + last;
  }

  void open(std::size_t at, const std::string& name, const std::vector<Attribute>& attributes) {
    if (++elements_ > limits::maxXmlElements)
      fail(at, "more than " + std::to_string(limits::maxXmlElements) + " elements (the most soma reads)");
    const std::size_t depth = stack_.size() + 1;  // the root element has depth 1
    if (depth > limits::maxDepth)
      fail(at, "elements nested deeper than " + std::to_string(limits::maxDepth) + " levels (the most soma reads)");
    Element e{name, name};
    const std::string* nameAttr = attribute(attributes, "name");
    if (depth == 2 && (name == "link" || name == "joint")) {
      if (!nameAttr || nameAttr->empty()) fail(at, "a <" + name + "> without a name");
      e.label = name + " " + quoted(*nameAttr);
      if (name == "link") {
        links_.push_back(*nameAttr);
      } else {
        if (joints_.size() >= limits::maxJoints)
          fail(at, "more than " + std::to_string(limits::maxJoints) + " joints (the most soma reads)");
        joints_.push_back({*nameAttr, "", "", false, false});
      }
    }
    // Inside a <link>, a <joint> or a <material> of the robot: the numbers and the joint's links.
    const std::string top = depth >= 2 ? (depth == 2 ? name : stack_[1].name) : std::string();
    if (top == "link" || top == "joint" || top == "material") checkNumbers(name, attributes);
    if (depth == 3 && top == "joint" && (name == "parent" || name == "child")) {
      const std::string* link = attribute(attributes, "link");
      JointRecord& j = joints_.back();
      if (!link || link->empty()) fail(at, path(name) + ": no link=\"…\"");
      (name == "parent" ? j.parent : j.child) = *link;
      (name == "parent" ? j.hasParent : j.hasChild) = true;
    }
    stack_.push_back(std::move(e));
  }
  void close() { stack_.pop_back(); }

  void checkNumbers(const std::string& element, const std::vector<Attribute>& attributes) const {
    for (const NumericAttribute& na : numericAttributes) {
      if (na.element != element) continue;
      const std::string* value = attribute(attributes, na.attribute);
      if (!value) continue;
      const std::string where = origin_ + ": " + path(element) + "@" + std::string(na.attribute);
      std::vector<std::string> tokens;
      std::size_t k = 0;
      while (k < value->size()) {
        while (k < value->size() && isSpace((*value)[k])) ++k;
        const std::size_t b = k;
        while (k < value->size() && !isSpace((*value)[k])) ++k;
        if (k > b) tokens.push_back(value->substr(b, k - b));
      }
      if (int(tokens.size()) != na.count)
        throw InvalidInput(where + ": " + quoted(*value) + " has " + std::to_string(tokens.size()) + " numbers, " +
                           std::to_string(na.count) + " expected");
      for (std::size_t m = 0; m < tokens.size(); ++m)
        (void)parseDecimal<double>(tokens[m], na.count == 1 ? where : where + "[" + std::to_string(m) + "]");
    }
  }

  // ---- the joint graph: a tree of links ----------------------------------------------------------
  void checkJointGraph() const {
    std::map<std::string, int> linkIndex;
    for (const std::string& l : links_)
      if (!linkIndex.emplace(l, int(linkIndex.size())).second) failGraph("link " + quoted(l) + " is defined twice");
    if (links_.empty()) failGraph("no <link> (a robot has at least one link)");
    std::map<std::string, const JointRecord*> jointNames;
    std::vector<int> parentOf(links_.size(), -1);
    std::vector<const JointRecord*> parentJoint(links_.size(), nullptr);
    for (const JointRecord& j : joints_) {
      const std::string w = "joint " + quoted(j.name);
      if (!jointNames.emplace(j.name, &j).second) failGraph(w + " is defined twice");
      if (!j.hasParent) failGraph(w + ": no <parent link=\"…\"/>");
      if (!j.hasChild) failGraph(w + ": no <child link=\"…\"/>");
      const auto p = linkIndex.find(j.parent), c = linkIndex.find(j.child);
      if (p == linkIndex.end()) failGraph(w + ": its parent link " + quoted(j.parent) + " is not defined");
      if (c == linkIndex.end()) failGraph(w + ": its child link " + quoted(j.child) + " is not defined");
      if (p->second == c->second) failGraph(w + ": link " + quoted(j.child) + " is its own parent (a self loop)");
      if (parentJoint[std::size_t(c->second)])
        failGraph("link " + quoted(j.child) + " is the child of joints " + quoted(parentJoint[std::size_t(c->second)]->name) +
                  " and " + quoted(j.name) + " (a link has one parent joint)");
      parentJoint[std::size_t(c->second)] = &j;
      parentOf[std::size_t(c->second)] = p->second;
    }
    std::vector<std::string> roots;
    for (std::size_t k = 0; k < links_.size(); ++k)
      if (parentOf[k] < 0) roots.push_back(links_[k]);
    if (roots.size() > 1)
      failGraph("links " + quoted(roots[0]) + " and " + quoted(roots[1]) +
                " are both roots (no joint connects them: a robot is one tree)");
    // Every link's ancestors, each link walked once: a walk that meets its own path is a cycle.
    std::vector<int> state(links_.size(), 0);  // 0 unseen, 1 on the current walk, 2 reaches the root
    for (std::size_t k = 0; k < links_.size(); ++k) {
      std::vector<int> walk;
      int x = int(k);
      while (x >= 0 && state[std::size_t(x)] == 0) {
        state[std::size_t(x)] = 1;
        walk.push_back(x);
        x = parentOf[std::size_t(x)];
      }
      if (x >= 0 && state[std::size_t(x)] == 1) {
        std::string cycle;
        const auto from = std::find(walk.begin(), walk.end(), x);
        for (auto it = from; it != walk.end(); ++it) cycle += (cycle.empty() ? "" : " → ") + quoted(links_[std::size_t(*it)]);
        failGraph("the joints form a cycle (" + cycle + " → " + quoted(links_[std::size_t(x)]) +
                  "): a link is its own ancestor");
      }
      for (const int w : walk) state[std::size_t(w)] = 2;
    }
    if (roots.empty()) failGraph("no root link: every link is some joint's child (the joints form a cycle)");
  }

  const std::string& t_;
  const std::string& origin_;
  std::vector<Element> stack_;
  std::size_t elements_ = 0;
  std::vector<std::string> links_;
  std::vector<JointRecord> joints_;
};

}  // namespace

void checkUrdfText(const std::string& xml, const std::string& origin) { Scanner(xml, origin).run(); }

}  // namespace soma::io::detail
