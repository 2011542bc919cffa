// holefill.Mesh: a holefill::Mesh held by Python, with the name its messages use (the file it
// was loaded from), and a mark while work that runs without the GIL (a fill, a save) uses it, so
// that another Python thread touching the same mesh meanwhile gets an error, not a torn mesh.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <cstdint>
#include <string>
#include <utility>

#include "holefill/mesh.h"

namespace holefill::python {

struct MeshObject {
  // `make` returns the mesh, which is built in place: assigning a Mesh copies it (OpenMesh's
  // kernel has no move assignment).
  template <class Make>
  MeshObject(Make&& make, std::string name_) : mesh(make()), name(std::move(name_)) {}

  Mesh mesh;
  std::string name;  // the file's path, or "Mesh(vertices, faces)"
  std::atomic<bool> busy{false};
  // Counts the changes made through Python (fills, stages, undos), so that a staged Fill can
  // tell that the mesh changed under it.
  std::uint64_t version = 0;
};

// Marks `object` as in use for its lifetime. Throws RuntimeError when another thread uses it.
class MeshUse {
 public:
  explicit MeshUse(MeshObject& object);
  ~MeshUse();
  MeshUse(const MeshUse&) = delete;
  MeshUse& operator=(const MeshUse&) = delete;

 private:
  MeshObject& object_;
};

// Throws RuntimeError while another thread uses `object` (for reads that hold the GIL).
void require_idle(const MeshObject& object);

// Adds Mesh, load() and the conversions from and to numpy arrays to `module`.
void bind_mesh(pybind11::module_& module);

}  // namespace holefill::python
