// The `soma` command line (DESIGN §6, a contract: keep it stable; every subcommand, flag, exit
// code and JSON field is in docs/cli.md). Each subcommand lives in its own file and registers
// itself (command.hpp); this file, the only one that includes CLI11, turns their option specs
// into CLI11 options, parses, and runs the subcommand given.
// Exit codes: 0 every check passed, 1 a check or study failed, 2 bad input (usage, unknown
// study or scalar, unwritable output).
#include "command.hpp"

#include "soma/studies/report.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>

namespace {

using namespace soma::cli;

/// The spec's options and nested subcommands as CLI11's, recording which app is which spec.
void bind(CLI::App* app, Spec& spec, std::vector<std::pair<CLI::App*, Spec*>>& apps) {
  apps.emplace_back(app, &spec);
  if (spec.requireSubcommand) app->require_subcommand(1);
  for (Option& o : spec.options) {
    if (bool** flag = std::get_if<bool*>(&o.target)) {
      app->add_flag(o.name, **flag, o.help);
      continue;
    }
    CLI::Option* c = std::visit([&](auto* t) { return app->add_option(o.name, *t, o.help); }, o.target);
    if (o.required) c->required();
    if (!o.oneOf.empty()) c->check(CLI::IsMember(o.oneOf));
    if (o.ranged) c->check(CLI::Range(o.low, o.high));
    if (o.showDefault) c->capture_default_str();
  }
  for (auto& sub : spec.subcommands) bind(app->add_subcommand(sub->name, sub->help), *sub, apps);
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
  for (const auto& r : registrations) {
    commands.push_back(r.make());
    specs.push_back(std::make_unique<Spec>());
    commands.back()->declare(*specs.back());
    bind(app.add_subcommand(specs.back()->name, specs.back()->help), *specs.back(), apps);
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
    for (std::size_t k = 0; k < commands.size(); ++k)
      if (specs[k]->parsed) return commands[k]->run(*specs[k], call);
  } catch (const std::exception& e) {  // InvalidInput, an unknown study, an unwritable output
    std::cerr << "soma: " << e.what() << "\n";
    return 2;
  }
  return 2;
}
