// libFuzzer harness: the URDF reader (io::parseUrdf: the structure scan, urdfdom, the chain to the tip).
#include "harness.hpp"

#include "soma/io/urdf_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string xml = soma::fuzz::text(data, size);
  soma::fuzz::expectReadOrInvalidInput("urdf", [&] { (void)soma::io::parseUrdf<double>(xml, "fuzz.urdf"); });
  return 0;
}
