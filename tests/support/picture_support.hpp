// Pictures the tests look at: a PNG read back (through libpng, where the build found it)
// from an SVG rendered by rsvg-convert.
#pragma once

#include <gtest/gtest.h>
#if BB_HAVE_PNG
#include <png.h>
#endif

#include <cstdlib>
#include <string>
#include <vector>

namespace bb::test {

/// An RGBA image, or empty when the file could not be read.
struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
  const unsigned char* at(int x, int y) const { return &rgba[4 * (y * width + x)]; }
};

/// Why pictures cannot be looked at here (rsvg-convert or libpng missing), or "".
inline std::string why_no_pictures() {
#if !BB_HAVE_PNG
  return "libpng-dev was not found when the tests were built (scripts/setup --tests installs it)";
#else
  if (std::system("rsvg-convert --version > /dev/null 2>&1") != 0)
    return "rsvg-convert is not installed (scripts/setup --tests installs librsvg2-bin)";
  return "";
#endif
}

inline Image read_png([[maybe_unused]] const std::string& path) {
  Image out;
#if BB_HAVE_PNG
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) return out;
  image.format = PNG_FORMAT_RGBA;
  out.rgba.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgba.data(), 0, nullptr)) return {};
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
#endif
  return out;
}

}  // namespace bb::test
