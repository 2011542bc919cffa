// All OpenGL drawing (3.3 core): the shaded surface with faces coloured by the stage that made
// them, the wireframe overlay, patch vertices as dots, every unfilled hole's boundary as a thick
// line (selected and hovered holes in their own colours), and the comparison's two viewports.
// The renderer only reads the session; it uploads a mesh again only when its version changes,
// and draws the scene again only when something it shows changed (scene_cache.h).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "camera.h"
#include "display.h"
#include "gl_program.h"
#include "mesh_buffers.h"
#include "scene_cache.h"
#include "session.h"

namespace holefill::viewer {

// A rectangle of the window in framebuffer pixels, origin top-left.
struct PixelRect {
  int x = 0, y = 0, width = 1, height = 1;
};

class Renderer {
 public:
  Renderer();

  // Draws the session's scene into `scene` of a `framebuffer_height`-tall framebuffer: one view,
  // or the comparison's two side by side sharing `camera`'s pose. `camera_moving`: a big mesh is
  // drawn as its coarse proxy (coarse_proxy.h), without wireframe and dots, so that the view
  // follows the mouse; the next frame without it draws the whole mesh again.
  void render(Session& session, const Camera& camera, const PixelRect& scene, int framebuffer_width,
              int framebuffer_height, const DisplayOptions& display, int hovered_hole,
              bool camera_moving = false);
  // Triangles of the main mesh's proxy (0: it has none, being small enough to draw whole).
  std::size_t proxy_triangles() const { return main_.proxy_triangles; }

  // The two halves the comparison view splits `scene` into.
  static std::pair<PixelRect, PixelRect> comparison_halves(const PixelRect& scene);

  // The framebuffer as RGB rows, top row first.
  std::vector<std::uint8_t> read_pixels(int width, int height) const;

 private:
  struct MeshLayer {
    MeshBuffers surface;
    MeshBuffers proxy;  // drawn while the camera moves, when proxy_triangles > 0
    std::size_t proxy_triangles = 0;
    BoundaryBuffers boundary;
    BoundaryBuffers borders;  // loops that look like the border of an open surface
    // The selected hole's feature lines and their continuations (main view only).
    BoundaryBuffers feature_lines;
    BoundaryBuffers feature_paths;
    std::uint64_t version = ~std::uint64_t{0};
    float radius = 1.0f;
    float patch_edge_length = 0.0f;
  };

  // Which loops stand out: the selected hole, the loops filled with it, the hovered one.
  struct Highlight {
    int selected = -1;
    const std::vector<int>* joined = nullptr;
    int hovered = -1;
  };
  static constexpr int kMaxJoined = 16;  // as in thick_line.frag; more are drawn as holes

  // What the three passes of a view share: the camera's matrices, the world size of a pixel at
  // unit depth, and how far dots and outlines are drawn toward the eye (world units).
  struct ViewTransform {
    glm::mat4 view;
    glm::mat4 projection;
    float pixel_size;
    float depth_bias;
  };

  void sync(Session& session);
  // One view: the surface, then the wireframe and new-vertex dots, then the loops' outlines.
  void draw_view(const MeshLayer& layer, const Camera& camera, const PixelRect& rect,
                 int framebuffer_height, const DisplayOptions& display, const Highlight& highlight,
                 bool coarse);
  void draw_surface(const MeshBuffers& surface, const ViewTransform& transform,
                    const DisplayOptions& display);
  void draw_edges_and_dots(const MeshLayer& layer, const ViewTransform& transform,
                           const PixelRect& rect, const DisplayOptions& display);
  void draw_outlines(const MeshLayer& layer, const ViewTransform& transform, const PixelRect& rect,
                     const Highlight& highlight);
  // Sets up the thick-line program for `highlight`, lines `width_pixels` wide.
  void use_line_program(const ViewTransform& transform, const PixelRect& rect,
                        const Highlight& highlight, float width_pixels);
  // The selected hole's feature lines and their continuations (feature_view.h).
  void draw_features(const MeshLayer& layer, const ViewTransform& transform, const PixelRect& rect);

  GlProgram surface_program_;
  GlProgram solid_program_;
  GlProgram line_program_;
  MeshLayer main_;
  std::uint64_t features_version_ = 0;  // of the features in main_'s buffers
  MeshLayer left_;
  MeshLayer right_;
  SceneCache cache_;  // the last picture, shown again while nothing in it changes
};

}  // namespace holefill::viewer
