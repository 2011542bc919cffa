# Writes OUTPUT: a C++ file defining holefill::viewer::shader_source(name) over the files in
# SHADERS (separated by |), each embedded as a raw string literal. Run by the build whenever a shader changes.
set(body "// Generated from shaders/ by app/viewer/embed_shaders.cmake; do not edit.\n")
string(APPEND body "#include \"shader_sources.h\"\n\n#include <stdexcept>\n#include <string>\n\n")
string(APPEND body "namespace holefill::viewer {\n\nstd::string_view shader_source(std::string_view name) {\n")
string(REPLACE "|" ";" SHADERS "${SHADERS}")
foreach(shader IN LISTS SHADERS)
  get_filename_component(name ${shader} NAME)
  file(READ ${shader} text)
  string(APPEND body "  if (name == \"${name}\") return R\"glsl(${text})glsl\";\n")
endforeach()
string(APPEND body "  throw std::runtime_error(\"no embedded shader named \" + std::string(name));\n}\n\n}  // namespace holefill::viewer\n")
file(WRITE ${OUTPUT}.tmp "${body}")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
