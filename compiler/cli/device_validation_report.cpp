#include "device_validation_report.h"

#include <fmt/core.h>

namespace matc::cli {
namespace {

std::string describe(const char* label, const Discrepancy& found, double tolerance, bool direct) {
  if (found.max_abs <= tolerance) return fmt::format("  {} {:.2e}", label, found.max_abs);
  const std::string where = direct ? fmt::format("mu {:.4f}", found.where.mu)
                                   : fmt::format("NdotV {:.4f}, roughness {:.4f}",
                                                 found.where.ndotv, found.where.roughness);
  return fmt::format("  {} {:.2e} > {:.0e} at {}", label, found.max_abs, tolerance, where);
}

}  // namespace

std::unique_ptr<DeviceValidator> open_device_validator(const Build& build,
                                                       const DeviceCliOptions& options) {
  try {
    auto validator = std::make_unique<DeviceValidator>(
        build, vulkan::ContextOptions{options.layers, options.name});
    const ValidationTolerance& tolerance = validator->tolerance();
    fmt::print(
        "matc: validating on {}{}; tolerances F {:.0e}, Fbar {:.0e}{}\n", validator->device_name(),
        options.layers ? " with the validation layer" : "", tolerance.fresnel,
        tolerance.preintegrated,
        build.embedded_lut() ? fmt::format(", embedded Fbar {:.0e}", tolerance.embedded) : "");
    return validator;
  } catch (const vulkan::VulkanError& error) {
    fmt::print(stderr, "matc: error: cannot validate on a Vulkan device: {}\n", error.what());
    return nullptr;
  }
}

bool validate_and_report(const DeviceValidator& validator, const CompiledMaterial& compiled) {
  const std::size_t messages_before = validator.layer_messages().size();
  const MaterialValidation result = validator.validate(compiled);
  const ValidationTolerance& tolerance = validator.tolerance();
  for (const PathValidation& path : result.paths) {
    std::string line = fmt::format("{:<20} {}", result.name,
                                   path.language == ShaderLanguage::glsl ? "GLSL" : "HLSL");
    line += describe("F", path.fresnel, tolerance.fresnel, true);
    line += describe("Fbar", path.preintegrated, tolerance.preintegrated, false);
    if (path.embedded) line += describe("embedded Fbar", *path.embedded, tolerance.embedded, false);
    fmt::print("{}  {}\n", line, path.passed ? "ok" : "FAILED");
  }
  const std::vector<std::string> messages = validator.layer_messages();
  for (std::size_t i = messages_before; i < messages.size(); ++i)
    fmt::print(stderr, "{}: validation layer: {}\n", result.name, messages[i]);
  return result.passed() && messages.size() == messages_before;
}

}  // namespace matc::cli
