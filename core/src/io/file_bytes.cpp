#include "file_bytes.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>

#include "huge_pages.h"
#include "text_scan.h"

namespace holefill::io {
namespace fs = std::filesystem;

namespace {

// The regular file at `path`, open for reading. Throws FileError when it is missing, a directory
// or another non-regular file, or cannot be opened.
std::FILE* open_regular_file(const fs::path& path) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  // Only a missing file is "no such file"; a link loop or a folder that cannot be searched says
  // why.
  if (ec && ec != std::errc::no_such_file_or_directory) {
    fail(path, "cannot be read (" + ec.message() + ")");
  }
  if (!fs::exists(status)) fail(path, "no such file");
  if (fs::is_directory(status)) fail(path, "is a directory, not a mesh file");
  if (!fs::is_regular_file(status)) fail(path, "is not a regular file");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) {
    fail(path, std::string("cannot be opened for reading (") + std::strerror(errno) + ")");
  }
  return file;
}

// Appends up to `limit` bytes of `file` to `bytes`, then closes it; throws FileError on a read
// error.
void read_and_close(std::FILE* file, std::uint64_t limit, std::string& bytes,
                    const fs::path& path) {
  char buffer[1 << 16];
  for (std::size_t got = 1; got > 0 && limit > 0; limit -= got) {
    got = std::fread(buffer, 1,
                     static_cast<std::size_t>(std::min<std::uint64_t>(sizeof buffer, limit)), file);
    bytes.append(buffer, got);
  }
  const bool failed = std::ferror(file) != 0;
  const int error = errno;
  std::fclose(file);
  if (failed) fail(path, std::string("could not be read (") + std::strerror(error) + ")");
}

}  // namespace

std::string read_file_bytes(const fs::path& path) {
  std::FILE* file = open_regular_file(path);
  std::string bytes;
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (!ec) {
    // On huge pages: a fault per 4 KB page of a big file's text was a large part of reading it.
    bytes.reserve(size);
    prefer_huge_pages(bytes.data(), size);
  }
  read_and_close(file, std::numeric_limits<std::uint64_t>::max(), bytes, path);
  return bytes;
}

FileStart read_file_start(const fs::path& path) {
  // 64 KiB, what telling the formats apart looks at, after a UTF-8 byte-order mark.
  constexpr std::uint64_t kFirstBytes = (1 << 16) + 3;
  std::FILE* file = open_regular_file(path);
  FileStart start;
  std::error_code ec;
  start.size = fs::file_size(path, ec);
  read_and_close(file, kFirstBytes, start.bytes, path);
  return start;
}

}  // namespace holefill::io
