// What the renderer uploads: here the per-vertex edge lengths that fade the wireframe where it
// crowds, against each vertex's edges walked on the mesh itself.
#include "scene_arrays.h"

#include <gtest/gtest.h>

#include "test_sessions.h"

namespace holefill::viewer {
namespace {

TEST(SceneArrays, EachVertexCarriesTheMeanLengthOfItsEdges) {
  const Session session = bunny_session();
  Mesh mesh = session.mesh();
  const VertexHandle lone = mesh.add_vertex(Point(9.0, 9.0, 9.0));  // no edges
  const SurfaceArrays arrays = surface_arrays(mesh, {});
  ASSERT_EQ(arrays.vertex_edge_lengths.size(), mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    double sum = 0.0;
    int count = 0;
    for (const auto w : mesh.vv_range(v)) {
      sum += (mesh.point(w) - mesh.point(v)).norm();
      ++count;
    }
    const double expected = count > 0 ? sum / count : 0.0;
    EXPECT_NEAR(arrays.vertex_edge_lengths[v.idx()], expected, 1e-5 * (1.0 + expected))
        << "vertex " << v.idx();
  }
  EXPECT_EQ(arrays.vertex_edge_lengths[lone.idx()], 0.0f);
}

}  // namespace
}  // namespace holefill::viewer
