// Tree combinatorics of GF §14.1 (tree_topology.hpp).
#include "soma/geometry/dynamics/tree_topology.hpp"

#include "soma/algebra/errors.hpp"

#include <functional>

namespace soma {

// GF §14.1 lines 8705–8726, GF-14.1-tree-structure
TreeTopology::TreeTopology(std::vector<int> parent) : parent_(std::move(parent)) {
  const int n = int(parent_.size());
  if (n == 0) throw InvalidInput("TreeTopology: the parent list is empty (a tree has at least one link)");
  children_.assign(std::size_t(n), {});
  level_.assign(std::size_t(n), 0);
  for (int i = 0; i < n; ++i) {
    const int p = parent_[std::size_t(i)];
    if (p < -1 || p >= n)
      throw InvalidInput("TreeTopology: parent of link " + std::to_string(i) + " is " + std::to_string(p) +
                         ", not −1 (ground) or a link 0.." + std::to_string(n - 1));
    if (p == i) throw InvalidInput("TreeTopology: link " + std::to_string(i) + " is its own parent (a cycle)");
  }
  for (int i = 0; i < n; ++i) {  // every link must reach the ground in < n steps
    int j = i, steps = 0;
    while (j != -1 && steps <= n) {
      j = parent_[std::size_t(j)];
      ++steps;
    }
    if (j != -1)
      throw InvalidInput("TreeTopology: link " + std::to_string(i) +
                         " lies on a cycle of parents (it never reaches the ground): not a tree");
    level_[std::size_t(i)] = steps;
  }
  for (int i = 0; i < n; ++i) {
    const int p = parent_[std::size_t(i)];
    if (p == -1)
      roots_.push_back(i);
    else
      children_[std::size_t(p)].push_back(i);
  }
  order_ = roots_;
  for (std::size_t k = 0; k < order_.size(); ++k)
    for (int c : children_[std::size_t(order_[k])]) order_.push_back(c);
}

TreeTopology TreeTopology::fromBookParents(const std::vector<int>& bookParent) {
  std::vector<int> p(bookParent.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = bookParent[i] - 1;
  return TreeTopology(p);
}

int TreeTopology::check(int i) const {
  if (i < 0 || i >= size())
    throw InvalidInput("TreeTopology: link index " + std::to_string(i) + " out of range 0.." + std::to_string(size() - 1));
  return i;
}

std::vector<int> TreeTopology::leaves() const {
  std::vector<int> out;
  for (int i = 0; i < size(); ++i)
    if (children_[std::size_t(i)].empty()) out.push_back(i);
  return out;
}

std::vector<int> TreeTopology::ancestry(int i) const {
  std::vector<int> a;
  for (int j = check(i); j != -1; j = parent_[std::size_t(j)]) a.insert(a.begin(), j);
  return a;
}

bool TreeTopology::precedes(int i, int j) const {
  check(i);
  for (int k = check(j); k != -1; k = parent_[std::size_t(k)])
    if (k == i) return true;
  return false;
}

std::vector<int> TreeTopology::subtree(int i) const {
  std::vector<int> out{check(i)};
  for (std::size_t k = 0; k < out.size(); ++k)
    for (int c : children_[std::size_t(out[k])]) out.push_back(c);
  return out;
}

std::string TreeTopology::nested() const {
  std::function<std::string(int)> rec = [&](int i) {
    std::string s = std::to_string(i + 1);
    const auto& ch = children_[std::size_t(i)];
    if (!ch.empty()) {
      s += "(";
      for (std::size_t k = 0; k < ch.size(); ++k) s += (k ? ", " : "") + rec(ch[k]);
      s += ")";
    }
    return s;
  };
  std::string s = "(";
  for (std::size_t k = 0; k < roots_.size(); ++k) s += (k ? ", " : "") + rec(roots_[k]);
  return s + ")";
}

}  // namespace soma
