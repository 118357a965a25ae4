#include "device_validation_report.h"

#include <fmt/core.h>

namespace matc::cli {

void add_device_options(CLI::App& command, DeviceCliOptions& device) {
  command.add_flag("--vk-validation", device.layers,
                   "Enable the Khronos validation layer; any message it reports fails");
  command.add_option("--device", device.name,
                     "Use the Vulkan device whose name contains this (default: a GPU if any, "
                     "else lavapipe)");
}

std::unique_ptr<DeviceValidator> open_device_validator(const Build& build,
                                                       const DeviceCliOptions& options) {
  try {
    auto validator = std::make_unique<DeviceValidator>(
        build, vulkan::ContextOptions{options.layers, options.name});
    const ValidationTolerance& tolerance = validator->tolerance();
    fmt::print(
        "matc: validating on {}{}; tolerances F {:.0e}, Fbar {:.0e}, closed-form Fbar {:.0e}{}\n",
        validator->device_name(), options.layers ? " with the validation layer" : "",
        tolerance.fresnel, tolerance.preintegrated, tolerance.analytic,
        build.embedded_lut() ? fmt::format(", embedded Fbar {:.0e}", tolerance.embedded) : "");
    return validator;
  } catch (const vulkan::VulkanError& error) {
    fmt::print(stderr, "matc: error: cannot validate on a Vulkan device: {}\n", error.what());
    return nullptr;
  }
}

namespace {

// Prints the validation layer's messages since `messages_before`; false when there were any.
bool report_layer_messages(const DeviceValidator& validator, std::size_t messages_before,
                           std::string_view subject) {
  const std::vector<std::string> messages = validator.layer_messages();
  for (std::size_t i = messages_before; i < messages.size(); ++i)
    fmt::print(stderr, "{}: validation layer: {}\n", subject, messages[i]);
  return messages.size() == messages_before;
}

}  // namespace

bool run_check_and_report(const DeviceValidator& validator, const DeviceCheck& check) {
  const std::size_t messages_before = validator.layer_messages().size();
  const CheckResult result = validator.run(check);
  for (const PathResult& path : result.paths) {
    std::string line = fmt::format("{:<20} {}", result.subject,
                                   path.language == ShaderLanguage::glsl ? "GLSL" : "HLSL");
    for (const CheckedQuantity& quantity : path.quantities) {
      line += fmt::format("  {} {:.2e}", quantity.label, quantity.max_abs);
      if (!quantity.passed()) {
        line += fmt::format(" > {:.0e} at {}", quantity.tolerance,
                            check.describe_query(quantity.worst_query, quantity.label));
      }
    }
    fmt::print("{}  {}\n", line, path.passed() ? "ok" : "FAILED");
  }
  return report_layer_messages(validator, messages_before, result.subject) && result.passed();
}

bool validate_and_report(const DeviceValidator& validator, const CompiledMaterial& compiled) {
  return run_check_and_report(validator,
                              *material_check(validator.build(), compiled, validator.tolerance()));
}

bool validate_shared_files_and_report(const DeviceValidator& validator,
                                      std::vector<std::string>* failed) {
  bool passed = true;
  for (const std::unique_ptr<DeviceCheck>& check : validator.shared_file_checks()) {
    if (run_check_and_report(validator, *check)) continue;
    passed = false;
    if (failed) failed->push_back(check->subject());
  }
  return passed;
}

}  // namespace matc::cli
