#include "screenshot.h"

#include <stb_image_write.h>

#include <stdexcept>

namespace holefill::viewer {

void write_png(const std::filesystem::path& path, int width, int height,
               const std::vector<std::uint8_t>& rgb) {
  if (rgb.size() != static_cast<std::size_t>(width) * height * 3) {
    throw std::runtime_error("screenshot: pixel buffer does not match its size");
  }
  if (!stbi_write_png(path.string().c_str(), width, height, 3, rgb.data(), width * 3)) {
    throw std::runtime_error("could not write " + path.string());
  }
}

}  // namespace holefill::viewer
