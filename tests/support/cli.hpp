#pragma once
// Running the newtop program from the tests. NEWTOP_EXE and NEWTOP_SOURCE_DIR are compile
// definitions of every test target (tests/CMakeLists.txt).

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <string>

namespace newtop::test {

struct CliResult {
  int code;         ///< exit code, −1 if the program did not exit normally
  std::string out;  ///< standard output (with standard error too when merged)
  std::string err;  ///< standard error when kept separate
};

enum class Stderr { merged, separate };

/// Runs `newtop ARGS` through the shell and collects its output.
inline CliResult run_newtop(const std::string& args, Stderr stderr_mode = Stderr::merged) {
  static int counter = 0;
  const std::filesystem::path err_file =
      std::filesystem::temp_directory_path() /
      ("newtop_stderr_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  const std::string redirect = stderr_mode == Stderr::merged ? " 2>&1" : " 2>" + err_file.string();
  FILE* p = popen((std::string(NEWTOP_EXE) + " " + args + redirect).c_str(), "r");
  CliResult r{-1, "", ""};
  char buf[4096];
  while (const std::size_t n = std::fread(buf, 1, sizeof buf, p)) r.out.append(buf, n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (stderr_mode == Stderr::separate) {
    std::ifstream in(err_file);
    std::stringstream ss;
    ss << in.rdbuf();
    r.err = ss.str();
    std::error_code ec;
    std::filesystem::remove(err_file, ec);
  }
  return r;
}

namespace detail {
/// The scratch folders this process made: removed, with everything in them, when it exits (kept
/// when the environment sets NEWTOP_KEEP_SCRATCH, to look at after a failure).
class ScratchFolders {
 public:
  void add(const std::filesystem::path& dir) {
    const std::lock_guard<std::mutex> lock(mutex_);
    dirs_.insert(dir);
  }
  ~ScratchFolders() {
    if (std::getenv("NEWTOP_KEEP_SCRATCH") != nullptr) return;
    for (const auto& dir : dirs_) {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  }

 private:
  std::mutex mutex_;
  std::set<std::filesystem::path> dirs_;
};
inline ScratchFolders& scratch_folders() {
  static ScratchFolders folders;
  return folders;
}
}  // namespace detail

/// A scratch folder of this test process's own: `folder_PID` in the temporary directory, created
/// on first use, removed when the process exits (detail::ScratchFolders).
inline std::filesystem::path scratch_dir(const std::string& folder) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / (folder + "_" + std::to_string(::getpid()));
  detail::scratch_folders().add(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// `name` in the scratch folder `folder` of this test process (scratch_dir).
inline std::filesystem::path scratch_path(const std::string& folder, const std::string& name) {
  return scratch_dir(folder) / name;
}

/// Writes `text` to `path` and returns the path.
inline std::filesystem::path write_text(const std::filesystem::path& path,
                                        const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

/// The whole content of a file ("" if it cannot be read).
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Path of a bundled example scenario.
inline std::string example_path(const std::string& name) {
  return std::string(NEWTOP_SOURCE_DIR) + "/examples/" + name;
}

}  // namespace newtop::test
