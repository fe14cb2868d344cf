#pragma once
// 8-bit RGB images and their PNG files (libpng), written atomically like
// every output (framework/process/output_file.h).
#include <ostream>
#include <string>
#include <vector>

namespace akvf {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // row-major from the top row, 3 bytes per pixel
  RgbImage(int w, int h, unsigned char fill = 255) : width(w), height(h), rgb(3 * std::size_t(w) * h, fill) {}
  unsigned char* pixel(int x, int y) { return rgb.data() + 3 * (std::size_t(y) * width + x); }
};

// OutputError naming the path if the file cannot be written.
void write_png(const std::string& path, const RgbImage& image);
// The PNG file's bytes into `out` (an embedded image); errors name `what`.
void write_png(std::ostream& out, const RgbImage& image, const std::string& what);

}  // namespace akvf
