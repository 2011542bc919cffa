// Writing an output file the way a careful command-line tool does: never a half-written file at
// the output's name, never a user's file clobbered by accident, and a reason when it fails.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace holefill {

// Puts `bytes` at `path`, so that a reader sees either the old file or the whole new one:
// - a regular file (or none yet) is written to a temporary file in the same folder, then renamed
//   over it; the temporary's name is unique, at most 255 bytes long, and the temporary is removed
//   when the write fails (and on the signals remove_partial_files_on_signals names, once it was
//   called);
// - symbolic links are followed: the file they lead to is replaced and the links are kept;
// - an existing file keeps its permissions (and, where the process may, its owner);
// - a file with other hard links is rewritten in place, so that every name keeps seeing it (after
//   the bytes were written once to a temporary file, so that a full disk is found before the file
//   is touched);
// - an existing file that is not regular (a pipe, a terminal) is written directly;
// - a name of one of the process's open descriptors (/dev/stdout, /dev/stderr, /dev/fd/N,
//   /proc/self/fd/N, or a link to one) is written through that descriptor, where it stands, as
//   `-` would be: the file behind it (stdout redirected to a file) keeps what was written before
//   (renaming over it lost that, and reopening it would write from its start). The C and C++
//   standard streams are flushed first.
// Throws FileError naming `path` and why: the system's reason (no space left on device, read-only
// file system, permission denied, name too long), a missing folder, a read-only file, a
// directory, a loop of symbolic links. Nothing at `path` changes then, except a non-regular file
// that was partly written.
void write_output_file(const std::filesystem::path& path, std::string_view bytes);

// Hands a file's bytes on, one piece at a time, in order.
using ByteWriter = std::function<void(std::string_view)>;

// write_output_file with the bytes `produce` hands to the ByteWriter it is given, piece by piece,
// so that a big file never exists whole in memory. `produce` may be called twice (a file with
// other hard links is first written to a temporary file) and must give the same bytes each time.
// What it throws passes through; nothing at `path` has changed then, except a non-regular file
// that was partly written (or, should the second call of a rewrite in place throw, that file).
void write_output_file(const std::filesystem::path& path,
                       const std::function<void(const ByteWriter&)>& produce);

// Checks before any work that write_output_file(path, ...) can succeed, as far as can be known
// without writing the bytes: the folder exists and accepts a new file, and `path` is not a
// directory, a read-only file or a loop of symbolic links. Throws FileError as write_output_file
// does; changes nothing.
void check_output_file(const std::filesystem::path& path);

// Whether `a` and `b` name the same file, through symbolic and hard links: the same device and
// inode where both exist, the same resolved location where neither does. Never throws.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// Installs handlers for SIGINT, SIGTERM, SIGHUP, SIGQUIT and SIGALRM that remove the temporary
// files that write_output_file is writing, then end the process as the signal would have. Signals
// the process ignores stay ignored. SIGXFSZ is ignored, so that a write past the file-size limit
// fails as an error of that file ("File too large") instead of ending the process. For programs:
// a library should not take its host's signals.
void remove_partial_files_on_signals();

}  // namespace holefill
