#pragma once
// The libFuzzer harnesses' one rule (tests/fuzz/README.md): a reader given any bytes either returns
// or throws soma::InvalidInput, the library's bad-input error (DESIGN §10). Anything else is a
// finding: a crash or sanitizer report (ASan/UBSan abort the process), a hang (libFuzzer's
// -timeout), an exception of another type (std::out_of_range, nlohmann's type_error,
// std::bad_alloc, ...), or an InvalidInput with an empty message (it must name the input).
#include "soma/algebra/errors.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace soma::fuzz {

/// The bytes as the readers take them (a file's text).
inline std::string text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Runs `read` and applies the rule: InvalidInput naming something is a normal outcome; every other
/// exception aborts (libFuzzer then saves the input as crash-<sha1>).
template <class F> void expectReadOrInvalidInput(const char* harness, F&& read) {
  try {
    read();
  } catch (const InvalidInput& e) {
    if (std::string(e.what()).empty()) {
      std::fprintf(stderr, "fuzz %s: InvalidInput with an empty message\n", harness);
      std::abort();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz %s: an exception that is not soma::InvalidInput: %s\n", harness, e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz %s: an exception of an unknown type\n", harness);
    std::abort();
  }
}

}  // namespace soma::fuzz
