#pragma once
// Shared pieces of the fuzz harnesses (tests/fuzz/fuzz_*.cpp). A harness feeds arbitrary bytes to
// one reader; the reader must return a result or throw InputError. Any other exception escapes the
// harness and aborts, so libFuzzer (and the corpus replay under ctest) reports it as a failure,
// exactly like a crash, a sanitizer report or a hang.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "newtop/core/types.hpp"

namespace newtop::fuzz {

/// The input as a string.
inline std::string bytes(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Runs f(); an InputError is the reader's legitimate answer to bad bytes and is swallowed.
template <class F>
void expect_result_or_input_error(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  }
}

/// Removes a folder, with everything in it, when destroyed (a static one: when the process exits).
struct FolderRemovedAtExit {
  std::filesystem::path dir;
  ~FolderRemovedAtExit() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

/// A file holding the input under a name with the given extension (readers choose the format by
/// it), unique per process so that parallel fuzzing jobs do not collide; removed when destroyed
/// (its folder too when empty).
class TempFile {
 public:
  TempFile(std::string_view contents, std::string_view extension, std::string_view stem = "input")
      : dir_(std::filesystem::temp_directory_path() /
             ("newtop_fuzz_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(dir_);
    path_ = dir_ / (std::string(stem) + std::string(extension));
    std::ofstream(path_, std::ios::binary)
        .write(contents.data(), static_cast<std::streamsize>(contents.size()));
  }
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
    std::filesystem::remove(dir_, ec);  // the folder too once no other TempFile holds a file in it
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path dir_;
  std::filesystem::path path_;
};

}  // namespace newtop::fuzz
