// PNG writer over libpng (see png_image.hpp).
#include "experiments/io/png_image.hpp"

#include <png.h>

#include <csetjmp>
#include <stdexcept>
#include <string>

#include "experiments/io/atomic_file.hpp"

namespace rice::experiments {
namespace {

// libpng's write callback: appends to the std::string given as io pointer. A C++ exception
// must not unwind through libpng's C frames, so a failure becomes png_error (a longjmp to the
// setjmp in encode_rows), raised once the exception is over.
void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  bool failed = false;
  try {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
  } catch (const std::exception&) {
    failed = true;
  }
  if (failed) png_error(png, "cannot grow the PNG's buffer");
}

// The libpng structures of one encoding, freed on every path (libpng accepts null ones).
struct PngWriter {
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngWriter() = default;
  PngWriter(const PngWriter&) = delete;
  PngWriter& operator=(const PngWriter&) = delete;
  ~PngWriter() { png_destroy_write_struct(&png, &info); }
};

// Encodes `image` into `*out`; false when libpng reported an error. libpng reports errors by
// longjmp back to the setjmp below, so what must outlive a jump (the libpng structures, the
// bytes) lives in the caller, and no local here is changed after setjmp and read after the
// jump (its value would be indeterminate).
bool encode_rows(png_structp png, png_infop info, const RgbImage& image, std::string* out) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, out, append_bytes, nullptr);
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) png_write_row(png, &image.pixels[3 * static_cast<size_t>(y) * image.width]);
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

std::string encode_png(const RgbImage& image) {
  PngWriter writer;
  writer.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (writer.png) writer.info = png_create_info_struct(writer.png);
  if (!writer.png || !writer.info) throw std::runtime_error("libpng could not start");
  std::string bytes;
  if (!encode_rows(writer.png, writer.info, image, &bytes))
    throw std::runtime_error("libpng failed while encoding a " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + " image");
  return bytes;
}

void write_png(const std::filesystem::path& path, const RgbImage& image) {
  write_file_atomically(path, encode_png(image));
}

}  // namespace rice::experiments
