#include "worker.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "background.h"
#include "test_sessions.h"

namespace holefill::viewer {
namespace {

const std::filesystem::path kAssets(HOLEFILL_TEST_ASSETS);

// Polls until the job has ended, as the frame loop does.
void wait(Worker& worker) {
  while (!worker.poll()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  EXPECT_FALSE(worker.busy());
}

TEST(Worker, TheFinishingStepRunsOnThePollingThread) {
  Worker worker;
  std::thread::id finished_on;
  ASSERT_TRUE(worker.start("job", [&](Progress& progress) -> Worker::Finish {
    progress.set_fraction(1.0);
    return [&] { finished_on = std::this_thread::get_id(); };
  }));
  EXPECT_TRUE(worker.busy());
  EXPECT_FALSE(worker.start("second", [](Progress&) { return Worker::Finish{}; }));
  wait(worker);
  EXPECT_EQ(finished_on, std::this_thread::get_id());
  EXPECT_DOUBLE_EQ(worker.fraction(), 1.0);
}

TEST(Worker, TellsThePhaseTheJobIsIn) {
  Worker worker;
  EXPECT_EQ(worker.phase(), "");
  std::atomic<bool> entered{false}, leave{false};
  ASSERT_TRUE(worker.start("job", [&](Progress& progress) -> Worker::Finish {
    progress.enter_phase(phase::kFactorising);
    entered = true;
    while (!leave) std::this_thread::yield();
    return {};
  }));
  while (!entered) std::this_thread::yield();
  EXPECT_EQ(worker.phase(), phase::kFactorising);
  leave = true;
  wait(worker);
  ASSERT_TRUE(worker.start("next", [](Progress&) { return Worker::Finish{}; }));
  EXPECT_EQ(worker.phase(), "");  // a new job starts in none
  wait(worker);
}

TEST(Worker, CancelDropsTheResult) {
  Worker worker;
  bool finished = false;
  worker.start("until cancelled", [&](Progress& progress) -> Worker::Finish {
    while (!progress.cancelled()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return [&] { finished = true; };
  });
  worker.cancel();
  EXPECT_TRUE(worker.busy() || !finished);
  wait(worker);
  EXPECT_FALSE(finished);
}

TEST(Worker, ACancelledJobSetAsideFreesTheWorkerAtOnce) {
  std::atomic<bool> release{false};
  bool finished = false;
  {
    Worker worker;
    // The job does not look at its Progress: only setting it aside frees the worker.
    ASSERT_TRUE(worker.start(
        "reading",
        [&](Progress&) -> Worker::Finish {
          while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
          return [&] { finished = true; };
        },
        Worker::OnCancel::SetAside));
    worker.cancel();
    EXPECT_FALSE(worker.busy());
    EXPECT_TRUE(worker.cancelling());
    EXPECT_TRUE(worker.poll());  // the end is reported once
    EXPECT_FALSE(worker.cancelling());
    EXPECT_TRUE(worker.cancelled());
    EXPECT_FALSE(worker.poll());
    bool second = false;
    ASSERT_TRUE(
        worker.start("next", [&](Progress&) -> Worker::Finish { return [&] { second = true; }; }));
    wait(worker);
    EXPECT_TRUE(second);
    release = true;
  }  // the destructor waits for the job set aside
  EXPECT_FALSE(finished);
}

TEST(Worker, EachJobsEndIsAnnouncedOnItsThread) {
  Worker worker;
  std::atomic<int> ended{0};
  worker.set_on_done([&] { ++ended; });
  worker.start("one", [](Progress&) { return Worker::Finish{}; });
  wait(worker);
  EXPECT_EQ(ended, 1);
  worker.start("two", [](Progress&) { return Worker::Finish{}; });
  wait(worker);
  EXPECT_EQ(ended, 2);
}

TEST(Background, ACancelledOpenLeavesTheSessionAlone) {
  Session session;
  ASSERT_TRUE(session.open(kAssets / "bunny.obj"));
  const std::size_t faces = session.mesh().n_faces();
  Session opened;
  Progress progress;
  progress.cancel();
  EXPECT_FALSE(opened.open(kAssets / "bunny.obj", &progress));
  EXPECT_EQ(opened.mesh().n_faces(), 0u);
  EXPECT_EQ(session.mesh().n_faces(), faces);
}

TEST(Worker, AnExceptionBecomesTheError) {
  Worker worker;
  worker.start("throws", [](Progress&) -> Worker::Finish { throw std::runtime_error("boom"); });
  wait(worker);
  EXPECT_EQ(worker.error(), "boom");
}

TEST(Background, FillAllOnTheWorkerMakesTheSameMeshAsInline) {
  Session inline_session, background_session;
  ASSERT_TRUE(inline_session.open(kAssets / "bunny.obj"));
  ASSERT_TRUE(background_session.open(kAssets / "bunny.obj"));
  inline_session.fill_all();
  Worker worker;
  ASSERT_TRUE(start_fill(worker, background_session, background_session.fill_all_request()));
  wait(worker);
  EXPECT_TRUE(same_mesh(inline_session.mesh(), background_session.mesh()));
  EXPECT_TRUE(background_session.modified());
  EXPECT_EQ(background_session.notice().text, "Filled 3 of 3 holes.");
  ASSERT_TRUE(background_session.undo());
  EXPECT_EQ(background_session.mesh().n_faces(), 3130u);
}

TEST(Background, ACancelledFillLeavesTheSessionExactlyAsItWas) {
  Session session;
  ASSERT_TRUE(session.open(kAssets / "bunny.obj"));
  session.select(2);
  ASSERT_TRUE(session.step(Stage::Triangulated));
  const Mesh before = session.mesh();
  const auto log_size = session.log().size();
  const std::uint64_t version = session.mesh_version();
  Worker worker;
  ASSERT_TRUE(start_fill(worker, session, session.fill_all_request()));
  worker.cancel();
  wait(worker);
  EXPECT_TRUE(same_mesh(before, session.mesh()));
  EXPECT_EQ(session.log().size(), log_size);
  EXPECT_EQ(session.mesh_version(), version);
  EXPECT_EQ(session.fill(0).stage(), Stage::Original);
  ASSERT_TRUE(session.undo());  // the history is the one before the cancelled fill
  EXPECT_FALSE(session.modified());
}

TEST(Background, ComputeStopsBetweenHolesWhenCancelled) {
  Session session;
  ASSERT_TRUE(session.open(kAssets / "bunny.obj"));
  const auto request = session.fill_all_request();
  ASSERT_TRUE(request);
  int reports = 0;
  Progress progress([&](double) {
    ++reports;
    progress.cancel();
  });
  EXPECT_FALSE(session.compute(*request, &progress));
  EXPECT_EQ(reports, 1);  // stopped after the first hole
  EXPECT_EQ(session.fill(0).stage(), Stage::Original);
  EXPECT_FALSE(session.modified());
}

TEST(Background, FillAllUpToNEdgesLeavesTheLargerHoles) {
  Session session;
  ASSERT_TRUE(session.open(kAssets / "bunny.obj"));  // holes of 99, 37 and 28 edges
  ASSERT_TRUE(session.fill_all(40));
  EXPECT_EQ(session.fill(0).stage(), Stage::Original);
  EXPECT_EQ(session.fill(1).stage(), Stage::Smoothed);
  EXPECT_EQ(session.fill(2).stage(), Stage::Smoothed);
  EXPECT_EQ(session.notice().text, "Filled 2 of 2 holes.");
  EXPECT_FALSE(session.fill_all_request(20));
}

TEST(Background, UndoAndOptionsRunOnTheWorkerAndCancelLeavesTheSession) {
  Session session;
  ASSERT_TRUE(session.open(kAssets / "bunny.obj"));
  session.select(0);
  ASSERT_TRUE(session.fill_selected());
  const Mesh filled = session.mesh();
  Worker worker;
  FillOptions options = session.options();
  options.refine.tau = 1.1;
  ASSERT_TRUE(start_options(worker, session, options));
  EXPECT_NE(session.options().refine.tau, 1.1);  // until the frame loop polls
  wait(worker);
  EXPECT_EQ(session.options().refine.tau, 1.1);
  EXPECT_NE(session.mesh().n_faces(), filled.n_faces());  // a sparser patch

  ASSERT_TRUE(start_change(worker, session, session.undo_request()));
  worker.cancel();
  wait(worker);
  EXPECT_EQ(session.options().refine.tau, 1.1);
  EXPECT_FALSE(session.can_redo());
  ASSERT_TRUE(start_change(worker, session, session.undo_request()));
  wait(worker);
  EXPECT_TRUE(same_mesh(session.mesh(), filled));
  EXPECT_TRUE(session.can_redo());
}

TEST(Background, OptionsWithNothingToRerunApplyAtOnce) {
  Session session;
  ASSERT_TRUE(session.open(kAssets / "bunny.obj"));
  Worker worker;
  FillOptions options = session.options();
  options.smooth.iterations = 4;
  ASSERT_TRUE(start_options(worker, session, options));
  EXPECT_FALSE(worker.busy());
  EXPECT_EQ(session.options().smooth.iterations, 4);
}

TEST(Background, TheComparisonIsMadeOnTheWorkerAndAChangeMeanwhileAsksAgain) {
  Session session = bunny_session();
  session.select(0);
  session.set_compare(true);
  EXPECT_EQ(session.shown_comparison(), nullptr);
  Worker worker;
  ASSERT_TRUE(start_comparison(worker, session));
  wait(worker);
  const Comparison* made = session.shown_comparison();
  ASSERT_NE(made, nullptr);
  EXPECT_FALSE(session.comparison_request());
  Session direct = bunny_session();
  direct.select(0);
  direct.set_compare(true);
  ASSERT_NE(direct.comparison(), nullptr);
  EXPECT_TRUE(same_mesh(made->left.mesh, direct.comparison()->left.mesh));
  EXPECT_TRUE(same_mesh(made->right.mesh, direct.comparison()->right.mesh));

  session.set_compare_mode(CompareMode::Smoothing);
  ASSERT_TRUE(start_comparison(worker, session));
  session.select(1);  // while it is made for hole 0
  wait(worker);
  EXPECT_EQ(session.shown_comparison(), nullptr);
  EXPECT_TRUE(session.comparison_request());
}

TEST(Background, OpeningOnTheWorkerReplacesTheSessionWhenRead) {
  Session session;
  FileActions files(session);
  ASSERT_TRUE(files.open_now(kAssets / "bunny.obj"));
  files.take_mesh_opened();
  Worker worker;
  ASSERT_TRUE(start_open(worker, session, files, kAssets / "no-such-file.obj"));
  wait(worker);
  EXPECT_EQ(session.name(), "bunny.obj");
  EXPECT_TRUE(session.notice().error);
  EXPECT_FALSE(files.take_mesh_opened());

  ASSERT_TRUE(start_open(worker, session, files, kAssets / "torus.obj"));
  EXPECT_EQ(session.name(), "bunny.obj");  // until the frame loop polls
  wait(worker);
  EXPECT_EQ(session.name(), "torus.obj");
  EXPECT_TRUE(files.take_mesh_opened());
  EXPECT_EQ(files.suggested_save_path(), kAssets / "torus-filled.obj");
}

}  // namespace
}  // namespace holefill::viewer
