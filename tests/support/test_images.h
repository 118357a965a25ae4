// Image files made in memory for the bake tests and the fuzzer's seed corpus: PNG (8 and 16 bits),
// JPEG and OpenEXR (half or float), so no binary test image is stored.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace matc::test {

// `values` holds width * height * channels samples, rows first.
std::string png_bytes(int width, int height, int channels, const std::vector<std::uint8_t>& values);
std::string png16_bytes(int width, int height, int channels,
                        const std::vector<std::uint16_t>& values);
std::string jpeg_bytes(int width, int height, int channels,
                       const std::vector<std::uint8_t>& values);
// Channel names "R", "G", "B" (channels = 3) or "Y" (channels = 1); half or float samples.
std::string exr_bytes(int width, int height, int channels, const std::vector<float>& values,
                      bool half = false);

// One image of `channels` named channels (e.g. {"Z"}), FLOAT or UINT samples (the unsupported
// layouts the catalogue checks).
std::string exr_bytes_with_channels(int width, int height, const std::vector<std::string>& names,
                                    bool unsigned_integers);

void write_file(const std::string& path, const std::string& bytes);

}  // namespace matc::test
