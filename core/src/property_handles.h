// Named OpenMesh properties that the library keeps on a mesh (stages, attributes, OBJ tables).
#pragma once

#include <type_traits>

#include "holefill/mesh.h"
#include "mesh_room.h"

namespace holefill::detail {

// Sets `handle` to the mesh's property called `name`, adding that property first when the mesh has
// none of the name (OpenMesh gives new elements its default value). A property added gets the
// room the mesh's own arrays have (mesh_room.h): OpenMesh makes it of the elements' count exactly,
// so the first element added would copy it into an array twice its size.
template <class Handle>
struct IsMeshProperty : std::false_type {};  // one value for the whole mesh, not one per element
template <class T>
struct IsMeshProperty<OpenMesh::MPropHandleT<T>> : std::true_type {};

template <class Handle>
void find_or_add_property(Mesh& mesh, Handle& handle, const char* name) {
  if (mesh.get_property_handle(handle, name)) return;
  mesh.add_property(handle, name);
  if constexpr (!IsMeshProperty<Handle>::value) {
    auto& values = mesh.property(handle).data_vector();
    const std::size_t count = values.size();
    std::remove_reference_t<decltype(values)>().swap(values);  // default values only: none kept
    values.reserve(with_room(count));
    values.resize(count);
  }
}

}  // namespace holefill::detail
