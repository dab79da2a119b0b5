// The fast double tracker's kernels (stewart_fast_lanes.hpp, GF §11.5.4): the same source compiled
// for the default instruction set and, on x86-64, for AVX2 + FMA and for AVX-512 (eight lanes), the
// widest the CPU has chosen at run time (no -march flag: the library runs on every x86-64 CPU).
#include "stewart_fast_tracker.hpp"

#include "soma/geometry/parallel/stewart.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace soma::stewart_fast {

namespace portable {
#include "stewart_fast_lanes.hpp"
}  // namespace portable

#if defined(__x86_64__) && (defined(__clang__) || defined(__GNUC__))
#define SOMA_STEWART_X86 1
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2,fma"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2,fma")
#endif
namespace avx2 {
#include "stewart_fast_lanes.hpp"
}  // namespace avx2
#if defined(__clang__)
#pragma clang attribute pop
#pragma clang attribute push(__attribute__((target("avx512f,avx512dq,avx512vl,avx2,fma"))), apply_to = function)
#else
#pragma GCC pop_options
#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq,avx512vl,avx2,fma")
#endif
namespace avx512 {
constexpr int kLanes = 8;  // one AVX-512 register of doubles (hides the outer four)
#include "stewart_fast_lanes.hpp"
}  // namespace avx512
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
#endif

namespace {
Kernel widest() {
#ifdef SOMA_STEWART_X86
  static const Kernel k = [] {
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) return Kernel::Portable;
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl"))
      return Kernel::Avx512;
    return Kernel::Avx2;
  }();
  return k;
#else
  return Kernel::Portable;
#endif
}
}  // namespace

Kernel kernel() {
  const Kernel k = widest();
  const char* cap = std::getenv("SOMA_STEWART_KERNEL");
  if (!cap) return k;
  if (std::strcmp(cap, "portable") == 0) return Kernel::Portable;
  if (std::strcmp(cap, "avx2") == 0) return std::min(k, Kernel::Avx2);
  return k;
}

const char* kernelName(Kernel k) {
  switch (k) {
    case Kernel::Avx512: return "avx512";
    case Kernel::Avx2: return "avx2";
    default: return "portable";
  }
}

void trackAll(const Homotopy& H, const std::vector<V8>& starts, const Settings& o, std::vector<Path>& out) {
  out.assign(starts.size(), Path{});
  if (starts.empty()) return;
  const int n = static_cast<int>(starts.size());
  switch (kernel()) {
#ifdef SOMA_STEWART_X86
    case Kernel::Avx512: avx512::trackAll(H, starts.data(), n, o, out.data()); return;
    case Kernel::Avx2: avx2::trackAll(H, starts.data(), n, o, out.data()); return;
#endif
    default: portable::trackAll(H, starts.data(), n, o, out.data()); return;
  }
}

}  // namespace soma::stewart_fast

namespace soma {
const char* stewartFastKernel() { return stewart_fast::kernelName(stewart_fast::kernel()); }
}  // namespace soma
