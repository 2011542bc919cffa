// The requests that wait while the worker computes from the session (issue 31): what would
// change the mesh or the files (undo, redo, fills, reset, open, save, a dropped file) is queued
// and carried out in order once the work ends, so that no key is lost (two quick Ctrl+Z undo
// two steps); the rest (help, screenshots, text size, the view) goes ahead at once. Cancel
// (Esc) drops the queue with the work. No GL.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>

#include "interaction.h"

namespace holefill::viewer {

// Whether `request` must wait while the worker runs.
bool waits_for_worker(const Request& request);

// How the user is told that `request` waits: "Waiting: undo (after the work in progress; Esc
// cancels)".
std::string waiting_notice(const Request& request);

class RequestQueue {
 public:
  // Queues `request` when it must wait: the worker is busy, or earlier requests wait (they go
  // first). False: carry it out now.
  bool defer(const Request& request, bool worker_busy);
  // The first waiting request, taken out, once the worker is free.
  std::optional<Request> next(bool worker_busy);
  void clear() { waiting_.clear(); }
  std::size_t size() const { return waiting_.size(); }
  bool empty() const { return waiting_.empty(); }

 private:
  std::deque<Request> waiting_;
};

}  // namespace holefill::viewer
