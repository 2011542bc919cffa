#include "window.h"

#include <GLFW/glfw3.h>

#include <stdexcept>
#include <string>

namespace holefill::viewer {

struct WindowCallbacks {
  // Every callback goes through here: any event wakes the frame loop.
  static Window& of(GLFWwindow* handle) {
    Window& window = *static_cast<Window*>(glfwGetWindowUserPointer(handle));
    window.woken_ = true;
    return window;
  }
  // Events that only ask for a new frame (Dear ImGui's own callbacks, chained after these,
  // read what they carry).
  static void wake(GLFWwindow* handle) { of(handle); }
  static void close(GLFWwindow* handle) { ++of(handle).close_requests_; }
  static void wake_int(GLFWwindow* handle, int) { of(handle); }
  static void wake_size(GLFWwindow* handle, int, int) { of(handle); }
  static void wake_char(GLFWwindow* handle, unsigned int) { of(handle); }
  static InputEvent event(Window& window, InputEvent::Kind kind) {
    InputEvent e;
    e.kind = kind;
    e.cursor = window.cursor_;
    e.shift = window.shift_;
    e.control = window.control_;
    return e;
  }
  static void modifiers(Window& window, int mods) {
    window.shift_ = (mods & GLFW_MOD_SHIFT) != 0;
    window.control_ = (mods & GLFW_MOD_CONTROL) != 0;
  }
  static void button(GLFWwindow* handle, int button, int action, int mods) {
    Window& window = of(handle);
    modifiers(window, mods);
    InputEvent e = event(
        window, action == GLFW_PRESS ? InputEvent::Kind::ButtonDown : InputEvent::Kind::ButtonUp);
    e.button = button == GLFW_MOUSE_BUTTON_RIGHT    ? MouseButton::Right
               : button == GLFW_MOUSE_BUTTON_MIDDLE ? MouseButton::Middle
                                                    : MouseButton::Left;
    window.events_.push_back(e);
  }
  static void cursor(GLFWwindow* handle, double x, double y) {
    Window& window = of(handle);
    window.cursor_ = {static_cast<float>(x), static_cast<float>(y)};
    window.events_.push_back(event(window, InputEvent::Kind::CursorMove));
  }
  static void scroll(GLFWwindow* handle, double, double y) {
    Window& window = of(handle);
    InputEvent e = event(window, InputEvent::Kind::Scroll);
    e.scroll = static_cast<float>(y);
    window.events_.push_back(e);
  }
  static void key(GLFWwindow* handle, int key, int, int action, int mods) {
    Window& window = of(handle);
    if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
    const bool modifier = key >= GLFW_KEY_LEFT_SHIFT && key <= GLFW_KEY_MENU;
    if (action == GLFW_PRESS && !modifier) ++window.keys_received_;
    modifiers(window, mods);
    InputEvent e = event(window, InputEvent::Kind::Key);
    if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z)
      e.key = 'A' + (key - GLFW_KEY_A);
    else if (key == GLFW_KEY_ESCAPE)
      e.key = kKeyEscape;
    else if (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER)
      e.key = kKeyEnter;
    else if (key == GLFW_KEY_DELETE)
      e.key = kKeyDelete;
    else if (key == GLFW_KEY_F1)
      e.key = kKeyF1;
    else if (key == GLFW_KEY_F12)
      e.key = kKeyF12;
    else if (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD)
      e.key = '+';
    else if (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT)
      e.key = '-';
    else if (key == GLFW_KEY_0 || key == GLFW_KEY_KP_0)
      e.key = '0';
    else
      return;
    window.events_.push_back(e);
  }
  static void drop(GLFWwindow* handle, int count, const char** paths) {
    Window& window = of(handle);
    for (int i = 0; i < count; ++i) {
      InputEvent e = event(window, InputEvent::Kind::Drop);
      e.path = paths[i];
      window.events_.push_back(e);
    }
  }
};

Window::Window(int width, int height, const char* title) {
  if (!glfwInit()) throw std::runtime_error("GLFW could not start (is there a display?)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw std::runtime_error("no window with an OpenGL 3.3 core context could be created");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  glfwSetWindowUserPointer(window_, this);
  glfwSetMouseButtonCallback(window_, WindowCallbacks::button);
  glfwSetCursorPosCallback(window_, WindowCallbacks::cursor);
  glfwSetScrollCallback(window_, WindowCallbacks::scroll);
  glfwSetKeyCallback(window_, WindowCallbacks::key);
  glfwSetDropCallback(window_, WindowCallbacks::drop);
  glfwSetCharCallback(window_, WindowCallbacks::wake_char);
  glfwSetWindowFocusCallback(window_, WindowCallbacks::wake_int);
  glfwSetCursorEnterCallback(window_, WindowCallbacks::wake_int);
  glfwSetWindowRefreshCallback(window_, WindowCallbacks::wake);
  glfwSetWindowSizeCallback(window_, WindowCallbacks::wake_size);
  glfwSetFramebufferSizeCallback(window_, WindowCallbacks::wake_size);
  glfwSetWindowCloseCallback(window_, WindowCallbacks::close);
}

Window::~Window() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool Window::should_close() const { return glfwWindowShouldClose(window_); }
void Window::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::cancel_close() { glfwSetWindowShouldClose(window_, GLFW_FALSE); }
void Window::set_title(const char* title) { glfwSetWindowTitle(window_, title); }

bool Window::wait(std::optional<double> seconds) {
  woken_ = false;
  if (seconds)
    glfwWaitEventsTimeout(*seconds);
  else
    glfwWaitEvents();
  return woken_;
}

void Window::wake() { glfwPostEmptyEvent(); }

std::vector<InputEvent> Window::poll() {
  woken_ = false;
  glfwPollEvents();
  polled_events_ = woken_;
  std::vector<InputEvent> events;
  events.swap(events_);
  return events;
}

void Window::swap() { glfwSwapBuffers(window_); }

glm::ivec2 Window::size() const {
  glm::ivec2 size;
  glfwGetWindowSize(window_, &size.x, &size.y);
  return size;
}

glm::ivec2 Window::framebuffer_size() const {
  glm::ivec2 size;
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

float Window::content_scale() const {
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window_, &x, &y);
  return x;
}

}  // namespace holefill::viewer
