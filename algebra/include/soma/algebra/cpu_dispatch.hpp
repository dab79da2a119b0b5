#pragma once
// Run-time choice of an AVX2 + FMA build of a hot double kernel. The library is built without
// -march (it runs on every x86-64 CPU); a kernel whose body is an always-inline template is
// compiled a second time inside a function marked SOMA_TARGET_AVX2_FMA and called when the CPU
// has both (as the Stewart tracker's lanes, geometry/src/parallel/stewart_fast_tracker.cpp).
// The AVX2 build contracts a·b + c to fused multiply–adds: the same computation, rounded
// differently.

#if defined(__x86_64__) && (defined(__clang__) || defined(__GNUC__))
#define SOMA_X86_AVX2_DISPATCH 1
#define SOMA_TARGET_AVX2_FMA __attribute__((target("avx2,fma")))
#endif

namespace soma::detail {

/// True when the kernels' AVX2 + FMA builds can run here (asked of the CPU once).
inline bool cpuHasAvx2Fma() {
#ifdef SOMA_X86_AVX2_DISPATCH
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
#else
  return false;
#endif
}

}  // namespace soma::detail
