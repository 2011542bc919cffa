// The project's exception hierarchy, thrown at the I/O boundary and for broken preconditions (the
// pipeline itself returns results that say why a hole was not filled, rather than throwing).
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

// A Hole handed to the pipeline is not a boundary loop of the mesh: it was filled since it was
// found (a stale Hole), it was found on another mesh, or it was made by hand over edges that are
// not on a boundary. Nothing was changed; find_holes gives the mesh's loops as they are.
class InvalidHoleError : public Error {
 public:
  using Error::Error;
};

}  // namespace holefill
