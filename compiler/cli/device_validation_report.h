// Running materials' shaders on a Vulkan device for `matc validate` and `matc --validate` (the
// public API's DeviceValidation, matc/api/validation.h), and printing what was found.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "matc/api/validation.h"

namespace matc::cli {

// Adds --vk-validation and --device to `command`.
void add_device_options(CLI::App& command, api::DeviceOptions& device);

// Opens the device and prints which one and the tolerances; on failure prints why and returns
// null (the caller exits with kExitNoDevice).
std::unique_ptr<api::DeviceValidation> open_device_validation(const api::Build& build,
                                                              const api::DeviceOptions& options);

// Prints a line for each front end of `result` (standard output), then the validation layer's
// messages (standard error). False when a front end failed or the layer spoke.
bool report_check(const api::CheckResult& result);

// One material's check, reported.
bool validate_and_report(const api::DeviceValidation& validation,
                         const api::CompiledMaterial& compiled);

// Every check of the build's shared files, reported; false when any failed, and `failed` gets
// their subjects.
bool validate_shared_files_and_report(const api::DeviceValidation& validation,
                                      std::vector<std::string>* failed = nullptr);

}  // namespace matc::cli
