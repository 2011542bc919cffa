// Loading the input mesh for a command, with the loader's warnings on stderr.
#pragma once

#include <string>

#include "commands.h"
#include "holefill/mesh.h"

namespace holefill::cli {

// Loads `path`, or standard input (streams.in) when it is "-", read as `format` (obj, off, ply
// or stl; required then). Prints each warning of the loader as "holefill: PATH: WARNING".
// Throws FileError (exit kBadInput) when the bytes cannot be read as a mesh, UsageError when "-"
// comes without a format. Reads on up to `threads` threads (load_mesh's; 0: every core).
Mesh load_and_warn(const std::string& path, const std::string& format, const Streams& streams,
                   unsigned threads = 0);

}  // namespace holefill::cli
