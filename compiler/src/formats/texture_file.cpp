#include "formats/texture_file.h"

#include <stdexcept>

#include "formats/dds_writer.h"
#include "formats/ktx2_writer.h"
#include "formats/texel_bytes.h"

namespace matc::formats {

std::string encode_texture_file(const TexelImage& image, LutFormat format, LutPrecision precision) {
  switch (format) {
    case LutFormat::ktx2:
      return encode_ktx2({&image, 1}, precision);
    case LutFormat::dds:
      return encode_dds({&image, 1}, precision);
    case LutFormat::raw:
      return texel_bytes(image.texels, precision);
    case LutFormat::header:
      break;
  }
  throw std::invalid_argument("encode_texture_file: a table's C++ header is written by its module");
}

}  // namespace matc::formats
