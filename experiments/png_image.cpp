// PNG writer over libpng (see png_image.hpp).
#include "experiments/png_image.hpp"

#include <png.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace rice::experiments {

void write_png(const std::filesystem::path& path, const RgbImage& image) {
  std::filesystem::path temporary = path;
  temporary += ".partial";
  {
    std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(temporary.c_str(), "wb"), &std::fclose);
    if (!file) throw std::runtime_error(path.string() + ": cannot open for writing");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
      png_destroy_write_struct(&png, nullptr);
      throw std::runtime_error(path.string() + ": libpng could not start");
    }
    if (setjmp(png_jmpbuf(png))) {  // libpng reports errors by longjmp
      png_destroy_write_struct(&png, &info);
      throw std::runtime_error(path.string() + ": libpng failed while writing");
    }
    png_init_io(png, file.get());
    png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y)
      png_write_row(png, &image.pixels[3 * static_cast<size_t>(y) * image.width]);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
  }
  std::filesystem::rename(temporary, path);
}

}  // namespace rice::experiments
