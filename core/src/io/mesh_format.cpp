#include "holefill/mesh_format.h"

#include <algorithm>

namespace holefill {

std::string lowercase_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string_view extension_of(MeshFormat format) {
  switch (format) {
    case MeshFormat::Obj:
      return ".obj";
    case MeshFormat::Off:
      return ".off";
    case MeshFormat::Ply:
      return ".ply";
    case MeshFormat::Stl:
      return ".stl";
  }
  return {};
}

std::string_view name_of(MeshFormat format) { return extension_of(format).substr(1); }

std::optional<MeshFormat> format_from_path(const std::filesystem::path& path) {
  const std::string ext = lowercase_extension(path);
  for (const MeshFormat format : kMeshFormats) {
    if (ext == extension_of(format)) return format;
  }
  return std::nullopt;
}

}  // namespace holefill
