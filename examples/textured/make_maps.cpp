// matc_example_maps: writes the example textured metal's maps, so that no image is stored in the
// repository or downloaded. Deterministic (a fixed-seed hash): the same arguments give the same
// bytes.
//
//   matc_example_maps [--size N] [--pattern tiles|noise] [--exr] -o DIR
//
// tiles: "inlaid_metals", 8-bit sRGB PNGs of a fine inlay of four metals (chromium, copper, gold,
//        aluminium in Gulbrandsen's r, g) under a little per-texel wear. The inlay's cells are a
//        few texels wide, so minification mixes very different Fresnel curves: where averaging the
//        maps and averaging the curves disagree most.
// noise: "noise_metal", every texel's r and g uniformly random: all 65,536 (r, g) pairs of an
//        8-bit map pair occur, the worst case for the bake's per-pair solve (bench/).
// --exr also writes NAME_n.exr and NAME_k.exr (float): the same metals as complex IOR maps.
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <fmt/core.h>
#include <stb/stb_image_write.h>
#include <CLI/CLI.hpp>

#include "matc/api/compiled_material.h"

namespace {

using Rgb = std::array<double, 3>;

struct Metal {
  Rgb reflectivity;
  Rgb edge_tint;
};

// Gulbrandsen's (r, g) of four metals, linear (close to the fits in his paper's table).
constexpr std::array<Metal, 4> kMetals = {{
    {{0.549, 0.556, 0.554}, {0.912, 0.914, 0.920}},  // chromium: near-grey, strong edge
    {{0.955, 0.638, 0.538}, {0.999, 0.894, 0.583}},  // copper
    {{0.944, 0.776, 0.373}, {0.998, 0.981, 0.751}},  // gold
    {{0.913, 0.922, 0.924}, {0.970, 0.979, 0.999}},  // aluminium
}};

std::uint32_t hash(std::uint32_t x) {  // a small integer hash (deterministic noise)
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
double unit_noise(std::uint32_t x, std::uint32_t y, std::uint32_t salt) {
  return hash(x * 73856093U ^ y * 19349663U ^ salt * 83492791U) / 4294967295.0;
}

double linear_to_srgb(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}
unsigned char encode_srgb8(double linear) {
  return static_cast<unsigned char>(
      std::lround(std::clamp(linear_to_srgb(linear), 0.0, 1.0) * 255));
}

// The metal of texel (x, y): cells of 3 to 5 texels, chosen by hash, with wear that darkens r
// and pulls g towards grey by a few per cent.
Metal tile_metal(std::size_t x, std::size_t y) {
  const auto cx = static_cast<std::uint32_t>(x / 4), cy = static_cast<std::uint32_t>(y / 3);
  Metal metal = kMetals[hash(cx * 2654435761U ^ cy) % kMetals.size()];
  const double wear =
      0.06 * unit_noise(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 1);
  for (std::size_t c = 0; c < 3; ++c) {
    metal.reflectivity[c] *= 1.0 - wear;
    metal.edge_tint[c] += (0.5 - metal.edge_tint[c]) * wear;
  }
  return metal;
}

void write_png(const std::filesystem::path& path, std::size_t size,
               const std::vector<unsigned char>& rgb) {
  const int side = static_cast<int>(size);
  if (stbi_write_png(path.string().c_str(), side, side, 3, rgb.data(), side * 3) == 0)
    throw std::runtime_error(fmt::format("cannot write {}", path.string()));
}

void write_exr(const std::filesystem::path& path, std::size_t size, std::vector<float>& rgb) {
  const int side = static_cast<int>(size);
  Imf::Header header(side, side);
  for (const char* name : {"R", "G", "B"})
    header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  Imf::OutputFile file(path.string().c_str(), header);
  Imf::FrameBuffer frame;
  const char* names[3] = {"R", "G", "B"};
  for (std::size_t c = 0; c < 3; ++c) {
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rgb.data() + c),
                                      3 * sizeof(float), 3 * sizeof(float) * size));
  }
  file.setFrameBuffer(frame);
  file.writePixels(side);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes the example textured metal's maps (deterministic)", "matc_example_maps"};
  std::size_t size = 512;
  std::string pattern = "tiles";
  std::string output = ".";
  bool exr = false;
  app.add_option("--size", size, "Width and height in texels")->check(CLI::Range(1, 16384));
  app.add_option("--pattern", pattern, "tiles or noise")->check(CLI::IsMember({"tiles", "noise"}));
  app.add_flag("--exr", exr, "Also write n and k as float OpenEXR maps");
  app.add_option("-o,--output", output, "Output directory")->required();
  CLI11_PARSE(app, argc, argv);

  const std::string name = pattern == "tiles" ? "inlaid_metals" : "noise_metal";
  std::vector<unsigned char> r(size * size * 3), g(size * size * 3);
  std::vector<float> n(size * size * 3), k(size * size * 3);
  for (std::size_t y = 0; y < size; ++y) {
    for (std::size_t x = 0; x < size; ++x) {
      const std::size_t texel = (y * size + x) * 3;
      if (pattern == "noise") {
        const std::uint32_t bits = hash(static_cast<std::uint32_t>(y * size + x) * 2654435761U);
        for (std::size_t c = 0; c < 3; ++c) {
          r[texel + c] = static_cast<unsigned char>(bits >> (8 * c));
          g[texel + c] = static_cast<unsigned char>(hash(bits + static_cast<std::uint32_t>(c)));
        }
        continue;
      }
      const Metal metal = tile_metal(x, y);
      const matc::api::ComplexIor ior =
          matc::api::ior_from_artistic({metal.reflectivity, metal.edge_tint});
      for (std::size_t c = 0; c < 3; ++c) {
        r[texel + c] = encode_srgb8(metal.reflectivity[c]);
        g[texel + c] = encode_srgb8(metal.edge_tint[c]);
        n[texel + c] = static_cast<float>(ior.n[c]);
        k[texel + c] = static_cast<float>(ior.k[c]);
      }
    }
  }
  std::filesystem::create_directories(output);
  const std::filesystem::path directory(output);
  write_png(directory / (name + "_r.png"), size, r);
  write_png(directory / (name + "_g.png"), size, g);
  if (exr) {
    write_exr(directory / (name + "_n.exr"), size, n);
    write_exr(directory / (name + "_k.exr"), size, k);
  }
  return 0;
}
