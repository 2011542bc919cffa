// The GLFW window with an OpenGL 3.3 core context. Its input callbacks only record events
// (events.h); the frame loop decides what they do.
#pragma once

#include <glm/glm.hpp>
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
  // Processes pending input and returns what happened since the last call.
  std::vector<InputEvent> poll();
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
  friend struct WindowCallbacks;
};

}  // namespace holefill::viewer
