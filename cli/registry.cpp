// The subcommand registry (command.hpp) and the shared scalar options (scalar_options.hpp).
#include "command.hpp"
#include "scalar_options.hpp"

#include "soma/algebra/errors.hpp"

namespace soma::cli {

std::vector<Registration>& registry() {
  static std::vector<Registration> commands;
  return commands;
}

Register::Register(int order, std::function<std::unique_ptr<Command>()> make) {
  registry().push_back({order, std::move(make)});
}

void ScalarOptions::declare(Spec& spec) {
  spec.add("--scalar", scalar, "scalar type of scalar-generic studies: " + scalarNames())
      .among({"float", "double", "long-double", "float128", "mpfr"})
      .withDefault();
  spec.add("--bits", bits, "mpfr precision in bits (with --scalar mpfr)").within(16, 8192).withDefault();
}

ScalarKind ScalarOptions::apply() const {
  const auto kind = parseScalarKind(scalar);
  if (!kind) throw InvalidInput("unknown scalar '" + scalar + "' (one of " + scalarNames() + ")");
  setMpfrBits(bits);
  return *kind;
}

}  // namespace soma::cli
