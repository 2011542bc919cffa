#include "file_dialog.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <thread>

#include "holefill/io.h"

namespace holefill::viewer {
namespace {

namespace fs = std::filesystem;

bool has(const std::vector<std::string>& command, const std::string& arg) {
  return std::find(command.begin(), command.end(), arg) != command.end();
}

TEST(FileDialog, ZenitySaveConfirmsOverwritingAndProposesTheSuggestedFile) {
  const auto command = native_dialog_command(
      {FileDialogRequest::Kind::Save, "/data/scans/bunny-filled.obj"}, "zenity");
  EXPECT_EQ(command[0], "zenity");
  EXPECT_TRUE(has(command, "--save"));
  EXPECT_TRUE(has(command, "--confirm-overwrite"));
  EXPECT_TRUE(has(command, "--filename=/data/scans/bunny-filled.obj"));
  const auto filter = std::find_if(command.begin(), command.end(), [](const std::string& arg) {
    return arg.starts_with("--file-filter=Meshes");
  });
  ASSERT_NE(filter, command.end());
  for (const auto& extension : writable_extensions())
    EXPECT_NE(filter->find("*" + extension), std::string::npos) << *filter;
}

TEST(FileDialog, ZenityOpenStartsInTheFolder) {
  const auto command =
      native_dialog_command({FileDialogRequest::Kind::Open, "/data/scans"}, "zenity");
  EXPECT_FALSE(has(command, "--save"));
  EXPECT_TRUE(has(command, "--filename=/data/scans/"));
}

TEST(FileDialog, KdialogGetsItsOwnVerbs) {
  const auto save =
      native_dialog_command({FileDialogRequest::Kind::Save, "/tmp/a-filled.ply"}, "kdialog");
  EXPECT_EQ(save[1], "--getsavefilename");
  EXPECT_EQ(save[2], "/tmp/a-filled.ply");
  const auto open = native_dialog_command({FileDialogRequest::Kind::Open, "/tmp"}, "kdialog");
  EXPECT_EQ(open[1], "--getopenfilename");
}

TEST(FileDialog, ReadsTheChosenPathFromTheProgramsOutput) {
  const auto chosen = run_native_dialog({"sh", "-c", "echo /tmp/chosen.obj"});
  EXPECT_TRUE(chosen.ran);
  ASSERT_TRUE(chosen.chosen);
  EXPECT_EQ(*chosen.chosen, fs::path("/tmp/chosen.obj"));

  const auto cancelled = run_native_dialog({"sh", "-c", "exit 1"});
  EXPECT_TRUE(cancelled.ran);
  EXPECT_FALSE(cancelled.chosen);

  EXPECT_FALSE(run_native_dialog({"sh", "-c", "exit 255"}).ran);
  EXPECT_FALSE(run_native_dialog({"holefill-no-such-dialog-program"}).ran);
}

TEST(FileDialog, ANativeDialogRunsBesideTheCallerAndAnswersOnce) {
  NativeDialog dialog;
  dialog.start({"sh", "-c", "sleep 0.2; echo /tmp/later.off"});
  EXPECT_TRUE(dialog.running());
  EXPECT_FALSE(dialog.poll());  // still open: the caller keeps drawing
  std::optional<NativeDialogResult> answer;
  while (!(answer = dialog.poll())) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(answer->chosen, fs::path("/tmp/later.off"));
  EXPECT_FALSE(dialog.running());
  EXPECT_FALSE(dialog.poll());
}

TEST(FileDialog, BuiltinChoiceTurnsTheNativeDialogOff) {
  setenv("HOLEFILL_FILE_DIALOG", "builtin", 1);
  EXPECT_EQ(find_native_dialog_program(), "");
  unsetenv("HOLEFILL_FILE_DIALOG");
}

TEST(FileDialog, FolderListingShowsFoldersThenMeshesSorted) {
  const fs::path folder = fs::temp_directory_path() / "holefill-folder-listing";
  fs::remove_all(folder);
  fs::create_directories(folder / "b-folder");
  fs::create_directories(folder / "a-folder");
  fs::create_directories(folder / ".hidden");
  for (const char* name : {"z.obj", "a.PLY", "notes.txt", ".x.obj"})
    std::ofstream(folder / name) << "x";
  const auto entries = list_folder(folder, {".obj", ".ply"});
  fs::remove_all(folder);
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_EQ(entries[0].name, "a-folder");
  EXPECT_TRUE(entries[0].folder);
  EXPECT_EQ(entries[1].name, "b-folder");
  EXPECT_EQ(entries[2].name, "a.PLY");
  EXPECT_FALSE(entries[2].folder);
  EXPECT_EQ(entries[3].name, "z.obj");
  EXPECT_TRUE(list_folder(folder / "gone", {".obj"}).empty());
}

}  // namespace
}  // namespace holefill::viewer
