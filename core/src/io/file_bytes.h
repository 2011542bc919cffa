// Whole files in: the bytes a reader scans (outputs go through holefill/output_file.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace holefill::io {

// The whole contents of the regular file at `path`. Throws FileError when it is missing, a
// directory or another non-regular file, or cannot be opened or read (with the system's reason).
std::string read_file_bytes(const std::filesystem::path& path);

// The first bytes of a file (up to 64 KiB after a byte-order mark) and its size, to refuse what
// they rule out before the whole file is read. Throws FileError as read_file_bytes does.
struct FileStart {
  std::string bytes;
  std::uint64_t size = 0;
};
FileStart read_file_start(const std::filesystem::path& path);

}  // namespace holefill::io
