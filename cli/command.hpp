#pragma once
// A subcommand of `soma` (docs/cli.md): it declares its own options into a Spec and runs from
// them. main.cpp turns every registered Spec into CLI11 options — the only translation unit that
// includes CLI11 (its header costs ~4 s per TU) — parses, and runs the one that was given.
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace soma::cli {

/// One option, flag or positional argument: what it is bound to and how it is checked.
struct Option {
  /// "robot" is a positional argument, "--json" an option or flag.
  std::string name;
  std::string help;
  std::variant<std::string*, std::vector<std::string>*, int*, double*, bool*> target;  ///< bool*: a flag
  bool required = false;
  bool showDefault = false;             ///< print the default value in --help
  std::vector<std::string> oneOf;       ///< allowed values (empty: any)
  /// An int or double option is bound as text and read by io's number reader (parseInteger,
  /// parseDecimal: decimal only, no hex, no inf) within [low, high]; main.cpp exits 2 with a
  /// message naming the flag, the value and the range otherwise.
  bool ranged = false;
  double low = 0, high = 0;

  Option& mustBeGiven() { return required = true, *this; }
  Option& withDefault() { return showDefault = true, *this; }
  Option& among(std::vector<std::string> values) { return oneOf = std::move(values), *this; }
  Option& within(double lo, double hi) { return ranged = true, low = lo, high = hi, *this; }
};

/// A subcommand's command line: its name, help, options and nested subcommands (`study list`).
struct Spec {
  std::string name, help;
  std::vector<Option> options;
  std::vector<std::unique_ptr<Spec>> subcommands;
  bool requireSubcommand = false;
  /// Set by main.cpp after parsing: this (sub)command was given.
  bool parsed = false;

  template <class T> Option& add(std::string optName, T& target, std::string optHelp) {
    Option o;
    o.name = std::move(optName);
    o.help = std::move(optHelp);
    o.target = &target;
    options.push_back(std::move(o));
    return options.back();
  }
  Option& flag(std::string optName, bool& target, std::string optHelp) { return add(std::move(optName), target, std::move(optHelp)); }
  Spec& subcommand(std::string subName, std::string subHelp) {
    subcommands.push_back(std::make_unique<Spec>());
    subcommands.back()->name = std::move(subName);
    subcommands.back()->help = std::move(subHelp);
    return *subcommands.back();
  }
};

/// What a command may need beyond its options.
struct Invocation {
  std::string commandLine;  ///< argv joined by spaces (the report records it)
};

class Command {
 public:
  virtual ~Command() = default;
  /// Name, help and options, bound to the command's own members.
  virtual void declare(Spec& spec) = 0;
  /// Runs after a successful parse: the exit code (0 passed, 1 a check failed); throws
  /// InvalidInput (or another std::exception) for bad input — main prints it and exits 2.
  virtual int run(const Spec& spec, const Invocation& call) = 0;
};

/// The registry: each subcommand file registers its command once, with its place in `--help`.
struct Registration {
  int order;
  std::function<std::unique_ptr<Command>()> make;
};
std::vector<Registration>& registry();
struct Register {
  Register(int order, std::function<std::unique_ptr<Command>()> make);
};

/// In a subcommand's .cpp: SOMA_CLI_COMMAND(IkCommand, 50) registers `IkCommand` 50th in --help.
#define SOMA_CLI_COMMAND(Type, order) \
  const ::soma::cli::Register soma_cli_register_##Type(order, [] { return std::make_unique<Type>(); })

}  // namespace soma::cli
