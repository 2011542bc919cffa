// The GLFW window with an OpenGL 3.3 core context. Its input callbacks only record events
// (events.h); the frame loop decides what they do.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "events.h"

struct GLFWwindow;

namespace holefill::viewer {

class Window {
 public:
  // Throws std::runtime_error when no window or GL 3.3 core context can be made.
  Window(int width, int height, const char* title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void request_close();
  // Takes back a close request (the user still has something to answer).
  void cancel_close();
  void set_title(const char* title);
  // Sleeps until the window system has an event for the window (input, a resize, an expose, a
  // close request) or `seconds` pass (nothing: no limit). True when an event came.
  bool wait(std::optional<double> seconds);
  // Ends a wait() under way (or the next one) at once, from any thread: work that ended wakes
  // the frame loop rather than waiting out the pause between frames. Returns false from wait().
  static void wake();
  // Processes pending input and returns what happened since the last call.
  std::vector<InputEvent> poll();
  // Whether the last poll() processed any event (input or not): what it changed needs frames
  // too, and a close request it took must not wait for the next event.
  bool polled_events() const { return polled_events_; }
  // Key presses received since the window opened (every key but Shift, Ctrl, Alt and Super, also
  // those no shortcut takes): the state report gives it, so a test knows its keys arrived.
  long keys_received() const { return keys_received_; }
  // Close requests received (the window manager's close button), for the state report too.
  long close_requests() const { return close_requests_; }
  void swap();
  glm::ivec2 size() const;              // window pixels (cursor coordinates)
  glm::ivec2 framebuffer_size() const;  // GL pixels
  // The monitor's content scale (1 on a plain screen, 1.5 or 2 on a HiDPI one).
  float content_scale() const;

 private:
  GLFWwindow* window_ = nullptr;
  std::vector<InputEvent> events_;
  glm::vec2 cursor_{0.0f};
  bool shift_ = false;
  bool control_ = false;
  bool woken_ = false;  // an event came since the last wait() or poll()
  bool polled_events_ = false;
  long keys_received_ = 0;
  long close_requests_ = 0;
  friend struct WindowCallbacks;
};

}  // namespace holefill::viewer
