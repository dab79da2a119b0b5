// The intersection ring of the Study quadric, GF §11.5 Table 11.2.
#include "soma/geometry/study/intersection_ring.hpp"

#include <stdexcept>

namespace soma {

int StudyClass::dimension(Cell c) {
  static constexpr int d[kCells] = {0, 1, 2, 3, 3, 4, 5, 6};
  return d[c];
}

bool StudyClass::isZero() const {
  for (long long x : c_)
    if (x != 0) return false;
  return true;
}

StudyClass StudyClass::operator+(const StudyClass& o) const {
  StudyClass r;
  for (int k = 0; k < kCells; ++k) r.c_[k] = c_[k] + o.c_[k];
  return r;
}

StudyClass StudyClass::operator*(long long k) const {
  StudyClass r;
  for (int i = 0; i < kCells; ++i) r.c_[i] = c_[i] * k;
  return r;
}

// GF §11.5, GF-11.5-table-11.2: the table's entries, the rest by symmetry and σ₆ = unit.
StudyClass cellProduct(StudyClass::Cell a, StudyClass::Cell b) {
  using C = StudyClass;
  if (a == C::S6) return C::cell(b);
  if (b == C::S6) return C::cell(a);
  if (C::dimension(a) > C::dimension(b) || (a == C::SB && b == C::SA)) std::swap(a, b);
  if (C::dimension(a) + C::dimension(b) < 6) return C();
  switch (a) {
    case C::Point: return C();  // dimension 0 + ≤ 5 < 6, handled above
    case C::S1: return b == C::S5 ? C::point() : C();
    case C::S2: return b == C::S4 ? C::point() : b == C::S5 ? C::sigma1() : C();
    case C::SA:
      if (b == C::SA) return C();                     // σ_A·σ_A = 0
      if (b == C::SB) return C::point();              // σ_A·σ_B = 1
      return b == C::S4 ? C::sigma1() : C::sigma2();  // σ_A·σ₄ = σ₁, σ_A·σ₅ = σ₂
    case C::SB:
      if (b == C::SB) return C();
      return b == C::S4 ? C::sigma1() : C::sigma2();
    case C::S4: return b == C::S4 ? C::sigma2() * 2 : C::sigmaA() + C::sigmaB();  // σ₄² = 2σ₂, σ₄σ₅ = σ_A + σ_B
    case C::S5: return C::sigma4();                                                // σ₅² = σ₄
    default: break;
  }
  throw std::logic_error("cellProduct: unreachable");
}

StudyClass StudyClass::operator*(const StudyClass& o) const {
  StudyClass r;
  for (int i = 0; i < kCells; ++i) {
    if (c_[i] == 0) continue;
    for (int j = 0; j < kCells; ++j)
      if (o.c_[j] != 0) r = r + cellProduct(Cell(i), Cell(j)) * (c_[i] * o.c_[j]);
  }
  return r;
}

StudyClass StudyClass::pow(int n) const {
  if (n < 0) throw std::invalid_argument("StudyClass::pow: negative exponent " + std::to_string(n));
  StudyClass r = fundamental();
  for (int k = 0; k < n; ++k) r = r * *this;
  return r;
}

std::string StudyClass::toString() const {
  static const char* names[kCells] = {"1", "σ₁", "σ₂", "σ_A", "σ_B", "σ₄", "σ₅", "σ₆"};
  std::string s;
  for (int k = 0; k < kCells; ++k) {
    if (c_[k] == 0) continue;
    long long v = c_[k];
    if (!s.empty()) s += v < 0 ? " − " : " + ";
    else if (v < 0) s += "−";
    v = v < 0 ? -v : v;
    if (k == Point) s += std::to_string(v);
    else s += (v == 1 ? "" : std::to_string(v)) + names[k];
  }
  return s.empty() ? "0" : s;
}

}  // namespace soma
