// Proof on a device (docs/validation.md): a build's shared files and each compiled material's
// shaders run on a Vulkan device (lavapipe in CI), from the GLSL and from the HLSL path, and
// compared with the CPU runtime. In libmatc_validate (CMake target matc::validate), apart from
// libmatc, so that a pipeline that only compiles does not link Vulkan.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "matc/api/build.h"
#include "matc/api/compiled_material.h"

namespace matc {
class DeviceValidator;
}

namespace matc::api {

struct DeviceOptions {
  bool validation_layer = false;  // Khronos validation layer on; any message it reports fails
  std::string device_name;        // a substring of the device's name; empty: a GPU if any
};

// One compared quantity of one front end's run ("F", "Fbar", "Fbar(r, g)", "L").
struct CheckedQuantity {
  std::string label;
  double max_abs = 0.0;  // the largest |device - CPU| over the queries and channels
  double tolerance = 0.0;
  std::string worst_query;  // where max_abs was met, described
  bool passed() const { return max_abs <= tolerance; }
};

struct FrontEndResult {
  std::string language;  // "GLSL" or "HLSL"
  std::vector<CheckedQuantity> quantities;
  bool passed() const;
};

struct CheckResult {
  std::string subject;  // the material's name, or the shared file's check
  std::vector<FrontEndResult> front_ends;
  std::vector<std::string> layer_messages;  // the validation layer's, during this check
  bool passed() const;
};

// A device the build's tables are uploaded to once. Immutable after construction; its checks run
// one at a time.
class DeviceValidation {
 public:
  // Throws DeviceError when no usable device can be opened.
  DeviceValidation(const Build& build, const DeviceOptions& options = {});
  ~DeviceValidation();
  DeviceValidation(const DeviceValidation&) = delete;
  DeviceValidation& operator=(const DeviceValidation&) = delete;

  std::string device_name() const;
  // The tolerances of F, Fbar, the closed-form Fbar and the embedded table's Fbar.
  double fresnel_tolerance() const;
  double preintegrated_tolerance() const;
  double analytic_tolerance() const;
  double embedded_tolerance() const;

  // The shaders of `compiled` (compiled with the build's options: std::invalid_argument
  // otherwise), and the checks of the build's shared files (the library's functions, the
  // coefficient-table and area-light paths).
  CheckResult check(const CompiledMaterial& compiled) const;
  std::vector<CheckResult> check_shared_files() const;

 private:
  Build build_;
  std::unique_ptr<DeviceValidator> validator_;
};

class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace matc::api
