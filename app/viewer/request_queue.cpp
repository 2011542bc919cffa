#include "request_queue.h"

namespace holefill::viewer {

bool waits_for_worker(const Request& request) {
  if (!request.command) return true;  // a dropped file
  switch (*request.command) {
    case Command::Help:
    case Command::Screenshot:
    case Command::ZoomIn:
    case Command::ZoomOut:
    case Command::ZoomReset:
    case Command::Deselect:
    case Command::Frame:
    case Command::ResetView:
      return false;
    default:
      return true;
  }
}

std::string waiting_notice(const Request& request) {
  const std::string what =
      request.command ? describe(*request.command) : "open " + request.path.string();
  return "Waiting: " + what + " (after the work in progress; Esc cancels)";
}

bool RequestQueue::defer(const Request& request, bool worker_busy) {
  if (!waits_for_worker(request) || (!worker_busy && waiting_.empty())) return false;
  waiting_.push_back(request);
  return true;
}

std::optional<Request> RequestQueue::next(bool worker_busy) {
  if (worker_busy || waiting_.empty()) return std::nullopt;
  Request request = waiting_.front();
  waiting_.pop_front();
  return request;
}

}  // namespace holefill::viewer
