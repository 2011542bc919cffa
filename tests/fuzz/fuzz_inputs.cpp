#include "fuzz_inputs.h"

#include <cmath>
#include <cstring>
#include <exception>

#include "fill_guarantees.h"
#include "holefill/attributes.h"
#include "holefill/errors.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"

namespace holefill::fuzz {
namespace {

// Inputs are small: holes up to this size are filled, and refinement is capped, so that one
// input takes milliseconds.
constexpr std::size_t kMaxFilledEdges = 24;
constexpr std::size_t kMaxFilledHoles = 6;
constexpr std::size_t kMaxPatchFaces = 20000;

std::string fill_and_check(const Mesh& before, const FillOptions& options, bool stepped) {
  const auto holes = find_holes(before);
  HoleSelection selection;
  selection.max_boundary_edges = kMaxFilledEdges;
  for (const auto& hole : holes) {
    if (selection.hole_ids.size() < kMaxFilledHoles && selection.includes(hole)) {
      selection.hole_ids.push_back(hole.id);
    }
  }
  if (selection.hole_ids.empty()) return {};
  Mesh after = before;
  std::vector<HoleFill> fills;
  if (stepped) {
    fills.resize(holes.size());
    for (bool progress = true; progress;) {
      progress = false;
      for (const int id : selection.hole_ids) {
        if (fills[id].stage() < options.last_stage &&
            advance(after, holes[id], fills[id], options) == StageRun::Ran) {
          progress = true;
        }
      }
    }
  } else {
    fills = fill_holes(after, holes, options, selection);
  }
  return testing::check_fill_guarantees(before, holes, after, fills);
}

// What was loaded, saved in its format and loaded again, is the same mesh: every position and
// attribute value bit for bit, the same faces. STL is left out: its positions are floats and
// equal ones are welded.
std::string round_trip_problem(const Mesh& mesh, const std::string& extension) {
  if (extension != ".obj" && extension != ".off" && extension != ".ply") return {};
  const Mesh again =
      load_mesh_from_memory(mesh_to_bytes(mesh, "again" + extension), "again" + extension);
  if (again.n_vertices() != mesh.n_vertices() || again.n_faces() != mesh.n_faces()) {
    return "saved and loaded again, the mesh has other counts";
  }
  for (const auto v : mesh.vertices()) {
    if (std::memcmp(&mesh.point(v), &again.point(v), sizeof(Point)) != 0) {
      return "saved and loaded again, vertex " + std::to_string(v.idx()) + " moved";
    }
  }
  for (const auto& a : attribute_layout(mesh).vertex) {
    const auto before = vertex_attribute(mesh, a.name), after = vertex_attribute(again, a.name);
    if (!after.is_valid()) return "saved and loaded again, the attribute " + a.name + " is gone";
    for (const auto v : mesh.vertices()) {
      const double x = mesh.property(before, v), y = again.property(after, v);
      if (std::memcmp(&x, &y, sizeof x) != 0 && !(std::isnan(x) && std::isnan(y))) {
        return "saved and loaded again, " + a.name + " of vertex " + std::to_string(v.idx()) +
               " changed";
      }
    }
  }
  return {};
}

}  // namespace

std::string load_input(const std::string& bytes, const std::string& extension) {
  try {
    LoadReport report;
    const Mesh mesh = load_mesh_from_memory(bytes, "input" + extension, &report);
    if (auto problem = testing::check_oriented(mesh); !problem.empty()) {
      return "the loaded mesh: " + problem;
    }
    for (const auto v : mesh.vertices()) {
      const Point& p = mesh.point(v);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
        return "the loaded mesh has a non-finite point";
      }
    }
    if (auto problem = round_trip_problem(mesh, extension); !problem.empty()) return problem;
    FillOptions options;
    options.refine.max_patch_faces = kMaxPatchFaces;
    return fill_and_check(mesh, options, false);
  } catch (const FileError&) {
    return {};
  } catch (const std::exception& e) {
    return std::string("unexpected exception: ") + e.what();
  }
}

std::string fill_input(const std::string& bytes) {
  auto byte = [&bytes](std::size_t i) {
    return i < bytes.size() ? static_cast<unsigned char>(bytes[i]) : 0u;
  };
  const int n = 3 + static_cast<int>(byte(0) % 30);
  FillOptions options;
  options.triangulate.weight = static_cast<WeightKind>(byte(1) % 3);
  options.triangulate.fold_limit = 0.3 + 2.9 * byte(2) / 255.0;
  options.smooth.method = (byte(3) & 1) ? SmoothMethod::Fair : SmoothMethod::Umbrella;
  options.last_stage = static_cast<Stage>(1 + (byte(3) >> 1) % 3);
  const bool stepped = (byte(3) & 8) != 0;
  options.smooth.fair.order = 2 + ((byte(3) >> 4) & 1);
  options.refine.tau = 0.5 + byte(4) / 64.0;
  options.smooth.iterations = static_cast<int>(byte(5) % 20);
  options.smooth.step = (1 + byte(6)) / 256.0;
  options.refine.max_patch_faces = kMaxPatchFaces;
  options.refine.remesh = (byte(6) & 1) != 0;  // shares the step's byte, so inputs keep meaning

  // The polygon's points on a grid of 0.1, and an outer ring pushed out from their centre.
  std::vector<Point> inner;
  Point centre(0, 0, 0);
  for (int i = 0; i < n; ++i) {
    Point p;
    for (int axis = 0; axis < 3; ++axis) {
      p[axis] = 0.1 * static_cast<signed char>(byte(7 + 3 * i + axis));
    }
    inner.push_back(p);
    centre += p / n;
  }
  Mesh mesh;
  for (const auto& p : inner) mesh.add_vertex(p);
  for (const auto& p : inner) mesh.add_vertex(centre + (p - centre) * 2.0 + Point(0, 0, 1));
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.add_face(VertexHandle(i), VertexHandle(n + i), VertexHandle(n + j));
    mesh.add_face(VertexHandle(i), VertexHandle(n + j), VertexHandle(j));
  }
  try {
    return fill_and_check(mesh, options, stepped);
  } catch (const std::exception& e) {
    return std::string("unexpected exception: ") + e.what();
  }
}

}  // namespace holefill::fuzz
