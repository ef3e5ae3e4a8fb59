#pragma once
// Subcommand registry: each subcommand lives in its own file and registers itself with a
// RegisterCommand object; main() builds the CLI from the registry.

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace newtop::app {

/// Exit codes (docs/cli.md).
inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitIncomplete = 3;  // the integration ended before t_end (outcome reported)

/// setup adds the subcommand's options to `sub` and returns the action run when it is chosen.
struct Command {
  std::string name;
  std::string description;
  std::function<std::function<int()>(CLI::App& sub)> setup;
};

std::vector<Command>& commands();

struct RegisterCommand {
  explicit RegisterCommand(Command c) { commands().push_back(std::move(c)); }
};

}  // namespace newtop::app
