// Named OpenMesh properties that the library keeps on a mesh (stages, attributes, OBJ tables).
#pragma once

#include "holefill/mesh.h"

namespace holefill::detail {

// Sets `handle` to the mesh's property called `name`, adding that property first when the mesh has
// none of the name (OpenMesh gives new elements its default value).
template <class Handle>
void find_or_add_property(Mesh& mesh, Handle& handle, const char* name) {
  if (!mesh.get_property_handle(handle, name)) mesh.add_property(handle, name);
}

}  // namespace holefill::detail
