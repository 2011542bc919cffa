// Gives a mesh built from a soup (soup_to_mesh) what the soup carried beyond positions and
// faces: attributes.h's vertex and face values and obj_attributes.h's corners, faces and tables.
#pragma once

#include <vector>

#include "mesh_from_triangles.h"
#include "soup.h"

namespace holefill::io {

// Where the mesh's elements came from: the soup position of each vertex, the soup polygon of
// each face, and, when the soup has corner values, for each face the soup corners (indices
// into soup.corners) its triangle was made of, in the triangle's order: the order of the face's
// halfedges from its own, corner c at the end of the c-th (mesh_from_triangles.h: a face's
// halfedge arrives at its triangle's first corner).
struct SoupOrigins {
  std::vector<int> vertex;             // per mesh vertex: soup position
  std::vector<int> face;               // per mesh face: soup polygon
  std::vector<Triangle> face_corners;  // per mesh face: soup corners (when needed)
};

// Whether the soup carries values per corner (the origins' corners are then needed).
bool has_corner_values(const Soup& soup);

// Whether the soup carries anything copy_soup_attributes would copy.
bool has_attributes(const Soup& soup);

// Records on the mesh how the file stored positions and faces (a PLY's encoding and types),
// when that differs from what a PLY is written as by default, so that a PLY with no other
// properties is written back as it was read (binary stays binary, floats stay floats).
void keep_file_format(const Soup& soup, Mesh& mesh);

// Adds to `mesh`, which has no elements yet, the OBJ properties copy_soup_attributes fills (when
// the soup carries OBJ values): added to a mesh with elements, each was made, zeroed and made
// again with the mesh's room; added before, they take the room the mesh is reserved with (on huge
// pages, mesh_from_triangles.h).
void add_soup_properties(const Soup& soup, Mesh& mesh);

// Copies the soup's attributes to the mesh's elements (nothing when it carries none), each half
// of the elements on its own thread when `two`; the soup's OBJ tables are moved to the mesh.
void copy_soup_attributes(Soup& soup, const SoupOrigins& origins, Mesh& mesh, bool two);

}  // namespace holefill::io
