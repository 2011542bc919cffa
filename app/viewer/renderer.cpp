#include "renderer.h"

#include <algorithm>

#include "coarse_proxy.h"
#include "palette.h"

namespace holefill::viewer {
namespace {

// How far, in pixels, outlines are drawn toward the eye (thick_line.vert): enough for a loop on
// a silhouette, where the surface beside it rises steeply toward the eye, to stay whole.
constexpr float kOutlinePixelBias = 24.0f;
// Wireframe lines closer than [0] pixels apart are not drawn, from [1] apart fully.
constexpr float kWireframeFadePixels[2] = {2.5f, 8.0f};
// New-vertex dots on patches whose edges are closer than [0] pixels on screen are not drawn, from
// [1] apart fully (a 10,000-vertex patch seen whole was a red blot).
constexpr float kDotFadePixels[2] = {4.0f, 12.0f};

glm::vec3 rgb(const palette::Rgb& c) { return glm::vec3(c[0], c[1], c[2]) / 255.0f; }
glm::vec4 rgba(const palette::Rgb& c) { return glm::vec4(rgb(c), 1.0f); }

void clear_rect(const PixelRect& rect, int framebuffer_height, const palette::Rgb& color) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect.x, framebuffer_height - rect.y - rect.height, rect.width, rect.height);
  const glm::vec3 c = rgb(color);
  glClearColor(c.r, c.g, c.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

template <class Layer>
void upload(Layer& layer, const Mesh& mesh, const Session& session,
            const std::vector<const HoleFill*>& fills) {
  const SurfaceArrays arrays = surface_arrays(mesh, fills);
  layer.surface.upload(arrays);
  layer.proxy_triangles = 0;
  if (arrays.triangles.size() / 3 > kProxyAboveTriangles) {
    const SurfaceArrays proxy = coarse_proxy(arrays, kProxyTriangles);
    layer.proxy.upload(proxy);
    layer.proxy_triangles = proxy.triangles.size() / 3;
  }
  std::vector<Hole> holes, borders;
  for (const auto& hole : session.holes()) {
    (session.is_border(hole.id) ? borders : holes).push_back(hole);
  }
  layer.boundary.upload(boundary_segments(mesh, holes));
  layer.borders.upload(boundary_segments(mesh, borders));
  layer.radius = std::max(0.5f * glm::length(arrays.hi - arrays.lo), 1e-6f);
  layer.patch_edge_length = arrays.patch_edge_length;
}

}  // namespace

Renderer::Renderer()
    : surface_program_("surface.vert", "surface.frag"),
      solid_program_("solid.vert", "solid.frag"),
      line_program_("thick_line.vert", "thick_line.frag") {}

std::pair<PixelRect, PixelRect> Renderer::comparison_halves(const PixelRect& scene) {
  constexpr int kDivider = 4;
  const int left_width = (scene.width - kDivider) / 2;
  const PixelRect left{scene.x, scene.y, left_width, scene.height};
  const PixelRect right{scene.x + left_width + kDivider, scene.y,
                        scene.width - left_width - kDivider, scene.height};
  return {left, right};
}

void Renderer::sync(Session& session) {
  if (main_.version != session.mesh_version()) {
    std::vector<const HoleFill*> fills;
    for (const auto& hole : session.holes()) fills.push_back(&session.fill(hole.id));
    upload(main_, session.mesh(), session, fills);
    main_.version = session.mesh_version();
  }
  const HoleFeatures& features = session.selected_features();
  if (features_version_ != session.features_version()) {
    main_.feature_lines.upload(feature_segments(features, false));
    main_.feature_paths.upload(feature_segments(features, true));
    features_version_ = session.features_version();
  }
  if (const Comparison* comparison = session.shown_comparison();
      comparison && left_.version != session.comparison_version()) {
    upload(left_, comparison->left.mesh, session, {&comparison->left.fill});
    upload(right_, comparison->right.mesh, session, {&comparison->right.fill});
    left_.version = right_.version = session.comparison_version();
  }
}

void Renderer::render(Session& session, const Camera& camera, const PixelRect& scene,
                      int framebuffer_width, int framebuffer_height, const DisplayOptions& display,
                      int hovered_hole, bool camera_moving) {
  sync(session);
  const bool coarse = camera_moving && (session.shown_comparison() ? left_.proxy_triangles > 0 ||
                                                                         right_.proxy_triangles > 0
                                                                   : main_.proxy_triangles > 0);
  SceneKey key{camera.view(),
               camera.projection(),
               {scene.x, scene.y, scene.width, scene.height},
               {framebuffer_width, framebuffer_height},
               session.mesh_version(),
               session.comparison_version(),
               session.shown_comparison() != nullptr,
               session.selected(),
               hovered_hole,
               session.joined(),
               {display.wireframe, display.flat, display.patch_vertices, display.feature_lines},
               session.features_version(),
               coarse};
  if (cache_.show(key)) return;
  cache_.begin(key);
  glViewport(0, 0, framebuffer_width, framebuffer_height);
  clear_rect({0, 0, framebuffer_width, framebuffer_height}, framebuffer_height,
             palette::kBackground);
  if (session.shown_comparison()) {
    clear_rect(scene, framebuffer_height, palette::kDivider);
    const auto [left, right] = comparison_halves(scene);
    Camera half = camera;
    half.set_viewport({static_cast<float>(left.width), static_cast<float>(left.height)});
    clear_rect(left, framebuffer_height, palette::kBackground);
    clear_rect(right, framebuffer_height, palette::kBackground);
    const Highlight highlight{session.selected(), &session.joined(), -1};
    draw_view(left_, half, left, framebuffer_height, display, highlight, coarse);
    draw_view(right_, half, right, framebuffer_height, display, highlight, coarse);
  } else {
    Camera whole = camera;
    whole.set_viewport({static_cast<float>(scene.width), static_cast<float>(scene.height)});
    draw_view(main_, whole, scene, framebuffer_height, display,
              {session.selected(), &session.joined(), hovered_hole}, coarse);
  }
  glViewport(0, 0, framebuffer_width, framebuffer_height);
  cache_.end();
}

void Renderer::draw_view(const MeshLayer& layer, const Camera& camera, const PixelRect& rect,
                         int framebuffer_height, const DisplayOptions& display,
                         const Highlight& highlight, bool coarse) {
  glViewport(rect.x, framebuffer_height - rect.y - rect.height, rect.width, rect.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  const ViewTransform transform{camera.view(), camera.projection(),
                                camera.pixel_size_at_unit_depth(), 0.004f * layer.radius};
  if (coarse && layer.proxy_triangles > 0) {
    draw_surface(layer.proxy, transform, display);  // no wireframe or dots: a proxy has neither
  } else {
    draw_surface(layer.surface, transform, display);
    draw_edges_and_dots(layer, transform, rect, display);
  }
  draw_outlines(layer, transform, rect, highlight);
  if (display.feature_lines) draw_features(layer, transform, rect);
  glDisable(GL_DEPTH_TEST);
}

void Renderer::draw_surface(const MeshBuffers& surface, const ViewTransform& transform,
                            const DisplayOptions& display) {
  // The surface is pushed back a little so that edges and dots drawn on it win the depth test.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  surface_program_.use();
  surface_program_.set("u_view", transform.view);
  surface_program_.set("u_projection", transform.projection);
  surface_program_.set("u_flat", display.flat ? 1 : 0);
  surface_program_.set("u_face_stages", 0);
  const glm::vec3 stage_colors[4] = {rgb(palette::kSurface), rgb(palette::kTriangulated),
                                     rgb(palette::kRefined), rgb(palette::kSmoothed)};
  surface_program_.set("u_stage_colors", stage_colors, 4);
  surface.draw_surface(0);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void Renderer::draw_edges_and_dots(const MeshLayer& layer, const ViewTransform& transform,
                                   const PixelRect& rect, const DisplayOptions& display) {
  solid_program_.use();
  solid_program_.set("u_view", transform.view);
  solid_program_.set("u_projection", transform.projection);
  solid_program_.set("u_depth_bias", 0.0f);
  solid_program_.set("u_pixel_size", transform.pixel_size);
  if (display.wireframe) {
    // Lines fade out where they run closer than a few pixels apart (solid.vert); faint lines
    // leave the depth buffer to the surface.
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    solid_program_.set("u_round", 0);
    solid_program_.set("u_fade", 1);
    solid_program_.set("u_fade_pixels",
                       glm::vec2(kWireframeFadePixels[0], kWireframeFadePixels[1]));
    solid_program_.set("u_color", rgba(palette::kWireframe));
    layer.surface.draw_edges();
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }
  solid_program_.set("u_fade", 0);
  if (display.patch_vertices) {
    glEnable(GL_PROGRAM_POINT_SIZE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    solid_program_.set("u_fade_pixels", glm::vec2(kDotFadePixels[0], kDotFadePixels[1]));
    solid_program_.set("u_round", 1);
    solid_program_.set("u_point_size", 6.0f);
    // A dot at most a third of the patch's mean edge across.
    solid_program_.set("u_point_world_size", layer.patch_edge_length / 3.0f);
    solid_program_.set("u_viewport_height", static_cast<float>(rect.height));
    solid_program_.set("u_depth_bias", transform.depth_bias);
    solid_program_.set("u_color", rgba(palette::kPatchVertex));
    layer.surface.draw_patch_vertices();
    glDisable(GL_BLEND);
    glDisable(GL_PROGRAM_POINT_SIZE);
  }
}

void Renderer::use_line_program(const ViewTransform& transform, const PixelRect& rect,
                                const Highlight& highlight, float width_pixels) {
  line_program_.use();
  line_program_.set("u_view", transform.view);
  line_program_.set("u_projection", transform.projection);
  line_program_.set("u_viewport", glm::vec2(rect.width, rect.height));
  line_program_.set("u_width", width_pixels);
  line_program_.set("u_depth_bias", transform.depth_bias);
  line_program_.set("u_pixel_size", transform.pixel_size);
  line_program_.set("u_pixel_bias", kOutlinePixelBias);
  line_program_.set("u_selected", highlight.selected);
  const int joined = std::min<int>(static_cast<int>(highlight.joined->size()), kMaxJoined);
  line_program_.set("u_joined_count", joined);
  if (joined > 0) line_program_.set("u_joined", highlight.joined->data(), joined);
  line_program_.set("u_hovered", highlight.hovered);
  line_program_.set("u_selected_color", rgba(palette::kSelectedBoundary));
  line_program_.set("u_joined_color", rgba(palette::kJoinedBoundary));
  line_program_.set("u_hovered_color", rgba(palette::kHoveredBoundary));
}

void Renderer::draw_outlines(const MeshLayer& layer, const ViewTransform& transform,
                             const PixelRect& rect, const Highlight& highlight) {
  use_line_program(transform, rect, highlight, 5.0f);
  line_program_.set("u_color", rgba(palette::kBoundary));
  layer.boundary.draw();
  line_program_.set("u_color", rgba(palette::kBorder));
  layer.borders.draw();
}

void Renderer::draw_features(const MeshLayer& layer, const ViewTransform& transform,
                             const PixelRect& rect) {
  // Thinner than the outlines, each kind in one colour (no highlighted id matches their -1).
  const std::vector<int> none;
  use_line_program(transform, rect, Highlight{-2, &none, -2}, 3.0f);
  line_program_.set("u_color", rgba(palette::kFeatureLine));
  layer.feature_lines.draw();
  line_program_.set("u_color", rgba(palette::kFeaturePath));
  layer.feature_paths.draw();
}

std::vector<std::uint8_t> Renderer::read_pixels(int width, int height) const {
  std::vector<std::uint8_t> bottom_up(static_cast<std::size_t>(width) * height * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.data());
  std::vector<std::uint8_t> top_down(bottom_up.size());
  const std::size_t row = static_cast<std::size_t>(width) * 3;
  for (int y = 0; y < height; ++y) {
    std::copy_n(bottom_up.begin() + static_cast<std::ptrdiff_t>(y * row), row,
                top_down.begin() + static_cast<std::ptrdiff_t>((height - 1 - y) * row));
  }
  return top_down;
}

}  // namespace holefill::viewer
