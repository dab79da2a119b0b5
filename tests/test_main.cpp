// Catch2 main for every soma test executable. Fixed seeds: tests draw from soma::test::rng().
#define CATCH_CONFIG_RUNNER
#include "soma/algebra/scalar.hpp"
#include <catch2/catch.hpp>

int main(int argc, char* argv[]) {
  soma::setMpfrBits(256);
  return Catch::Session().run(argc, argv);
}
