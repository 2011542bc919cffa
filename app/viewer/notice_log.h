// The messages the session has shown, oldest first, for the status bar's history (issue 31): the
// panel shows the latest in a fixed place and lets the user scroll back through the rest,
// instead of messages above the controls that push them down and vanish. No GL.
#pragma once

#include <cstddef>
#include <deque>

#include "session.h"

namespace holefill::viewer {

class NoticeLog {
 public:
  static constexpr std::size_t kLimit = 200;  // the oldest go beyond this

  // Called every frame with the session's notice: a new, non-empty message is added.
  void observe(const Notice& notice);
  const std::deque<Notice>& entries() const { return entries_; }

 private:
  std::deque<Notice> entries_;
  Notice last_;
};

}  // namespace holefill::viewer
