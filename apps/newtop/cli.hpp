#pragma once
// The whole command line as one call, for the program and for the Python module.

#include <string>

namespace newtop::app {

/// Bad input: one line on std::cerr, "newtop: error: WHAT", and returns the exit code 2.
int bad_input(std::string what);

/// A warning: one line on std::cerr, "newtop: warning: WHAT", unless --quiet was given.
void warn(std::string what);

/// Parses argv (argv[0] is the program's name), runs the chosen subcommand with its output on
/// std::cout and its messages on std::cerr, and returns the exit code of docs/cli.md. With
/// remove_partial_files_on_signals, SIGINT and SIGTERM outside a run's own handling remove the
/// temporaries of open output files (the program; an embedding interpreter keeps its handlers).
int run_newtop(int argc, char** argv, bool remove_partial_files_on_signals);

}  // namespace newtop::app
