#include "openexr_decode.h"

#include <cstring>
#include <exception>
#include <mutex>
#include <new>
#include <vector>

#include <OpenEXR/Iex.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <fmt/format.h>

namespace matc {
namespace {

// The file's bytes as an OpenEXR input stream; reading past the end throws, as a file would.
class MemoryStream final : public Imf::IStream {
 public:
  explicit MemoryStream(std::span<const unsigned char> bytes)
      : Imf::IStream("memory"), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || static_cast<std::size_t>(n) > bytes_.size() - position_)
      throw Iex::InputExc("the file ends early (truncated)");
    std::memcpy(c, bytes_.data() + position_, static_cast<std::size_t>(n));
    position_ += static_cast<std::size_t>(n);
    return position_ < bytes_.size();
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t position) override {
    if (position > bytes_.size()) throw Iex::InputExc("the file ends early (truncated)");
    position_ = static_cast<std::size_t>(position);
  }

 private:
  std::span<const unsigned char> bytes_;
  std::size_t position_ = 0;
};

ImageReadResult failure(std::string reason) {
  return {std::nullopt, std::move(reason)};
}

}  // namespace

ImageReadResult decode_openexr(std::span<const unsigned char> bytes) {
  // The library checks headers against this before allocating anything for the image.
  static std::once_flag limits;
  std::call_once(limits, [] {
    Imf::Header::setMaxImageSize(static_cast<int>(kMaxImageSide), static_cast<int>(kMaxImageSide));
    Imf::Header::setMaxTileSize(static_cast<int>(kMaxImageSide), static_cast<int>(kMaxImageSide));
  });
  try {
    MemoryStream stream(bytes);
    Imf::InputFile file(stream);
    const Imf::Header& header = file.header();
    const Imath::Box2i window = header.dataWindow();
    const auto width = static_cast<std::size_t>(window.max.x) - window.min.x + 1;
    const auto height = static_cast<std::size_t>(window.max.y) - window.min.y + 1;
    if (auto too_large = image_size_limit_failure(width, height))
      return failure(std::move(*too_large));
    const Imf::ChannelList& channels = header.channels();
    const bool rgb =
        channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    const bool grey = !rgb && channels.findChannel("Y");
    if (!rgb && !grey) {
      std::string names;
      for (auto it = channels.begin(); it != channels.end(); ++it)
        names += fmt::format("{}{}", names.empty() ? "" : ", ", it.name());
      return failure(
          fmt::format("has the channels {{{}}}; an OpenEXR map needs R, G and B, or Y", names));
    }
    const char* const names[3] = {rgb ? "R" : "Y", rgb ? "G" : "Y", rgb ? "B" : "Y"};
    int bits = 16;
    for (const char* name : names) {
      const Imf::Channel& channel = *channels.findChannel(name);
      if (channel.type == Imf::UINT)
        return failure(
            fmt::format("channel {} holds unsigned integers; a map needs HALF or FLOAT", name));
      if (channel.xSampling != 1 || channel.ySampling != 1)
        return failure(fmt::format("channel {} is subsampled; a map needs every texel", name));
      if (channel.type == Imf::FLOAT) bits = 32;
    }
    ImageMap map;
    map.width = width;
    map.height = height;
    map.format = ImageFileFormat::openexr;
    map.file_channels =
        rgb ? (channels.findChannel("A") ? 4 : 3) : (channels.findChannel("A") ? 2 : 1);
    map.bits = bits;
    map.encoding = MapEncoding::linear;
    map.values.assign(width * height * 3, 0.0f);
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < (rgb ? 3 : 1); ++c) {
      frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, map.values.data() + c, window,
                                              3 * sizeof(float), 3 * sizeof(float) * width));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    if (grey) {
      for (std::size_t texel = 0; texel < width * height; ++texel)
        map.values[3 * texel + 1] = map.values[3 * texel + 2] = map.values[3 * texel];
    }
    return {std::move(map), {}};
  } catch (const std::bad_alloc&) {
    return failure("is too large to read into memory");
  } catch (const std::exception& error) {
    return failure(fmt::format("is not a readable OpenEXR file ({})", error.what()));
  }
}

}  // namespace matc
