#include "mesh_object.h"

#include <pybind11/stl/filesystem.h>

#include <memory>
#include <stdexcept>

#include "array_conversion.h"
#include "errors.h"
#include "holefill/io.h"
#include "holefill/mesh_arrays.h"

namespace py = pybind11;

namespace holefill::python {
namespace {

const char* const kMeshDoc = R"doc(A triangle mesh, as holefill fills it.

Mesh(vertices, faces, vertex_colors=None, vertex_normals=None, vertex_attributes=None,
face_attributes=None) builds one from arrays: vertices n x 3 (float64; other real dtypes are
converted), faces m x 3 vertex indices (int64; other integer dtypes are converted, floats
refused); vertex_colors n x 3 or n x 4 (uint8 0-255 or floating-point 0-1), vertex_normals
n x 3, and named columns of vertex or face values (dicts of name -> 1-D array). The arrays go
through the checks and repairs a loaded file gets (faces flipped to agree, duplicates dropped,
non-manifold edges split apart), each kind named in a HolefillWarning; bad arrays raise
holefill.Error.

The arrays the properties give are copies: changing them leaves the mesh as it is.)doc";

std::string lines_of(const std::vector<std::string>& warnings, const std::string& name) {
  std::string text;
  for (const auto& warning : warnings) text += name + ": " + warning + "\n";
  return text;
}

std::unique_ptr<MeshObject> from_arrays(py::handle vertices, py::handle faces, py::handle colors,
                                        py::handle normals, py::handle vertex_attributes,
                                        py::handle face_attributes) {
  MeshArrays arrays =
      arrays_from_python(vertices, faces, colors, normals, vertex_attributes, face_attributes);
  LoadReport report;
  std::unique_ptr<MeshObject> object;
  {
    const py::gil_scoped_release release;
    const std::string name = "Mesh(vertices, faces)";
    object = std::make_unique<MeshObject>(
        [&] { return mesh_from_arrays(std::move(arrays), name, &report); }, name);
  }
  warn_lines(lines_of(report.warnings, object->name));
  return object;
}

std::unique_ptr<MeshObject> load(const std::filesystem::path& path, unsigned threads) {
  LoadReport report;
  std::unique_ptr<MeshObject> object;
  {
    const py::gil_scoped_release release;
    object = std::make_unique<MeshObject>([&] { return load_mesh(path, &report, threads); },
                                          path.string());
  }
  warn_lines(lines_of(report.warnings, object->name));
  return object;
}

void save(MeshObject& object, const std::filesystem::path& path) {
  const MeshUse use(object);
  std::vector<std::string> losses;
  {
    const py::gil_scoped_release release;
    save_mesh(object.mesh, path);
    losses = attributes_not_written(object.mesh, path);
  }
  std::string text;
  for (const auto& lost : losses) {
    text += path.string() + ": not written (the format cannot hold them): " + lost + "\n";
  }
  warn_lines(text);
}

std::unique_ptr<MeshObject> copy(const MeshObject& object) {
  require_idle(object);
  return std::make_unique<MeshObject>([&] { return Mesh(object.mesh); }, object.name);
}

// A read of the mesh while no other thread uses it.
template <class Read>
auto reading(Read read) {
  return [read](const MeshObject& object) {
    require_idle(object);
    return read(object.mesh);
  };
}

}  // namespace

MeshUse::MeshUse(MeshObject& object) : object_(object) {
  require_idle(object);
  object_.busy = true;
}

MeshUse::~MeshUse() { object_.busy = false; }

void require_idle(const MeshObject& object) {
  if (object.busy) {
    throw std::runtime_error(object.name +
                             ": the mesh is in use by another thread (a fill or a save)");
  }
}

void bind_mesh(py::module_& module) {
  py::class_<MeshObject>(module, "Mesh", kMeshDoc)
      .def(py::init(&from_arrays), py::arg("vertices"), py::arg("faces"),
           py::arg("vertex_colors") = py::none(), py::arg("vertex_normals") = py::none(),
           py::arg("vertex_attributes") = py::none(), py::arg("face_attributes") = py::none())
      .def_property_readonly("vertices", reading(vertex_array),
                             "Positions, n x 3 float64 (a copy).")
      .def_property_readonly("faces", reading(face_array),
                             "Triangles, m x 3 int64 vertex indices in the order files are "
                             "written (a copy).")
      .def_property_readonly("vertex_colors", reading(color_array),
                             "Vertex colours in [0, 1], n x 3 float64 (red, green, blue over the "
                             "type's full intensity: 255 for uint8), or None.")
      .def_property_readonly("vertex_normals", reading(normal_array),
                             "Vertex normals (nx, ny, nz), n x 3 float64, or None.")
      .def_property_readonly("vertex_attributes", reading(vertex_attribute_arrays),
                             "Every vertex attribute (colours, normals, quality, any PLY "
                             "property): name -> float64 array of the values as held.")
      .def_property_readonly("face_attributes", reading(face_attribute_arrays),
                             "Every face attribute: name -> float64 array of the values as held.")
      .def_property_readonly("n_vertices", reading([](const Mesh& mesh) {
                               return static_cast<std::size_t>(mesh.n_vertices());
                             }))
      .def_property_readonly("n_faces", reading([](const Mesh& mesh) {
                               return static_cast<std::size_t>(mesh.n_faces());
                             }))
      .def_readonly("name", &MeshObject::name,
                    "The file the mesh was loaded from, or 'Mesh(vertices, faces)'; messages "
                    "name it.")
      .def("save", &save, py::arg("path"),
           "Writes the mesh as OBJ, OFF, PLY or binary STL (by extension) with every attribute "
           "the format holds, atomically (the whole file or nothing); a HolefillWarning names "
           "what the format cannot hold. Raises holefill.Error when it cannot be written.")
      .def("copy", &copy, "A copy of the mesh, with its attributes.")
      .def("__copy__", &copy)
      .def("__deepcopy__", [](const MeshObject& object, py::handle) { return copy(object); })
      .def("__repr__", [](const MeshObject& object) {
        require_idle(object);
        return "<holefill.Mesh " + object.name + ": " + std::to_string(object.mesh.n_vertices()) +
               " vertices, " + std::to_string(object.mesh.n_faces()) + " faces>";
      });
  module.def("load", &load, py::arg("path"), py::kw_only(), py::arg("threads") = 0u,
             "Loads an OBJ, OFF, PLY or STL mesh with the attributes its file carries; what "
             "loading repaired or could not keep comes as a HolefillWarning each. Raises "
             "holefill.Error when the file cannot be read as a mesh. A big file is read on up "
             "to `threads` threads (0: every core this process may run on), as fill's threads= "
             "bounds preparing and filling: several loads or fills at once (Python threads: "
             "they run without the GIL) should share the cores, e.g. threads=os.cpu_count() // "
             "n each for n at once, or they run n x cores threads. The mesh is the same "
             "whatever the number.");
}

}  // namespace holefill::python
