// The mesh type every stage works on: an OpenMesh triangle mesh with double-precision points,
// so that original coordinates read from a file survive a fill bit for bit. What a file carries
// beyond positions (colours, normals, any PLY property) rides along as named OpenMesh properties
// ("holefill:attributes", "holefill:v:NAME", "holefill:f:NAME"): see attributes.h; code that
// re-adds elements should copy all properties (copy_all_properties) so they survive.
// A Mesh carries no status flags (OpenMesh's 4 bytes on every element, a quarter of a big mesh):
// the library's code that deletes elements requests them only for the deletion's duration, so
// between operations no element is marked deleted and the iterators skip none.
#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace holefill {

struct MeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};

using Mesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;
using Point = Mesh::Point;
using VertexHandle = OpenMesh::VertexHandle;
using FaceHandle = OpenMesh::FaceHandle;
using EdgeHandle = OpenMesh::EdgeHandle;
using HalfedgeHandle = OpenMesh::HalfedgeHandle;

}  // namespace holefill
