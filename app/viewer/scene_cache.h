// The 3D view's last picture, kept in an offscreen framebuffer (issue 31): while nothing it shows
// changes (the camera, the mesh, the comparison, the selection, the hovered hole, the display
// options, the window's size), a frame copies it instead of drawing the mesh again. A frame that
// only changes the panel, a tooltip or the progress box then costs the panel alone: on a
// 2M-face mesh under llvmpipe drawing the mesh takes about half a second. GL 3.3 core.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace holefill::viewer {

// Everything the 3D view's picture depends on.
struct SceneKey {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  int scene[4] = {0, 0, 0, 0};  // x, y, width, height in framebuffer pixels
  int framebuffer[2] = {0, 0};
  std::uint64_t mesh_version = 0;
  std::uint64_t comparison_version = 0;
  bool comparison = false;
  int selected = -1;
  int hovered = -1;
  std::vector<int> joined;
  bool display[4] = {false, false, false, false};  // wireframe, flat, patch vertices, features
  std::uint64_t features_version = 0;
  bool coarse = false;  // drawn as the proxy (the camera moves)
  bool operator==(const SceneKey&) const = default;
};

class SceneCache {
 public:
  SceneCache() = default;
  ~SceneCache();
  SceneCache(const SceneCache&) = delete;
  SceneCache& operator=(const SceneCache&) = delete;

  // True when the picture for `key` is kept: it has been copied into the window's framebuffer.
  bool show(const SceneKey& key);
  // Directs drawing to the offscreen framebuffer (when one can be made) for the picture of
  // `key`; end() copies it into the window's framebuffer.
  void begin(const SceneKey& key);
  void end();

 private:
  bool make(int width, int height);
  void copy_to_window() const;
  void release();

  GLuint framebuffer_ = 0, color_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0;
  bool drawing_ = false;
  std::optional<SceneKey> key_;
};

}  // namespace holefill::viewer
