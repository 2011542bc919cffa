#include "background.h"

#include <memory>
#include <string>
#include <utility>

namespace holefill::viewer {

namespace {

constexpr const char* kOpening = "Opening ";

// Computes `request` (a FillRequest or a LogChange) on the worker and applies it when done.
template <class Request>
bool start_compute(Worker& worker, Session& session, std::string label, const Request& request) {
  return worker.start(std::move(label), [&session, request](Progress& progress) -> Worker::Finish {
    auto result =
        std::make_shared<decltype(session.compute(request))>(session.compute(request, &progress));
    if (!*result) return {};
    return [&session, result] { session.apply(std::move(**result)); };
  });
}

}  // namespace

bool start_fill(Worker& worker, Session& session, const std::optional<FillRequest>& request) {
  if (!request) return false;
  const std::string label = request->hole_ids.size() == 1
                                ? "Filling hole " + std::to_string(request->hole_ids[0])
                                : "Filling " + std::to_string(request->hole_ids.size()) + " holes";
  return start_compute(worker, session, label, *request);
}

bool start_change(Worker& worker, Session& session, const std::optional<LogChange>& change) {
  if (!change) return false;
  const char* labels[] = {"Undoing", "Redoing", "Resetting the hole", "Applying the options",
                          "Keeping the result"};
  return start_compute(worker, session, labels[static_cast<int>(change->kind)], *change);
}

bool start_comparison(Worker& worker, Session& session) {
  const auto request = session.comparison_request();
  if (!request || worker.busy()) return false;
  return start_compute(worker, session, "Comparing on hole " + std::to_string(request->hole_id),
                       *request);
}

bool start_options(Worker& worker, Session& session, const FillOptions& options) {
  if (worker.busy()) return false;
  if (!start_change(worker, session, session.options_request(options)))
    session.set_options(options);
  return true;
}

bool start_open(Worker& worker, Session& session, FileActions& files,
                const std::filesystem::path& path, std::size_t remove_pieces_up_to) {
  // The job reads into a session of its own and touches `session` and `files` only in its
  // finishing step: a cancel sets it aside at once, however long the file takes to read.
  return worker.start(
      kOpening + path.filename().string(),
      [&session, &files, path, threads = session.threads(),
       remove_pieces_up_to](Progress& progress) {
        auto opened = std::make_shared<Session>();
        opened->set_threads(threads);
        const bool read = opened->open(path, &progress, remove_pieces_up_to);
        return [&session, &files, opened, read, path] {
          if (!read) {
            session.tell(opened->notice());
            return;
          }
          session = std::move(*opened);
          files.opened(path);
        };
      },
      Worker::OnCancel::SetAside);
}

bool opening(const Worker& worker) {
  return worker.busy() && worker.label().rfind(kOpening, 0) == 0;
}

std::string cancelled_notice(const Worker& worker) {
  const bool open = worker.label().rfind(kOpening, 0) == 0;
  return worker.label() + (open ? ": cancelled" : ": cancelled, mesh unchanged");
}

}  // namespace holefill::viewer
