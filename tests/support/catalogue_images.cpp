// matc_catalogue_images DIR: writes the small image files the bake cases of the bad-input
// catalogue start from (tests/data/bad_inputs/README.md); their .setup scripts then break copies.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "test_images.h"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const std::string dir = std::string(argv[1]) + "/";
  using namespace matc::test;
  std::vector<std::uint8_t> rgb(4 * 4 * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i)
    rgb[i] = static_cast<std::uint8_t>(40 + 13 * i);
  write_file(dir + "r.png", png_bytes(4, 4, 3, rgb));
  write_file(dir + "g.png", png_bytes(4, 4, 3, rgb));
  write_file(dir + "small.png", png_bytes(2, 2, 3, std::vector<std::uint8_t>(12, 100)));
  write_file(dir + "r.jpg", jpeg_bytes(16, 16, 3, std::vector<std::uint8_t>(768, 180)));
  std::vector<float> half_grey(4 * 4 * 3, 0.5f);
  write_file(dir + "r.exr", exr_bytes(4, 4, 3, half_grey));
  const auto with_value = [&](float value) {
    std::vector<float> values = half_grey;
    values[3 * 5 + 1] = value;  // texel (1, 1), green
    return exr_bytes(4, 4, 3, values);
  };
  write_file(dir + "nan.exr", with_value(std::numeric_limits<float>::quiet_NaN()));
  write_file(dir + "inf.exr", with_value(std::numeric_limits<float>::infinity()));
  write_file(dir + "negative.exr", with_value(-0.25f));
  write_file(dir + "above_one.exr", with_value(1.5f));
  write_file(dir + "depth.exr", exr_bytes_with_channels(4, 4, {"Z"}, false));
  write_file(dir + "ids.exr", exr_bytes_with_channels(4, 4, {"R", "G", "B"}, true));
  return 0;
}
