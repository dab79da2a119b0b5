// fkSGP comparison (papers/benchmarks/stewart.md): writes soma's bench/stewart.cpp pool (seed 20261130, 32
// platforms) as one line per platform: base (18), platform (18), leg lengths (6). Not part of soma's
// build. bench/stewart.cpp draws inside constructor arguments, whose order of evaluation C++ leaves
// open; soma's build uses clang++ (left to right), so this file draws left to right explicitly and
// gives the bench's pool with any compiler (g++ evaluates right to left: a different pool).
#include "soma/algebra/se3.hpp"
#include <cstdio>
#include <random>
using namespace soma;
int main() {
  std::mt19937_64 g(20261130);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 32; ++k) {
    Vec3<double> b[6], p[6];
    for (int i = 0; i < 6; ++i) {
      const double b0 = u(g), b1 = u(g), b2 = u(g);
      b[i] = Vec3<double>(b0, b1, 0.2 * b2);
      const double p0 = u(g), p1 = u(g), p2 = u(g);
      p[i] = Vec3<double>(0.6 * p0, 0.6 * p1, 0.1 * p2);
    }
    Vec6<double> xi;
    xi << 0.3 * u(g), 0.3 * u(g), 0.3 * u(g), 0.2 * u(g), 0.2 * u(g), 1.0 + 0.2 * u(g);  // comma operator: in order
    const SE3<double> T = SE3Tangent<double>(xi).exp();
    for (int i = 0; i < 6; ++i) std::printf("%.17g %.17g %.17g ", b[i][0], b[i][1], b[i][2]);
    for (int i = 0; i < 6; ++i) std::printf("%.17g %.17g %.17g ", p[i][0], p[i][1], p[i][2]);
    for (int i = 0; i < 6; ++i) std::printf("%.17g ", (T.act(p[i]) - b[i]).norm());
    std::printf("\n");
  }
}
