// Long work (opening a mesh, filling holes) on a thread of its own, one job at a time, so that
// the window keeps drawing and offers Cancel. The job computes its result without changing the
// session and returns the step that takes the result in; poll() runs that step on the frame
// loop's thread, the only one that changes the session. Cancel drops the result, so the session
// stays exactly as it was before the job. No GL.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <string>
#include <thread>

#include "holefill/progress.h"

namespace holefill::viewer {

class Worker {
 public:
  using Finish = std::function<void()>;
  // Runs on the worker thread; checks the Progress where it can stop. Returns the finishing
  // step (may be empty).
  using Job = std::function<Finish(Progress&)>;

  Worker() = default;
  ~Worker();  // cancels the job and waits for its thread
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  // Starts `job`, described to the user as `label`; false (nothing started) while busy.
  bool start(std::string label, Job job);
  bool busy() const { return thread_.joinable(); }
  // Asks the job to stop; its result will be dropped. The thread may run on until the job's
  // next check; busy() stays true until then.
  void cancel();
  bool cancelling() const { return busy() && progress_ && progress_->cancelled(); }
  // Whether the last job was cancelled (its result dropped).
  bool cancelled() const { return progress_ && progress_->cancelled(); }

  // On the frame loop's thread, every frame: when the job has ended, runs its finishing step
  // (unless cancelled) and returns true. An exception the job threw becomes error().
  bool poll();
  // The message of the last job's exception, empty if none; cleared by start().
  const std::string& error() const { return error_; }

  const std::string& label() const { return label_; }
  double fraction() const { return progress_ ? progress_->fraction() : 0.0; }
  double seconds() const;

 private:
  std::thread thread_;
  std::unique_ptr<Progress> progress_;
  std::atomic<bool> done_{false};
  Finish finish_;
  std::string label_;
  std::string error_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace holefill::viewer
