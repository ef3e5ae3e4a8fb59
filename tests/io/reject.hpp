#pragma once
// Bad scenario files checked twice: through the library (parse_scenario throws InputError with the
// exact message) and through the program (`newtop SUBCOMMAND FILE` exits with code 2 and prints
// exactly that message on one line of stderr, nothing on stdout).

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "newtop/io/scenario.hpp"
#include "support/cli.hpp"

namespace newtop::io::test {

/// A file holding `bytes` exactly, in the test's scratch folder.
inline std::string write_file(const std::string& name, const std::string& bytes) {
  const std::string path = testing::TempDir() + "newtop_io_" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

/// The message for `bytes` read under the name "s.toml" is "s.toml" + `tail` (tail begins with
/// the position, e.g. ":3:8: [body] mass: …"), and the program says the same for the file.
inline void expect_rejected(const std::string& name, const std::string& bytes,
                            const std::string& tail, const std::string& subcommand = "integrals") {
  try {
    parse_scenario(bytes, "s.toml");
    ADD_FAILURE() << name << ": accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "s.toml" + tail) << name;
  }
  const std::string path = write_file(name + ".toml", bytes);
  const newtop::test::CliResult r =
      newtop::test::run_newtop(subcommand + " " + path, newtop::test::Stderr::separate);
  EXPECT_EQ(r.code, 2) << name;
  EXPECT_EQ(r.err, "newtop: error: " + path + tail + "\n") << name;
  EXPECT_EQ(r.out, "") << name;
}

}  // namespace newtop::io::test
