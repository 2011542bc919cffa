#include "holefill/output_file.h"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>

#include "holefill/errors.h"
#include "partial_file.h"

namespace holefill {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void fail(const fs::path& path, const std::string& reason) {
  throw FileError(path, reason);
}

[[noreturn]] void fail_with_errno(const fs::path& path, int error) {
  fail(path, std::string("could not be written (") + std::strerror(error) + ")");
}

// Where `path` leads once every symbolic link on it is followed (links to missing files lead to
// the missing file, which writing creates). Throws FileError on a loop.
fs::path resolve_links(const fs::path& path) {
  fs::path current = path;
  for (int hops = 0; hops <= 40; ++hops) {  // Linux's own limit is 40
    struct stat info {};
    if (::lstat(current.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return current;
    std::error_code ec;
    const fs::path target = fs::read_symlink(current, ec);
    if (ec) return current;  // unreadable link: open() will say why
    current = target.is_absolute() ? target : current.parent_path() / target;
  }
  fail(path, "could not be written (a loop of symbolic links)");
}

// A pipe, terminal or device, reached through any links, /proc's included (/dev/stdout leads to
// "pipe:[N]", which is no path): written directly, by its own name.
bool is_special_file(const fs::path& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode);
}

// N when `path` is /proc/PID/fd/N or /proc/PID/task/TID/fd/N of this process (PID its own,
// /proc/self and /proc/thread-self resolved to it); -1 otherwise.
int descriptor_number(const fs::path& path) {
  const std::string own = "/proc/" + std::to_string(::getpid()) + "/";
  const std::string text = path.native();
  if (text.rfind(own, 0) != 0) return -1;
  const std::size_t fd = text.rfind("/fd/");
  if (fd == std::string::npos) return -1;
  const std::string middle = text.substr(own.size() - 1, fd - own.size() + 1);
  const bool task = middle.rfind("/task/", 0) == 0 && middle.find('/', 6) == std::string::npos;
  if (!middle.empty() && !task) return -1;
  const std::string number = text.substr(fd + 4);
  if (number.empty() || number.size() > 9 ||
      number.find_first_not_of("0123456789") != std::string::npos) {
    return -1;
  }
  return std::stoi(number);
}

// The open descriptor of this process that `path` names, through any symbolic links (/dev/stdout
// leads to /proc/self/fd/1, /dev/fd is /proc/self/fd); -1 when it names none. Each link is
// looked at before it is followed: the link /proc/PID/fd/N leads to the file the descriptor has
// open, whose name is no longer the descriptor's.
int named_descriptor(const fs::path& path) {
  fs::path current = path;
  for (int hops = 0; hops <= 40; ++hops) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(current, ec);
    if (ec || !absolute.has_filename()) return -1;
    const fs::path folder = fs::canonical(absolute.parent_path(), ec);
    if (ec) return -1;
    const fs::path name = folder / absolute.filename();
    if (const int fd = descriptor_number(name); fd >= 0) {
      return ::fcntl(fd, F_GETFD) == -1 ? -1 : fd;
    }
    struct stat info {};
    if (::lstat(name.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return -1;
    const fs::path target = fs::read_symlink(name, ec);
    if (ec) return -1;
    current = target.is_absolute() ? target : folder / target;
  }
  return -1;
}

fs::path folder_of(const fs::path& file) {
  return file.has_parent_path() ? file.parent_path() : fs::path(".");
}

// The target's status when it exists; throws when it is a directory or read-only.
std::optional<struct stat> existing_target(const fs::path& path, const fs::path& target) {
  struct stat info {};
  if (::stat(target.c_str(), &info) != 0) {
    if (errno == ENOENT) return std::nullopt;
    fail_with_errno(path, errno);
  }
  if (S_ISDIR(info.st_mode)) fail(path, "could not be written (it is a directory)");
  const bool read_only = (info.st_mode & 0222) == 0 || ::access(target.c_str(), W_OK) != 0;
  if (S_ISREG(info.st_mode) && read_only) {
    fail(path, "could not be written (the file is read-only; holefill does not replace it)");
  }
  return info;
}

void check_name_length(const fs::path& path, const fs::path& target) {
  if (target.filename().native().size() > NAME_MAX) {
    fail(path, "could not be written (" + std::string(std::strerror(ENAMETOOLONG)) + ")");
  }
  struct stat folder {};
  if (::stat(folder_of(target).c_str(), &folder) != 0) {
    if (errno == ENOENT) fail(path, "could not be written (its folder does not exist)");
    fail_with_errno(path, errno);
  }
  if (!S_ISDIR(folder.st_mode)) fail_with_errno(path, ENOTDIR);
}

using Producer = std::function<void(const ByteWriter&)>;

// Writes what `produce` makes to `fd`, adding its size to `size`: 0, or the first error (errno),
// after which the rest is made but not written.
int write_produced(int fd, const Producer& produce, std::uint64_t& size) {
  int error = 0;
  produce([&](std::string_view piece) {
    if (error == 0) error = detail::write_all(fd, piece.data(), piece.size());
    size += piece.size();
  });
  return error;
}

// Opens `target` for writing in place; closes it when it goes, even when `produce` throws.
class OpenForWriting {
 public:
  OpenForWriting(const fs::path& path, const fs::path& target)
      : fd_(::open(target.c_str(), O_WRONLY | O_CLOEXEC)) {
    if (fd_ < 0) fail_with_errno(path, errno);
  }
  ~OpenForWriting() {
    if (fd_ >= 0) ::close(fd_);
  }
  OpenForWriting(const OpenForWriting&) = delete;
  OpenForWriting& operator=(const OpenForWriting&) = delete;
  int descriptor() const { return fd_; }
  // Closes the file: 0, or the error (errno).
  int close() {
    const int closed = ::close(fd_);
    fd_ = -1;
    return closed != 0 ? errno : 0;
  }

 private:
  int fd_;
};

void write_directly(const fs::path& path, const fs::path& target, const Producer& produce) {
  OpenForWriting file(path, target);
  std::uint64_t size = 0;
  int error = write_produced(file.descriptor(), produce, size);
  if (const int closed = file.close(); error == 0) error = closed;
  if (error != 0) fail_with_errno(path, error);
}

// Writes to the process's descriptor `fd` where it stands, after what the standard streams hold.
void write_to_descriptor(const fs::path& path, int fd, const Producer& produce) {
  std::cout.flush();
  std::cerr.flush();
  std::clog.flush();
  std::fflush(nullptr);
  std::uint64_t size = 0;
  if (const int error = write_produced(fd, produce, size); error != 0) {
    fail_with_errno(path, error);
  }
}

// Writes the bytes to a fresh temporary file beside `target`, complete and on disk.
void write_partial(detail::PartialFile& partial, const fs::path& path, const Producer& produce,
                   const std::optional<struct stat>& existing) {
  const int fd = partial.descriptor();
  std::uint64_t size = 0;
  int error = write_produced(fd, produce, size);
  if (error == 0 && existing) {
    if (::fchmod(fd, existing->st_mode & 07777) != 0) error = errno;
    if (::fchown(fd, existing->st_uid, existing->st_gid) != 0) {
    }  // only root may give files away
  }
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (const int closed = partial.close(); error == 0) error = closed;
  if (error != 0) fail_with_errno(path, error);
}

// A file with several names is rewritten where it is, once the bytes were shown to fit on disk.
void rewrite_in_place(const fs::path& path, const fs::path& target, const Producer& produce) {
  OpenForWriting file(path, target);
  const int fd = file.descriptor();
  std::uint64_t size = 0;
  int error = write_produced(fd, produce, size);
  if (error == 0 && ::ftruncate(fd, static_cast<off_t>(size)) != 0) error = errno;
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (const int closed = file.close(); error == 0) error = closed;
  if (error != 0) fail_with_errno(path, error);
}

}  // namespace

void write_output_file(const fs::path& path, std::string_view bytes) {
  write_output_file(path, [bytes](const ByteWriter& write) { write(bytes); });
}

void write_output_file(const fs::path& path, const Producer& produce) {
  if (const int fd = named_descriptor(path); fd >= 0) {
    return write_to_descriptor(path, fd, produce);
  }
  if (is_special_file(path)) return write_directly(path, path, produce);
  const fs::path target = resolve_links(path);
  const auto existing = existing_target(path, target);
  check_name_length(path, target);
  const bool has_other_names = existing && existing->st_nlink > 1;
  {
    detail::PartialFile partial(path, folder_of(target), 0666);
    write_partial(partial, path, produce, existing);
    if (!has_other_names) {
      if (::rename(partial.path().c_str(), target.c_str()) != 0) fail_with_errno(path, errno);
      partial.renamed();
      return;
    }
  }  // the temporary is removed: its space is free again for the rewrite
  rewrite_in_place(path, target, produce);
}

void check_output_file(const fs::path& path) {
  if (named_descriptor(path) >= 0 || is_special_file(path)) return;
  const fs::path target = resolve_links(path);
  existing_target(path, target);  // throws for a directory or a read-only file
  check_name_length(path, target);
  detail::PartialFile probe(path, folder_of(target), 0600);  // can the folder take a new file?
}

bool same_file(const fs::path& a, const fs::path& b) {
  struct stat first {
  }, second{};
  const bool a_exists = ::stat(a.c_str(), &first) == 0;
  const bool b_exists = ::stat(b.c_str(), &second) == 0;
  if (a_exists && b_exists) return first.st_dev == second.st_dev && first.st_ino == second.st_ino;
  if (a_exists || b_exists) return false;
  try {
    std::error_code ec_a, ec_b;
    const fs::path resolved_a = fs::weakly_canonical(fs::absolute(resolve_links(a)), ec_a);
    const fs::path resolved_b = fs::weakly_canonical(fs::absolute(resolve_links(b)), ec_b);
    return !ec_a && !ec_b && resolved_a == resolved_b;
  } catch (const std::exception&) {
    return false;  // a loop of links or an unreadable path: neither can be written anyway
  }
}

void remove_partial_files_on_signals() { detail::install_partial_file_cleanup(); }

}  // namespace holefill
