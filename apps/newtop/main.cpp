// newtop: command-line front end. Parses, dispatches to one subcommand, maps errors to exit codes.

#include <algorithm>
#include <iostream>

#include "command.hpp"
#include "newtop/core/types.hpp"

namespace newtop::app {

std::vector<Command>& commands() {
  static std::vector<Command> c;
  return c;
}

}  // namespace newtop::app

int main(int argc, char** argv) {
  using namespace newtop::app;
  CLI::App app{
      "newtop: rigid body about a fixed point in the field of a distant centre "
      "(Euler–Poisson equations, first integrals, geometric integrators)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "newtop 0.1.0");
  auto& cmds = commands();
  std::sort(cmds.begin(), cmds.end(),
            [](const Command& a, const Command& b) { return a.name < b.name; });
  std::vector<std::pair<CLI::App*, std::function<int()>>> actions;
  for (const auto& c : cmds) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    actions.emplace_back(sub, c.setup(*sub));
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }
  try {
    for (auto& [sub, action] : actions) {
      if (sub->parsed()) return action();
    }
  } catch (const newtop::InputError& e) {
    std::cerr << "newtop: error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "newtop: internal error: " << e.what() << '\n';
    return kExitInternal;
  }
  return kExitInternal;
}
