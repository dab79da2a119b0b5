// The `soma` command line (DESIGN §6, a contract: keep it stable; every subcommand, flag, exit
// code and JSON field is in docs/cli.md). Each subcommand lives in its own file and registers
// itself (command.hpp); this file, the only one that includes CLI11, turns their option specs
// into CLI11 options, parses, and runs the subcommand given.
// Exit codes: 0 every check passed, 1 a check or study failed, 2 bad input (usage, unknown
// study or scalar, unwritable output).
#include "command.hpp"

#include "soma/algebra/errors.hpp"
#include "soma/io/number.hpp"
#include "soma/studies/report.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <deque>
#include <iostream>

namespace {

using namespace soma::cli;

/// An int or double option as CLI11 sees it: text, read after parsing by io's number reader (the
/// one reader of every file and flag: decimal only, no hex, no inf; integers decided on the text).
struct NumberText {
  Option* option;
  CLI::Option* given = nullptr;
  std::string text;
};

std::string shown(double v) { return fmt::format("{:g}", v); }

/// The value of a numeric option's text, in its range. InvalidInput (exit 2) naming the flag, the
/// value and the range: `--bits: "100000" is outside 16 … 8192`.
void readNumber(const NumberText& n) {
  const Option& o = *n.option;
  if (int* const* i = std::get_if<int*>(&o.target)) {
    const long long lo = o.ranged ? static_cast<long long>(o.low) : INT_MIN;
    const long long hi = o.ranged ? static_cast<long long>(o.high) : INT_MAX;
    **i = static_cast<int>(soma::io::parseInteger(n.text, o.name, lo, hi));
  } else if (double* const* d = std::get_if<double*>(&o.target)) {
    const double v = soma::io::parseDecimal<double>(n.text, o.name);
    if (o.ranged && !(v >= o.low && v <= o.high))
      throw soma::InvalidInput(o.name + ": \"" + n.text + "\" is outside " + shown(o.low) + " … " + shown(o.high));
    **d = v;
  }
}

/// The spec's options and nested subcommands as CLI11's, recording which app is which spec.
void bind(CLI::App* app, Spec& spec, std::vector<std::pair<CLI::App*, Spec*>>& apps, std::deque<NumberText>& numbers) {
  apps.emplace_back(app, &spec);
  if (spec.requireSubcommand) app->require_subcommand(1);
  for (Option& o : spec.options) {
    if (bool** flag = std::get_if<bool*>(&o.target)) {
      app->add_flag(o.name, **flag, o.help);
      continue;
    }
    CLI::Option* c = nullptr;
    const bool isInt = std::holds_alternative<int*>(o.target);
    if (isInt || std::holds_alternative<double*>(o.target)) {
      NumberText& n = numbers.emplace_back(NumberText{&o, nullptr, {}});
      c = n.given = app->add_option(o.name, n.text, o.help);
      std::string type = isInt ? "INT" : "FLOAT";
      auto bound = [&](double v) { return isInt ? std::to_string(static_cast<long long>(v)) : shown(v); };
      if (o.ranged) type += " in [" + bound(o.low) + " - " + bound(o.high) + "]";
      c->type_name(type);
      if (o.showDefault) c->default_str(isInt ? std::to_string(*std::get<int*>(o.target)) : shown(*std::get<double*>(o.target)));
    } else {
      c = std::visit([&](auto* t) { return app->add_option(o.name, *t, o.help); }, o.target);
      if (o.showDefault) c->capture_default_str();
    }
    if (o.required) c->required();
    if (!o.oneOf.empty()) c->check(CLI::IsMember(o.oneOf));
  }
  for (auto& sub : spec.subcommands) bind(app->add_subcommand(sub->name, sub->help), *sub, apps, numbers);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"soma — geometry of robot kinematics (J.M. Selig, Geometric Fundamentals of Robotics)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(soma::studies::somaVersion()));

  auto registrations = registry();
  std::stable_sort(registrations.begin(), registrations.end(),
                   [](const Registration& a, const Registration& b) { return a.order < b.order; });
  std::vector<std::unique_ptr<Command>> commands;
  std::vector<std::unique_ptr<Spec>> specs;
  std::vector<std::pair<CLI::App*, Spec*>> apps;
  std::deque<NumberText> numbers;  // stable addresses: CLI11 writes into each text
  for (const auto& r : registrations) {
    commands.push_back(r.make());
    specs.push_back(std::make_unique<Spec>());
    commands.back()->declare(*specs.back());
    bind(app.add_subcommand(specs.back()->name, specs.back()->help), *specs.back(), apps, numbers);
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  for (auto& [a, s] : apps) s->parsed = a->parsed();

  Invocation call;
  for (int i = 0; i < argc; ++i) call.commandLine += (i ? " " : "") + std::string(argv[i]);
  try {
    for (const NumberText& n : numbers)  // every numeric flag read before any command runs
      if (n.given->count() > 0) readNumber(n);
    for (std::size_t k = 0; k < commands.size(); ++k)
      if (specs[k]->parsed) {
        const int rc = commands[k]->run(*specs[k], call);
        // An answer that did not reach stdout (a full disk, /dev/full, a closed pipe) is no
        // answer: exit 2 with a message rather than 0.
        errno = 0;
        std::cout.flush();
        if (!std::cout) {
          std::cerr << "soma: cannot write to standard output" << (errno ? std::string(": ") + std::strerror(errno) : "")
                    << "\n";
          return 2;
        }
        return rc;
      }
  } catch (const std::exception& e) {  // InvalidInput, an unknown study, an unwritable output
    std::cerr << "soma: " << e.what() << "\n";
    return 2;
  }
  return 2;
}
