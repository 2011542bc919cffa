// The mesh file formats holefill reads and writes, and the one place where a file name's
// extension becomes a format: reading (io.h, where the contents do not say), writing, the command
// line's check of -o and the viewer's file dialogs all ask format_from_path.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace holefill {

// OBJ and OFF are text; PLY is text or binary (written in the encoding it was read with,
// attributes.h); STL is read as text or binary and written binary.
enum class MeshFormat { Obj, Off, Ply, Stl };

// Every format, in the order messages list them (".obj, .off, .ply or .stl").
inline constexpr std::array<MeshFormat, 4> kMeshFormats{MeshFormat::Obj, MeshFormat::Off,
                                                        MeshFormat::Ply, MeshFormat::Stl};

// The format `path`'s extension names, in any case (".PLY" is PLY); nullopt for another
// extension or none.
std::optional<MeshFormat> format_from_path(const std::filesystem::path& path);

// `path`'s extension in lower case with its dot, "" when it has none: what a message about an
// extension that names no format quotes.
std::string lowercase_extension(const std::filesystem::path& path);

// ".obj", ".off", ".ply" or ".stl".
std::string_view extension_of(MeshFormat format);

// "obj", "off", "ply" or "stl" (LoadReport::format, the CLI's --format).
std::string_view name_of(MeshFormat format);

}  // namespace holefill
