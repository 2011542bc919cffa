#include "array_conversion.h"

#include <optional>

#include "holefill/errors.h"

namespace py = pybind11;

namespace holefill::python {
namespace {

const char* const kArraysName = "Mesh(vertices, faces)";

[[noreturn]] void refuse(const std::string& reason) { throw InvalidMeshError(kArraysName, reason); }

py::array as_array(py::handle value) {
  return py::module_::import("numpy").attr("asarray")(value).cast<py::array>();
}

std::string dtype_name(const py::array& array) {
  return py::str(array.dtype()).cast<std::string>();
}

// `value` as an array of `columns` columns (any when 0) and `rows` rows (any when -1).
py::array table(py::handle value, const std::string& what, py::ssize_t columns, py::ssize_t rows) {
  py::array array = as_array(value);
  const bool shaped =
      columns == 0 ? array.ndim() == 1 : array.ndim() == 2 && array.shape(1) == columns;
  if (!shaped || (rows >= 0 && array.shape(0) != rows)) {
    std::string shape;
    for (py::ssize_t d = 0; d < array.ndim(); ++d)
      shape += (d ? " x " : "") + std::to_string(array.shape(d));
    const std::string wanted = (rows >= 0 ? std::to_string(rows) : std::string("n")) +
                               (columns ? " x " + std::to_string(columns) : std::string());
    refuse(what + " must be an array of " + wanted + ", got shape (" + shape + ")");
  }
  return array;
}

template <class T>
py::array_t<T, py::array::c_style | py::array::forcecast> converted(const py::array& array) {
  return py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(array);
}

std::optional<ScalarType> scalar_type(const py::array& array) {
  const auto size = array.dtype().itemsize();
  switch (array.dtype().kind()) {
    case 'i':
      if (size == 1) return ScalarType::Int8;
      if (size == 2) return ScalarType::Int16;
      if (size == 4) return ScalarType::Int32;
      break;
    case 'u':
      if (size == 1) return ScalarType::UInt8;
      if (size == 2) return ScalarType::UInt16;
      if (size == 4) return ScalarType::UInt32;
      break;
    case 'f':
      if (size == 4) return ScalarType::Float32;
      if (size == 8) return ScalarType::Float64;
      break;
    default:
      break;
  }
  return std::nullopt;
}

// Adds each column of `array` (n x k, or a vector when `names` has one name) as an attribute.
void add_columns(const py::array& array, const std::vector<std::string>& names, ScalarType type,
                 std::vector<ScalarAttribute>& layout, std::vector<std::vector<double>>& columns) {
  const auto values = converted<double>(array);
  const auto rows = static_cast<std::size_t>(array.shape(0));
  const double* data = values.data();
  for (std::size_t c = 0; c < names.size(); ++c) {
    for (const auto& existing : layout) {
      if (existing.name == names[c]) refuse("the attribute '" + names[c] + "' is given twice");
    }
    layout.push_back({names[c], type});
    std::vector<double>& column = columns.emplace_back(rows);
    for (std::size_t r = 0; r < rows; ++r) column[r] = data[r * names.size() + c];
  }
}

void add_colors(py::handle value, py::ssize_t rows, MeshArrays& arrays) {
  py::array array = as_array(value);
  const py::ssize_t channels = array.ndim() == 2 ? array.shape(1) : 0;
  array = table(value, "vertex_colors", channels == 4 ? 4 : 3, rows);
  const char kind = array.dtype().kind();
  const bool bytes = kind == 'u' && array.dtype().itemsize() == 1;
  if (!bytes && kind != 'f') {
    refuse("vertex_colors must be uint8 (0-255) or floating-point (0-1), got " + dtype_name(array));
  }
  std::vector<std::string> names{"red", "green", "blue", "alpha"};
  names.resize(static_cast<std::size_t>(array.shape(1)));
  add_columns(array, names, bytes ? ScalarType::UInt8 : ScalarType::Float64, arrays.layout.vertex,
              arrays.vertex_values);
}

void add_named(py::handle dict, py::ssize_t rows, const char* what,
               std::vector<ScalarAttribute>& layout, std::vector<std::vector<double>>& columns) {
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(dict)) {
    const std::string name = py::str(key).cast<std::string>();
    const py::array array = table(value, std::string(what) + "['" + name + "']", 0, rows);
    const auto type = scalar_type(array);
    if (!type) {
      refuse(std::string(what) + "['" + name +
             "'] must be of a type a PLY property holds (int8 to uint32, float32, float64), got " +
             dtype_name(array));
    }
    add_columns(array, {name}, *type, layout, columns);
  }
}

py::array_t<double> column_array(const std::vector<double>& values) {
  py::array_t<double> array(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

// The values of the named vertex attributes, one column each; empty when one is missing.
std::vector<std::vector<double>> vertex_columns(const Mesh& mesh,
                                                const std::vector<std::string>& names) {
  std::vector<std::vector<double>> columns;
  for (const auto& name : names) {
    const auto handle = vertex_attribute(mesh, name);
    if (!handle.is_valid()) return {};
    auto& column = columns.emplace_back(mesh.n_vertices());
    for (const auto v : mesh.vertices()) column[v.idx()] = mesh.property(handle, v);
  }
  return columns;
}

py::object three_columns(const std::vector<std::vector<double>>& columns,
                         const std::vector<double>& scale) {
  if (columns.empty()) return py::none();
  const auto rows = static_cast<py::ssize_t>(columns[0].size());
  py::array_t<double> array({rows, py::ssize_t{3}});
  auto out = array.mutable_unchecked<2>();
  for (py::ssize_t r = 0; r < rows; ++r) {
    for (py::ssize_t c = 0; c < 3; ++c) out(r, c) = columns[c][r] / scale[c];
  }
  return array;
}

}  // namespace

MeshArrays arrays_from_python(py::handle vertices, py::handle faces, py::handle vertex_colors,
                              py::handle vertex_normals, py::handle vertex_attributes,
                              py::handle face_attributes) {
  MeshArrays arrays;
  const py::array v = table(vertices, "vertices", 3, -1);
  const char v_kind = v.dtype().kind();
  if (v_kind != 'f' && v_kind != 'i' && v_kind != 'u') {
    refuse("vertices must be real numbers (float64, or another float or integer type), got " +
           dtype_name(v));
  }
  const auto v_values = converted<double>(v);  // alive while its proxy reads it
  const auto positions = v_values.unchecked<2>();
  arrays.positions.resize(static_cast<std::size_t>(v.shape(0)));
  for (py::ssize_t i = 0; i < v.shape(0); ++i) {
    arrays.positions[i] = Point(positions(i, 0), positions(i, 1), positions(i, 2));
  }
  const py::array f = table(faces, "faces", 3, -1);
  const char f_kind = f.dtype().kind();
  if (f_kind != 'i' && f_kind != 'u') {
    refuse("faces must be integer vertex indices (int64, or another integer type), got " +
           dtype_name(f));
  }
  const auto f_values = converted<std::int64_t>(f);
  const auto corners = f_values.unchecked<2>();
  arrays.triangles.resize(static_cast<std::size_t>(f.shape(0)));
  for (py::ssize_t i = 0; i < f.shape(0); ++i) {
    arrays.triangles[i] = {corners(i, 0), corners(i, 1), corners(i, 2)};
  }
  const py::ssize_t n = v.shape(0);
  if (!vertex_colors.is_none()) add_colors(vertex_colors, n, arrays);
  if (!vertex_normals.is_none()) {
    const py::array normals = table(vertex_normals, "vertex_normals", 3, n);
    if (normals.dtype().kind() != 'f') {
      refuse("vertex_normals must be floating-point, got " + dtype_name(normals));
    }
    add_columns(normals, {"nx", "ny", "nz"}, ScalarType::Float64, arrays.layout.vertex,
                arrays.vertex_values);
  }
  if (!vertex_attributes.is_none()) {
    add_named(vertex_attributes, n, "vertex_attributes", arrays.layout.vertex,
              arrays.vertex_values);
  }
  if (!face_attributes.is_none()) {
    add_named(face_attributes, f.shape(0), "face_attributes", arrays.layout.face,
              arrays.face_values);
  }
  return arrays;
}

py::array_t<double> vertex_array(const Mesh& mesh) {
  py::array_t<double> array({static_cast<py::ssize_t>(mesh.n_vertices()), py::ssize_t{3}});
  auto out = array.mutable_unchecked<2>();
  for (const auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    for (int c = 0; c < 3; ++c) out(v.idx(), c) = p[c];
  }
  return array;
}

py::array_t<std::int64_t> face_array(const Mesh& mesh) {
  py::array_t<std::int64_t> array({static_cast<py::ssize_t>(mesh.n_faces()), py::ssize_t{3}});
  auto out = array.mutable_unchecked<2>();
  for (const auto f : mesh.faces()) {
    int c = 0;
    for (const auto v : mesh.fv_range(f)) out(f.idx(), c++) = v.idx();
  }
  return array;
}

py::object color_array(const Mesh& mesh) {
  const auto columns = vertex_columns(mesh, {"red", "green", "blue"});
  std::vector<double> full;
  const auto layout = attribute_layout(mesh).vertex;
  for (const char* name : {"red", "green", "blue"}) {
    for (const auto& attribute : layout) {
      if (attribute.name == name) full.push_back(full_intensity(attribute.type));
    }
  }
  return three_columns(columns, full);
}

py::object normal_array(const Mesh& mesh) {
  return three_columns(vertex_columns(mesh, {"nx", "ny", "nz"}), {1.0, 1.0, 1.0});
}

py::dict vertex_attribute_arrays(const Mesh& mesh) {
  py::dict result;
  for (const auto& attribute : attribute_layout(mesh).vertex) {
    result[py::str(attribute.name)] = column_array(vertex_columns(mesh, {attribute.name})[0]);
  }
  return result;
}

py::dict face_attribute_arrays(const Mesh& mesh) {
  py::dict result;
  for (const auto& attribute : attribute_layout(mesh).face) {
    const auto handle = face_attribute(mesh, attribute.name);
    std::vector<double> column(mesh.n_faces());
    for (const auto f : mesh.faces()) column[f.idx()] = mesh.property(handle, f);
    result[py::str(attribute.name)] = column_array(column);
  }
  return result;
}

}  // namespace holefill::python
