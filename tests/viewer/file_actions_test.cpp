#include "file_actions.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "holefill/io.h"

namespace holefill::viewer {
namespace {

namespace fs = std::filesystem;
using Answer = FileActions::Answer;
using Question = FileActions::Question;

// A folder of its own per test with a copy of the bunny, removed afterwards.
class FileActionsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("holefill-file-actions-" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
    bunny_ = folder_ / "bunny.obj";
    fs::copy_file(fs::path(HOLEFILL_TEST_ASSETS) / "bunny.obj", bunny_);
    ASSERT_TRUE(actions_.open_now(bunny_)) << session_.notice().text;
    original_size_ = fs::file_size(bunny_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  void fill_a_hole() {
    session_.select(2);
    ASSERT_TRUE(session_.step(Stage::Triangulated));
  }

  Session session_;
  FileActions actions_{session_};
  fs::path folder_, bunny_;
  std::uintmax_t original_size_ = 0;
};

TEST_F(FileActionsTest, FirstSaveAsksWhereAndSuggestsTheFilledNameBesideTheMesh) {
  fill_a_hole();
  actions_.save();
  ASSERT_TRUE(actions_.dialog());
  EXPECT_EQ(actions_.dialog()->kind, FileDialogRequest::Kind::Save);
  EXPECT_EQ(actions_.dialog()->start, folder_ / "bunny-filled.obj");
  EXPECT_EQ(fs::file_size(bunny_), original_size_);  // nothing written before the answer
}

TEST_F(FileActionsTest, SaveAsWritesTheChosenFileAndLaterSavesGoThereWithoutAsking) {
  fill_a_hole();
  EXPECT_EQ(actions_.window_title(), "*bunny.obj - holefill viewer");
  actions_.save_as();
  const fs::path out = folder_ / "out.ply";
  actions_.dialog_closed(out, false);
  ASSERT_TRUE(fs::exists(out));
  EXPECT_FALSE(session_.modified());
  EXPECT_EQ(actions_.window_title(), "out.ply - holefill viewer");
  EXPECT_EQ(load_mesh(out).n_faces(), session_.mesh().n_faces());

  session_.select(1);
  ASSERT_TRUE(session_.step(Stage::Triangulated));
  actions_.save();
  EXPECT_FALSE(actions_.dialog());
  EXPECT_EQ(load_mesh(out).n_faces(), session_.mesh().n_faces());
  EXPECT_EQ(fs::file_size(bunny_), original_size_);
}

TEST_F(FileActionsTest, SaveAsOverAnExistingFileAsksAndCancelReturnsToTheDialog) {
  fill_a_hole();
  actions_.save_as();
  actions_.dialog_closed(bunny_, false);
  ASSERT_EQ(actions_.question(), Question::Overwrite);
  EXPECT_EQ(actions_.overwrite_path(), bunny_);
  actions_.answer(Answer::Cancel);
  EXPECT_EQ(fs::file_size(bunny_), original_size_);
  ASSERT_TRUE(actions_.dialog());
  EXPECT_EQ(actions_.dialog()->start, bunny_);

  actions_.dialog_closed(bunny_, false);
  actions_.answer(Answer::Save);
  EXPECT_NE(fs::file_size(bunny_), original_size_);
  EXPECT_FALSE(session_.modified());
}

TEST_F(FileActionsTest, ADialogThatConfirmedOverwritingIsNotAskedAgain) {
  fill_a_hole();
  actions_.save_as();
  actions_.dialog_closed(bunny_, true);
  EXPECT_EQ(actions_.question(), Question::None);
  EXPECT_NE(fs::file_size(bunny_), original_size_);
}

TEST_F(FileActionsTest, ANameWithoutExtensionGetsTheOpenedFormat) {
  fill_a_hole();
  actions_.save_as();
  actions_.dialog_closed(folder_ / "result", false);
  EXPECT_TRUE(fs::exists(folder_ / "result.obj"));
}

TEST_F(FileActionsTest, QuitWithoutChangesQuitsAtOnce) {
  actions_.quit();
  EXPECT_TRUE(actions_.quitting());
  EXPECT_EQ(actions_.question(), Question::None);
}

TEST_F(FileActionsTest, QuitWithUnsavedFillsAsksAndCancelKeepsWorking) {
  fill_a_hole();
  actions_.quit();
  EXPECT_FALSE(actions_.quitting());
  ASSERT_EQ(actions_.question(), Question::SaveChanges);
  actions_.answer(Answer::Cancel);
  EXPECT_FALSE(actions_.quitting());
  EXPECT_TRUE(session_.modified());

  actions_.quit();
  actions_.answer(Answer::Discard);
  EXPECT_TRUE(actions_.quitting());
}

// A close request while the Save dialog or the overwrite question shows is not ignored.
TEST_F(FileActionsTest, QuitWhileADialogShowsDismissesItAndAsksOrQuits) {
  actions_.save_as();
  ASSERT_TRUE(actions_.dialog());
  actions_.quit();
  EXPECT_FALSE(actions_.dialog());
  EXPECT_TRUE(actions_.quitting());  // nothing unsaved

  FileActions again(session_);
  fill_a_hole();
  again.save_as();
  again.dialog_closed(bunny_, false);  // exists: asks first
  ASSERT_EQ(again.question(), Question::Overwrite);
  again.quit();
  EXPECT_EQ(again.question(), Question::SaveChanges);
  EXPECT_FALSE(again.quitting());
  again.answer(Answer::Discard);
  EXPECT_TRUE(again.quitting());
  EXPECT_EQ(fs::file_size(bunny_), original_size_);  // the overwrite never happened
}

TEST_F(FileActionsTest, QuitThenSaveQuitsOnlyOnceTheFileIsWritten) {
  fill_a_hole();
  actions_.quit();
  actions_.answer(Answer::Save);
  ASSERT_TRUE(actions_.dialog());  // first save: where to?
  EXPECT_FALSE(actions_.quitting());
  actions_.dialog_closed(std::nullopt, false);  // cancelled: no quit either
  EXPECT_FALSE(actions_.quitting());

  actions_.quit();
  actions_.answer(Answer::Save);
  actions_.dialog_closed(folder_ / "kept.off", false);
  EXPECT_TRUE(fs::exists(folder_ / "kept.off"));
  EXPECT_TRUE(actions_.quitting());
}

TEST_F(FileActionsTest, AFailedSaveDoesNotQuit) {
  fill_a_hole();
  actions_.quit();
  actions_.answer(Answer::Save);
  actions_.dialog_closed(folder_ / "no-such-folder" / "x.obj", false);
  EXPECT_FALSE(actions_.quitting());
  EXPECT_TRUE(session_.notice().error);
  EXPECT_TRUE(session_.modified());
}

TEST_F(FileActionsTest, UndoingBackToTheSavedStateIsUnmodified) {
  fill_a_hole();
  EXPECT_TRUE(session_.modified());
  ASSERT_TRUE(session_.undo());
  EXPECT_FALSE(session_.modified());
  ASSERT_TRUE(session_.redo());
  EXPECT_TRUE(session_.modified());
}

TEST_F(FileActionsTest, DroppingAFileWithUnsavedFillsAsksFirstAndDiscardOpensIt) {
  fill_a_hole();
  const fs::path other = folder_ / "torus.obj";
  fs::copy_file(fs::path(HOLEFILL_TEST_ASSETS) / "torus.obj", other);
  actions_.open_file(other);
  EXPECT_EQ(session_.name(), "bunny.obj");
  ASSERT_EQ(actions_.question(), Question::SaveChanges);
  actions_.answer(Answer::Discard);
  EXPECT_EQ(session_.name(), "torus.obj");
  EXPECT_TRUE(actions_.take_mesh_opened());
  EXPECT_FALSE(actions_.take_mesh_opened());
  EXPECT_EQ(actions_.suggested_save_path(), folder_ / "torus-filled.obj");
}

TEST_F(FileActionsTest, OpeningAnotherMeshForgetsTheSaveTarget) {
  fill_a_hole();
  actions_.save_as();
  actions_.dialog_closed(folder_ / "first.obj", false);
  ASSERT_TRUE(actions_.save_target());
  const fs::path other = folder_ / "torus.obj";
  fs::copy_file(fs::path(HOLEFILL_TEST_ASSETS) / "torus.obj", other);
  actions_.open_file(other);
  EXPECT_FALSE(actions_.save_target());
  const auto first_size = fs::file_size(folder_ / "first.obj");
  session_.select(0);
  ASSERT_TRUE(session_.step(Stage::Triangulated));
  actions_.save();
  ASSERT_TRUE(actions_.dialog());  // asks again rather than writing the torus over first.obj
  EXPECT_EQ(fs::file_size(folder_ / "first.obj"), first_size);
}

TEST_F(FileActionsTest, AFailedOpenKeepsTheMeshAndWhereItSaves) {
  fill_a_hole();
  actions_.save_as();
  actions_.dialog_closed(folder_ / "first.obj", false);
  std::ofstream(folder_ / "garbage.obj") << "v 1 2\nf 1 2 x\n";
  actions_.open();
  ASSERT_TRUE(actions_.dialog());
  EXPECT_EQ(actions_.dialog()->kind, FileDialogRequest::Kind::Open);
  EXPECT_EQ(actions_.dialog()->start, folder_);
  actions_.dialog_closed(folder_ / "garbage.obj", false);
  EXPECT_TRUE(session_.notice().error);
  EXPECT_EQ(session_.name(), "bunny.obj");
  EXPECT_EQ(actions_.save_target(), folder_ / "first.obj");
}

// Open and Save As wait while a dialog shows (closing the window does not: see
// QuitWhileADialogShowsDismissesItAndAsksOrQuits).
TEST_F(FileActionsTest, RequestsWaitWhileADialogIsShowing) {
  actions_.save_as();
  actions_.open();
  actions_.open_file(folder_ / "other.obj");
  EXPECT_EQ(actions_.dialog()->kind, FileDialogRequest::Kind::Save);
  EXPECT_EQ(session_.name(), "bunny.obj");
}

}  // namespace
}  // namespace holefill::viewer
