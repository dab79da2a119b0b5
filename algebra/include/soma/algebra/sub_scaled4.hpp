#pragma once
// x[0..4) −= f·y[0..4) as one vector of four in double (GNU vector extension; two SSE2 halves in a
// build without AVX): the row updates of the small dense kernels (ELMHES, the general 6R's 12×12
// LU) run over whole vectors of four, but their loops have a runtime length of 4 to 12, which the
// compiler leaves scalar (its vector loop wants 16). Other scalars: the plain loop. Double4 is the
// vector type, for the kernels' other loops of four (read and written through a cast pointer:
// unaligned, and allowed to alias the doubles it covers).
#include <type_traits>

namespace soma::detail {

#if defined(__clang__) || defined(__GNUC__)
typedef double Double4 __attribute__((vector_size(32), aligned(8), may_alias));
#endif

template <class S> [[gnu::always_inline]] inline void subScaled4(S* __restrict x, const S* __restrict y, const S& f) {
#if defined(__clang__) || defined(__GNUC__)
  if constexpr (std::is_same_v<S, double>) {
    *reinterpret_cast<Double4*>(x) -= f * *reinterpret_cast<const Double4*>(y);
    return;
  }
#endif
  for (int t = 0; t < 4; ++t) x[t] -= f * y[t];
}

}  // namespace soma::detail
