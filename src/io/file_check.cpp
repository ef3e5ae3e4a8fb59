#include "file_check.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "newtop/core/types.hpp"

namespace newtop::io {
namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& what, const std::string& why) {
  throw InputError(path + ": " + what + ": " + why);
}

std::string stat_problem(const struct stat& st, std::uintmax_t max_bytes) {
  if (!S_ISREG(st.st_mode))
    return std::string("expected a regular file, found ") + file_kind(st.st_mode);
  if (st.st_size < 0 || static_cast<std::uintmax_t>(st.st_size) > max_bytes) {
    return "expected at most " + std::to_string(max_bytes) + " bytes, found " +
           std::to_string(st.st_size);
  }
  return {};
}

std::string errno_text(int err) {
  return err == ENOENT ? "no such file" : err == EACCES ? "permission denied" : std::strerror(err);
}

}  // namespace

const char* file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string regular_file_problem(const std::string& path, std::uintmax_t max_bytes) {
  if (path.empty()) return "expected a file name, found an empty string";
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return "cannot read it: " + errno_text(errno);
  return stat_problem(st, max_bytes);
}

std::string read_regular_file(const std::string& path, std::uintmax_t max_bytes,
                              const std::string& what) {
  if (path.empty()) throw InputError(what + ": expected a file name, found an empty string");
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) refuse(path, what, "cannot read it: " + errno_text(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) refuse(path, what, "cannot read it: " + errno_text(errno));
  if (const std::string why = stat_problem(st, max_bytes); !why.empty()) refuse(path, what, why);
  std::string bytes;
  bytes.resize(static_cast<std::size_t>(st.st_size));
  std::size_t got = 0;
  // Read to the end, but never more than max_bytes + 1 (a file growing meanwhile).
  for (;;) {
    if (got == bytes.size()) {
      if (bytes.size() > max_bytes) break;
      bytes.resize(std::min<std::size_t>(bytes.size() + 4096, max_bytes + 1));
    }
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) refuse(path, what, "cannot read it: " + errno_text(errno));
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  if (got > max_bytes) {
    refuse(path, what, "expected at most " + std::to_string(max_bytes) + " bytes, found more");
  }
  bytes.resize(got);
  return bytes;
}

}  // namespace newtop::io
