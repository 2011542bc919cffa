#include "background.h"

#include <memory>
#include <string>

namespace holefill::viewer {

bool start_fill(Worker& worker, Session& session, const std::optional<FillRequest>& request) {
  if (!request) return false;
  const std::string label = request->hole_ids.size() == 1
                                ? "Filling hole " + std::to_string(request->hole_ids[0])
                                : "Filling " + std::to_string(request->hole_ids.size()) + " holes";
  return worker.start(label, [&session, request = *request](Progress& progress) -> Worker::Finish {
    auto result = std::make_shared<std::optional<FillResult>>(session.compute(request, &progress));
    if (!*result) return {};
    return [&session, result] { session.apply(std::move(**result)); };
  });
}

bool start_open(Worker& worker, Session& session, FileActions& files,
                const std::filesystem::path& path) {
  return worker.start("Opening " + path.filename().string(), [&session, &files, path](Progress&) {
    auto opened = std::make_shared<Session>();
    const bool read = opened->open(path);
    return [&session, &files, opened, read, path] {
      if (!read) {
        session.tell(opened->notice());
        return;
      }
      session = std::move(*opened);
      files.opened(path);
    };
  });
}

}  // namespace holefill::viewer
