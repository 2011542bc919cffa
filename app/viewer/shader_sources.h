// The GLSL sources of shaders/, embedded into the binary at build time (embed_shaders.cmake).
#pragma once

#include <string_view>

namespace holefill::viewer {

// The text of shaders/<name>, e.g. shader_source("surface.vert"); throws for an unknown name.
std::string_view shader_source(std::string_view name);

}  // namespace holefill::viewer
