#pragma once
// The intersection ring of the (complexified) Study quadric Q⁶ (GF §11.5, Table 11.2): classes
// of subvarieties as integer combinations of the cells 1 (a point), σ₁ (a line), σ₂ (a 2-plane),
// σ_A, σ_B (the two families of 3-planes), σ₄, σ₅ (linear sections of codimension 2 and 1) and
// σ₆ = [Q] (the fundamental class, the unit of the ring). Intersecting two varieties in general
// position is the product of their classes; a count of points is the coefficient of 1.
#include <array>
#include <string>

namespace soma {

class StudyClass {
 public:
  /// Index of each basis cell, ordered by complex dimension.
  enum Cell { Point = 0, S1 = 1, S2 = 2, SA = 3, SB = 4, S4 = 5, S5 = 6, S6 = 7 };
  static constexpr int kCells = 8;
  /// The complex dimension of a cell: 0, 1, 2, 3, 3, 4, 5, 6.
  static int dimension(Cell c);

  StudyClass() { c_.fill(0); }
  static StudyClass cell(Cell c, long long k = 1) {
    StudyClass x;
    x.c_[c] = k;
    return x;
  }
  static StudyClass point() { return cell(Point); }
  static StudyClass sigma1() { return cell(S1); }
  static StudyClass sigma2() { return cell(S2); }
  static StudyClass sigmaA() { return cell(SA); }
  static StudyClass sigmaB() { return cell(SB); }
  static StudyClass sigma4() { return cell(S4); }
  static StudyClass sigma5() { return cell(S5); }
  static StudyClass fundamental() { return cell(S6); }

  long long operator[](Cell c) const { return c_[c]; }
  /// The number of points (coefficient of the point class) — a count of solutions.
  long long degree() const { return c_[Point]; }
  bool isZero() const;

  StudyClass operator+(const StudyClass& o) const;
  StudyClass operator*(long long k) const;
  friend StudyClass operator*(long long k, const StudyClass& x) { return x * k; }
  /// The intersection product (GF Table 11.2, extended bilinearly; σ₆ is the unit).
  /// GF §11.5, GF-11.5-table-11.2
  StudyClass operator*(const StudyClass& o) const;
  StudyClass pow(int n) const;
  bool operator==(const StudyClass& o) const { return c_ == o.c_; }

  /// "2σ_A + 4σ_B" style text; "0" for the zero class.
  std::string toString() const;

 private:
  std::array<long long, kCells> c_;
};

/// The product of two basis cells as printed in GF Table 11.2 (σ₆ the unit; products whose
/// dimensions add to less than 6 vanish). GF §11.5, GF-11.5-table-11.2
StudyClass cellProduct(StudyClass::Cell a, StudyClass::Cell b);

}  // namespace soma
