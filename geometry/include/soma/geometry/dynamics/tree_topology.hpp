#pragma once
// The combinatorics of a tree-structured mechanism (GF §14.1, GF-14.1-tree-structure): links
// 0..n−1, link i joined to its parent by joint i (so #links = #joints), parent −1 = ground.
// Several links may hang from the ground (a forest: e.g. a 4-bar cut open at one joint is a crank
// tree and a rocker tree). Levels: a link on the ground has level 1 (ground = 0). The partial order
// i ⪯ j ("j is above or equal to i", GF line 8719): i lies on the ancestry of j. The book numbers
// links from 1 with 0 = ground; here links are numbered from 0 and the ground is −1
// (fromBookParents converts).
#include <string>
#include <vector>

namespace soma {

class TreeTopology {
 public:
  /// parent[i] ∈ {−1, 0..n−1} \ {i}. InvalidInput for an empty list, an index out of range, a
  /// self-loop or a cycle (a link that never reaches the ground), naming the link.
  explicit TreeTopology(std::vector<int> parent);
  /// The book's numbering (links 1..n, 0 = ground), e.g. Fig. 14.1 = {0, 1, 1, 3, 3, 4}.
  static TreeTopology fromBookParents(const std::vector<int>& bookParent);

  int size() const { return int(parent_.size()); }
  int parent(int i) const { return parent_[std::size_t(check(i))]; }
  const std::vector<int>& children(int i) const { return children_[std::size_t(check(i))]; }
  const std::vector<int>& roots() const { return roots_; }
  /// Links with no children (leaf-links have one joint, GF line 8707).
  std::vector<int> leaves() const;
  /// Level of link i: 1 for a link on the ground.
  int level(int i) const { return level_[std::size_t(check(i))]; }
  /// The ancestry (root, …, i) of link i (GF line 8726: ancestry of 6 in Fig. 14.1 is (1, 3, 4, 6)).
  std::vector<int> ancestry(int i) const;
  /// i ⪯ j: i is on the ancestry of j (equal included).
  bool precedes(int i, int j) const;
  /// The subtree {j : i ⪯ j} of link i, breadth-first.
  std::vector<int> subtree(int i) const;
  /// All links, breadth-first (parents before children): the order of the up pass (GF §14.1.3).
  const std::vector<int>& breadthFirst() const { return order_; }
  /// "(1(2, 3(4(6), 5)))": the nested-parenthesis form of GF §14.3.1, in the book's 1-based numbers.
  std::string nested() const;

 private:
  int check(int i) const;
  std::vector<int> parent_, roots_, level_, order_;
  std::vector<std::vector<int>> children_;
};

}  // namespace soma
