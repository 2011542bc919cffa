#include "writers.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "holefill/attributes.h"
#include "text_out.h"

namespace holefill::io {
namespace {

// The value as `type` stores it: rounded and clamped for integer types (interpolated colours).
template <class T>
T stored(double value) {
  if constexpr (std::is_floating_point_v<T>) {
    return static_cast<T>(value);
  } else {
    if (std::isnan(value)) return T{0};
    const double clamped = std::clamp(std::round(value), double(std::numeric_limits<T>::min()),
                                      double(std::numeric_limits<T>::max()));
    return static_cast<T>(clamped);
  }
}

// Appends `value` as `type`: text (shortest round trip) or binary in the encoding's byte order.
class ValueWriter {
 public:
  ValueWriter(std::string& out, FileEncoding encoding) : out_(out), encoding_(encoding) {}

  void write(double value, ScalarType type) {
    switch (type) {
      case ScalarType::Int8:
        return put<std::int8_t>(value);
      case ScalarType::UInt8:
        return put<std::uint8_t>(value);
      case ScalarType::Int16:
        return put<std::int16_t>(value);
      case ScalarType::UInt16:
        return put<std::uint16_t>(value);
      case ScalarType::Int32:
        return put<std::int32_t>(value);
      case ScalarType::UInt32:
        return put<std::uint32_t>(value);
      case ScalarType::Float32:
        return put<float>(value);
      case ScalarType::Float64:
        return put<double>(value);
    }
  }
  // Between values of a record (text only).
  void separate() {
    if (encoding_ == FileEncoding::Ascii) out_ += ' ';
  }
  void end_record() {
    if (encoding_ == FileEncoding::Ascii) out_ += '\n';
  }

 private:
  template <class T>
  void put(double value) {
    const T typed = stored<T>(value);
    if (encoding_ == FileEncoding::Ascii) {
      if constexpr (std::is_floating_point_v<T>) {
        append_number(out_, typed);
      } else {
        append_number(out_, static_cast<long long>(typed));
      }
      return;
    }
    char raw[sizeof(T)];
    std::memcpy(raw, &typed, sizeof(T));
    const bool big = encoding_ == FileEncoding::BinaryBigEndian;
    if (big != (std::endian::native == std::endian::big)) std::reverse(raw, raw + sizeof(T));
    out_.append(raw, sizeof(T));
  }

  std::string& out_;
  FileEncoding encoding_;
};

const char* type_name(ScalarType type) {
  static const char* const kNames[] = {"char", "uchar", "short", "ushort",
                                       "int",  "uint",  "float", "double"};
  return kNames[static_cast<int>(type)];
}

std::string ply_header(const Mesh& mesh, const AttributeLayout& layout) {
  static const char* const kEncodings[] = {"ascii", "binary_little_endian", "binary_big_endian"};
  std::string out = std::string("ply\nformat ") + kEncodings[static_cast<int>(layout.encoding)] +
                    " 1.0\ncomment written by holefill\nelement vertex " +
                    std::to_string(mesh.n_vertices()) + "\n";
  for (int axis = 0; axis < 3; ++axis) {
    out += std::string("property ") + type_name(layout.position_types[axis]) + " " +
           static_cast<char>('x' + axis) + "\n";
  }
  for (const auto& a : layout.vertex)
    out += "property " + std::string(type_name(a.type)) + " " + a.name + "\n";
  out += "element face " + std::to_string(mesh.n_faces()) + "\nproperty list " +
         type_name(layout.face_count_type) + " " + type_name(layout.face_index_type) +
         " vertex_indices\n";
  for (const auto& a : layout.face)
    out += "property " + std::string(type_name(a.type)) + " " + a.name + "\n";
  return out + "end_header\n";
}

// PLY in the layout's encoding and types (ASCII doubles when the mesh came from elsewhere).
void write_ply(const Mesh& mesh, PieceOut& out) {
  const AttributeLayout layout = attribute_layout(mesh);
  out.text = ply_header(mesh, layout);
  const auto vertex_values = vertex_attributes(mesh, layout.vertex);
  out.records(mesh.n_vertices(), [&](std::string& text, std::size_t first, std::size_t last) {
    ValueWriter writer(text, layout.encoding);
    for (std::size_t i = first; i < last; ++i) {
      const VertexHandle v(static_cast<int>(i));
      for (int axis = 0; axis < 3; ++axis) {
        if (axis) writer.separate();
        writer.write(mesh.point(v)[axis], layout.position_types[axis]);
      }
      for (std::size_t a = 0; a < vertex_values.size(); ++a) {
        writer.separate();
        writer.write(mesh.property(vertex_values[a], v), layout.vertex[a].type);
      }
      writer.end_record();
    }
  });
  const auto face_values = face_attributes(mesh, layout.face);
  out.records(mesh.n_faces(), [&](std::string& text, std::size_t first, std::size_t last) {
    ValueWriter writer(text, layout.encoding);
    for (std::size_t i = first; i < last; ++i) {
      const FaceHandle f(static_cast<int>(i));
      writer.write(3.0, layout.face_count_type);
      for (const auto v : mesh.fv_range(f)) {
        writer.separate();
        writer.write(v.idx(), layout.face_index_type);
      }
      for (std::size_t a = 0; a < face_values.size(); ++a) {
        writer.separate();
        writer.write(mesh.property(face_values[a], f), layout.face[a].type);
      }
      writer.end_record();
    }
  });
}

// OFF; COFF, NOFF or CNOFF with the colours (in their own type: 0-255 or 0-1) and normals the
// mesh carries, in the order the format puts them: position, normal, colour.
void write_off(const Mesh& mesh, PieceOut& out) {
  const AttributeLayout layout = attribute_layout(mesh);
  std::vector<std::pair<OpenMesh::VPropHandleT<double>, ScalarType>> normal, colour;
  for (const auto& a : layout.vertex) {
    if (a.name == "nx" || a.name == "ny" || a.name == "nz") {
      normal.emplace_back(vertex_attribute(mesh, a.name), a.type);
    }
  }
  for (const char* name : {"red", "green", "blue", "alpha"}) {
    const auto found = std::find_if(layout.vertex.begin(), layout.vertex.end(),
                                    [&](const ScalarAttribute& a) { return a.name == name; });
    if (found != layout.vertex.end())
      colour.emplace_back(vertex_attribute(mesh, name), found->type);
  }
  if (normal.size() != 3) normal.clear();
  if (colour.size() < 3) colour.clear();
  out.text = std::string(colour.empty() ? "" : "C") + (normal.empty() ? "" : "N") + "OFF\n" +
             std::to_string(mesh.n_vertices()) + ' ' + std::to_string(mesh.n_faces()) + " 0\n";
  out.records(mesh.n_vertices(), [&](std::string& text, std::size_t first, std::size_t last) {
    ValueWriter writer(text, FileEncoding::Ascii);
    append_vertices(mesh, text, first, last, "", [&](VertexHandle v) {
      for (const auto& list : {normal, colour}) {
        for (const auto& [property, type] : list) {
          writer.separate();
          writer.write(mesh.property(property, v), type);
        }
      }
    });
  });
  // Face attributes other than colours have no place in OFF.
  const bool only_colours = std::all_of(layout.face.begin(), layout.face.end(), [](const auto& a) {
    return a.name == "red" || a.name == "green" || a.name == "blue" || a.name == "alpha";
  });
  const auto face_colour = only_colours ? face_attributes(mesh, layout.face)
                                        : std::vector<OpenMesh::FPropHandleT<double>>{};
  out.records(mesh.n_faces(), [&](std::string& text, std::size_t first, std::size_t last) {
    ValueWriter writer(text, FileEncoding::Ascii);
    append_faces(mesh, text, first, last, "3 ", 0, [&](FaceHandle f) {
      for (std::size_t a = 0; a < face_colour.size(); ++a) {
        writer.separate();
        writer.write(mesh.property(face_colour[a], f), layout.face[a].type);
      }
    });
  });
}

// Binary STL: an 80-byte header, the count, and per triangle its normal, corners and 2 spare
// bytes, all little-endian floats.
void write_stl(const Mesh& mesh, PieceOut& out) {
  out.text = "binary STL written by holefill";
  out.text.resize(80, ' ');
  ValueWriter(out.text, FileEncoding::BinaryLittleEndian)
      .write(static_cast<double>(mesh.n_faces()), ScalarType::UInt32);
  out.records(mesh.n_faces(), [&](std::string& text, std::size_t first, std::size_t last) {
    ValueWriter writer(text, FileEncoding::BinaryLittleEndian);
    for (std::size_t i = first; i < last; ++i) {
      const FaceHandle f(static_cast<int>(i));
      const Point normal = mesh.calc_face_normal(f);
      for (int axis = 0; axis < 3; ++axis) writer.write(normal[axis], ScalarType::Float32);
      for (const auto v : mesh.fv_range(f)) {
        for (int axis = 0; axis < 3; ++axis) {
          writer.write(mesh.point(v)[axis], ScalarType::Float32);
        }
      }
      writer.write(0.0, ScalarType::UInt16);
    }
  });
}

}  // namespace

void write_mesh_file(const Mesh& mesh, MeshFormat format, const std::filesystem::path& output,
                     const ByteWriter& write, unsigned threads) {
  PieceOut out(write, threads);
  switch (format) {
    case MeshFormat::Obj:
      write_obj(mesh, output, out);
      break;
    case MeshFormat::Off:
      write_off(mesh, out);
      break;
    case MeshFormat::Ply:
      write_ply(mesh, out);
      break;
    case MeshFormat::Stl:
      write_stl(mesh, out);
      break;
  }
  out.flush();
}

}  // namespace holefill::io
