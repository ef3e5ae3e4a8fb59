// The command line run in-process: the per-subcommand functions of python/newtop/commands.py call
// it with --json and read the JSON the program would print, so that both give the same numbers.

#include <pybind11/stl.h>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "cli.hpp"

namespace py = pybind11;

namespace newtop::python {
namespace {

/// Sends std::cout and std::cerr to strings while it lives.
class CaptureStreams {
 public:
  CaptureStreams()
      : out_(std::cout.rdbuf(out_text.rdbuf())), err_(std::cerr.rdbuf(err_text.rdbuf())) {}
  ~CaptureStreams() {
    std::cout.rdbuf(out_);
    std::cerr.rdbuf(err_);
  }
  CaptureStreams(const CaptureStreams&) = delete;
  CaptureStreams& operator=(const CaptureStreams&) = delete;
  std::ostringstream out_text, err_text;

 private:
  std::streambuf* out_;
  std::streambuf* err_;
};

py::tuple run_command_line(const std::vector<std::string>& args) {
  std::vector<std::string> words{"newtop"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  int code = 0;
  std::string out, err;
  {
    CaptureStreams capture;
    code = app::run_newtop(static_cast<int>(words.size()), argv.data(), false);
    out = capture.out_text.str();
    err = capture.err_text.str();
  }
  return py::make_tuple(code, py::bytes(out), py::bytes(err));
}

}  // namespace

void bind_command_line(py::module_& m) {
  m.def("_run_command_line", &run_command_line, py::arg("args"),
        "Runs `newtop ARGS...` in this process; returns (exit code, stdout, stderr) as bytes.");
}

}  // namespace newtop::python
