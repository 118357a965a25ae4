#include "test_images.h"

#include <array>
#include <fstream>
#include <stdexcept>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <stb/stb_image_write.h>

// In Debian's libstb but declared only inside the implementation section of the header.
extern "C" unsigned char* stbi_zlib_compress(unsigned char* data, int data_len, int* out_len,
                                             int quality);

namespace matc::test {
namespace {

void append(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

std::uint32_t crc32(const std::string& bytes) {  // PNG's CRC (ISO 3309)
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const char byte : bytes) {
    crc ^= static_cast<std::uint8_t>(byte);
    for (int bit = 0; bit < 8; ++bit)
      crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

void put_be32(std::string& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<char>(value >> shift));
}

void chunk(std::string& png, const char* type, const std::string& data) {
  put_be32(png, static_cast<std::uint32_t>(data.size()));
  const std::string body = std::string(type, 4) + data;
  png += body;
  put_be32(png, crc32(body));
}

}  // namespace

std::string png_bytes(int width, int height, int channels,
                      const std::vector<std::uint8_t>& values) {
  std::string out;
  stbi_write_png_to_func(append, &out, width, height, channels, values.data(), width * channels);
  return out;
}

// stb_image_write has no 16-bit PNG: the chunks are written here (filter 0 on every row).
std::string png16_bytes(int width, int height, int channels,
                        const std::vector<std::uint16_t>& values) {
  constexpr std::array<std::uint8_t, 5> kColourType = {0, 0, 4, 2, 6};  // by channel count
  std::string png = "\x89PNG\r\n\x1a\n";
  std::string header;
  put_be32(header, static_cast<std::uint32_t>(width));
  put_be32(header, static_cast<std::uint32_t>(height));
  header += {16, static_cast<char>(kColourType[static_cast<std::size_t>(channels)]), 0, 0, 0};
  chunk(png, "IHDR", header);
  std::string raw;
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);
    for (int i = 0; i < width * channels; ++i) {
      const std::uint16_t value = values[static_cast<std::size_t>(y * width * channels + i)];
      raw.push_back(static_cast<char>(value >> 8));
      raw.push_back(static_cast<char>(value & 0xFF));
    }
  }
  int length = 0;
  unsigned char* compressed = stbi_zlib_compress(reinterpret_cast<unsigned char*>(raw.data()),
                                                 static_cast<int>(raw.size()), &length, 8);
  chunk(png, "IDAT",
        std::string(reinterpret_cast<char*>(compressed), static_cast<std::size_t>(length)));
  free(compressed);  // NOLINT: stb allocates with malloc
  chunk(png, "IEND", "");
  return png;
}

std::string jpeg_bytes(int width, int height, int channels,
                       const std::vector<std::uint8_t>& values) {
  std::string out;
  stbi_write_jpg_to_func(append, &out, width, height, channels, values.data(), 95);
  return out;
}

std::string exr_bytes(int width, int height, int channels, const std::vector<float>& values,
                      bool half) {
  Imf::StdOSStream output;
  Imf::Header header(width, height);
  const std::vector<std::string> names =
      channels == 1 ? std::vector<std::string>{"Y"} : std::vector<std::string>{"R", "G", "B"};
  for (const std::string& name : names)
    header.channels().insert(name, Imf::Channel(half ? Imf::HALF : Imf::FLOAT));
  std::vector<::half> halves(values.begin(), values.end());
  {  // the file is complete once OutputFile is destroyed
    Imf::OutputFile file(output, header);
    Imf::FrameBuffer frame;
    const std::size_t stride = static_cast<std::size_t>(channels);
    for (std::size_t c = 0; c < names.size(); ++c) {
      char* base = half ? reinterpret_cast<char*>(halves.data() + c)
                        : reinterpret_cast<char*>(const_cast<float*>(values.data() + c));
      const std::size_t size = half ? sizeof(::half) : sizeof(float);
      frame.insert(names[c], Imf::Slice(half ? Imf::HALF : Imf::FLOAT, base, stride * size,
                                        stride * size * static_cast<std::size_t>(width)));
    }
    file.setFrameBuffer(frame);
    file.writePixels(height);
  }
  return output.str();
}

std::string exr_bytes_with_channels(int width, int height, const std::vector<std::string>& names,
                                    bool unsigned_integers) {
  Imf::StdOSStream output;
  Imf::Header header(width, height);
  const Imf::PixelType type = unsigned_integers ? Imf::UINT : Imf::FLOAT;
  for (const std::string& name : names)
    header.channels().insert(name, Imf::Channel(type));
  std::vector<std::uint32_t> samples(static_cast<std::size_t>(width * height), 1);
  {
    Imf::OutputFile file(output, header);
    Imf::FrameBuffer frame;
    for (const std::string& name : names)
      frame.insert(name, Imf::Slice(type, reinterpret_cast<char*>(samples.data()), 4,
                                    4 * static_cast<std::size_t>(width)));
    file.setFrameBuffer(frame);
    file.writePixels(height);
  }
  return output.str();
}

void write_file(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace matc::test
