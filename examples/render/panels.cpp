#include "panels.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <span>
#include <stdexcept>
#include <string>

#include <fmt/core.h>
#include <stb_image_write.h>

namespace matc::render {
namespace {

constexpr std::uint32_t kSamplesPerPass = 64;
constexpr double kDifferenceScale = 4.0;

// A value in [0, 1] through the sRGB transfer function, to 8 bits.
std::uint8_t srgb_8bit(double value) {
  const double x = std::clamp(value, 0.0, 1.0);
  const double encoded = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(encoded * 255.0));
}

void write_png(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
               const std::vector<std::uint8_t>& rgb) {
  std::string bytes;
  stbi_write_png_to_func(
      [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<std::size_t>(size));
      },
      &bytes, static_cast<int>(width), static_cast<int>(height), 3, rgb.data(),
      static_cast<int>(width * 3));
  if (bytes.empty()) throw std::runtime_error("cannot encode " + path.string());
  const std::filesystem::path temporary = path.string() + ".tmp";
  std::ofstream(temporary, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  std::filesystem::rename(temporary, path);
}

}  // namespace

void add_render_options(CLI::App& app, RenderSettings& settings, const std::string& check_help) {
  app.add_option("--size", settings.size, "Width and height of each panel in pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 2048));
  app.add_option("--samples", settings.samples, "Samples per pixel (reference and prefiltering)")
      ->capture_default_str()
      ->check(CLI::Range(16, 1 << 20));
  app.add_option("-o,--output", settings.output, "Where the PNG files go")->capture_default_str();
  app.add_flag("--check", settings.check, check_help);
  app.add_flag("--vk-validation", settings.validation, "Enable the Khronos validation layer");
  app.add_option("--device", settings.device, "A substring of the Vulkan device's name");
}

Panel Panel::times(const Panel& fresnel) const {
  Panel product = *this;
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    if (!sphere[i]) continue;  // the background keeps its colour
    for (std::size_t c = 0; c < 3; ++c)
      product.rgb[i][c] *= fresnel.rgb[i][c];
  }
  return product;
}

std::vector<Panel> render_estimates(vulkan::FullscreenPass& pass, std::uint32_t size,
                                    std::uint32_t samples, float roughness,
                                    EstimateMethods methods) {
  std::vector<Panel> panels(static_cast<std::size_t>(methods.count));
  const std::size_t pixels = std::size_t{size} * size;
  for (std::int32_t method = 0; method < methods.count; ++method) {
    std::vector<std::array<double, 4>> sums(pixels, {0.0, 0.0, 0.0, 0.0});
    // Table lookups are exact in one pass; Monte-Carlo estimates take all the samples.
    const std::uint32_t method_samples = method >= methods.first_lookup ? 1 : samples;
    for (std::uint32_t first = 0; first < method_samples; first += kSamplesPerPass) {
      const PanelConstants constants{method, first,
                                     std::min(kSamplesPerPass, method_samples - first),
                                     method_samples, roughness};
      pass.draw(std::as_bytes(std::span(&constants, 1)));
      const std::vector<float> result = pass.read_pixels();
      for (std::size_t i = 0; i < pixels; ++i) {
        for (std::size_t c = 0; c < 4; ++c)
          sums[i][c] += result[4 * i + c];
      }
    }
    Panel& panel = panels[static_cast<std::size_t>(method)];
    panel.rgb.resize(pixels);
    panel.sphere.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
      panel.sphere[i] = sums[i][3] > 0.0;
      for (std::size_t c = 0; c < 3; ++c)
        panel.rgb[i][c] = sums[i][3] != 0.0 ? sums[i][c] / sums[i][3] : 0.0;
    }
  }
  return panels;
}

void print_error_rows(const std::string& material, const std::string& roughness,
                      std::span<const ErrorRow> rows, const Panel& reference, const Panel& exact) {
  for (const ErrorRow& row : rows) {
    const ErrorStats total = error_against(*row.panel, reference);
    const ErrorStats fresnel = error_against(*row.panel, exact);
    fmt::print("| {} | {} | {} | {:.4f} | {:.1f}% | {:.3f} | {} | {} |\n", material, roughness,
               row.label, total.mean, 100.0 * total.relative_mean, total.max,
               row.fresnel_alone ? fmt::format("{:.4f}", fresnel.mean) : "-",
               row.fresnel_alone ? fmt::format("{:.3f}", fresnel.max) : "-");
  }
}

ErrorStats error_against(const Panel& panel, const Panel& reference) {
  ErrorStats stats;
  double reference_sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < panel.rgb.size(); ++i) {
    if (!reference.sphere[i]) continue;
    for (std::size_t c = 0; c < 3; ++c) {
      const double difference = std::abs(panel.rgb[i][c] - reference.rgb[i][c]);
      stats.mean += difference;
      stats.max = std::max(stats.max, difference);
      reference_sum += reference.rgb[i][c];
      ++count;
    }
  }
  stats.relative_mean = stats.mean / std::max(reference_sum, 1e-30);
  stats.mean /= static_cast<double>(std::max<std::size_t>(count, 1));
  return stats;
}

std::vector<std::array<double, 3>> difference(const Panel& panel, const Panel& reference) {
  std::vector<std::array<double, 3>> result(panel.rgb.size(), {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < panel.rgb.size(); ++i) {
    if (!reference.sphere[i]) continue;
    for (std::size_t c = 0; c < 3; ++c)
      result[i][c] = std::abs(panel.rgb[i][c] - reference.rgb[i][c]);
  }
  return result;
}

std::uint8_t display(double linear) {
  const double x = std::max(linear, 0.0);
  return srgb_8bit(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14));
}

std::uint8_t display_difference(double difference) {
  return srgb_8bit(difference * kDifferenceScale);
}

void write_panels(const std::filesystem::path& path,
                  const std::vector<std::vector<std::array<double, 3>>>& panels, std::uint32_t size,
                  std::uint8_t (*to_display)(double)) {
  const std::size_t width = size * panels.size();
  std::vector<std::uint8_t> rgb(width * size * 3);
  for (std::size_t p = 0; p < panels.size(); ++p) {
    for (std::size_t y = 0; y < size; ++y) {
      for (std::size_t x = 0; x < size; ++x) {
        for (std::size_t c = 0; c < 3; ++c)
          rgb[(y * width + p * size + x) * 3 + c] = to_display(panels[p][y * size + x][c]);
      }
    }
  }
  write_png(path, static_cast<std::uint32_t>(width), size, rgb);
}

void write_difference_panels(const std::filesystem::path& directory, const std::string& stem,
                             std::initializer_list<const Panel*> compared, const Panel& reference,
                             const Panel& exact, std::uint32_t size) {
  std::vector<std::vector<std::array<double, 3>>> against_reference, against_exact;
  for (const Panel* panel : compared) {
    against_reference.push_back(difference(*panel, reference));
    against_exact.push_back(difference(*panel, exact));
  }
  write_panels(directory / (stem + "_difference.png"), against_reference, size, display_difference);
  write_panels(directory / (stem + "_fresnel_difference.png"), against_exact, size,
               display_difference);
}

bool validation_clean(const vulkan::Context& context) {
  for (const std::string& message : context.validation_messages())
    fmt::print(stderr, "validation layer: {}\n", message);
  return context.validation_messages().empty();
}

}  // namespace matc::render
