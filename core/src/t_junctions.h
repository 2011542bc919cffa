// T-junctions along cracks (stitch.h): where the two sides of a zero-width crack were meshed
// apart, one side has vertices where the other has none (CAD faces tessellated one by one, pieces
// remeshed separately). Such a vertex lies inside a boundary edge of the other side, so no pair
// of boundary edges matches end to end and stitching alone leaves a sliver "hole" that no
// triangle of positive area can fill. Splitting that edge at the vertex gives the stitch its pair.
#pragma once

#include <vector>

#include "boundary_points.h"
#include "holefill/mesh.h"

namespace holefill::detail {

// A boundary vertex lying inside a boundary halfedge of the other side of a crack.
struct TJunction {
  HalfedgeHandle edge;  // the boundary halfedge a->b to split
  VertexHandle vertex;  // the vertex on it
  double along = 0.0;   // where the vertex projects onto a->b, 0 at a and 1 at b
};

// The T-junctions of the mesh, ordered by halfedge and then by `along`. A boundary vertex v is
// one for halfedge a->b when it lies within `tolerance` of the segment, farther than `tolerance`
// from both ends, and its own boundary runs back along the segment: a boundary neighbour of v
// (the vertex before or after it on its loop) lies within `tolerance` of the line through a and b
// on the side that makes the two boundaries run in opposite directions, as the two sides of a
// crack do (the stitch could not match the split edge otherwise: this spares it the trial). A
// vertex merely touching an edge (a fin, a pinch) is not one, nor is any vertex on
// an edge that already has a partner end to end (the stitch joins that pair; a third sheet's
// vertex on it does not make a crack).
// `index` is the mesh's (boundary_points.h); `with_partner` lists, in increasing order, the
// boundary halfedges that already lie on another end to end (the stitch's matching). Searches
// on up to `threads` threads; the junctions are the same on any number.
std::vector<TJunction> find_t_junctions(const Mesh& mesh, const BoundaryIndex& index,
                                        double tolerance, const std::vector<int>& with_partner,
                                        unsigned threads = 1);

// Splits each junction's edge at a new vertex placed exactly on the junction's vertex, which the
// stitch then merges into it (the new vertex has the higher index, so the junction's vertex is
// the one kept). The face beside the edge is split in two: both halves keep the face's
// properties; OBJ corners (texture coordinates, normals) at the new vertex are interpolated
// along the edge, the other corners keep their values. Returns the new vertices, one per
// junction in the order given. `junctions` must come from find_t_junctions on this mesh.
std::vector<VertexHandle> split_at_t_junctions(Mesh& mesh, const std::vector<TJunction>& junctions);

}  // namespace holefill::detail
