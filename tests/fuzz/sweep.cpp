// libFuzzer harness: the sweep reader (io::parseSweep: parameters, quantities, the base scene with
// its files read in, the first point's scene parsed and validated), then the scene of point 0 and of
// the last point. Relative paths resolve against examples/sweeps/ (SOMA_FUZZ_SWEEP_DIR), so the
// corpus's sweeps reach the example robots, scenes and platforms.
#include "harness.hpp"

#include "soma/io/sweep_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string body = soma::fuzz::text(data, size);
  soma::fuzz::expectReadOrInvalidInput("sweep", [&] {
    const soma::io::SweepFile sweep = soma::io::parseSweep(body, "fuzz.json", SOMA_FUZZ_SWEEP_DIR);
    if (sweep.points() > 0) {
      (void)soma::io::sweepPointScene(sweep, 0);
      (void)soma::io::sweepPointScene(sweep, sweep.points() - 1);
    }
  });
  return 0;
}
