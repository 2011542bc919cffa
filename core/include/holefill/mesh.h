// The mesh type every stage works on: an OpenMesh triangle mesh with double-precision points,
// so that original coordinates read from a file survive a fill bit for bit. What a file carries
// beyond positions (colours, normals, any PLY property) rides along as named OpenMesh properties
// ("holefill:attributes", "holefill:v:NAME", "holefill:f:NAME"): see attributes.h; code that
// re-adds elements should copy all properties (copy_all_properties) so they survive.
#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace holefill {

struct MeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status);
};

using Mesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;
using Point = Mesh::Point;
using VertexHandle = OpenMesh::VertexHandle;
using FaceHandle = OpenMesh::FaceHandle;
using EdgeHandle = OpenMesh::EdgeHandle;
using HalfedgeHandle = OpenMesh::HalfedgeHandle;

}  // namespace holefill
