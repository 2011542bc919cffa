// Long work (opening a mesh, filling holes) on a thread of its own, one job at a time, so that
// the window keeps drawing and offers Cancel. The job computes its result without changing the
// session and returns the step that takes the result in; poll() runs that step on the frame
// loop's thread, the only one that changes the session. Cancel drops the result, so the session
// stays exactly as it was before the job. No GL.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "holefill/progress.h"

namespace holefill::viewer {

class Worker {
 public:
  using Finish = std::function<void()>;
  // Runs on the worker thread; checks the Progress where it can stop. Returns the finishing
  // step (may be empty).
  using Job = std::function<Finish(Progress&)>;
  // What cancel() does to the job: wait for it to notice (it reads the session), or set it
  // aside at once (it reads nothing but its own data until its finishing step, e.g. a file
  // read into a session of its own): the worker is free, the job's thread ends on its own.
  enum class OnCancel { Wait, SetAside };

  Worker() = default;
  ~Worker();  // cancels the job and waits for its thread (and those set aside)
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  // Starts `job`, described to the user as `label`; false (nothing started) while busy.
  bool start(std::string label, Job job, OnCancel on_cancel = OnCancel::Wait);
  bool busy() const { return running_.has_value(); }
  // Asks the job to stop; its result will be dropped. A job to wait for may run on until its
  // next check (busy() stays true until then); one set aside ends busy() at once.
  void cancel();
  // A cancel was asked for and poll() has not yet reported the job's end.
  bool cancelling() const { return (busy() || set_aside_unreported_) && cancelled(); }
  // Whether the last job was cancelled (its result dropped).
  bool cancelled() const { return last_ && last_->progress.cancelled(); }

  // On the frame loop's thread, every frame: when the job has ended (or was set aside), runs its
  // finishing step (unless cancelled) and returns true. An exception the job threw becomes
  // error().
  bool poll();
  // Whether poll() has something to report now (the job ended or was set aside).
  bool ended() const { return set_aside_unreported_ || (running_ && running_->state->done); }
  // The message of the last job's exception, empty if none; cleared by start().
  const std::string& error() const { return error_; }

  const std::string& label() const { return label_; }
  double fraction() const { return last_ ? last_->progress.fraction() : 0.0; }
  // The long phase the last job entered last (Progress::enter_phase), empty before any.
  std::string phase() const;
  double seconds() const;
  // Called on the job's thread as each job ends (e.g. to wake a frame loop that sleeps); must be
  // thread-safe. Empty: nothing.
  void set_on_done(std::function<void()> on_done);

 private:
  struct State {
    State();
    Progress progress;
    mutable std::mutex phase_mutex;
    std::string phase;
    std::atomic<bool> done{false};
    Finish finish;
    std::string error;
  };
  struct Running {
    std::thread thread;
    std::shared_ptr<State> state;
    OnCancel on_cancel = OnCancel::Wait;
  };
  struct OnDone {
    std::mutex mutex;
    std::function<void()> call;
  };

  std::optional<Running> running_;
  std::vector<Running> set_aside_;
  bool set_aside_unreported_ = false;
  std::shared_ptr<State> last_;
  std::shared_ptr<OnDone> on_done_ = std::make_shared<OnDone>();
  std::string label_;
  std::string error_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace holefill::viewer
