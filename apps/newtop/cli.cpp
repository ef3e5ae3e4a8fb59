// The command line: parses, dispatches to one subcommand, maps errors to exit codes (docs/cli.md).
// Shared by the program (main.cpp) and the Python module, which runs it in-process.

#include "cli.hpp"

#include <algorithm>
#include <iostream>

#include "command.hpp"
#include "interrupt.hpp"
#include "newtop/core/types.hpp"
#include "newtop/io/suggest.hpp"

namespace newtop::app {

std::vector<Command>& commands() {
  static std::vector<Command> c;
  return c;
}

namespace {
bool quiet = false;  // --quiet: no warnings
}  // namespace

void warn(std::string what) {
  if (quiet) return;
  std::replace(what.begin(), what.end(), '\n', ' ');
  std::cerr << "newtop: warning: " << what << '\n';
}

int bad_input(std::string what) {
  std::replace(what.begin(), what.end(), '\n', ' ');
  std::cerr << "newtop: error: " << what << '\n';
  return kExitBadInput;
}

namespace {

// `word` (a subcommand, an option of `where`) is not one of `names`: say so, with the closest
// name or the list.
std::string unknown(const std::string& kind, const std::string& word, const std::string& where,
                    const std::vector<std::string>& names) {
  const std::string msg = "unknown " + kind + " '" + word + "'" + where;
  if (const auto close = io::closest_name(word, names))
    return msg + " — did you mean '" + *close + "'?";
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  return msg + " (expected one of: " + list + ")";
}

// An argument CLI11 did not expect, named with the closest option of the subcommand it was given
// to.
std::string unexpected(const CLI::App& app, const std::string& arg) {
  const std::string name = " for newtop " + app.get_name();
  if (arg.rfind("-", 0) != 0) return "unexpected argument '" + arg + "'" + name;
  std::vector<std::string> options;
  for (const CLI::Option* o : app.get_options()) {
    for (const auto& l : o->get_lnames()) options.push_back("--" + l);
    for (const auto& s : o->get_snames()) options.push_back("-" + s);
  }
  return unknown("option", arg.substr(0, arg.find('=')), name, options);
}

}  // namespace
}  // namespace newtop::app

namespace newtop::app {

// The orbital frame of the orbit scenarios' attitude outputs (docs/orbit.md §11).
constexpr const char* kLvlhHelp =
    "Orbit scenarios: attitude relative to LVLH: z to nadir (-gamma), y opposite the orbit normal "
    "(-n), x = y cross z (along-track); q0..q3 = rotation LVLH -> body (scalar first, q0 >= 0); "
    "roll, pitch, yaw [rad] with C(body<-LVLH) = R1(roll) R2(pitch) R3(yaw).";

int run_newtop(int argc, char** argv, bool remove_partial_files_on_signals) {
  CLI::App app{
      "newtop: rigid body about a fixed point in the field of a distant centre "
      "(Euler–Poisson equations, first integrals, geometric integrators)"};
  app.require_subcommand(1);
  app.footer(kLvlhHelp);
  quiet = false;
  app.add_flag("--quiet", quiet, "no warnings on stderr (give it before the subcommand)");
  app.set_version_flag("--version", "newtop 0.1.0");
  auto& cmds = commands();
  std::sort(cmds.begin(), cmds.end(),
            [](const Command& a, const Command& b) { return a.name < b.name; });
  std::vector<std::pair<CLI::App*, std::function<int()>>> actions;
  std::vector<std::string> names;
  for (const auto& c : cmds) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    actions.emplace_back(sub, c.setup(*sub));
    names.push_back(c.name);
  }
  // The first word names the subcommand: an unknown one is named with the closest subcommand.
  if (argc > 1 && argv[1][0] != '-' &&
      std::find(names.begin(), names.end(), argv[1]) == names.end()) {
    return bad_input(unknown("subcommand", argv[1], "", names));
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    for (auto& [sub, action] : actions) {
      if (sub->parsed() && !sub->remaining().empty()) {
        return bad_input(unexpected(*sub, sub->remaining().front()));
      }
    }
    return bad_input(e.what());
  } catch (const CLI::ParseError& e) {
    return bad_input(std::string(e.what()) + (argc == 1 ? " (newtop --help lists them)" : ""));
  }
  if (remove_partial_files_on_signals) remove_partial_files_on_signal();
  try {
    for (auto& [sub, action] : actions) {
      if (sub->parsed()) return action();
    }
  } catch (const newtop::InputError& e) {
    return bad_input(e.what());
  } catch (const std::exception& e) {
    std::cerr << "newtop: internal error: " << e.what() << '\n';
    return kExitInternal;
  }
  return kExitInternal;
}

}  // namespace newtop::app
