#pragma once
// Multivectors of Cl(p,q,r) (GF §9.1), dense or grade-sparse, templated on the scalar.
//
// `Multivector<Sig, S, M>` stores one coefficient per basis blade whose grade is in the
// compile-time grade mask M (bit k ⇔ grade k). `Dense<Sig,S>` keeps all 2^n; a `Bivector`,
// `Vector` or `Even` (rotors, motors) keeps only its grades. The result type of a product keeps
// exactly the grades that can be nonzero (degenerate generators included). Three kernels:
//  * small products (|A|·|B| ≤ 1024 coefficient pairs, e.g. everything in Cl(0,3,1)): a
//    compile-time table of the (i, j, k, sign) terms with nonzero sign, unrolled to straight-line
//    code for built-in floating types when it has ≤ 256 terms — a motor times a motor in
//    Cl(0,3,1) is 48 multiplies and adds, no loads of a table, no branches (≈ a hand-written
//    dual-quaternion product, bench/clifford.cpp);
//  * large geometric products (n ≥ 5, built-in floating types): the blocked kernel
//    detail::Blocked — blades split into low/high generator bits, the sign factorised, whole
//    blocks vanishing on shared null generators skipped, one signed permuted copy of b, then
//    width-8 axpys into a register block of the result (Cl(0,6,2) Even × Even 128×128 ≈ 2.5 µs,
//    Dense × Dense ≈ 8 µs in double, x86-64 baseline SSE2);
//  * everything else (other large products, mpfr): a term table built once at run time.
// All three sum each coefficient's terms in the same order, so sparse and dense operands give
// bitwise-equal results.
//
// Operator map (one place, used throughout soma):
//   a * b   geometric product                        geometric(a, b)
//   a ^ b   outer (exterior, wedge, "meet" in the plane-based reading)   outer(a, b)
//   a & b   regressive (join, shuffle) via Poincaré duality on the basis   regressive(a, b)
//   a | b   left contraction a ⌋ b (grade gb − ga)    leftContraction(a, b)
//           right contraction a ⌊ b (grade ga − gb)   rightContraction(a, b)
//           scalar product ⟨a b⟩₀                     scalarProduct(a, b)
//   ~a      reverse ã                                 a.reverse()
//           grade (main) involution α(a)              a.involute()
//           Clifford conjugation a* = α(ã)            a.conjugate()   (GF's c*)
//           grade projection ⟨a⟩_k                    a.grade<k>(), a.grades<M>(), a.gradeProject(k)
// Precedence caution: in C++ `^`, `&`, `|` bind more loosely than `+` and `==`: parenthesise.
#include "soma/algebra/clifford/signature.hpp"
#include "soma/algebra/errors.hpp"
#include "soma/algebra/scalar.hpp"
#include "soma/algebra/tolerance.hpp"

#include <Eigen/LU>
#include <sstream>
#include <string>
#include <type_traits>
#include <memory>
#include <utility>
#include <vector>

namespace soma::clifford {

enum class Op { Geometric, Outer, LeftContraction, RightContraction, Scalar, Regressive };

namespace detail {

template <class Sig> constexpr int maskSize(GradeMask m) {
  int c = 0;
  for (Blade b = 0; b < Blade(Sig::dim); ++b)
    if (m & gradeBit(bladeGrade(b))) ++c;
  return c;
}

/// Storage layout of mask M: blades ordered by grade, then by bitmask value.
template <class Sig, GradeMask M> struct Layout {
  static constexpr int size = maskSize<Sig>(M);
  static constexpr std::array<Blade, size> blades = [] {
    std::array<Blade, size> a{};
    int c = 0;
    for (int k = 0; k <= Sig::n; ++k)
      if (M & gradeBit(k))
        for (Blade b = 0; b < Blade(Sig::dim); ++b)
          if (bladeGrade(b) == k) a[c++] = b;
    return a;
  }();
  /// Storage index of each blade, −1 if its grade is not in M.
  static constexpr std::array<std::int16_t, Sig::dim> index = [] {
    std::array<std::int16_t, Sig::dim> ix{};
    for (auto& v : ix) v = -1;
    for (int i = 0; i < size; ++i) ix[blades[i]] = std::int16_t(i);
    return ix;
  }();
};

template <class Sig, Op op> constexpr int termSign(Blade a, Blade b) {
  switch (op) {
    case Op::Geometric: return Sig::productSign(a, b);
    case Op::Outer: return Sig::outerSign(a, b);
    case Op::LeftContraction: return (a & ~b) == 0 ? Sig::productSign(a, b) : 0;
    case Op::RightContraction: return (b & ~a) == 0 ? Sig::productSign(a, b) : 0;
    case Op::Scalar: return a == b ? Sig::productSign(a, b) : 0;
    case Op::Regressive: return Sig::regressiveSign(a, b);
  }
  return 0;
}
template <Op op> constexpr Blade termBlade(Blade a, Blade b) {
  return op == Op::Regressive ? (a & b) : (a ^ b);
}

struct Term {
  std::uint16_t i, j, k;
  std::int8_t s;
};

/// Grades that product `op` of a grade-ga and a grade-gb blade can reach, from counting shared
/// generators c: the product of blades sharing c generators has grade ga+gb−2c and is nonzero
/// only if none of the shared ones is null (c ≤ p+q). O(n²), so result types cost no blade loop.
template <class Sig, Op op> constexpr GradeMask resultGrades(GradeMask A, GradeMask B) {
  constexpr int n = Sig::n, nn = Sig::p + Sig::q;
  GradeMask m = 0;
  for (int ga = 0; ga <= n; ++ga)
    for (int gb = 0; gb <= n; ++gb) {
      if (!(A & gradeBit(ga)) || !(B & gradeBit(gb))) continue;
      switch (op) {
        case Op::Geometric: {
          const int lo = ga + gb - n > 0 ? ga + gb - n : 0;
          int hi = ga < gb ? ga : gb;
          if (hi > nn) hi = nn;
          for (int c = lo; c <= hi; ++c) m |= gradeBit(ga + gb - 2 * c);
          break;
        }
        case Op::Outer:
          if (ga + gb <= n) m |= gradeBit(ga + gb);
          break;
        case Op::LeftContraction:
          if (ga <= gb && ga <= nn) m |= gradeBit(gb - ga);
          break;
        case Op::RightContraction:
          if (gb <= ga && gb <= nn) m |= gradeBit(ga - gb);
          break;
        case Op::Scalar:
          if (ga == gb && ga <= nn) m |= gradeBit(0);
          break;
        case Op::Regressive:
          if (ga + gb >= n) m |= gradeBit(ga + gb - n);
          break;
      }
    }
  return m;
}

/// The nonzero terms of product `op` between masks A and B. Small tables (|A|·|B| ≤ 1024 pairs,
/// e.g. every product of Cl(0,3,1) and Cl(3,1,1)) are built at compile time and checked there
/// against resultGrades; larger ones once at run time on first use (a function-local static),
/// which keeps the compile time of dense 256×256 products low.
template <class Sig, Op op, GradeMask A, GradeMask B> struct ProductTable {
  using LA = Layout<Sig, A>;
  using LB = Layout<Sig, B>;
  static constexpr GradeMask result = resultGrades<Sig, op>(A, B);
  using LR = Layout<Sig, result>;
  static constexpr bool atCompileTime = std::size_t(LA::size) * std::size_t(LB::size) <= 1024;

  struct Shape {
    GradeMask mask;
    int count;
  };
  static constexpr Shape shapeOf() {
    Shape sh{0, 0};
    for (int i = 0; i < LA::size; ++i)
      for (int j = 0; j < LB::size; ++j)
        if (termSign<Sig, op>(LA::blades[i], LB::blades[j]) != 0) {
          sh.mask |= gradeBit(bladeGrade(termBlade<op>(LA::blades[i], LB::blades[j])));
          ++sh.count;
        }
    return sh;
  }
  /// Writes the terms into t (an array or a vector large enough); returns how many.
  template <class Out> static constexpr int fill(Out& t) {
    int c = 0;
    for (int i = 0; i < LA::size; ++i)
      for (int j = 0; j < LB::size; ++j) {
        const Blade a = LA::blades[i], b = LB::blades[j];
        const int s = termSign<Sig, op>(a, b);
        if (s != 0)
          t[std::size_t(c++)] = Term{std::uint16_t(i), std::uint16_t(j),
                                     std::uint16_t(LR::index[termBlade<op>(a, b)]),
                                     std::int8_t(s)};
      }
    return c;
  }

  static const auto& terms();
};

/// The compile-time term table of a small product (atCompileTime), with `first` marking, for
/// each result index, the first term that writes it (so the unrolled kernel assigns instead of
/// adding to zero).
template <class PT, bool = PT::atCompileTime> struct StaticTerms {
  static constexpr int count = 0;
};
template <class PT> struct StaticTerms<PT, true> {
  static constexpr typename PT::Shape shape = PT::shapeOf();
  static_assert(shape.mask == PT::result,
                "clifford: resultGrades disagrees with the blade table");
  static constexpr int count = shape.count;
  static constexpr std::array<Term, std::size_t(count)> table = [] {
    std::array<Term, std::size_t(count)> t{};
    PT::fill(t);
    return t;
  }();
  static constexpr std::array<bool, std::size_t(count)> first = [] {
    std::array<bool, std::size_t(count)> f{};
    std::array<bool, std::size_t(PT::LR::size) + 1> seen{};
    for (int c = 0; c < count; ++c) {
      f[std::size_t(c)] = !seen[table[std::size_t(c)].k];
      seen[table[std::size_t(c)].k] = true;
    }
    return f;
  }();
};

template <class Sig, Op op, GradeMask A, GradeMask B>
const auto& ProductTable<Sig, op, A, B>::terms() {
  if constexpr (atCompileTime) {
    return StaticTerms<ProductTable>::table;
  } else {
    static const std::vector<Term> table = [] {
      std::vector<Term> v(std::size_t(LA::size) * std::size_t(LB::size));
      v.resize(std::size_t(fill(v)));
      return v;
    }();
    return table;
  }
}

/// Straight-line product for a compile-time table: every index and sign is a constant, so the
/// compiler emits one multiply and one add (or a move) per term, no loads of the table and no
/// branches. Used for tables of at most kUnrollTerms terms and built-in floating types.
inline constexpr int kUnrollTerms = 256;
/// The operands are copied to local arrays and the result accumulated in one: locals that never
/// escape stay in registers, whereas the inputs (possibly aliasing the result object as far as
/// the compiler knows) would otherwise be reloaded and the result stored after every term.
template <class TT, class Out, class XA, class XB, std::size_t... I>
inline void applyUnrolled(Out& out, const XA& a, const XB& b, std::index_sequence<I...>) {
  constexpr auto& t = TT::table;
  constexpr auto& f = TT::first;
  [[maybe_unused]] const auto av = a.coeffs();  // unused when the table is empty (e ∧ e = 0)
  [[maybe_unused]] const auto bv = b.coeffs();
  std::array<typename Out::Scalar, std::size_t(Out::size)> acc{};
  (((f[I] ? (t[I].s > 0 ? void(acc[t[I].k] = av[t[I].i] * bv[t[I].j])
                        : void(acc[t[I].k] = -(av[t[I].i] * bv[t[I].j])))
          : (t[I].s > 0 ? void(acc[t[I].k] += av[t[I].i] * bv[t[I].j])
                        : void(acc[t[I].k] -= av[t[I].i] * bv[t[I].j])))),
   ...);
  for (int k = 0; k < Out::size; ++k) out[k] = acc[std::size_t(k)];
}

/// Blocked geometric product for large algebras (n ≥ 5, built-in floating types).
/// Split each blade into its low L generator bits (al, never null: L ≤ p+q) and the rest (ah).
/// The blade sign factorises, s(a, b) = s(ah, bh) · s(al, bl) · (−1)^{|ah|·|bl|}, and the
/// result blade is (ah ⊕ bh, al ⊕ bl). For fixed a and a block bh the W = 2^L products with
/// the blades (bh, ·) of b land in the block kh = ah ⊕ bh of the result, so after one signed,
/// permuted copy of b per (|ah| mod 2, al) the whole block is an axpy of width W:
///   c[kh][·] += (s(ah,bh) a_a) · b'[|ah| mod 2][al][bh][·].
/// Blocks with s(ah, bh) = 0 (a shared null generator: ah ∧ bh ∋ e_null) are skipped whole —
/// this is where degenerate generators remove 7/16 of the work of Cl(0,6,2). When both
/// operands have a single parity (Even, Odd, a single grade), so has the result, and only the
/// W/2 lanes of that parity are stored and computed.
template <class Sig, GradeMask A, GradeMask B> struct Blocked {
  static constexpr int L = Sig::p + Sig::q < 4 ? Sig::p + Sig::q : 4;
  static constexpr int W = 1 << L, D = Sig::dim, NB = D / W;
  static constexpr bool enabled = Sig::n >= 5 && L >= 2;
  static constexpr GradeMask R = resultGrades<Sig, Op::Geometric>(A, B);
  static constexpr bool pureParity(GradeMask m) {
    return (m & Sig::evenGrades) == m || (m & Sig::oddGrades) == m;
  }
  static constexpr bool compact = pureParity(A) && pureParity(B);
  static constexpr int parR = (R & Sig::oddGrades) ? 1 : 0;  // used only when compact
  static constexpr int WB = compact ? W / 2 : W;
  static constexpr int par(unsigned x) { return std::popcount(x) & 1; }
  /// lane[q][t]: the t-th low index kl stored in a result block whose lanes have parity q
  /// (compact), or kl = t.
  static constexpr std::array<std::array<std::uint8_t, W>, 2> lane = [] {
    std::array<std::array<std::uint8_t, W>, 2> l{};
    for (int q = 0; q < 2; ++q) {
      int t = 0;
      for (int kl = 0; kl < W; ++kl)
        if (!compact || par(unsigned(kl)) == q) l[q][t++] = std::uint8_t(kl);
    }
    return l;
  }();
  /// s(ah, bh) for the blades above the low L generators.
  static constexpr std::array<std::int8_t, std::size_t(NB) * NB> hiSign = [] {
    std::array<std::int8_t, std::size_t(NB) * NB> s{};
    for (int ah = 0; ah < NB; ++ah)
      for (int bh = 0; bh < NB; ++bh)
        s[std::size_t(ah) * NB + bh] = std::int8_t(Sig::productSign(Blade(ah) << L, Blade(bh) << L));
    return s;
  }();
  /// Which (|ah| mod 2, al) occur among a's blades, and which blocks bh hold any of b's blades.
  static constexpr std::array<bool, 2 * W> usedA = [] {
    std::array<bool, 2 * W> u{};
    for (Blade a : Layout<Sig, A>::blades) u[std::size_t(par(a >> L) * W + (a & (W - 1)))] = true;
    return u;
  }();
  static constexpr std::array<bool, NB> usedB = [] {
    std::array<bool, NB> u{};
    for (Blade b : Layout<Sig, B>::blades) u[b >> L] = true;
    return u;
  }();
  /// For each result block kh, the blades a of the left operand that reach it, in storage
  /// order (so each coefficient sums its terms in the same order as the term tables): storage
  /// index i, sign flag, and offset of the block bh = ah ⊕ kh in the signed copy of b.
  struct Entry {
    std::uint16_t i;
    std::uint16_t off;
    bool neg;
  };
  static constexpr int kEntryMax = NB * Layout<Sig, A>::size;
  struct Entries {
    std::array<Entry, std::size_t(kEntryMax)> e;
    std::array<int, std::size_t(NB) + 1> start;
  };
  static constexpr Entries kAll = [] {
    Entries r{};
    int m = 0;
    for (int kh = 0; kh < NB; ++kh) {
      r.start[std::size_t(kh)] = m;
      for (int i = 0; i < Layout<Sig, A>::size; ++i) {
        const Blade ab = Layout<Sig, A>::blades[std::size_t(i)];
        const int ah = int(ab >> L), al = int(ab & (W - 1)), bh = ah ^ kh;
        const int s = hiSign[std::size_t(ah) * NB + bh];
        if (s == 0 || !usedB[std::size_t(bh)]) continue;
        r.e[std::size_t(m++)] = Entry{std::uint16_t(i),
                                      std::uint16_t((par(unsigned(ah)) * W + al) * NB * WB + bh * WB),
                                      s < 0};
      }
    }
    r.start[std::size_t(NB)] = m;
    return r;
  }();
  static constexpr const auto& kEntries = kAll.e;
  static constexpr const auto& kStart = kAll.start;
  /// For (p, al, q) and lane t: the low index bl = al ⊕ lane[q][t] of b and whether
  /// s(al, bl) (−1)^{p|bl|} is negative.
  struct Lo {
    std::array<std::uint8_t, W> src;
    std::array<bool, W> neg;
  };
  static constexpr std::array<Lo, 4 * W> loTerms = [] {
    std::array<Lo, 4 * W> r{};
    for (int p = 0; p < 2; ++p)
      for (int al = 0; al < W; ++al)
        for (int q = 0; q < 2; ++q) {
          Lo& lo = r[std::size_t((p * W + al) * 2 + q)];
          for (int t = 0; t < WB; ++t) {
            const int bl = al ^ lane[q][t];
            lo.src[std::size_t(t)] = std::uint8_t(bl);
            lo.neg[std::size_t(t)] =
                Sig::productSign(Blade(al), Blade(bl)) * ((p & par(unsigned(bl))) ? -1 : 1) < 0;
          }
        }
    return r;
  }();
  /// Storage index in the result type of (kh, lane t), −1 if not stored.
  static constexpr std::array<std::int16_t, std::size_t(NB) * WB> outIndex = [] {
    std::array<std::int16_t, std::size_t(NB) * WB> o{};
    for (int kh = 0; kh < NB; ++kh)
      for (int t = 0; t < WB; ++t) {
        const int q = compact ? (parR ^ par(unsigned(kh))) : 0;
        o[std::size_t(kh) * WB + t] = Layout<Sig, R>::index[(kh << L) | lane[q][t]];
      }
    return o;
  }();

  /// Blocks bh of each parity (the lanes of a compact block depend on it).
  static constexpr std::array<std::array<std::uint8_t, NB / 2>, 2> bhOfParity = [] {
    std::array<std::array<std::uint8_t, NB / 2>, 2> r{};
    int n0 = 0, n1 = 0;
    for (int bh = 0; bh < NB; ++bh) {
      if (par(unsigned(bh))) r[1][std::size_t(n1++)] = std::uint8_t(bh);
      else r[0][std::size_t(n0++)] = std::uint8_t(bh);
    }
    return r;
  }();
  /// dst[t] = ±blk[src[t]] with the constants of loTerms[LI]: straight-line loads and stores.
  template <int LI, class S> static void copyLanes(const S* blk, S* dst) {
    constexpr const Lo& lo = loTerms[std::size_t(LI)];
    [&]<std::size_t... T>(std::index_sequence<T...>) {
      ((dst[T] = lo.neg[T] ? -blk[lo.src[T]] : blk[lo.src[T]]), ...);
    }(std::make_index_sequence<std::size_t(WB)>{});
  }
  /// The signed, permuted copy of b for one (p, al) = (C / W, C % W), if a has such blades.
  template <int C, class S> static void fillCombo(const S* bd, S* bt) {
    if constexpr (usedA[std::size_t(C)]) {
      constexpr int p = C / W;
      S* dst = bt + std::size_t(C) * NB * WB;
      for (int h = 0; h < 2; ++h) {
        for (int m = 0; m < NB / 2; ++m) {
          const int bh = bhOfParity[std::size_t(h)][std::size_t(m)];
          if (h == 0 || !compact)
            copyLanes<C * 2 + (compact ? (parR ^ p) : 0)>(bd + (bh << L), dst + bh * WB);
          else
            copyLanes<C * 2 + (parR ^ p ^ 1)>(bd + (bh << L), dst + bh * WB);
        }
      }
    }
  }

  template <class S, class XA, class XB, class Out>
  static void apply(const XA& a, const XB& b, Out& out) {
    // Blocks of WB scalars start at multiples of WB·sizeof(S) (a power of two) in arrays
    // aligned to 64 bytes.
    constexpr std::size_t kAlign = WB * sizeof(S) < 64 ? WB * sizeof(S) : 64;
    std::array<S, D> bd{};  // b in blade (bitmask) order
    for (int j = 0; j < XB::size; ++j) bd[XB::blade(j)] = b[j];
    // b'[p][al][bh][t] = s(al, bl) (−1)^{p|bl|} b[bh, bl], bl = al ⊕ kl(t), kl the lane of the
    // result block kh = ah ⊕ bh (parity p ⊕ par(bh) ⊕ parR when compact).
    alignas(64) std::array<S, std::size_t(2 * W) * D / W * WB> bt;
    [&]<std::size_t... C>(std::index_sequence<C...>) {
      (fillCombo<int(C)>(bd.data(), bt.data()), ...);
    }(std::make_index_sequence<std::size_t(2 * W)>{});
    alignas(64) std::array<S, std::size_t(NB) * WB> c;
    for (int kh = 0; kh < NB; ++kh) {
      // Result block kh in registers: every a meets the single block bh = ah ⊕ kh of b.
      alignas(64) S acc[WB] = {};
      for (int m = kStart[std::size_t(kh)]; m < kStart[std::size_t(kh) + 1]; ++m) {
        const Entry e = kEntries[std::size_t(m)];
        const S x = a[e.i];
        const S y = e.neg ? -x : x;
        const S* __restrict sb = std::assume_aligned<kAlign>(&bt[e.off]);
        for (int t = 0; t < WB; ++t) acc[t] += y * sb[t];
      }
      for (int t = 0; t < WB; ++t) c[std::size_t(kh * WB + t)] = acc[t];
    }
    finish(c, out);
  }
  template <class C, class Out> static void finish(const C& c, Out& out) {
    for (std::size_t m = 0; m < c.size(); ++m)
      if (outIndex[m] >= 0) out[outIndex[m]] = c[m];
  }
};

}  // namespace detail

template <class Sig, class S, GradeMask M = Sig::allGrades> class Multivector {
  static_assert((M & ~Sig::allGrades) == 0, "Multivector: grade mask has grades above n");

 public:
  using Signature = Sig;
  using Scalar = S;
  using Layout = detail::Layout<Sig, M>;
  static constexpr GradeMask mask = M;
  static constexpr int size = Layout::size;

  Multivector() { c_.fill(S(0)); }
  /// A scalar (requires grade 0 in the mask).
  explicit Multivector(const S& s)
    requires((M & 1) != 0)
  {
    c_.fill(S(0));
    c_[0] = s;
  }
  /// Widening from a multivector whose grades are a subset of ours (e.g. Bivector → Even).
  template <GradeMask M2>
    requires((M2 & ~M) == 0 && M2 != M)
  Multivector(const Multivector<Sig, S, M2>& o) {
    c_.fill(S(0));
    for (int i = 0; i < o.size; ++i) c_[Layout::index[o.blade(i)]] = o[i];
  }

  static Multivector zero() { return Multivector(); }
  /// v · (basis blade b); InvalidInput if the grade of b is not stored by this type.
  static Multivector basisBlade(Blade b, const S& v = S(1)) {
    Multivector m;
    m.setCoeff(b, v);
    return m;
  }
  /// The generator e_i, i ∈ [0, n).
  static Multivector generator(int i) {
    if (i < 0 || i >= Sig::n)
      throw InvalidInput("clifford generator index " + std::to_string(i) + " is outside [0, " +
                         std::to_string(Sig::n) + ")");
    return basisBlade(Blade(1) << i);
  }

  /// Coefficient by storage index (blade(i) tells which blade).
  S& operator[](int i) { return c_[i]; }
  const S& operator[](int i) const { return c_[i]; }
  static constexpr Blade blade(int i) { return Layout::blades[i]; }
  /// Coefficient of basis blade b (0 if its grade is not stored).
  S coeff(Blade b) const {
    const int i = b < Blade(Sig::dim) ? Layout::index[b] : -1;
    return i < 0 ? S(0) : c_[i];
  }
  void setCoeff(Blade b, const S& v) {
    const int i = b < Blade(Sig::dim) ? Layout::index[b] : -1;
    if (i < 0)
      throw InvalidInput("clifford blade " + std::to_string(b) + " (grade " +
                         std::to_string(bladeGrade(b)) + ") is not stored by this grade mask");
    c_[i] = v;
  }
  const std::array<S, size>& coeffs() const { return c_; }
  S scalarPart() const { return coeff(0); }

  /// Grade projection onto the grades in M2 (GF §9.1 grading): a new type with mask M2 ∩ M.
  template <GradeMask M2> Multivector<Sig, S, M2 & M> grades() const {
    Multivector<Sig, S, M2 & M> out;
    for (int i = 0; i < out.size; ++i) out[i] = c_[Layout::index[out.blade(i)]];
    return out;
  }
  /// ⟨a⟩_k as a grade-k type.
  template <int k> auto grade() const { return grades<gradeBit(k)>(); }
  /// ⟨a⟩_k keeping this type (runtime k).
  Multivector gradeProject(int k) const {
    Multivector out;
    for (int i = 0; i < size; ++i)
      if (bladeGrade(blade(i)) == k) out.c_[i] = c_[i];
    return out;
  }

  /// Reverse ã: (e_i…e_k)~ = e_k…e_i, sign (−1)^{k(k−1)/2} on grade k.
  Multivector reverse() const { return withGradeSigns(reverseSign); }
  /// Grade (main) involution α: e_i ↦ −e_i, an automorphism (GF-9.1-conjugation-involution).
  Multivector involute() const { return withGradeSigns(involutionSign); }
  /// Clifford conjugation c* = α(c̃), the anti-involution of GF §9.1 (e_i* = −e_i).
  Multivector conjugate() const { return withGradeSigns(conjugationSign); }
  Multivector operator~() const { return reverse(); }

  Multivector operator-() const {
    Multivector o;
    for (int i = 0; i < size; ++i) o.c_[i] = -c_[i];
    return o;
  }
  Multivector& operator+=(const Multivector& o) {
    for (int i = 0; i < size; ++i) c_[i] += o.c_[i];
    return *this;
  }
  Multivector& operator-=(const Multivector& o) {
    for (int i = 0; i < size; ++i) c_[i] -= o.c_[i];
    return *this;
  }
  Multivector& operator*=(const S& s) {
    for (auto& v : c_) v *= s;
    return *this;
  }
  Multivector& operator/=(const S& s) {
    for (auto& v : c_) v /= s;
    return *this;
  }

  /// Largest |coefficient| (a basis-dependent size, for tolerances and tests).
  S maxAbs() const {
    using std::abs;
    S m(0);
    for (const auto& v : c_)
      if (abs(v) > m) m = abs(v);
    return m;
  }
  /// Same element with the coefficients converted to scalar T.
  template <class T> Multivector<Sig, T, M> cast() const {
    Multivector<Sig, T, M> o;
    for (int i = 0; i < size; ++i) o[i] = scalarCast<T>(c_[i]);
    return o;
  }

 private:
  Multivector withGradeSigns(int (*sign)(int)) const {
    Multivector o;
    for (int i = 0; i < size; ++i) o.c_[i] = sign(bladeGrade(blade(i))) < 0 ? -c_[i] : c_[i];
    return o;
  }
  std::array<S, size> c_;
};

template <class Sig, class S> using Dense = Multivector<Sig, S, Sig::allGrades>;
template <class Sig, class S> using ScalarMV = Multivector<Sig, S, gradeBit(0)>;
template <class Sig, class S> using Vector = Multivector<Sig, S, gradeBit(1)>;
template <class Sig, class S> using Bivector = Multivector<Sig, S, gradeBit(2)>;
template <class Sig, class S> using Trivector = Multivector<Sig, S, gradeBit(3)>;
/// The even subalgebra Cl⁺: rotors, motors, Spin groups (GF §9.1).
template <class Sig, class S> using Even = Multivector<Sig, S, Sig::evenGrades>;
template <class Sig, class S> using Odd = Multivector<Sig, S, Sig::oddGrades>;

/// Generic bilinear product `op` (see the operator map at the top of this file).
template <Op op, class Sig, class S, GradeMask A, GradeMask B>
auto product(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  using T = detail::ProductTable<Sig, op, A, B>;
  using Out = Multivector<Sig, S, T::result>;
  Out out;
  constexpr bool builtin = std::is_floating_point_v<S> || std::is_same_v<S, __float128>;
  if constexpr (builtin && T::atCompileTime) {
    using TT = detail::StaticTerms<T>;
    if constexpr (TT::count <= detail::kUnrollTerms) {
      detail::applyUnrolled<TT>(out, a, b, std::make_index_sequence<std::size_t(TT::count)>{});
      return out;
    }
  }
  if constexpr (builtin && op == Op::Geometric && !T::atCompileTime &&
                detail::Blocked<Sig, A, B>::enabled) {
    detail::Blocked<Sig, A, B>::template apply<S>(a, b, out);
    return out;
  }
  for (const auto& t : T::terms()) {
    if (t.s > 0)
      out[t.k] += a[t.i] * b[t.j];
    else
      out[t.k] -= a[t.i] * b[t.j];
  }
  return out;
}

/// Geometric product (GF §9.1: e_i e_j + e_j e_i = 2 Q_ij).
template <class Sig, class S, GradeMask A, GradeMask B>
auto geometric(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  return product<Op::Geometric>(a, b);
}
/// Exterior product a ∧ b, metric-free (GF-9.1-exterior-product).
template <class Sig, class S, GradeMask A, GradeMask B>
auto outer(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  return product<Op::Outer>(a, b);
}
/// Regressive product a ∨ b = lc(rc(a) ∧ rc(b)), rc/lc the right/left complements on the basis
/// (a ∧ rc(a) = I, lc(a) ∧ a = I). Needs no metric, so it works in degenerate Cl(0,3,1) and
/// Cl(0,6,2) (SB's join). I ∨ b = b and a ∨ I = a.
template <class Sig, class S, GradeMask A, GradeMask B>
auto regressive(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  return product<Op::Regressive>(a, b);
}
/// Left contraction a ⌋ b: for blades, the geometric product when a's factors ⊆ b's, else 0.
template <class Sig, class S, GradeMask A, GradeMask B>
auto leftContraction(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  return product<Op::LeftContraction>(a, b);
}
/// Right contraction a ⌊ b: for blades, the geometric product when b's factors ⊆ a's, else 0.
template <class Sig, class S, GradeMask A, GradeMask B>
auto rightContraction(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  return product<Op::RightContraction>(a, b);
}
/// Scalar product ⟨a b⟩₀.
template <class Sig, class S, GradeMask A, GradeMask B>
S scalarProduct(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  return product<Op::Scalar>(a, b).scalarPart();
}

template <class Sig, class S, GradeMask A, GradeMask B>
auto operator*(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  return product<Op::Geometric>(a, b);
}
template <class Sig, class S, GradeMask A, GradeMask B>
auto operator^(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  return product<Op::Outer>(a, b);
}
template <class Sig, class S, GradeMask A, GradeMask B>
auto operator&(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  return product<Op::Regressive>(a, b);
}
template <class Sig, class S, GradeMask A, GradeMask B>
auto operator|(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  return product<Op::LeftContraction>(a, b);
}

template <class Sig, class S, GradeMask A, GradeMask B>
Multivector<Sig, S, A | B> operator+(const Multivector<Sig, S, A>& a,
                                     const Multivector<Sig, S, B>& b) {
  Multivector<Sig, S, A | B> out(a);
  out += Multivector<Sig, S, A | B>(b);
  return out;
}
template <class Sig, class S, GradeMask A, GradeMask B>
Multivector<Sig, S, A | B> operator-(const Multivector<Sig, S, A>& a,
                                     const Multivector<Sig, S, B>& b) {
  Multivector<Sig, S, A | B> out(a);
  out -= Multivector<Sig, S, A | B>(b);
  return out;
}
template <class Sig, class S, GradeMask A>
Multivector<Sig, S, A | 1> operator+(const Multivector<Sig, S, A>& a,
                                     const std::type_identity_t<S>& s) {
  Multivector<Sig, S, A | 1> out(a);
  out[0] += s;
  return out;
}
template <class Sig, class S, GradeMask A>
Multivector<Sig, S, A | 1> operator+(const std::type_identity_t<S>& s,
                                     const Multivector<Sig, S, A>& a) {
  return a + s;
}
template <class Sig, class S, GradeMask A>
Multivector<Sig, S, A | 1> operator-(const Multivector<Sig, S, A>& a,
                                     const std::type_identity_t<S>& s) {
  Multivector<Sig, S, A | 1> out(a);
  out[0] -= s;
  return out;
}
template <class Sig, class S, GradeMask A>
Multivector<Sig, S, A> operator*(Multivector<Sig, S, A> a, const std::type_identity_t<S>& s) {
  return a *= s;
}
template <class Sig, class S, GradeMask A>
Multivector<Sig, S, A> operator*(const std::type_identity_t<S>& s, Multivector<Sig, S, A> a) {
  return a *= s;
}
template <class Sig, class S, GradeMask A>
Multivector<Sig, S, A> operator/(Multivector<Sig, S, A> a, const std::type_identity_t<S>& s) {
  return a /= s;
}

/// max |a_i − b_i| over all blades (masks may differ).
template <class Sig, class S, GradeMask A, GradeMask B>
S maxAbsDiff(const Multivector<Sig, S, A>& a, const Multivector<Sig, S, B>& b) {
  return (a - b).maxAbs();
}

/// ⟨a ã⟩₀, signed: for a vector x of Cl(0,n,0) this is x² = −|x|², for a rotor of Cl(0,3,0)
/// it is a₀² + |a|². In degenerate algebras the null parts do not contribute.
template <class Sig, class S, GradeMask A> S norm2(const Multivector<Sig, S, A>& a) {
  return scalarProduct(a, a.reverse());
}
/// sqrt|⟨a ã⟩₀|.
template <class Sig, class S, GradeMask A> S norm(const Multivector<Sig, S, A>& a) {
  using std::abs;
  using std::sqrt;
  return sqrt(abs(norm2(a)));
}

/// Inverse of a versor (an element with a ã a nonzero scalar: rotors, motors, invertible
/// vectors): ã / (a ã), same grades as a. InvalidInput when a ã is not a nonzero scalar.
template <class Sig, class S, GradeMask A>
Multivector<Sig, S, A> versorInverse(const Multivector<Sig, S, A>& a) {
  using std::abs;
  const auto r = a.reverse();
  const auto aa = a * r;
  const S s = aa.scalarPart();
  const S scale = a.maxAbs() * a.maxAbs();
  const S rest = (aa - s).maxAbs();
  if (!(abs(s) > Tolerance<S>::rank() * scale) || rest > Tolerance<S>::input() * scale)
    throw InvalidInput("clifford versorInverse: a·reverse(a) = " + soma::toString(s) +
                       " + (non-scalar part of size " + soma::toString(rest) +
                       ") is not a nonzero scalar, so the element is not an invertible versor");
  return r / s;
}

/// The 2^n × 2^n matrix of left multiplication x ↦ a x on the dense basis.
template <class Sig, class S, GradeMask A>
Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> leftMultiplicationMatrix(
    const Multivector<Sig, S, A>& a) {
  using L = detail::Layout<Sig, Sig::allGrades>;
  Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> m =
      Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>::Zero(Sig::dim, Sig::dim);
  for (int i = 0; i < a.size; ++i)
    for (int j = 0; j < L::size; ++j) {
      const Blade bi = a.blade(i), bj = L::blades[j];
      const int s = Sig::productSign(bi, bj);
      if (s > 0) m(L::index[bi ^ bj], j) += a[i];
      if (s < 0) m(L::index[bi ^ bj], j) -= a[i];
    }
  return m;
}

/// General inverse: solves a x = 1 with the left-multiplication matrix (full-pivot LU, rank
/// threshold Tolerance<S>::rank()). In a finite-dimensional algebra a left inverse is two-sided.
/// InvalidInput for zero divisors (GF-9.1-zero-divisor) and null elements.
template <class Sig, class S, GradeMask A> Dense<Sig, S> inverse(const Multivector<Sig, S, A>& a) {
  const auto m = leftMultiplicationMatrix(a);
  Eigen::FullPivLU<Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>> lu(m);
  lu.setThreshold(Tolerance<S>::rank());
  if (!lu.isInvertible())
    throw InvalidInput("clifford inverse: the element has no inverse (its left-multiplication "
                       "matrix has rank " + std::to_string(lu.rank()) + " < " +
                       std::to_string(Sig::dim) + "; a zero divisor or a null element)");
  Eigen::Matrix<S, Eigen::Dynamic, 1> one = Eigen::Matrix<S, Eigen::Dynamic, 1>::Zero(Sig::dim);
  one(0) = S(1);
  const Eigen::Matrix<S, Eigen::Dynamic, 1> x = lu.solve(one);
  Dense<Sig, S> out;
  for (int i = 0; i < out.size; ++i) out[i] = x(i);  // dense layout index 0 is the scalar
  return out;
}

/// Exponential of a bivector B, an element of the even subalgebra.
/// Closed form when B² = a + R with R (the grade-4 part) zero — simple bivectors, all bivectors
/// for n ≤ 3 — or R nilpotent and commuting with B — all bivectors of Cl(0,3,1) (R ∝ the null
/// pseudoscalar, the dual-angle case of GF-9.3-exp-log):
///   exp B = C(a) + S(a)/2 R + S(a) B + G(a) R B,
///   C = cos θ, S = sin θ/θ, G = (sin θ − θ cos θ)/(2θ³) with θ² = −a (cosh/sinh for a > 0),
/// each replaced by its Taylor series in a for |a| < Tolerance<S>::precision(3) (error < ε).
/// Otherwise: scaling and squaring (argument scaled below 1/2) with the Taylor series summed until
/// the next term is below Tolerance<S>::epsilon() relative to the sum.
template <class Sig, class S, GradeMask M> Even<Sig, S> exp(const Multivector<Sig, S, M>& B) {
  static_assert(M == gradeBit(2), "clifford exp: the argument must be a Bivector");
  using std::abs;
  using std::cos;
  using std::cosh;
  using std::sin;
  using std::sinh;
  using std::sqrt;
  using E = Even<Sig, S>;
  const auto B2 = B * B;  // grades 0, 4 (the grade-2 part is a commutator, identically 0)
  const S a = B2.scalarPart();
  const auto R = B2.template grades<gradeBit(4)>();
  const S b = B.maxAbs();
  const S scale = b * b > S(1) ? b * b : S(1);
  const S tol = Tolerance<S>::identity() * scale;
  bool closed = R.maxAbs() <= tol;
  if (!closed) {
    const auto RR = R * R;
    const auto comm = R * B - B * R;
    closed = RR.maxAbs() <= tol * scale && comm.maxAbs() <= tol * b;
  }
  if (closed) {
    S c, s, g;
    if (abs(a) < Tolerance<S>::precision(3)) {
      c = S(1) + a / S(2) + a * a / S(24) + a * a * a / S(720);
      s = S(1) + a / S(6) + a * a / S(120) + a * a * a / S(5040);
      g = S(1) / S(6) + a / S(60) + a * a / S(1680) + a * a * a / S(90720);
    } else if (a < S(0)) {
      const S th = sqrt(-a);
      c = cos(th);
      s = sin(th) / th;
      g = (sin(th) - th * cos(th)) / (S(2) * th * th * th);
    } else {
      const S mu = sqrt(a);
      c = cosh(mu);
      s = sinh(mu) / mu;
      g = (mu * cosh(mu) - sinh(mu)) / (S(2) * mu * mu * mu);
    }
    E out(E(c) + E(R * (s / S(2))) + E(B * s));
    out += E((R * B) * g);
    return out;
  }
  // Series with scaling and squaring.
  int k = 0;
  S bs = b;
  while (bs > S(1) / S(2)) {
    bs /= S(2);
    ++k;
  }
  S factor(1);
  for (int i = 0; i < k; ++i) factor *= S(2);
  const auto X = B / factor;
  E sum(S(1)), term(S(1));
  for (int m = 1; m < 1000; ++m) {
    term = E(term * X) / S(m);
    sum += term;
    if (term.maxAbs() <= Tolerance<S>::epsilon() * sum.maxAbs()) break;
  }
  for (int i = 0; i < k; ++i) sum = E(sum * sum);
  return sum;
}

/// "2 + 3 e0 - e01" style text (blade names list generator indices).
template <class Sig, class S, GradeMask A> std::string toString(const Multivector<Sig, S, A>& a) {
  std::ostringstream os;
  bool first = true;
  for (int i = 0; i < a.size; ++i) {
    if (a[i] == S(0)) continue;
    if (!first) os << " + ";
    first = false;
    os << soma::toString(a[i]);
    if (a.blade(i) != 0) {
      os << " e";
      for (int g = 0; g < Sig::n; ++g)
        if (a.blade(i) & (Blade(1) << g)) os << g;
    }
  }
  if (first) os << "0";
  return os.str();
}

}  // namespace soma::clifford
