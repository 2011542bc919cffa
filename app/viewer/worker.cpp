#include "worker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <exception>
#include <memory>
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

Worker::~Worker() {
  cancel();
  if (thread_.joinable()) thread_.join();
}

bool Worker::start(std::string label, Job job) {
  if (busy()) return false;
  label_ = std::move(label);
  error_.clear();
  progress_ = std::make_unique<Progress>();
  done_ = false;
  started_ = std::chrono::steady_clock::now();
  thread_ = std::thread([this, job = std::move(job), progress = progress_.get()] {
    yield_to_the_window();
    try {
      finish_ = job(*progress);
    } catch (const std::exception& error) {
      error_ = error.what();
    }
    done_ = true;  // publishes finish_ and error_ to poll()
  });
  return true;
}

void Worker::cancel() {
  if (progress_) progress_->cancel();
}

bool Worker::poll() {
  if (!busy() || !done_) return false;
  thread_.join();
  Finish finish = std::exchange(finish_, {});
  if (finish && !progress_->cancelled()) finish();
  return true;
}

double Worker::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

}  // namespace holefill::viewer
