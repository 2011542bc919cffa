// Loading the input mesh for a command, with the loader's warnings on stderr.
#pragma once

#include <string>

#include "commands.h"
#include "holefill/mesh.h"

namespace holefill::cli {

// Loads `path`; prints each warning of the loader as "holefill: PATH: WARNING".
// Throws FileError (exit kBadInput) when the file cannot be read as a mesh.
Mesh load_and_warn(const std::string& path, const Streams& streams);

}  // namespace holefill::cli
