#include "io/png_image.h"

#include <png.h>

#include <csetjmp>
#include <ostream>

#include "akvf/error.h"
#include "framework/process/output_file.h"

namespace akvf {

namespace {

void write_to_stream(png_structp png, png_bytep data, png_size_t length) {
  static_cast<std::ostream*>(png_get_io_ptr(png))
      ->write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
}
void flush_stream(png_structp png) { static_cast<std::ostream*>(png_get_io_ptr(png))->flush(); }
void on_png_warning(png_structp, png_const_charp) {}

// The image through libpng; false when libpng failed (its errors longjmp
// back here, as libpng requires: no C++ object lives in this frame).
bool encode(png_structp png, png_infop info, const RgbImage& image) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y)
    png_write_row(png, const_cast<png_bytep>(image.rgb.data() + 3 * std::size_t(y) * image.width));
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

void write_png(const std::string& path, const RgbImage& image) {
  write_file_atomically(path, [&](std::ostream& out) { write_png(out, image, path); });
}

void write_png(std::ostream& out, const RgbImage& image, const std::string& what) {
  if (image.width <= 0 || image.height <= 0) throw OutputError(what + ": an empty image");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  bool ok = false;
  if (info) {
    png_set_write_fn(png, &out, write_to_stream, flush_stream);
    ok = encode(png, info, image);
  }
  png_destroy_write_struct(&png, &info);
  if (!ok) throw OutputError(what + ": libpng could not encode the image");
}

}  // namespace akvf
