// The command line: parses, dispatches to one subcommand, maps errors to exit codes (docs/cli.md).
// Shared by the program (main.cpp) and the Python module, which runs it in-process.

#include "cli.hpp"

#include <algorithm>
#include <charconv>
#include <iostream>
#include <limits>
#include <stdexcept>

#include "command.hpp"
#include "interrupt.hpp"
#include "newtop/analysis/rotations.hpp"
#include "newtop/core/types.hpp"
#include "newtop/integrate/options.hpp"
#include "newtop/io/suggest.hpp"
#include "summary.hpp"

namespace newtop::app {

std::vector<Command>& commands() {
  static std::vector<Command> c;
  return c;
}

int bad_input(std::string what) {
  std::replace(what.begin(), what.end(), '\n', ' ');
  std::cerr << "newtop: error: " << what << '\n';
  return kExitBadInput;
}

namespace {

bool quiet_flag = false;  // --quiet of the running subcommand

// Passes everything to `to` and counts what it passed: whether a command wrote to std::cout.
class CountingBuf : public std::streambuf {
 public:
  explicit CountingBuf(std::streambuf* to) : to_(to) {}
  std::int64_t count() const { return count_; }

 protected:
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    ++count_;
    return to_->sputc(traits_type::to_char_type(c));
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    count_ += n;
    return to_->sputn(s, n);
  }
  int sync() override { return to_->pubsync(); }

 private:
  std::streambuf* to_;
  std::int64_t count_ = 0;
};

// std::cout through a CountingBuf while it lives.
class CountOutput {
 public:
  CountOutput() : buf_(std::cout.rdbuf()), old_(std::cout.rdbuf(&buf_)) {}
  ~CountOutput() { std::cout.rdbuf(old_); }
  CountOutput(const CountOutput&) = delete;
  CountOutput& operator=(const CountOutput&) = delete;
  std::int64_t count() const { return buf_.count(); }

 private:
  CountingBuf buf_;
  std::streambuf* old_;
};

// The units line that ends every human summary: after a command that wrote to std::cout without
// --json and ended with a report (exit 0 or 3).
int with_units_line(const CLI::App& sub, const std::function<int()>& action) {
  const CLI::Option* json = sub.get_option_no_throw("--json");
  int code = 0;
  std::int64_t written = 0;
  {
    const CountOutput counted;
    code = action();
    written = counted.count();
  }
  if (written > 0 && !(json && json->count() > 0) && !units_line_printed() &&
      (code == kExitOk || code == kExitIncomplete)) {
    print_units_line(std::cout);
  }
  return code;
}

}  // namespace

void warn(std::string what) {
  if (quiet_flag) return;
  std::replace(what.begin(), what.end(), '\n', ' ');
  std::cerr << "newtop: warning: " << what << '\n';
}

bool quiet() { return quiet_flag; }

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

// The range of every integer option of every subcommand, checked at parsing, before any work:
// a value that is not an integer, or lies outside [lo, hi], is refused in one line naming the
// option, the range and the value. Beyond the bounds the value would be meaningless (below) or
// the run absurd (above: e.g. 10^5 orbits of a portrait, 10^6 analytic samples).
struct IntegerRange {
  const char* command;
  const char* option;
  std::int64_t lo, hi;
  std::vector<std::int64_t> only{};  ///< the values allowed, if not every one of [lo, hi]
};

const std::vector<IntegerRange>& integer_ranges() {
  static const std::vector<IntegerRange> r{
      {"analytic", "samples", 1, 1'000'000},
      {"analytic", "dense", 2, 1'000'000},
      {"continue", "mode", 1, 2},
      {"find-integrals", "degree", 1, 6},
      // The library bounds the points further, by the degree (kMaxConditionEntries entries).
      {"find-integrals", "points", 1, std::numeric_limits<int>::max()},
      {"libration", "iterates", 1, 100'000},
      {"rotations", "samples", 2, kMaxRotationSamples},
      {"section", "crossings", 1, 1'000'000'000},
      {"section", "orbits", 1, 100'000},
      {"simulate", "every", 1, static_cast<std::int64_t>(kMaxStepCount)},
      {"simulate", "euler", 313, 321, {321, 313}},
      {"stability", "equilibrium", 1, 1'000'000},
      {"sweep", "threads", 1, 4096},
      {"view", "max-frames", 2, 100'000'000},
  };
  return r;
}

// The check of one integer option: the text is an integer ([+-]digits) in the range.
std::string check_integer(const IntegerRange& r, const std::string& text) {
  std::string expected;
  for (const std::int64_t v : r.only)
    expected += (expected.empty() ? "" : " or ") + std::to_string(v);
  if (expected.empty()) {
    expected = "an integer from " + std::to_string(r.lo) + " to " + std::to_string(r.hi);
  }
  std::int64_t v = 0;
  const char* first = text.data() + (text.rfind('+', 0) == 0 ? 1 : 0);
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(first, last, v);
  const bool integer = first != last && end == last && ec != std::errc::invalid_argument;
  const bool in_range = integer && ec == std::errc{} && v >= r.lo && v <= r.hi &&
                        (r.only.empty() || std::count(r.only.begin(), r.only.end(), v) > 0);
  if (in_range) return "";
  return "expected " + expected + ", found " + (integer ? text : "'" + text + "'");
}

// Adds the range check to every integer option of `sub` (CLI11 types them "INT"); an integer
// option without a range is a programming error, caught by the tests that run every subcommand.
void check_integer_options(CLI::App& sub) {
  for (CLI::Option* o : sub.get_options()) {
    if (o->get_type_name().rfind("INT", 0) != 0) continue;
    const auto& ranges = integer_ranges();
    const auto it = std::find_if(ranges.begin(), ranges.end(), [&](const IntegerRange& r) {
      return sub.get_name() == r.command && o->check_lname(r.option);
    });
    if (it == ranges.end()) {
      throw std::logic_error("no range for the integer option --" + o->get_lnames().front() +
                             " of newtop " + sub.get_name());
    }
    const IntegerRange r = *it;
    o->check(CLI::Validator([r](std::string& text) { return check_integer(r, text); }, ""));
  }
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
  app.set_version_flag("--version", "newtop 0.1.0");
  quiet_flag = false;  // the Python module runs the command line more than once in a process
  app.add_flag("--quiet", quiet_flag, "no warnings on stderr (before or after the subcommand)");
  set_units(kUnitFree);
  auto& cmds = commands();
  std::sort(cmds.begin(), cmds.end(),
            [](const Command& a, const Command& b) { return a.name < b.name; });
  std::vector<std::pair<CLI::App*, std::function<int()>>> actions;
  std::vector<std::string> names;
  for (const auto& c : cmds) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    actions.emplace_back(sub, c.setup(*sub));
    try {
      check_integer_options(*sub);
    } catch (const std::logic_error& e) {
      std::cerr << "newtop: internal error: " << e.what() << '\n';
      return kExitInternal;
    }
    sub->add_flag("--quiet", quiet_flag,
                  "silence warnings (and sweep's progress) on stderr; errors are still printed");
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
      if (sub->parsed()) return with_units_line(*sub, action);
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
