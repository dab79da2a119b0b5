#pragma once
// Where each study is written (its SOMA_STUDY line under studies/) and recorded (its row in
// papers/), and every erratum papers/ records: what the report links to and indexes (issue 25).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace soma::studies {

/// A place in the source tree: a path relative to the tree's root and a 1-based line.
struct SourcePlace {
  std::string file;
  int line = 0;
};

/// One erratum as papers/ records it.
struct Erratum {
  std::string label;                 ///< "E4.1"; numbered lists in chNN.md become "E<NN>.<n>"
  SourcePlace place;                 ///< its entry: the errata section's item, else its first mention
  std::string text;                  ///< the entry as markdown (a table row as "header: cell · …")
  std::vector<std::string> studies;  ///< the study IDs named with it anywhere in papers/
};

struct SourceIndex {
  std::map<std::string, SourcePlace> code;    ///< study ID → the line of its ID literal in studies/
  std::map<std::string, SourcePlace> papers;  ///< study ID → the table row it starts (else its first mention) in papers/
  std::vector<Erratum> errata;                ///< in file order, then order of appearance
};

/// Scan root/studies/**.cpp for each ID as a string literal and root/papers/**.md for the rows and
/// errata. Only IDs in `studyIds` are indexed; a missing folder gives empty maps (never throws).
SourceIndex indexSources(const std::filesystem::path& root, const std::vector<std::string>& studyIds);

}  // namespace soma::studies
