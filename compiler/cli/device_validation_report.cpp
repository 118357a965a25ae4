#include "device_validation_report.h"

#include <fmt/core.h>

namespace matc::cli {

void add_device_options(CLI::App& command, api::DeviceOptions& device) {
  command.add_flag("--vk-validation", device.validation_layer,
                   "Enable the Khronos validation layer; any message it reports fails");
  command.add_option("--device", device.device_name,
                     "Use the Vulkan device whose name contains this (default: a GPU if any, "
                     "else lavapipe)");
}

std::unique_ptr<api::DeviceValidation> open_device_validation(const api::Build& build,
                                                              const api::DeviceOptions& options) {
  try {
    auto validation = std::make_unique<api::DeviceValidation>(build, options);
    fmt::print(
        "matc: validating on {}{}; tolerances F {:.0e}, Fbar {:.0e}, closed-form Fbar {:.0e}{}\n",
        validation->device_name(), options.validation_layer ? " with the validation layer" : "",
        validation->fresnel_tolerance(), validation->preintegrated_tolerance(),
        validation->analytic_tolerance(),
        build.options().embed_lut != 0
            ? fmt::format(", embedded Fbar {:.0e}", validation->embedded_tolerance())
            : "");
    return validation;
  } catch (const api::DeviceError& error) {
    fmt::print(stderr, "matc: error: cannot validate on a Vulkan device: {}\n", error.what());
    return nullptr;
  }
}

bool report_check(const api::CheckResult& result) {
  for (const api::FrontEndResult& front_end : result.front_ends) {
    std::string line = fmt::format("{:<20} {}", result.subject, front_end.language);
    for (const api::CheckedQuantity& quantity : front_end.quantities) {
      line += fmt::format("  {} {:.2e}", quantity.label, quantity.max_abs);
      if (!quantity.passed())
        line += fmt::format(" > {:.0e} at {}", quantity.tolerance, quantity.worst_query);
    }
    fmt::print("{}  {}\n", line, front_end.passed() ? "ok" : "FAILED");
  }
  for (const std::string& message : result.layer_messages)
    fmt::print(stderr, "{}: validation layer: {}\n", result.subject, message);
  return result.passed();
}

bool validate_and_report(const api::DeviceValidation& validation,
                         const api::CompiledMaterial& compiled) {
  return report_check(validation.check(compiled));
}

bool validate_shared_files_and_report(const api::DeviceValidation& validation,
                                      std::vector<std::string>* failed) {
  bool passed = true;
  for (const api::CheckResult& result : validation.check_shared_files()) {
    if (report_check(result)) continue;
    passed = false;
    if (failed) failed->push_back(result.subject);
  }
  return passed;
}

}  // namespace matc::cli
