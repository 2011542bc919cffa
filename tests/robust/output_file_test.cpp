// Writing outputs (holefill/output_file.h): links followed, modes kept, hard links kept together,
// read-only files refused, non-regular files written directly, the system's reason on failure,
// long names, and no temporary file left behind, even when a signal ends the process.
#include "holefill/output_file.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <thread>

#include "partial_file.h"
#include "robust_test_util.h"

namespace holefill {
namespace {
namespace fs = std::filesystem;
using testing::ScratchTest;

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::size_t files_in(const fs::path& dir) {
  return static_cast<std::size_t>(
      std::distance(fs::directory_iterator(dir), fs::directory_iterator{}));
}

std::string write_error(const fs::path& path, const std::string& bytes) {
  try {
    write_output_file(path, bytes);
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

using OutputFile = ScratchTest;

// Lowers the soft limit `resource` of this process (a death test's child) to `most`.
void limit(int resource, rlim_t most) {
  rlimit now{};
  ::getrlimit(resource, &now);
  now.rlim_cur = most;
  ::setrlimit(resource, &now);
}

// A symbolic link was replaced by a regular file (as root, --report /dev/stdout replaced the
// system's link).
TEST_F(OutputFile, WritesThroughSymbolicLinksAndKeepsThem) {
  const fs::path target = write("target.obj", "old");
  fs::create_symlink("target.obj", dir_ / "link.obj");
  fs::create_symlink(dir_ / "link.obj", dir_ / "link2.obj");
  write_output_file(dir_ / "link2.obj", "new");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.obj"));
  EXPECT_TRUE(fs::is_symlink(dir_ / "link2.obj"));
  EXPECT_EQ(contents(target), "new");
  EXPECT_EQ(files_in(dir_), 3u);
}

TEST_F(OutputFile, ADanglingLinkCreatesItsTarget) {
  fs::create_symlink("made.obj", dir_ / "link.obj");
  write_output_file(dir_ / "link.obj", "new");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.obj"));
  EXPECT_EQ(contents(dir_ / "made.obj"), "new");
}

// An existing 0600 file came back 0644.
TEST_F(OutputFile, KeepsTheFilesPermissions) {
  const fs::path file = write("private.obj", "old");
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);
  write_output_file(file, "new");
  EXPECT_EQ(fs::status(file).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(contents(file), "new");
}

TEST_F(OutputFile, ANewFileGetsTheUmasksPermissions) {
  const mode_t mask = ::umask(022);
  write_output_file(dir_ / "new.obj", "new");
  ::umask(mask);
  EXPECT_EQ(fs::status(dir_ / "new.obj").permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                fs::perms::others_read);
}

// A read-only file was overwritten (also as root, who may write anything).
TEST_F(OutputFile, RefusesAReadOnlyFile) {
  const fs::path file = write("locked.obj", "old");
  fs::permissions(file, fs::perms::owner_read | fs::perms::group_read);
  EXPECT_NE(write_error(file, "new").find("read-only"), std::string::npos);
  EXPECT_THROW(check_output_file(file), FileError);
  EXPECT_EQ(contents(file), "old");
  EXPECT_EQ(files_in(dir_), 1u);
}

// A hard link was split: the other name kept the old contents.
TEST_F(OutputFile, KeepsHardLinksTogether) {
  const fs::path file = write("a.obj", "the old, longer contents");
  fs::create_hard_link(file, dir_ / "b.obj");
  write_output_file(file, "new");
  EXPECT_EQ(contents(dir_ / "b.obj"), "new");
  EXPECT_EQ(fs::hard_link_count(file), 2u);
  EXPECT_EQ(files_in(dir_), 2u);
}

// A file made in pieces: every piece in order, to a new file, over an old one, to both names of a
// hard-linked file (made twice: a first time into a temporary, then in place, shortening it).
TEST_F(OutputFile, WritesWhatAProducerHandsOnPieceByPiece) {
  int calls = 0;
  auto produce = [&calls](const ByteWriter& write) {
    ++calls;
    for (int i = 0; i < 1000; ++i) write("piece " + std::to_string(i) + "\n");
  };
  std::string expected;
  for (int i = 0; i < 1000; ++i) expected += "piece " + std::to_string(i) + "\n";
  write_output_file(dir_ / "new.ply", produce);
  EXPECT_EQ(contents(dir_ / "new.ply"), expected);
  EXPECT_EQ(calls, 1);
  const fs::path file = write("a.ply", expected + "and a longer tail than the new file has");
  fs::create_hard_link(file, dir_ / "b.ply");
  write_output_file(file, produce);
  EXPECT_EQ(contents(dir_ / "b.ply"), expected);
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(files_in(dir_), 3u);
}

// A producer that fails half-way (out of memory, a bad value) leaves the old file as it was and
// no temporary behind; a full disk found in the middle is reported as for a whole buffer.
TEST_F(OutputFile, AProducerThatThrowsChangesNothing) {
  write("a.ply", "old");
  auto failing = [](const ByteWriter& write) {
    write("the first half");
    throw std::runtime_error("no more");
  };
  EXPECT_THROW(write_output_file(dir_ / "a.ply", failing), std::runtime_error);
  EXPECT_EQ(contents(dir_ / "a.ply"), "old");
  EXPECT_EQ(files_in(dir_), 1u);
  fs::create_symlink("/dev/full", dir_ / "full.ply");
  try {
    write_output_file(dir_ / "full.ply", [](const ByteWriter& write) {
      for (int i = 0; i < 100; ++i) write(std::string(100000, 'x'));
    });
    ADD_FAILURE() << "a full device took the bytes";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos);
  }
}

TEST_F(OutputFile, WritesAPipeDirectly) {
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink(fifo, dir_ / "pipe.obj");
  std::string received;
  std::thread reader([&] { received = contents(fifo); });
  check_output_file(dir_ / "pipe.obj");
  write_output_file(dir_ / "pipe.obj", "through the pipe");
  reader.join();
  EXPECT_EQ(received, "through the pipe");
  EXPECT_EQ(fs::status(fifo).type(), fs::file_type::fifo);
}

// /dev/stdout leads through /proc/self/fd/1 to "pipe:[N]", which is not a path to follow.
TEST_F(OutputFile, WritesThroughProcsDescriptorLinks) {
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  const fs::path descriptor = "/proc/self/fd/" + std::to_string(ends[1]);
  check_output_file(descriptor);
  write_output_file(descriptor, "to the pipe");
  ::close(ends[1]);
  char received[32] = {};
  EXPECT_EQ(::read(ends[0], received, sizeof received), 11);
  ::close(ends[0]);
  EXPECT_EQ(std::string(received), "to the pipe");
}

// With stdout redirected to a file, --report /dev/stdout renamed a new file over it: what was
// written to it before was lost (and reopening it by name would write from its start). Every name
// of an open descriptor writes through the descriptor, where it stands.
TEST_F(OutputFile, NamesOfAnOpenDescriptorWriteThroughItWhereItStands) {
  const fs::path file = dir_ / "redirected.txt";
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::write(fd, "before\n", 7), 7);
  const std::string number = std::to_string(fd);
  fs::create_symlink("/dev/fd/" + number, dir_ / "link");
  fs::create_symlink(dir_ / "link", dir_ / "link-to-link");
  std::string expected = "before\n";
  for (const fs::path& name :
       {fs::path("/proc/self/fd/" + number), fs::path("/dev/fd/" + number),
        fs::path("/proc/" + std::to_string(::getpid()) + "/fd/" + number), dir_ / "link-to-link"}) {
    SCOPED_TRACE(name.string());
    check_output_file(name);
    write_output_file(name, name.string() + "\n");
    expected += name.string() + "\n";
    EXPECT_EQ(contents(file), expected);
  }
  ::close(fd);
  // The links are kept and no temporary file was left.
  EXPECT_TRUE(fs::is_symlink(dir_ / "link"));
  EXPECT_EQ(files_in(dir_), 3u);
  // A closed descriptor's name is no descriptor: /proc says there is no such file.
  EXPECT_NE(write_error("/proc/self/fd/" + number, "x"), "");
}

// "could not be written" never said why.
TEST_F(OutputFile, SaysWhyItFailed) {
  fs::create_symlink("/dev/full", dir_ / "full.obj");
  EXPECT_NE(write_error(dir_ / "full.obj", "bytes").find("No space left on device"),
            std::string::npos);
  EXPECT_NE(write_error(dir_ / "no" / "x.obj", "bytes").find("folder does not exist"),
            std::string::npos);
  write("file", "");
  EXPECT_NE(write_error(dir_ / "file" / "x.obj", "bytes").find("Not a directory"),
            std::string::npos);
  fs::create_directory(dir_ / "dir.obj");
  EXPECT_NE(write_error(dir_ / "dir.obj", "bytes").find("directory"), std::string::npos);
  EXPECT_THROW(check_output_file(dir_ / "no" / "x.obj"), FileError);
}

TEST_F(OutputFile, ALoopOfLinksSaysSo) {
  fs::create_symlink("b.obj", dir_ / "a.obj");
  fs::create_symlink("a.obj", dir_ / "b.obj");
  EXPECT_NE(write_error(dir_ / "a.obj", "bytes").find("loop of symbolic links"), std::string::npos);
  EXPECT_THROW(check_output_file(dir_ / "a.obj"), FileError);
}

// Names of 236 to 255 bytes always failed: the temporary name went past 255.
TEST_F(OutputFile, NamesUpToTheSystemsLimitWork) {
  for (const std::size_t length : {236u, 250u, 255u}) {
    const fs::path file = dir_ / (std::string(length - 4, 'n') + ".obj");
    check_output_file(file);
    write_output_file(file, "long");
    EXPECT_EQ(contents(file), "long") << length;
  }
  EXPECT_NE(write_error(dir_ / (std::string(256, 'n')), "x").find("too long"), std::string::npos);
}

// The report's temporary had a fixed name (REPORT.partial): a user's file of that name was
// consumed.
TEST_F(OutputFile, LeavesOtherFilesAloneAndNoTemporaryBehind) {
  write("r.json.partial", "mine");
  write("r.json", "old");
  write_output_file(dir_ / "r.json", "new");
  EXPECT_EQ(contents(dir_ / "r.json.partial"), "mine");
  EXPECT_EQ(contents(dir_ / "r.json"), "new");
  EXPECT_EQ(files_in(dir_), 2u);
}

TEST_F(OutputFile, SameFileComparesIdentityNotText) {
  const fs::path file = write("m.obj", "x");
  fs::create_symlink("m.obj", dir_ / "link.obj");
  fs::create_hard_link(file, dir_ / "hard.obj");
  EXPECT_TRUE(same_file(file, dir_ / "link.obj"));
  EXPECT_TRUE(same_file(file, dir_ / "hard.obj"));
  EXPECT_TRUE(same_file(file, dir_ / "." / "m.obj"));
  EXPECT_TRUE(same_file(dir_ / "new.json", dir_ / "sub" / ".." / "new.json"));
  fs::create_symlink("later.json", dir_ / "dangling.json");
  EXPECT_TRUE(same_file(dir_ / "dangling.json", dir_ / "later.json"));
  EXPECT_FALSE(same_file(file, dir_ / "new.json"));
  EXPECT_FALSE(same_file(dir_ / "a.json", dir_ / "b.json"));
}

// Interrupted writes left `.OUT.partial-N.ext` files (26 MB in one test).
// SIGQUIT and SIGALRM left them too.
TEST_F(OutputFile, ASignalRemovesTheTemporaryFile) {
  for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM}) {
    EXPECT_EXIT(
        {
          limit(RLIMIT_CORE, 0);  // SIGQUIT's default action dumps core
          remove_partial_files_on_signals();
          detail::PartialFile partial(dir_ / "out.obj", dir_, 0666);
          if (!fs::exists(partial.path())) std::exit(1);
          std::raise(signal);
        },
        ::testing::KilledBySignal(signal), "");
    EXPECT_EQ(files_in(dir_), 0u) << signal;
  }
}

// A write past the file-size limit (ulimit -f) ended the process by SIGXFSZ and left the
// temporary file; now it is an error of that file, with the system's reason.
TEST_F(OutputFile, AFileSizeLimitIsAnErrorOfTheFileNotASignal) {
  EXPECT_EXIT(
      {
        remove_partial_files_on_signals();
        limit(RLIMIT_FSIZE, 1000);
        const std::string error = write_error(dir_ / "big.obj", std::string(5000, 'v'));
        std::exit(error.find("File too large") != std::string::npos && files_in(dir_) == 0 ? 4 : 1);
      },
      ::testing::ExitedWithCode(4), "");
  EXPECT_EQ(files_in(dir_), 0u);
}

}  // namespace
}  // namespace holefill
