// The panel's scale: the monitor's content scale times the user's zoom, the font at whole pixels
// and the widths following the font.
#include "ui_scale.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holefill::viewer {
namespace {

TEST(UiScale, FollowsTheMonitorsContentScale) {
  EXPECT_EQ(ui_scale(1.0f, {}).font_pixels, 13);
  EXPECT_FLOAT_EQ(ui_scale(1.0f, {}).factor, 1.0f);
  EXPECT_EQ(ui_scale(2.0f, {}).font_pixels, 26);
  EXPECT_FLOAT_EQ(ui_scale(2.0f, {}).factor, 2.0f);
  // 13 x 1.5 = 19.5: the nearest whole size, and the widths grow as much as the font did.
  const UiScale hidpi = ui_scale(1.5f, {});
  EXPECT_EQ(hidpi.font_pixels, 20);
  EXPECT_FLOAT_EQ(hidpi.factor, 20.0f / 13.0f);
  EXPECT_FLOAT_EQ(hidpi.panel_width(), 600.0f);  // 390 x 20 / 13
  // A platform without a content scale reports 0.
  EXPECT_EQ(ui_scale(0.0f, {}).font_pixels, 13);
}

TEST(UiScale, CtrlPlusAndMinusClimbTheLadderAndCtrlZeroComesBack) {
  UiZoom zoom;
  int last = ui_scale(1.0f, zoom).font_pixels;
  int climbed = 0;
  for (int i = 0; i < 20; ++i) {
    const UiZoom next = zoom_after(zoom, Command::ZoomIn);
    if (next.level == zoom.level) break;  // the top rung
    zoom = next;
    ++climbed;
    const int pixels = ui_scale(1.0f, zoom).font_pixels;
    EXPECT_GT(pixels, last) << "rung " << zoom.level;  // every press shows
    last = pixels;
  }
  EXPECT_EQ(climbed, 7);
  EXPECT_FLOAT_EQ(zoom_factor(zoom), 3.0f);
  EXPECT_EQ(ui_scale(1.0f, zoom).font_pixels, 39);
  // One step down from the top works at once (no presses lost beyond the end).
  EXPECT_EQ(ui_scale(1.0f, zoom_after(zoom, Command::ZoomOut)).font_pixels, 33);  // 2.5 x 13
  EXPECT_EQ(zoom_after(zoom, Command::ZoomReset).level, 0);
  EXPECT_EQ(zoom_after(zoom, Command::Undo).level, zoom.level);
  for (int i = 0; i < 20; ++i) zoom = zoom_after(zoom, Command::ZoomOut);
  EXPECT_FLOAT_EQ(zoom_factor(zoom), 0.6f);
  EXPECT_EQ(ui_scale(1.0f, zoom).font_pixels, 8);  // 7.8 rounded
}

TEST(UiScale, TheFontStaysReadableAndWithinTheAtlas) {
  UiZoom top, bottom;
  for (int i = 0; i < 20; ++i) {
    top = zoom_after(top, Command::ZoomIn);
    bottom = zoom_after(bottom, Command::ZoomOut);
  }
  EXPECT_EQ(ui_scale(3.0f, top).font_pixels, 48);    // 117 wanted
  EXPECT_EQ(ui_scale(0.5f, bottom).font_pixels, 8);  // 3.9 wanted
  EXPECT_FLOAT_EQ(ui_scale(3.0f, top).factor, 48.0f / 13.0f);
}

}  // namespace
}  // namespace holefill::viewer
