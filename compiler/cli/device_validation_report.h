// Running materials' shaders on a Vulkan device for `matc validate` and `matc --validate`, and
// printing what was found.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "matc/validate/device_check.h"
#include "matc/validate/device_validator.h"

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

// Runs one check from GLSL and HLSL and prints a line for each front end (standard output), then
// the validation layer's new messages. False when a path failed or the layer spoke.
bool run_check_and_report(const DeviceValidator& validator, const DeviceCheck& check);

// The same for one material (material_check()).
bool validate_and_report(const DeviceValidator& validator, const CompiledMaterial& compiled);

// Every check of the build's shared files (shared_file_checks()); false when any failed, and
// `failed` gets their subjects.
bool validate_shared_files_and_report(const DeviceValidator& validator,
                                      std::vector<std::string>* failed = nullptr);

}  // namespace matc::cli
