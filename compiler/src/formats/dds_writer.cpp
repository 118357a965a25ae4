// DirectDraw Surface with the DX10 extension header (Microsoft, "DDS file layout"): one 2D
// texture, DXGI_FORMAT_R16G16[B16A16]_FLOAT or DXGI_FORMAT_R32G32[B32A32]_FLOAT, with its mip
// levels (largest first) when it has more than one.
#include "formats/dds_writer.h"
#include "formats/texel_bytes.h"

namespace matc::formats {
namespace {

constexpr std::uint32_t kDdsdCaps = 0x1, kDdsdHeight = 0x2, kDdsdWidth = 0x4, kDdsdPitch = 0x8;
constexpr std::uint32_t kDdsdPixelFormat = 0x1000, kDdsdMipMapCount = 0x20000;
constexpr std::uint32_t kDdpfFourCc = 0x4;
constexpr std::uint32_t kDdsCapsComplex = 0x8, kDdsCapsTexture = 0x1000, kDdsCapsMipMap = 0x400000;
constexpr std::uint32_t kDxgiR32G32B32A32Float = 2;
constexpr std::uint32_t kDxgiR16G16B16A16Float = 10;
constexpr std::uint32_t kDxgiR32G32Float = 16;
constexpr std::uint32_t kDxgiR16G16Float = 34;
constexpr std::uint32_t kResourceDimensionTexture2d = 3;

std::uint32_t four_cc(const char (&code)[5]) {
  return static_cast<std::uint32_t>(code[0]) | (static_cast<std::uint32_t>(code[1]) << 8) |
         (static_cast<std::uint32_t>(code[2]) << 16) | (static_cast<std::uint32_t>(code[3]) << 24);
}

}  // namespace

std::string encode_dds(std::span<const TexelImage> levels, LutPrecision precision) {
  const TexelImage& image = levels.front();
  const bool mipmapped = levels.size() > 1;
  const bool half = precision == LutPrecision::f16;
  const auto texel_size = static_cast<std::uint32_t>(image.channels * (half ? 2 : 4));
  const auto width = static_cast<std::uint32_t>(image.width);
  std::string out;
  put_u32(out, four_cc("DDS "));
  // DDS_HEADER
  put_u32(out, 124);
  put_u32(out, kDdsdCaps | kDdsdHeight | kDdsdWidth | kDdsdPitch | kDdsdPixelFormat |
                   (mipmapped ? kDdsdMipMapCount : 0));
  put_u32(out, static_cast<std::uint32_t>(image.height));
  put_u32(out, width);
  put_u32(out, width * texel_size);                         // pitch: bytes per row
  put_u32(out, 0);                                          // depth
  put_u32(out, static_cast<std::uint32_t>(levels.size()));  // mipMapCount
  for (int i = 0; i < 11; ++i)
    put_u32(out, 0);  // reserved1
  // DDS_PIXELFORMAT: the format lives in the DX10 header.
  put_u32(out, 32);
  put_u32(out, kDdpfFourCc);
  put_u32(out, four_cc("DX10"));
  for (int i = 0; i < 5; ++i)
    put_u32(out, 0);  // bit count and masks
  put_u32(out, kDdsCapsTexture | (mipmapped ? kDdsCapsComplex | kDdsCapsMipMap : 0));
  for (int i = 0; i < 4; ++i)
    put_u32(out, 0);  // caps2..4, reserved2
  // DDS_HEADER_DXT10
  if (image.channels == 2)
    put_u32(out, half ? kDxgiR16G16Float : kDxgiR32G32Float);
  else
    put_u32(out, half ? kDxgiR16G16B16A16Float : kDxgiR32G32B32A32Float);
  put_u32(out, kResourceDimensionTexture2d);
  put_u32(out, 0);  // miscFlag
  put_u32(out, 1);  // arraySize
  put_u32(out, 0);  // miscFlags2: alpha mode unknown
  std::size_t offset = out.size();
  for (const TexelImage& level : levels)
    offset += level.texels.size() * component_bytes(precision);
  out.resize(offset, '\0');
  offset = out.size();
  for (auto level = levels.rbegin(); level != levels.rend(); ++level) {
    offset -= level->texels.size() * component_bytes(precision);
    write_texel_bytes(level->texels, precision, out.data() + offset);
  }
  return out;
}

}  // namespace matc::formats
