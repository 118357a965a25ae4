// Proof that generated shaders compute what the CPU runtime computes: each material's validation
// kernel (emit/validation_kernel.h), built from the GLSL and from the HLSL path, runs on a Vulkan
// device (lavapipe in CI) over a grid of queries, and its results are compared with runtime/.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "matc/compile.h"
#include "matc/emit/build.h"
#include "matc/emit/shader_literals.h"
#include "matc/vulkan/context.h"

namespace matc {

// Largest differences allowed between device and CPU (docs/validation.md says why these).
struct ValidationTolerance {
  // F(mu): float32 arithmetic on the same polynomial and coefficients.
  double fresnel = 1e-5;
  // Fbar through the device's sampler: hardware bilinear weights may carry as few as 8 bits.
  double preintegrated = 1e-4;
  // Fbar from the embedded table: bilinear filtering in float32 shader code.
  double embedded = 1e-5;
  // Fbar from the closed form: float32 Chebyshev sums (coefficients below ~1).
  double analytic = 1e-5;
};

// One query of the kernel: mu for F, (NdotV, roughness) for Fbar.
struct ValidationQuery {
  float mu = 0.0f;
  float ndotv = 0.0f;
  float roughness = 0.0f;
};

// A 41 x 41 grid of (NdotV, roughness) over [0, 1]^2 (table edges, texel centres and points in
// between), paired with as many cosines mu evenly spread over [0, 1].
std::vector<ValidationQuery> validation_queries();

// The largest difference over the queries and channels, and where it happened.
struct Discrepancy {
  double max_abs = 0.0;
  ValidationQuery where;
};

struct PathValidation {
  ShaderLanguage language = ShaderLanguage::glsl;
  Discrepancy fresnel;
  Discrepancy preintegrated;
  std::optional<Discrepancy> embedded;  // with an embedded table only
  Discrepancy analytic;                 // the closed form (matc_preintegrated_basis_analytic)
  bool passed = false;
};

struct MaterialValidation {
  std::string name;
  std::vector<PathValidation> paths;  // GLSL, then HLSL
  bool passed() const;
};

// The coefficient-table path (textured metals): per query a reflectivity, edge tint, n and k per
// channel, a cosine mu and (NdotV, roughness). table_validation_queries() spreads them over
// [0, 1] (table edges included) and n in [0.05, 4], k in [0, 8].
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

struct TableDiscrepancy {
  double max_abs = 0.0;
  std::size_t query = 0;  // index into table_validation_queries()
};

struct TablePathValidation {
  ShaderLanguage language = ShaderLanguage::glsl;
  TableDiscrepancy fresnel;        // F(mu) from (r, g)
  TableDiscrepancy preintegrated;  // Fbar from (r, g)
  TableDiscrepancy from_ior;       // F(mu) from (n, k)
  // F(mu) from matc_coefficients_from_baked (`matc bake`'s textures), with the query's r as F0,
  // g - 0.5 as c_2 and k / 8 - 0.5 as c_3: values of either sign, as baked texels hold.
  TableDiscrepancy baked;
  bool passed = false;
};

struct TableValidation {
  std::vector<TablePathValidation> paths;  // GLSL, then HLSL
  bool passed() const;
};

// The area-light functions (docs/ltc.md): per query a quad, disk or sphere light in world space
// around a shading point at the origin, a shading frame (N, V) turned by a random rotation, and
// coefficients from the coefficient table. area_light_validation_queries() draws lights above,
// across and partly below the horizon, at (NdotV, roughness) over [0, 1]^2.
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

struct AreaLightPathValidation {
  ShaderLanguage language = ShaderLanguage::glsl;
  TableDiscrepancy radiance;  // L = I_ltc * Fbar per channel
  TableDiscrepancy integral;  // I_ltc alone
  bool passed = false;
};

struct AreaLightValidation {
  std::vector<AreaLightPathValidation> paths;  // GLSL, then HLSL
  bool passed() const;
};

class DeviceValidator {
 public:
  // Opens the device and uploads the build's stored table once. Throws vulkan::VulkanError
  // (vulkan::NoDeviceError without a usable device).
  DeviceValidator(const Build& build, const vulkan::ContextOptions& device,
                  ValidationTolerance tolerance = {});
  ~DeviceValidator();
  DeviceValidator(const DeviceValidator&) = delete;
  DeviceValidator& operator=(const DeviceValidator&) = delete;

  // Runs both front ends' kernels for one material.
  MaterialValidation validate(const CompiledMaterial& compiled) const;
  // Runs both front ends' coefficient-table kernels against the CPU runtime (tolerance: the
  // preintegrated one, since every result goes through a sampler).
  TableValidation validate_coefficient_table() const;
  // Runs both front ends' area-light kernels against the CPU runtime (tolerance: the
  // preintegrated one: the LTC matrix and Fbar both come through the sampler).
  AreaLightValidation validate_area_lights() const;

  std::string device_name() const;
  const ValidationTolerance& tolerance() const { return tolerance_; }
  // Warnings and errors from the validation layer so far (with ContextOptions::validation).
  std::vector<std::string> layer_messages() const;

 private:
  PathValidation run(ShaderLanguage language, const CompiledMaterial& compiled) const;
  TablePathValidation run_table(ShaderLanguage language) const;
  AreaLightPathValidation run_area_lights(ShaderLanguage language) const;

  struct Device;
  const Build& build_;
  ValidationTolerance tolerance_;
  std::vector<ValidationQuery> queries_;
  std::unique_ptr<Device> device_;
};

}  // namespace matc
