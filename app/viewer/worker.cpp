#include "worker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <exception>
#include <utility>

namespace holefill::viewer {
namespace {

// The job's thread (and the threads it starts, which inherit it) yields the cores to the frame
// loop's: while a fill keeps every core busy, the window still draws its progress and takes Esc
// at once (Linux keeps a nice value per thread). Elsewhere nothing changes.
void yield_to_the_window() {
#ifdef __linux__
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 4);
#endif
}

}  // namespace

Worker::State::State()
    : progress({}, [this](std::string_view entered) {
        const std::lock_guard lock(phase_mutex);
        phase = entered;
      }) {}

std::string Worker::phase() const {
  if (!last_) return {};
  const std::lock_guard lock(last_->phase_mutex);
  return last_->phase;
}

Worker::~Worker() {
  cancel();
  if (running_) running_->thread.join();
  for (auto& aside : set_aside_) aside.thread.join();
}

bool Worker::start(std::string label, Job job, OnCancel on_cancel) {
  if (busy()) return false;
  label_ = std::move(label);
  error_.clear();
  set_aside_unreported_ = false;
  last_ = std::make_shared<State>();
  started_ = std::chrono::steady_clock::now();
  // The thread keeps its own references: a job set aside outlives its place here.
  std::thread thread([job = std::move(job), state = last_, on_done = on_done_] {
    yield_to_the_window();
    try {
      state->finish = job(state->progress);
    } catch (const std::exception& error) {
      state->error = error.what();
    }
    state->done = true;  // publishes finish and error to poll()
    const std::lock_guard lock(on_done->mutex);
    if (on_done->call) on_done->call();
  });
  running_ = Running{std::move(thread), last_, on_cancel};
  return true;
}

void Worker::cancel() {
  if (!running_) return;
  running_->state->progress.cancel();
  if (running_->on_cancel != OnCancel::SetAside) return;
  set_aside_.push_back(std::move(*running_));
  running_.reset();
  set_aside_unreported_ = true;
}

bool Worker::poll() {
  // Threads set aside are joined once they have ended, so none is left behind.
  std::erase_if(set_aside_, [](Running& aside) {
    if (!aside.state->done) return false;
    aside.thread.join();
    return true;
  });
  if (set_aside_unreported_) {
    set_aside_unreported_ = false;
    return true;
  }
  if (!running_ || !running_->state->done) return false;
  running_->thread.join();
  const std::shared_ptr<State> state = std::move(running_->state);
  running_.reset();
  error_ = std::move(state->error);
  Finish finish = std::exchange(state->finish, {});
  if (finish && !state->progress.cancelled()) finish();
  return true;
}

double Worker::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

void Worker::set_on_done(std::function<void()> on_done) {
  const std::lock_guard lock(on_done_->mutex);
  on_done_->call = std::move(on_done);
}

}  // namespace holefill::viewer
