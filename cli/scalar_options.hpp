#pragma once
// `--scalar T` and `--bits N`, shared by the subcommands that run in any scalar of the ladder.
#include "command.hpp"

#include "soma/algebra/scalar.hpp"

#include <string>

namespace soma::cli {

struct ScalarOptions {
  std::string scalar = "double";
  int bits = 256;

  /// Adds --scalar (one of float double long-double float128 mpfr) and --bits (16..8192).
  void declare(Spec& spec);
  /// Sets the mpfr precision and returns the kind (the name was already checked by the parser).
  ScalarKind apply() const;
};

}  // namespace soma::cli
