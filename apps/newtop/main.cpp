// newtop: the command-line program (apps/newtop/cli.cpp parses and dispatches).

#include "cli.hpp"

int main(int argc, char** argv) { return newtop::app::run_newtop(argc, argv, true); }
