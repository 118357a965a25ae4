// Running materials' shaders on a Vulkan device for `matc validate` and `matc --validate`, and
// printing what was found.
#pragma once

#include <memory>

#include <string>

#include <CLI/CLI.hpp>

#include "matc/validate/device_validation.h"

namespace matc::cli {

// Where `matc validate` and `matc --validate` run the generated shaders.
struct DeviceCliOptions {
  bool layers = false;  // --vk-validation: Khronos validation layer on, any message fails
  std::string name;     // --device: a substring of the device's name
};

// Adds --vk-validation and --device to `command`.
void add_device_options(CLI::App& command, DeviceCliOptions& device);

// Opens the device and prints which one and the tolerances; on failure prints why and returns
// null (the caller exits with kExitNoDevice).
std::unique_ptr<DeviceValidator> open_device_validator(const Build& build,
                                                       const DeviceCliOptions& options);

// Validates one material's GLSL and HLSL paths and prints a line for each (standard output);
// prints the validation layer's new messages. False when a path failed or the layer spoke.
bool validate_and_report(const DeviceValidator& validator, const CompiledMaterial& compiled);

// Validates the coefficient-table path (textured metals) from GLSL and HLSL and prints a line
// for each. False when a path failed or the layer spoke.
bool validate_coefficient_table_and_report(const DeviceValidator& validator);

// Validates the area-light functions (LTC quad, disk and sphere lights) from GLSL and HLSL and
// prints a line for each. False when a path failed or the layer spoke.
bool validate_area_lights_and_report(const DeviceValidator& validator);

}  // namespace matc::cli
