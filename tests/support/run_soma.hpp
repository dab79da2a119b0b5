#pragma once
// The stdout of `soma ARGS` (SOMA_EXE, set for test_cli by tests/CMakeLists.txt) and its exit code:
// the CLI tests that read soma's answers back (tests/cli/*.cpp).
#include <catch2/catch.hpp>

#include <array>
#include <cstdio>
#include <string>

#include <sys/wait.h>

namespace soma::test {

inline std::string runSoma(const std::string& args, int& rc) {
  const std::string cmd = std::string(SOMA_EXE) + " " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  std::string out;
  std::array<char, 4096> buf{};
  while (const std::size_t n = std::fread(buf.data(), 1, buf.size(), p)) out.append(buf.data(), n);
  rc = WEXITSTATUS(pclose(p));
  return out;
}

}  // namespace soma::test
