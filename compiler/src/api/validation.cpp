// The public face of device validation; compiled into libmatc_validate (compiler/CMakeLists.txt).
#include "matc/api/validation.h"

#include <algorithm>

#include "checked_options.h"
#include "matc/vulkan/context.h"
#include "validate/device_check.h"
#include "validate/device_validator.h"

namespace matc::api {
namespace {

// The check run, each front end's quantities described, and the layer's messages it added.
CheckResult run_check(const DeviceValidator& validator, const DeviceCheck& check) {
  const std::size_t messages_before = validator.layer_messages().size();
  const matc::CheckResult result = validator.run(check);
  CheckResult out;
  out.subject = result.subject;
  for (const PathResult& path : result.paths) {
    FrontEndResult front_end;
    front_end.language = path.language == ShaderLanguage::glsl ? "GLSL" : "HLSL";
    for (const matc::CheckedQuantity& quantity : path.quantities) {
      front_end.quantities.push_back(
          {quantity.label, quantity.max_abs, quantity.tolerance,
           quantity.passed() ? std::string()
                             : check.describe_query(quantity.worst_query, quantity.label)});
    }
    out.front_ends.push_back(std::move(front_end));
  }
  const std::vector<std::string> messages = validator.layer_messages();
  out.layer_messages.assign(messages.begin() + static_cast<std::ptrdiff_t>(messages_before),
                            messages.end());
  return out;
}

}  // namespace

bool FrontEndResult::passed() const {
  return std::all_of(quantities.begin(), quantities.end(),
                     [](const CheckedQuantity& quantity) { return quantity.passed(); });
}

bool CheckResult::passed() const {
  return layer_messages.empty() &&
         std::all_of(front_ends.begin(), front_ends.end(),
                     [](const FrontEndResult& front_end) { return front_end.passed(); });
}

DeviceValidation::DeviceValidation(const Build& build, const DeviceOptions& options)
    : build_(build) {
  try {
    validator_ = std::make_unique<DeviceValidator>(
        build_.value(), vulkan::ContextOptions{options.validation_layer, options.device_name});
  } catch (const vulkan::VulkanError& error) {
    throw DeviceError(error.what());
  }
}

DeviceValidation::~DeviceValidation() = default;

std::string DeviceValidation::device_name() const {
  return validator_->device_name();
}
double DeviceValidation::fresnel_tolerance() const {
  return validator_->tolerance().fresnel;
}
double DeviceValidation::preintegrated_tolerance() const {
  return validator_->tolerance().preintegrated;
}
double DeviceValidation::analytic_tolerance() const {
  return validator_->tolerance().analytic;
}
double DeviceValidation::embedded_tolerance() const {
  return validator_->tolerance().embedded;
}

CheckResult DeviceValidation::check(const CompiledMaterial& compiled) const {
  check_same_options(compiled, build_.value().options());
  return run_check(*validator_,
                   *material_check(build_.value(), compiled.value(), validator_->tolerance()));
}

std::vector<CheckResult> DeviceValidation::check_shared_files() const {
  std::vector<CheckResult> results;
  for (const std::unique_ptr<DeviceCheck>& check : validator_->shared_file_checks())
    results.push_back(run_check(*validator_, *check));
  return results;
}

}  // namespace matc::api
