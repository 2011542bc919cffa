// The idle window's frame pacing, the state report tests wait on, and the requests that wait
// for the worker instead of being lost (issue 31).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "background.h"
#include "frame_pacer.h"
#include "request_queue.h"
#include "state_report.h"
#include "test_sessions.h"

namespace holefill::viewer {
namespace {

TEST(FramePacer, DrawsAFewFramesAfterAnEventThenWaitsForTheNext) {
  FramePacer pacer;
  for (int i = 0; i < FramePacer::kSettleFrames; ++i) {
    EXPECT_EQ(pacer.wait_before_frame(false), 0.0) << "frame " << i;
    pacer.frame_drawn();
  }
  EXPECT_FALSE(pacer.wait_before_frame(false).has_value());  // idle: sleep until an event
  EXPECT_TRUE(pacer.idle(false));
  pacer.wake();
  EXPECT_EQ(pacer.wait_before_frame(false), 0.0);
}

TEST(FramePacer, KeepsDrawingWhileWorkRuns) {
  FramePacer pacer;
  for (int i = 0; i < FramePacer::kSettleFrames; ++i) pacer.frame_drawn();
  EXPECT_EQ(pacer.wait_before_frame(true), FramePacer::kBusySeconds);
  EXPECT_FALSE(pacer.idle(true));
  // A slow frame (a big mesh): the loop waits as long again, leaving the work half the time.
  pacer.frame_drawn(0.4);
  EXPECT_EQ(pacer.wait_before_frame(true), 0.4);
  EXPECT_FALSE(pacer.wait_before_frame(false).has_value());
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(StateReport, WritesTheStateWhenItChangesButNotForFramesAlone) {
  const auto path = std::filesystem::temp_directory_path() / "holefill-state-report-test";
  std::filesystem::remove(path);
  StateReport report(path);
  ViewerState state;
  state.frames = 3;
  state.keys = 2;
  state.idle = true;
  state.question = "save-changes";
  state.title = "*bunny.obj - holefill viewer";
  state.notice = "Opened bunny.obj\nStitched 2 boundary edges";
  report.update(state);
  EXPECT_EQ(
      read(path),
      "frames 3\nkeys 2\ncloses 0\nidle 1\nbusy 0\nwaiting 0\nquestion save-changes\ndialog 0\n"
      "title *bunny.obj - holefill viewer\nnotice Opened bunny.obj\nphase \n");
  state.frames = 9;
  report.update(state);
  EXPECT_NE(read(path).find("frames 3\n"), std::string::npos);  // unchanged otherwise
  state.idle = false;
  report.update(state);
  EXPECT_NE(read(path).find("frames 9\nkeys 2\ncloses 0\nidle 0\n"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  std::filesystem::remove(path);
}

Request command(Command c) { return {c, {}}; }

TEST(RequestQueue, WhatChangesTheMeshWaitsForTheWorkerInOrder) {
  RequestQueue queue;
  EXPECT_FALSE(queue.defer(command(Command::Undo), false));  // idle: at once
  EXPECT_TRUE(queue.defer(command(Command::Undo), true));
  EXPECT_TRUE(queue.defer(command(Command::Save), true));
  EXPECT_FALSE(queue.defer(command(Command::Screenshot), true));  // never waits
  EXPECT_FALSE(queue.defer(command(Command::ZoomIn), true));
  EXPECT_TRUE(queue.defer({std::nullopt, "dropped.obj"}, true));
  // Once something waits, what follows waits behind it even when the worker is free.
  EXPECT_TRUE(queue.defer(command(Command::Redo), false));
  EXPECT_EQ(queue.size(), 4u);
  EXPECT_FALSE(queue.next(true));  // still busy
  EXPECT_EQ(queue.next(false)->command, Command::Undo);
  EXPECT_EQ(queue.next(false)->command, Command::Save);
  EXPECT_EQ(queue.next(false)->path, std::filesystem::path("dropped.obj"));
  EXPECT_EQ(queue.next(false)->command, Command::Redo);
  EXPECT_FALSE(queue.next(false));
  EXPECT_EQ(waiting_notice(command(Command::Undo)),
            "Waiting: undo (after the work in progress; Esc cancels)");
}

void wait_for(Worker& worker) {
  while (!worker.poll()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

// Two Ctrl+Z pressed while the first undo runs on the worker undo two steps.
TEST(RequestQueue, TwoQuickUndosUndoTwoSteps) {
  Session session = bunny_session();
  const Mesh original = session.mesh();
  session.select(0);
  ASSERT_TRUE(session.step(Stage::Triangulated));
  ASSERT_TRUE(session.step(Stage::Refined));
  Worker worker;
  RequestQueue queue;
  int undos = 0;
  for (int press = 0; press < 2; ++press) {
    if (!queue.defer(command(Command::Undo), worker.busy())) {
      ASSERT_TRUE(start_change(worker, session, session.undo_request()));
      ++undos;
    }
  }
  EXPECT_EQ(undos, 1);  // the second waits
  EXPECT_EQ(queue.size(), 1u);
  while (worker.busy() || !queue.empty()) {
    wait_for(worker);
    if (const auto request = queue.next(worker.busy())) {
      ASSERT_EQ(request->command, Command::Undo);
      ASSERT_TRUE(start_change(worker, session, session.undo_request()));
    }
  }
  EXPECT_FALSE(session.can_undo());
  EXPECT_FALSE(session.modified());
  EXPECT_TRUE(same_mesh(session.mesh(), original));
}

}  // namespace
}  // namespace holefill::viewer
