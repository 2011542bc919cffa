// The temporary file an output is written to before it takes the output's name, removed when it
// is not renamed: on an error (the destructor) and on SIGINT, SIGTERM, SIGHUP, SIGQUIT or SIGALRM
// (the handlers of
// remove_partial_files_on_signals, which see every PartialFile alive).
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>

namespace holefill::detail {

class PartialFile {
 public:
  // Creates ".NAME.partial-XXXXXXXX" in `folder` (NAME shortened so that the whole name fits in
  // 255 bytes; X random, the file created exclusively) with permissions `mode` less the umask.
  // Throws FileError naming `output` with the system's reason when it cannot be created.
  PartialFile(const std::filesystem::path& output, const std::filesystem::path& folder,
              mode_t mode);
  ~PartialFile();  // closes the file and removes it unless it was renamed
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;

  int descriptor() const { return fd_; }
  const std::filesystem::path& path() const { return path_; }
  // Closes the file; returns 0 or the system's error number.
  int close();
  // The file has been renamed to the output: nothing to remove any more.
  void renamed();

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  int slot_ = -1;  // where the signal handlers find path_, or -1 when there was no free slot
};

// Writes all of `bytes` to `fd` (retrying short writes and interruptions); returns 0 or the
// system's error number.
int write_all(int fd, const char* bytes, std::size_t size);

// See remove_partial_files_on_signals in output_file.h.
void install_partial_file_cleanup();

}  // namespace holefill::detail
