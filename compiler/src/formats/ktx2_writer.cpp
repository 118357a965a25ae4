// KTX 2.0 (Khronos, https://registry.khronos.org/KTX/specs/2.0/ktxspec.v2.html): a 2D texture
// with one or more mip levels,
// VK_FORMAT_R16G16[B16A16]_SFLOAT or VK_FORMAT_R32G32[B32A32]_SFLOAT, a basic data format
// descriptor and a KTXwriter key.
#include <utility>
#include <vector>

#include "formats/ktx2_writer.h"
#include "formats/texel_bytes.h"
#include "matc/version.h"

namespace matc::formats {
namespace {

constexpr unsigned char kIdentifier[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32,
                                           0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
constexpr std::uint32_t kVkFormatR16G16Sfloat = 83;
constexpr std::uint32_t kVkFormatR32G32Sfloat = 103;
constexpr std::uint32_t kVkFormatR16G16B16A16Sfloat = 97;
constexpr std::uint32_t kVkFormatR32G32B32A32Sfloat = 109;

std::uint32_t vk_format(std::size_t channels, std::uint32_t channel_bytes) {
  if (channels == 2) return channel_bytes == 2 ? kVkFormatR16G16Sfloat : kVkFormatR32G32Sfloat;
  return channel_bytes == 2 ? kVkFormatR16G16B16A16Sfloat : kVkFormatR32G32B32A32Sfloat;
}
constexpr std::size_t kHeaderAndIndexBytes = 80;
constexpr std::size_t kLevelIndexBytes = 24;

// Khronos Data Format 1.3 basic descriptor for 2 (R, G) or 4 (R, G, B, A) little-endian
// signed-float channels.
std::string data_format_descriptor(std::size_t channels, std::uint32_t channel_bytes) {
  const auto samples = static_cast<std::uint32_t>(channels);
  const std::uint32_t block_bytes = 24 + 16 * samples;
  std::string out;
  put_u32(out, 4 + block_bytes);           // dfdTotalSize
  put_u32(out, 0);                         // vendorId KHRONOS, descriptorType BASICFORMAT
  put_u32(out, 2u | (block_bytes << 16));  // versionNumber 1.3, descriptorBlockSize
  // colorModel RGBSDA, colorPrimaries BT709, transferFunction LINEAR, flags ALPHA_STRAIGHT.
  put_u32(out, 1u | (1u << 8) | (1u << 16));
  put_u32(out, 0);                                         // texelBlockDimension 1x1x1x1
  put_u32(out, samples * channel_bytes);                   // bytesPlane0
  put_u32(out, 0);                                         // bytesPlane4..7
  constexpr std::uint32_t kChannelIds[4] = {0, 1, 2, 15};  // R, G, B, A
  constexpr std::uint32_t kFloatSigned = 0x80 | 0x40;
  for (std::uint32_t s = 0; s < samples; ++s) {
    put_u32(out, (s * channel_bytes * 8) | ((channel_bytes * 8 - 1) << 16) |
                     ((kChannelIds[s] | kFloatSigned) << 24));
    put_u32(out, 0);           // samplePosition
    put_u32(out, 0xBF800000);  // sampleLower: -1.0f, as KTX-Software writes for SFLOAT
    put_u32(out, 0x3F800000);  // sampleUpper: 1.0f
  }
  return out;
}

std::string key_value_data() {
  const std::string key = "KTXwriter";
  const std::string value = std::string("matc ") + kVersion;
  std::string out;
  put_u32(out, static_cast<std::uint32_t>(key.size() + 1 + value.size() + 1));
  out += key;
  out.push_back('\0');
  out += value;
  out.push_back('\0');
  pad_to(out, 4);
  return out;
}

}  // namespace

std::string encode_ktx2(std::span<const TexelImage> levels, LutPrecision precision) {
  const TexelImage& base = levels.front();
  const std::uint32_t channel_bytes = precision == LutPrecision::f16 ? 2 : 4;
  const std::string dfd = data_format_descriptor(base.channels, channel_bytes);
  const std::string kvd = key_value_data();

  const std::size_t dfd_offset = kHeaderAndIndexBytes + kLevelIndexBytes * levels.size();
  const std::size_t kvd_offset = dfd_offset + dfd.size();
  // Level data is aligned to lcm(texel block size, 4) = the texel size (4 to 16 bytes), and
  // stored smallest level first (the index lists level 0 first).
  const std::size_t texel_size = base.channels * channel_bytes;
  std::vector<std::pair<std::size_t, std::size_t>> placement(levels.size());  // offset, length
  std::size_t end = kvd_offset + kvd.size();
  for (std::size_t k = levels.size(); k-- > 0;) {
    end += (texel_size - end % texel_size) % texel_size;
    placement[k] = {end, levels[k].texels.size() * channel_bytes};
    end += placement[k].second;
  }

  std::string out(reinterpret_cast<const char*>(kIdentifier), sizeof kIdentifier);
  put_u32(out, vk_format(base.channels, channel_bytes));
  put_u32(out, channel_bytes);                              // typeSize
  put_u32(out, static_cast<std::uint32_t>(base.width));     // pixelWidth
  put_u32(out, static_cast<std::uint32_t>(base.height));    // pixelHeight
  put_u32(out, 0);                                          // pixelDepth
  put_u32(out, 0);                                          // layerCount
  put_u32(out, 1);                                          // faceCount
  put_u32(out, static_cast<std::uint32_t>(levels.size()));  // levelCount
  put_u32(out, 0);                                          // supercompressionScheme
  put_u32(out, static_cast<std::uint32_t>(dfd_offset));
  put_u32(out, static_cast<std::uint32_t>(dfd.size()));
  put_u32(out, static_cast<std::uint32_t>(kvd_offset));
  put_u32(out, static_cast<std::uint32_t>(kvd.size()));
  put_u64(out, 0);  // sgdByteOffset
  put_u64(out, 0);  // sgdByteLength
  for (const auto& [offset, length] : placement) {
    put_u64(out, offset);
    put_u64(out, length);  // byteLength
    put_u64(out, length);  // uncompressedByteLength
  }
  out += dfd;
  out += kvd;
  // The texels go straight to their place: textures of `matc bake` run to hundreds of MB.
  out.resize(end, '\0');
  for (std::size_t k = 0; k < levels.size(); ++k)
    write_texel_bytes(levels[k].texels, precision, out.data() + placement[k].first);
  return out;
}

}  // namespace matc::formats
