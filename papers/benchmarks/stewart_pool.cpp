// fkSGP comparison (papers/benchmarks/stewart.md): writes soma's bench/stewart.cpp pool (seed 20261130, 32
// platforms; compile with g++ like build/bench, the joints are drawn in its argument order) as
// one line per platform: base (18), platform (18), leg lengths (6). Not part of soma's build.
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
      b[i] = Vec3<double>(u(g), u(g), 0.2 * u(g));
      p[i] = Vec3<double>(0.6 * u(g), 0.6 * u(g), 0.1 * u(g));
    }
    Vec6<double> xi;
    xi << 0.3 * u(g), 0.3 * u(g), 0.3 * u(g), 0.2 * u(g), 0.2 * u(g), 1.0 + 0.2 * u(g);
    const SE3<double> T = SE3Tangent<double>(xi).exp();
    for (int i = 0; i < 6; ++i) std::printf("%.17g %.17g %.17g ", b[i][0], b[i][1], b[i][2]);
    for (int i = 0; i < 6; ++i) std::printf("%.17g %.17g %.17g ", p[i][0], p[i][1], p[i][2]);
    for (int i = 0; i < 6; ++i) std::printf("%.17g ", (T.act(p[i]) - b[i]).norm());
    std::printf("\n");
  }
}
