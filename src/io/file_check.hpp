#pragma once
// Internal: files named by the user (scenario, potential file, files a scenario names) are
// checked before anything reads them: a regular file of bounded size, never a directory, a device
// (/dev/zero), a FIFO or a socket, on which a reader would fail late, read forever or block.

#include <sys/types.h>

#include <cstdint>
#include <string>

namespace newtop::io {

/// What a file of mode `mode` (from stat) is when it is not a regular file: "a directory",
/// "a character device", "a FIFO (named pipe)", …
const char* file_kind(mode_t mode);

/// Why `path` cannot be read as a regular file (after symbolic links) of at most `max_bytes`
/// bytes: "expected a regular file, found a directory", "cannot read it: no such file", …; empty
/// when it can.
std::string regular_file_problem(const std::string& path, std::uintmax_t max_bytes);

/// The bytes of a regular file of at most `max_bytes`, checked as above on the opened file itself
/// (opened without blocking, so a FIFO swapped in after a check cannot hang the program). Throws
/// InputError `PATH: WHAT: problem`; `what` names the file's role ("scenario file").
std::string read_regular_file(const std::string& path, std::uintmax_t max_bytes,
                              const std::string& what);

}  // namespace newtop::io
