// What the comparison renders (render.cpp) and the textured render (textured_render.cpp) share:
// the estimates their fragment shaders compute, accumulating them from a full-screen pass,
// error statistics, and PNG output.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include <string>

#include <CLI/CLI.hpp>

#include "matc/vulkan/fullscreen_pass.h"

namespace matc::render {

// What both programs take on the command line.
struct RenderSettings {
  std::uint32_t size = 256;      // panel width and height
  std::uint32_t samples = 1024;  // per pixel, reference and prefiltering
  std::filesystem::path output = "render-out";
  bool check = false;
  bool validation = false;  // the Khronos validation layer
  std::string device;       // a substring of the Vulkan device's name
};

// --size, --samples, -o, --check (meaning `check_help`), --vk-validation, --device.
void add_render_options(CLI::App& app, RenderSettings& settings, const std::string& check_help);

inline constexpr double kDefaultRoughness = 0.3;

// The estimates comparison_render.frag and textured_render.frag compute, by their `method` number.
enum Estimate : std::int32_t {
  kReference = 0,
  kPrefilteredRadiance = 1,
  kExactFbar = 2,
  kSchlickFbar = 3,
  kOursFbar = 4,
  kOursClosedFormFbar = 5,  // the table's closed form (area-light render: the quality level)
  kEstimateCount = 6,
};

// Matches the push-constant block of both fragment shaders.
struct PanelConstants {
  std::int32_t method;
  std::uint32_t first_sample;
  std::uint32_t sample_count;
  std::uint32_t total_samples;
  float roughness;
};

// Linear RGB per pixel; background pixels flagged.
struct Panel {
  std::vector<std::array<double, 3>> rgb;
  std::vector<bool> sphere;

  // The split sum: this (prefiltered radiance) times a preintegrated Fresnel, per pixel.
  Panel times(const Panel& fresnel) const;
};

// What a render's fragment shader computes: `count` methods, the Monte-Carlo ones first, table
// lookups from `first_lookup` on (comparison_render.frag's: Estimate).
struct EstimateMethods {
  std::int32_t count = kEstimateCount;
  std::int32_t first_lookup = kSchlickFbar;
};

// Every estimate, linear RGB, indexed by method (Estimate for the default methods): Monte-Carlo
// ones over `samples` samples (in passes of 64), table lookups in one pass.
std::vector<Panel> render_estimates(vulkan::FullscreenPass& pass, std::uint32_t size,
                                    std::uint32_t samples, float roughness,
                                    EstimateMethods methods = {});

struct ErrorStats {
  double mean = 0.0;
  double max = 0.0;
  double relative_mean = 0.0;  // mean |difference| / mean reference
};

// Over the sphere's pixels and all channels.
ErrorStats error_against(const Panel& panel, const Panel& reference);

// One row of a render's error table: an estimate and whether its Fresnel-alone columns (against
// the same method with the exact Fresnel) are printed.
struct ErrorRow {
  const char* label;
  const Panel* panel;
  bool fresnel_alone = true;
};

// The rows of a render's error table ("| material | roughness | label | mean | relative | max |
// Fresnel alone: mean | max |"): each row's error against `reference`, and against `exact`.
void print_error_rows(const std::string& material, const std::string& roughness,
                      std::span<const ErrorRow> rows, const Panel& reference, const Panel& exact);

// |panel - reference| per pixel and channel; zero on the background.
std::vector<std::array<double, 3>> difference(const Panel& panel, const Panel& reference);

// Tone-mapped (Narkowicz's ACES fit) and sRGB-encoded, or a difference times 4, to 8 bits.
std::uint8_t display(double linear);
std::uint8_t display_difference(double difference);

// Prints the Khronos validation layer's messages (if it ran) on standard error; true when there
// were none. The three renders fail on any.
bool validation_clean(const vulkan::Context& context);

// Panels side by side, each pixel through `to_display`, written as an RGB PNG (atomically).
void write_panels(const std::filesystem::path& path,
                  const std::vector<std::vector<std::array<double, 3>>>& panels, std::uint32_t size,
                  std::uint8_t (*to_display)(double));

// The two error images every render writes, differences times 4: <stem>_difference.png (each of
// `compared`, Schlick's then ours, against the reference) and <stem>_fresnel_difference.png (each
// against the same estimate with the exact Fresnel: the Fresnel's share alone).
void write_difference_panels(const std::filesystem::path& directory, const std::string& stem,
                             std::initializer_list<const Panel*> compared, const Panel& reference,
                             const Panel& exact, std::uint32_t size);

}  // namespace matc::render
