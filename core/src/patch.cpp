#include "holefill/patch.h"

#include <cmath>

#include "geometry.h"
#include "property_handles.h"

namespace holefill {
namespace {
constexpr const char* kFaceStage = "holefill:face_stage";
constexpr const char* kVertexStage = "holefill:vertex_stage";
constexpr const char* kScale = "holefill:scale";

}  // namespace

const char* to_string(Stage stage) {
  switch (stage) {
    case Stage::Original:
      return "open";
    case Stage::Triangulated:
      return "triangulated";
    case Stage::Refined:
      return "refined";
    case Stage::Smoothed:
      return "smoothed";
  }
  return "?";
}

PatchTags::PatchTags(Mesh& mesh) {
  detail::find_or_add_property(mesh, face_stage, kFaceStage);
  detail::find_or_add_property(mesh, vertex_stage, kVertexStage);
  detail::find_or_add_property(mesh, scale, kScale);
}

Stage face_stage(const Mesh& mesh, FaceHandle face) {
  OpenMesh::FPropHandleT<std::uint8_t> handle;
  if (!mesh.get_property_handle(handle, kFaceStage)) return Stage::Original;
  return static_cast<Stage>(mesh.property(handle, face));
}

}  // namespace holefill
