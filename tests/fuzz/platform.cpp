// libFuzzer harness: the Stewart platform reader (io::parsePlatform: six base and platform points,
// six leg lengths, validated).
#include "harness.hpp"

#include "soma/io/platform_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string body = soma::fuzz::text(data, size);
  soma::fuzz::expectReadOrInvalidInput("platform", [&] { (void)soma::io::parsePlatform<double>(body, "fuzz.json"); });
  return 0;
}
