// A coarse stand-in for a big mesh, drawn while the camera moves (issue 31, #10): under a
// software renderer a million-triangle mesh takes about half a second a frame, so orbiting it
// jumps; MeshLab and Meshmixer draw a coarser proxy while the view moves and the whole mesh once
// it stops. The proxy clusters the vertices on a uniform grid (Rossignac & Borrel's vertex
// clustering): each occupied cell becomes one vertex at the mean of its vertices, and a triangle
// whose corners fall in three different cells becomes one proxy triangle (once, however many
// triangles map to it, and not when it turns against its corners' normals: a fold). Linear in
// the mesh but for a sort of the proxy's triangles; no GL.
#pragma once

#include <cstddef>

#include "scene_arrays.h"

namespace holefill::viewer {

// Meshes above this many triangles get a proxy (below, a frame is fast enough as it is).
inline constexpr std::size_t kProxyAboveTriangles = 400'000;
// About how many triangles the proxy aims at.
inline constexpr std::size_t kProxyTriangles = 60'000;

// The proxy of `full` with about `target` triangles (between a quarter and twice as many on a
// surface mesh, never more than `full` has): positions, normals and colours (the means of the
// cell's vertices') and the stage of one of the triangles each proxy triangle stands for; no edges,
// no patch vertices. The bounding box is `full`'s. No triangles at all when the vertices scatter
// over more than 2^21 cells (then there is no proxy to draw).
SurfaceArrays coarse_proxy(const SurfaceArrays& full, std::size_t target);

}  // namespace holefill::viewer
