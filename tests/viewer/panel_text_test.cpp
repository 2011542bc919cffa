// What the panel says without drawing it: the status bar's history, the reasons greyed-out
// buttons give, and the messages that replace a stale one (issue 31).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "disabled_reasons.h"
#include "file_actions.h"
#include "notice_log.h"
#include "test_sessions.h"

namespace holefill::viewer {
namespace {

TEST(NoticeLog, KeepsEachNewMessageOnceOldestFirstUpToTheLimit) {
  NoticeLog log;
  log.observe({"Opened bunny.obj", false});
  log.observe({"Opened bunny.obj", false});  // the same message, frame after frame
  log.observe({});                           // cleared: nothing to add
  log.observe({"Could not save x", true});
  log.observe({"Opened bunny.obj", false});  // shown again later: a new entry
  ASSERT_EQ(log.entries().size(), 3u);
  EXPECT_EQ(log.entries()[0].text, "Opened bunny.obj");
  EXPECT_TRUE(log.entries()[1].error);
  EXPECT_EQ(log.entries()[2].text, "Opened bunny.obj");
  for (std::size_t i = 0; i < NoticeLog::kLimit + 5; ++i)
    log.observe({"message " + std::to_string(i), false});
  EXPECT_EQ(log.entries().size(), NoticeLog::kLimit);
  EXPECT_EQ(log.entries().back().text, "message " + std::to_string(NoticeLog::kLimit + 4));
}

TEST(DisabledReasons, EachGreyedButtonSaysWhy) {
  Session session = bunny_session();
  EXPECT_NE(why_not_step(session, Stage::Triangulated).find("Select a hole first"),
            std::string::npos);
  EXPECT_EQ(why_not_undo(session), "Nothing to undo");
  EXPECT_EQ(why_not_redo(session), "Nothing to redo");
  EXPECT_EQ(why_not_fill_all(session, 0), "");
  session.select(1);
  EXPECT_EQ(why_not_step(session, Stage::Triangulated), "");
  EXPECT_EQ(why_not_step(session, Stage::Refined),
            "Run the stages in order: triangulated comes first");
  EXPECT_EQ(why_not_reset(session), "Hole 1 has no patch to take out");
  EXPECT_EQ(why_not_fill_selected(session), "");
  ASSERT_TRUE(session.fill_selected());
  EXPECT_EQ(why_not_step(session, Stage::Refined), "Hole 1 is filled: every stage has run");
  EXPECT_EQ(why_not_fill_selected(session), "Hole 1 is filled: every stage has run");
  EXPECT_EQ(why_not_reset(session), "");
  EXPECT_EQ(why_not_undo(session), "");
  // The bunny's three holes are all small: none is left under 10 edges.
  EXPECT_EQ(why_not_fill_all(session, 10),
            "No open hole of at most 10 edges is left (borders of open surfaces are filled one by "
            "one)");
}

// After Undo, "Filled 3 of 3 holes." no longer holds: the status bar says what happened.
TEST(SessionNotice, UndoAndRedoReplaceTheFillsMessage) {
  Session session = bunny_session();
  ASSERT_TRUE(session.fill_all());
  EXPECT_NE(session.notice().text.find("Filled 3"), std::string::npos) << session.notice().text;
  ASSERT_TRUE(session.undo());
  EXPECT_EQ(session.notice().text, "Undone.");
  ASSERT_TRUE(session.redo());
  EXPECT_EQ(session.notice().text, "Redone.");
  session.select(0);
  ASSERT_TRUE(session.reset_selected());
  EXPECT_EQ(session.notice().text, "Took the patch of hole 0 out.");
}

}  // namespace
}  // namespace holefill::viewer

namespace holefill::viewer {
namespace {

// F12 numbers its screenshots instead of replacing the last one.
TEST(UnusedPath, NumbersAFileThatExistsAlready) {
  const auto folder = std::filesystem::temp_directory_path() / "holefill-unused-path-test";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const auto shot = folder / "shot.png";
  EXPECT_EQ(unused_path(shot), shot);
  std::ofstream(shot) << "1";
  EXPECT_EQ(unused_path(shot), folder / "shot-2.png");
  std::ofstream(folder / "shot-2.png") << "2";
  EXPECT_EQ(unused_path(shot), folder / "shot-3.png");
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace holefill::viewer
