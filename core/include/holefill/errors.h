// The project's exception hierarchy, thrown at the I/O boundary (the pipeline itself returns
// results that say why a hole was not filled, rather than throwing).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace holefill {

// Base of every error holefill throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file could not be read or written: missing, unreadable, wrong format, broken contents.
class FileError : public Error {
 public:
  FileError(const std::filesystem::path& path, const std::string& reason)
      : Error(path.string() + ": " + reason), path_(path), reason_(reason) {}
  const std::filesystem::path& path() const { return path_; }
  const std::string& reason() const { return reason_; }

 private:
  std::filesystem::path path_;
  std::string reason_;
};

// A file was read but its mesh is unusable (no faces, non-finite coordinates, ...).
class InvalidMeshError : public FileError {
 public:
  using FileError::FileError;
};

}  // namespace holefill
