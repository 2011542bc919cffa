#include "partial_file.h"

#include <fcntl.h>
#include <limits.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <random>

#include "holefill/errors.h"

namespace holefill::detail {
namespace {

// Paths the signal handlers remove. A handler may only use async-signal-safe calls, so the
// paths live in fixed buffers and are published with atomics: `claimed` reserves a slot,
// `ready` says its path is complete.
struct PendingSlot {
  std::atomic<bool> claimed{false};
  std::atomic<bool> ready{false};
  char path[PATH_MAX];
};
constexpr int kSlots = 16;
PendingSlot pending[kSlots];

int publish(const std::filesystem::path& path) {
  if (path.native().size() >= PATH_MAX) return -1;
  for (int i = 0; i < kSlots; ++i) {
    bool expected = false;
    if (pending[i].claimed.compare_exchange_strong(expected, true)) {
      std::memcpy(pending[i].path, path.c_str(), path.native().size() + 1);
      pending[i].ready.store(true);
      return i;
    }
  }
  return -1;  // more outputs at once than slots: this one is only removed on errors
}

void withdraw(int slot) {
  if (slot < 0) return;
  pending[slot].ready.store(false);
  pending[slot].claimed.store(false);
}

extern "C" void remove_pending_and_reraise(int signal) {
  for (auto& slot : pending) {
    if (slot.ready.load()) ::unlink(slot.path);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);  // delivered when this handler returns: the default action ends the process
}

std::string partial_name(const std::filesystem::path& output) {
  constexpr std::size_t kMaxName = 255;
  std::random_device random;
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, ".partial-%08x", static_cast<unsigned>(random()));
  std::string name = output.filename().string();
  name.resize(std::min(name.size(), kMaxName - 1 - std::strlen(suffix)));
  return "." + name + suffix;
}

}  // namespace

PartialFile::PartialFile(const std::filesystem::path& output, const std::filesystem::path& folder,
                         mode_t mode) {
  for (int attempt = 0; fd_ < 0; ++attempt) {
    path_ = folder / partial_name(output);
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (fd_ < 0 && (errno != EEXIST || attempt == 100)) {
      throw FileError(output, std::string("could not be written (") + std::strerror(errno) + ")");
    }
  }
  slot_ = publish(path_);
}

PartialFile::~PartialFile() {
  close();
  if (!path_.empty()) ::unlink(path_.c_str());
  withdraw(slot_);
}

int PartialFile::close() {
  if (fd_ < 0) return 0;
  const int result = ::close(fd_);
  fd_ = -1;
  return result == 0 ? 0 : errno;
}

void PartialFile::renamed() {
  withdraw(slot_);
  slot_ = -1;
  path_.clear();
}

int write_all(int fd, const char* bytes, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  return 0;
}

void install_partial_file_cleanup() {
  // A write past the file-size limit (ulimit -f) ended the process by SIGXFSZ, leaving the
  // temporary file; ignored, the write fails with EFBIG, an error of that file like any other.
  std::signal(SIGXFSZ, SIG_IGN);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM}) {
    struct sigaction previous {};
    ::sigaction(signal, nullptr, &previous);
    if (previous.sa_handler == SIG_IGN) continue;  // e.g. SIGHUP under nohup: stay ignored
    struct sigaction action {};
    action.sa_handler = remove_pending_and_reraise;
    sigemptyset(&action.sa_mask);
    ::sigaction(signal, &action, nullptr);
  }
}

}  // namespace holefill::detail
