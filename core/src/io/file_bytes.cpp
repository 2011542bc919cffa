#include "file_bytes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>

#include "text_scan.h"

namespace holefill::io {
namespace fs = std::filesystem;

std::string read_file_bytes(const fs::path& path) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (!fs::exists(status)) fail(path, "no such file");
  if (fs::is_directory(status)) fail(path, "is a directory, not a mesh file");
  if (!fs::is_regular_file(status)) fail(path, "is not a regular file");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) {
    fail(path, std::string("cannot be opened for reading (") + std::strerror(errno) + ")");
  }
  std::string bytes;
  const auto size = fs::file_size(path, ec);
  if (!ec) bytes.reserve(size);
  char buffer[1 << 16];
  for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, file)) > 0;) {
    bytes.append(buffer, got);
  }
  const bool failed = std::ferror(file) != 0;
  const int error = errno;
  std::fclose(file);
  if (failed) fail(path, std::string("could not be read (") + std::strerror(error) + ")");
  return bytes;
}

void write_file_atomically(const fs::path& path, const std::string& bytes) {
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) fail(path, "folder does not exist");
  if (fs::is_directory(path, ec)) fail(path, "is a directory");
  std::random_device seed;
  std::string temp_name = path.stem().string();
  temp_name.insert(temp_name.begin(), '.');
  temp_name += ".partial-" + std::to_string(seed()) + path.extension().string();
  const fs::path temp = dir / temp_name;
  bool written = false;
  {
    std::ofstream out(temp, std::ios::binary);
    if (out) {
      out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      out.flush();
      written = static_cast<bool>(out);
    }
  }
  if (!written) {
    fs::remove(temp, ec);
    fail(path, "could not be written");
  }
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    fail(path, "could not be written (" + ec.message() + ")");
  }
}

}  // namespace holefill::io
