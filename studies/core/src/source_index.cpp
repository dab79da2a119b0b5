#include "soma/studies/source_index.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

namespace soma::studies {

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> filesUnder(const fs::path& dir, std::string_view ext) {
  std::vector<fs::path> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    if (it->is_regular_file(ec) && it->path().extension() == ext) out.push_back(it->path());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> readLines(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(f, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

std::string relPath(const fs::path& p, const fs::path& root) {
  return p.lexically_relative(root).generic_string();
}

bool idChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_';
}

/// The study IDs named in `text` (maximal runs of ID characters that are registered IDs).
std::vector<std::string> idsIn(std::string_view text, const std::set<std::string>& ids) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (!idChar(text[i])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && idChar(text[j])) ++j;
    std::string word(text.substr(i, j - i));
    while (!word.empty() && (word.back() == '.' || word.back() == '-')) word.pop_back();
    if (ids.count(word) && std::find(out.begin(), out.end(), word) == out.end()) out.push_back(word);
    i = j;
  }
  return out;
}

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t");
  return std::string(s.substr(b, e - b + 1));
}

/// The cells of a markdown table row ("| a | b |"); "\|" stays inside a cell.
std::vector<std::string> cells(std::string_view row) {
  std::vector<std::string> out;
  std::string cur;
  std::size_t i = row.find('|');
  if (i == std::string_view::npos) return out;
  for (++i; i < row.size(); ++i) {
    if (row[i] == '\\' && i + 1 < row.size() && row[i + 1] == '|') {
      cur += "\\|";
      ++i;
    } else if (row[i] == '|') {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += row[i];
    }
  }
  if (!trim(cur).empty()) out.push_back(trim(cur));
  return out;
}

bool separatorRow(std::string_view row) {
  return row.find("---") != std::string_view::npos &&
         row.find_first_not_of("|-: \t") == std::string_view::npos;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// "E<a>.<b>" labels in text, with their positions (not part of a longer word or number).
std::vector<std::pair<std::size_t, std::string>> eLabels(std::string_view t) {
  std::vector<std::pair<std::size_t, std::string>> out;
  for (std::size_t i = 0; i + 3 < t.size(); ++i) {
    if (t[i] != 'E' || (i > 0 && (std::isalnum(static_cast<unsigned char>(t[i - 1])) || t[i - 1] == '-')))
      continue;
    std::size_t j = i + 1;
    while (j < t.size() && std::isdigit(static_cast<unsigned char>(t[j]))) ++j;
    if (j == i + 1 || j >= t.size() || t[j] != '.') continue;
    std::size_t k = j + 1;
    while (k < t.size() && std::isdigit(static_cast<unsigned char>(t[k]))) ++k;
    if (k == j + 1) continue;
    if (k < t.size() && (std::isalpha(static_cast<unsigned char>(t[k])) ||
                         (t[k] == '.' && k + 1 < t.size() && std::isdigit(static_cast<unsigned char>(t[k + 1])))))
      continue;
    out.emplace_back(i, std::string(t.substr(i, k - i)));
    i = k - 1;
  }
  return out;
}

/// Bold numeric labels "**5**" or "**5, 6**" in text, with positions: the numbered errata lists.
std::vector<std::pair<std::size_t, std::vector<int>>> boldNumbers(std::string_view t) {
  std::vector<std::pair<std::size_t, std::vector<int>>> out;
  std::size_t i = 0;
  while ((i = t.find("**", i)) != std::string_view::npos) {
    const std::size_t end = t.find("**", i + 2);
    if (end == std::string_view::npos) break;
    const std::string_view inner = t.substr(i + 2, end - i - 2);
    std::vector<int> nums;
    bool ok = !inner.empty();
    int cur = -1;
    for (char c : inner) {
      if (std::isdigit(static_cast<unsigned char>(c))) cur = (cur < 0 ? 0 : cur * 10) + (c - '0');
      else if (c == ',' || c == ' ') {
        if (cur >= 0) nums.push_back(cur), cur = -1;
      } else {
        ok = false;
        break;
      }
    }
    if (cur >= 0) nums.push_back(cur);
    if (ok && !nums.empty()) out.emplace_back(i, nums);
    i = end + 2;
  }
  return out;
}

/// The label prefix of a numbered erratum in `file`: chNN.md → "E<NN>."; else "<ID prefix>-E"
/// from the first study named on the line ("SB-E"), else from the first word "XX-…" of `text`, else "E".
std::string numberedPrefix(const fs::path& file, const std::vector<std::string>& idsOnLine,
                           std::string_view text) {
  const std::string stem = file.stem().string();
  if (stem.size() >= 4 && stem[0] == 'c' && stem[1] == 'h' && std::isdigit(static_cast<unsigned char>(stem[2])) &&
      std::isdigit(static_cast<unsigned char>(stem[3])))
    return "E" + std::to_string(std::stoi(stem.substr(2, 2))) + ".";
  if (!idsOnLine.empty()) {
    const auto dash = idsOnLine.front().find('-');
    if (dash != std::string::npos) return idsOnLine.front().substr(0, dash) + "-E";
  }
  const auto b = text.find_first_not_of("`* ");
  if (b != std::string_view::npos) {
    std::size_t k = b;
    while (k < text.size() && std::isupper(static_cast<unsigned char>(text[k]))) ++k;
    if (k > b && k + 1 < text.size() && text[k] == '-' && std::isalnum(static_cast<unsigned char>(text[k + 1])))
      return std::string(text.substr(b, k - b)) + "-E";
  }
  return "E";
}

struct Block {
  int line = 0;                      // 1-based, first line
  std::string text;                  // joined lines
  bool errataSection = false;        // under a heading naming errata
  bool listItem = false;
  std::vector<std::string> header;   // a table row's header cells
  std::vector<std::string> row;      // a table row's cells
  std::vector<std::pair<std::size_t, int>> starts;  // (offset in text, line) of each joined line

  /// The line of the character at `pos` of text.
  int lineAt(std::size_t pos) const {
    int l = line;
    for (const auto& [off, ln] : starts)
      if (off <= pos) l = ln;
    return l;
  }
};

std::vector<Block> blocks(const std::vector<std::string>& lines) {
  std::vector<Block> out;
  bool errata = false;
  std::vector<std::string> header;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l.rfind("#", 0) == 0) {
      errata = lower(l).find("errat") != std::string::npos;
      continue;
    }
    if (trim(l).empty()) continue;
    Block b;
    b.line = static_cast<int>(i) + 1;
    b.errataSection = errata;
    if (l.front() == '|') {
      if (separatorRow(l)) continue;
      const bool first = i == 0 || lines[i - 1].empty() || lines[i - 1].front() != '|';
      if (first) {
        header = cells(l);
        continue;
      }
      b.row = cells(l);
      b.header = header;
      b.text = l;
      out.push_back(std::move(b));
      continue;
    }
    const std::string t = trim(l);
    b.listItem = t.rfind("- ", 0) == 0 || t.rfind("* ", 0) == 0;
    b.text = t;
    b.starts.push_back({0, b.line});
    // Continuation lines: indented or plain text up to a blank line, a new item, table or heading.
    while (i + 1 < lines.size()) {
      const std::string& n = lines[i + 1];
      const std::string nt = trim(n);
      if (nt.empty() || n.front() == '|' || n.front() == '#' || nt.rfind("- ", 0) == 0 ||
          nt.rfind("* ", 0) == 0 || nt.rfind("```", 0) == 0)
        break;
      b.text += " ";
      b.starts.push_back({b.text.size(), static_cast<int>(i) + 2});
      b.text += nt;
      ++i;
    }
    out.push_back(std::move(b));
  }
  return out;
}

std::string rowText(const Block& b) {
  std::string t;
  for (std::size_t k = 0; k < b.row.size(); ++k) {
    if (b.row[k].empty() || b.row[k] == "—") continue;
    if (!t.empty()) t += " · ";
    if (k < b.header.size() && !b.header[k].empty()) t += b.header[k] + ": ";
    t += b.row[k];
  }
  return t;
}

}  // namespace

SourceIndex indexSources(const fs::path& root, const std::vector<std::string>& studyIds) {
  SourceIndex index;
  const std::set<std::string> ids(studyIds.begin(), studyIds.end());

  // Code: the first "ID" string literal in studies/**.cpp.
  for (const auto& file : filesUnder(root / "studies", ".cpp")) {
    const auto lines = readLines(file);
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const std::string& l = lines[k];
      std::size_t q = 0;
      while ((q = l.find('"', q)) != std::string::npos) {
        const std::size_t e = l.find('"', q + 1);
        if (e == std::string::npos) break;
        const std::string lit = l.substr(q + 1, e - q - 1);
        if (ids.count(lit) && !index.code.count(lit))
          index.code[lit] = {relPath(file, root), static_cast<int>(k) + 1};
        q = e + 1;
      }
    }
  }

  // Papers: rows and errata.
  // One entry per label over all of papers/; its place and text come from the best mention: an
  // errata section's item (rank 2), else a block that names a study (1), else the first mention.
  std::map<std::string, std::size_t> errataAt;  // label → index
  std::vector<int> rank;
  auto note = [&](const std::string& file, const std::string& label, int line, const std::string& text,
                  const std::vector<std::string>& studies, bool definition) {
    auto [it, inserted] = errataAt.try_emplace(label, index.errata.size());
    const int r = definition ? 2 : studies.empty() ? 0 : 1;
    if (inserted) {
      index.errata.push_back({label, {file, line}, text, {}});
      rank.push_back(r);
    }
    Erratum& er = index.errata[it->second];
    if (r > rank[it->second]) {
      rank[it->second] = r;
      er.place = {file, line};
      er.text = text;
    }
    for (const auto& s : studies)
      if (std::find(er.studies.begin(), er.studies.end(), s) == er.studies.end()) er.studies.push_back(s);
  };

  std::map<std::string, SourcePlace> mentioned;
  for (const auto& path : filesUnder(root / "papers", ".md")) {
    const std::string file = relPath(path, root);
    for (const Block& b : blocks(readLines(path))) {
      const auto named = idsIn(b.text, ids);
      if (!b.row.empty()) {
        std::string first = b.row.front();
        first.erase(std::remove_if(first.begin(), first.end(), [](char c) { return c == '`' || c == '*'; }),
                    first.end());
        if (ids.count(first) && !index.papers.count(first)) index.papers[first] = {file, b.line};
      }
      for (const auto& s : named)  // a mention: used only where no table row starts with the ID
        if (!mentioned.count(s)) mentioned[s] = {file, b.line};

      if (!b.row.empty()) {
        // A table row: its E-labels; a numbered label in an "erratum"/"#" column.
        const std::string text = rowText(b);
        for (const auto& [pos, label] : eLabels(b.text)) note(file, label, b.line, text, named, b.errataSection);
        for (std::size_t k = 0; k < b.row.size() && k < b.header.size(); ++k) {
          const std::string h = lower(b.header[k]);
          if (h != "erratum" && h != "#" && h != "errata") continue;
          const std::string& c = b.row[k];
          std::size_t d = c.find_first_not_of("* ");
          if (d == std::string::npos || !std::isdigit(static_cast<unsigned char>(c[d]))) continue;
          if (!eLabels(c).empty()) continue;
          // "5, 6 (…)" or "2": the leading numbers.
          std::size_t p = d;
          while (p < c.size()) {
            std::size_t q = p;
            while (q < c.size() && std::isdigit(static_cast<unsigned char>(c[q]))) ++q;
            if (q == p) break;
            note(file, numberedPrefix(path, named, b.row.front()) + c.substr(p, q - p), b.line, text, named,
                 b.errataSection);
            while (q < c.size() && (c[q] == ',' || c[q] == ' ' || c[q] == '*')) ++q;
            p = q;
          }
        }
        continue;
      }
      // A list item or paragraph: in an errata section, each bold label opens an entry that runs
      // to the next bold label; elsewhere every E-label is a mention of the whole block.
      std::vector<std::pair<std::size_t, std::vector<std::string>>> opens;
      if (b.errataSection) {
        for (const auto& [pos, label] : eLabels(b.text))
          if (pos >= 2 && b.text.compare(pos - 2, 2, "**") == 0) opens.push_back({pos - 2, {label}});
        for (const auto& [pos, nums] : boldNumbers(b.text)) {
          std::vector<std::string> labels;
          for (int n : nums) labels.push_back(numberedPrefix(path, named, b.text) + std::to_string(n));
          opens.push_back({pos, labels});
        }
        std::sort(opens.begin(), opens.end());
      }
      if (!opens.empty()) {
        for (std::size_t k = 0; k < opens.size(); ++k) {
          const std::size_t from = opens[k].first;
          const std::size_t to = k + 1 < opens.size() ? opens[k + 1].first : b.text.size();
          std::string seg = trim(b.text.substr(from, to - from));
          auto segIds = idsIn(seg, ids);
          if (segIds.empty()) segIds = named;
          if (seg.rfind("- ", 0) == 0) seg.erase(0, 2);
          for (const auto& label : opens[k].second) note(file, label, b.lineAt(from), seg, segIds, true);
        }
        // Further E-labels that open no entry are mentions.
        for (const auto& [pos, label] : eLabels(b.text)) {
          const std::string& l = label;  // (a structured binding cannot be captured before C++20 in clang 14)
          if (std::none_of(opens.begin(), opens.end(), [&](const auto& o) {
                return std::find(o.second.begin(), o.second.end(), l) != o.second.end();
              }))
            note(file, label, b.lineAt(pos), b.text, named, false);
        }
      } else {
        for (const auto& [pos, label] : eLabels(b.text))
          note(file, label, b.lineAt(pos), b.text, named, b.errataSection);
      }
    }
  }
  for (const auto& [id, place] : mentioned) index.papers.try_emplace(id, place);
  // Natural order of the labels: E2.1 < E2.10 < E10.1; the SB-E… labels after the E… ones.
  auto key = [](const std::string& l) {
    std::vector<long> k{l.rfind("E", 0) == 0 ? 0L : 1L};
    long cur = -1;
    for (char c : l) {
      if (std::isdigit(static_cast<unsigned char>(c))) cur = (cur < 0 ? 0 : cur * 10) + (c - '0');
      else if (cur >= 0) k.push_back(cur), cur = -1;
    }
    if (cur >= 0) k.push_back(cur);
    return k;
  };
  std::stable_sort(index.errata.begin(), index.errata.end(),
                   [&](const Erratum& a, const Erratum& b) { return key(a.label) < key(b.label); });
  return index;
}

}  // namespace soma::studies
