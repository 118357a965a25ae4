// Runs device checks (device_check.h) on a Vulkan device (lavapipe in CI): the build's tables
// uploaded once, each check's kernel built from the GLSL and from the HLSL path and run over its
// queries. Also the queries the shipped checks use, for tests and reports.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "emit/build.h"
#include "matc/vulkan/context.h"
#include "validate/device_check.h"

namespace matc {

class DeviceValidator {
 public:
  // Opens the device and uploads the build's stored tables once. Throws vulkan::VulkanError
  // (vulkan::NoDeviceError without a usable device).
  DeviceValidator(const Build& build, const vulkan::ContextOptions& device,
                  ValidationTolerance tolerance = {});
  ~DeviceValidator();
  DeviceValidator(const DeviceValidator&) = delete;
  DeviceValidator& operator=(const DeviceValidator&) = delete;

  // Both front ends' kernels of `check`, compared with the CPU runtime.
  CheckResult run(const DeviceCheck& check) const;
  // The same for material_check() and shared_file_checks() with this validator's tolerance.
  CheckResult validate(const CompiledMaterial& compiled) const;
  std::vector<std::unique_ptr<DeviceCheck>> shared_file_checks() const;

  const Build& build() const { return build_; }
  std::string device_name() const;
  const ValidationTolerance& tolerance() const { return tolerance_; }
  // Warnings and errors from the validation layer so far (with ContextOptions::validation).
  std::vector<std::string> layer_messages() const;

 private:
  struct Device;
  const Build& build_;
  ValidationTolerance tolerance_;
  std::unique_ptr<Device> device_;
};

// The material check's queries: a 41 x 41 grid of (NdotV, roughness) over [0, 1]^2 (table edges,
// texel centres and points in between), paired with as many cosines mu evenly spread over [0, 1].
struct ValidationQuery {
  float mu = 0.0f;
  float ndotv = 0.0f;
  float roughness = 0.0f;
};
std::vector<ValidationQuery> validation_queries();

// The coefficient-table check's: per query a reflectivity, edge tint, n and k per channel, a
// cosine mu and (NdotV, roughness), spread over [0, 1] (table edges included) and n in [0.05, 4],
// k in [0, 8].
struct TableQuery {
  std::array<float, 3> reflectivity{};
  std::array<float, 3> edge_tint{};
  std::array<float, 3> n{};
  std::array<float, 3> k{};
  float mu = 0.0f;
  float ndotv = 0.0f;
  float roughness = 0.0f;
};
std::vector<TableQuery> table_validation_queries();

// The area-light check's: per query a quad, disk or sphere light in world space around a shading
// point at the origin, a shading frame (N, V) turned by a random rotation, and coefficients from
// the coefficient table; lights above, across and partly below the horizon, at (NdotV,
// roughness) over [0, 1]^2.
struct AreaLightQuery {
  std::array<float, 3> reflectivity{};
  std::array<float, 3> edge_tint{};
  float ndotv = 0.0f;
  float roughness = 0.0f;
  std::array<float, 3> normal{};
  std::array<float, 3> view{};
  enum class Kind { quad, disk, sphere };
  Kind kind = Kind::quad;
  float radius = 0.0f;  // disks and spheres
  // A quad's corners; a disk's centre and normal; a sphere's centre.
  std::array<std::array<float, 3>, 4> points{};
};
std::vector<AreaLightQuery> area_light_validation_queries();

}  // namespace matc
