// Saving the rendered window as a PNG (stb_image_write from Debian's libstb).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace holefill::viewer {

// `rgb` holds height rows of width RGB pixels, top row first. Throws std::runtime_error when
// the file cannot be written.
void write_png(const std::filesystem::path& path, int width, int height,
               const std::vector<std::uint8_t>& rgb);

}  // namespace holefill::viewer
