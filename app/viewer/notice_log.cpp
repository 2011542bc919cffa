#include "notice_log.h"

namespace holefill::viewer {

void NoticeLog::observe(const Notice& notice) {
  if (notice.text == last_.text && notice.error == last_.error) return;
  last_ = notice;
  if (notice.text.empty()) return;
  entries_.push_back(notice);
  if (entries_.size() > kLimit) entries_.pop_front();
}

}  // namespace holefill::viewer
