// Checks a screenshot of holefill-viewer for what the GUI tests expect to see. The colours come
// from the viewer's palette, so they cannot drift apart from what the renderer draws.
//   png_check IMAGE selected-present   the selected hole's outline colour covers >= 100 pixels
//   png_check IMAGE selected-absent    no pixel right of the panel has that colour
//   png_check IMAGE two-views          a divider column splits the 3D view into two halves,
//                                      each showing a mesh (many non-background pixels)
#include <stb_image.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "palette.h"
#include "ui_scale.h"

namespace palette = holefill::viewer::palette;

namespace {

struct Image {
  int width = 0, height = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> pixels{nullptr, stbi_image_free};
  bool is(int x, int y, const palette::Rgb& c) const {
    const unsigned char* p = pixels.get() + 3 * (static_cast<std::size_t>(y) * width + x);
    return p[0] == c[0] && p[1] == c[1] && p[2] == c[2];
  }
};

// Pixels of colour c in columns [x0, x1).
long count(const Image& image, int x0, int x1, const palette::Rgb& c) {
  long n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = x0; x < x1; ++x) n += image.is(x, y, c);
  }
  return n;
}

int check_two_views(const Image& image, int scene_x) {
  int divider = -1;
  for (int x = scene_x; x < image.width && divider < 0; ++x) {
    int rows = 0;
    for (int y = 0; y < image.height; ++y) rows += image.is(x, y, palette::kDivider);
    if (rows >= image.height * 9 / 10) divider = x;
  }
  if (divider < 0) {
    std::printf("FAIL: no divider column of colour (%d,%d,%d)\n", palette::kDivider[0],
                palette::kDivider[1], palette::kDivider[2]);
    return 1;
  }
  const auto mesh_pixels = [&](int x0, int x1) {
    const long area = static_cast<long>(x1 - x0) * image.height;
    return area - count(image, x0, x1, palette::kBackground) -
           count(image, x0, x1, palette::kDivider);
  };
  const long left = mesh_pixels(scene_x, divider);
  const long right = mesh_pixels(divider, image.width);
  const long needed = static_cast<long>(image.height) * (image.width - scene_x) / 20;
  std::printf("divider at x=%d; mesh pixels left %ld, right %ld (need %ld each)\n", divider, left,
              right, needed);
  const int centre = scene_x + (image.width - scene_x) / 2;
  if (divider < centre - 10 || divider > centre + 10) {
    std::printf("FAIL: the divider is not in the middle of the 3D view (x=%d)\n", centre);
    return 1;
  }
  return left >= needed && right >= needed ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr,
                 "usage: png_check IMAGE "
                 "selected-present|selected-absent|two-views|features-present|features-absent\n");
    return 2;
  }
  Image image;
  int channels = 0;
  image.pixels.reset(stbi_load(argv[1], &image.width, &image.height, &channels, 3));
  if (!image.pixels) {
    std::fprintf(stderr, "png_check: cannot read %s: %s\n", argv[1], stbi_failure_reason());
    return 2;
  }
  const int scene_x = static_cast<int>(holefill::viewer::kPanelWidth);  // at scale 1 (Xvfb)
  const std::string check = argv[2];
  std::printf("%s: %dx%d\n", argv[1], image.width, image.height);
  if (check == "selected-present" || check == "selected-absent") {
    const long n = count(image, scene_x, image.width, palette::kSelectedBoundary);
    std::printf("selected-outline pixels: %ld\n", n);
    return (check == "selected-present" ? n >= 100 : n == 0) ? 0 : 1;
  }
  if (check == "two-views") return check_two_views(image, scene_x);
  if (check == "features-present" || check == "features-absent") {
    const long traced = count(image, scene_x, image.width, palette::kFeatureLine);
    const long continued = count(image, scene_x, image.width, palette::kFeaturePath);
    std::printf("feature-line pixels: %ld, continued: %ld\n", traced, continued);
    return (check == "features-present" ? traced >= 50 && continued >= 50
                                        : traced == 0 && continued == 0)
               ? 0
               : 1;
  }
  std::fprintf(stderr, "png_check: unknown check %s\n", argv[2]);
  return 2;
}
