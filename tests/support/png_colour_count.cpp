// png_colour_count FILE.png #rrggbb [TOLERANCE]: prints how many pixels lie within TOLERANCE
// (default 24) of the colour in every channel. Lets a shell test check what a browser drew.
#include <cstdio>
#include <cstdlib>
#include <string>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

int main(int argc, char** argv) {
  if (argc < 3 || std::string(argv[2]).size() != 7 || argv[2][0] != '#') {
    std::fprintf(stderr, "usage: png_colour_count FILE.png #rrggbb [TOLERANCE]\n");
    return 2;
  }
  const long colour = std::strtol(argv[2] + 1, nullptr, 16);
  const int target[3] = {static_cast<int>((colour >> 16) & 0xff),
                         static_cast<int>((colour >> 8) & 0xff), static_cast<int>(colour & 0xff)};
  const int tolerance = argc > 3 ? std::atoi(argv[3]) : 24;
  int width = 0;
  int height = 0;
  int channels = 0;
  unsigned char* pixels = stbi_load(argv[1], &width, &height, &channels, 3);
  if (!pixels) {
    std::fprintf(stderr, "png_colour_count: cannot read %s: %s\n", argv[1], stbi_failure_reason());
    return 1;
  }
  long matches = 0;
  for (long i = 0; i < static_cast<long>(width) * height; ++i) {
    bool close = true;
    for (int c = 0; c < 3; ++c)
      close = close && std::abs(pixels[i * 3 + c] - target[c]) <= tolerance;
    matches += close ? 1 : 0;
  }
  stbi_image_free(pixels);
  std::printf("%ld\n", matches);
  return 0;
}
