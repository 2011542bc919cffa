// The side panel's status bar, at its bottom with a fixed height (issue 31): the latest message,
// wrapped and scrolling within its box (red when it is an error), a History button listing the
// earlier ones and Clear. Messages no longer appear above the controls and push them down.
#pragma once

#include "notice_log.h"
#include "session.h"

namespace holefill::viewer {

// The height the status bar takes at the current font size.
float status_bar_height();

// Draws it where the cursor is; records the session's notice in `notices`.
void draw_status_bar(Session& session, NoticeLog& notices);

}  // namespace holefill::viewer
