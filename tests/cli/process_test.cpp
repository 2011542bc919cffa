// The holefill program itself, run as a process: what its main() adds to cli::run (a closed or
// full standard output is reported after the files are written, not a silent death or exit 0).
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include "cli_test_util.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "test_meshes.h"

extern char** environ;

namespace holefill {
namespace {
using namespace holefill::testing;

// Runs the holefill program with `args`, its standard output on `stdout_fd` and its standard
// error in `err_path`; returns the wait status.
int run_program(std::vector<std::string> args, int stdout_fd, const std::string& err_path) {
  args.insert(args.begin(), HOLEFILL_CLI_PATH);
  std::vector<char*> argv;
  for (auto& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, stdout_fd, 1);
  posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

// `holefill fill ... | head -1`: the table came before the save, SIGPIPE ended the run and no
// output was written. A mesh with hundreds of holes makes a table larger than stdio's buffer.
TEST_F(Cli, AClosedStandardOutputCostsNoOutputFile) {
  const std::string input = in_dir("holes.obj"), out = in_dir("out.obj"), err = in_dir("err");
  save_mesh(grid_with_square_holes(45), input);
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  ::close(ends[0]);  // the reader is gone, as `head` is after its line
  const int status = run_program(
      {"fill", input, "-o", out, "--stage", "triangulate", "--max-boundary", "4"}, ends[1], err);
  ::close(ends[1]);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), cli::kWriteFailed);
  EXPECT_NE(read_text(err).find("standard output could not be written (Broken pipe)"),
            std::string::npos)
      << read_text(err);
  EXPECT_TRUE(find_holes(load_mesh(out)).size() == 1u);  // only the grid's outer border is left
}

// `holefill info > /dev/full` exited 0.
TEST_F(Cli, AFullStandardOutputFailsTheRun) {
  const int full = ::open("/dev/full", O_WRONLY);
  ASSERT_GE(full, 0);
  const std::string err = in_dir("err");
  const int status = run_program({"info", (kAssets / "bunny.obj").string()}, full, err);
  ::close(full);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), cli::kWriteFailed);
  EXPECT_NE(read_text(err).find("No space left on device"), std::string::npos) << read_text(err);
}

}  // namespace
}  // namespace holefill
