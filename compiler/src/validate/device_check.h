// One device check: proof that a family of generated functions computes on a Vulkan device what
// the CPU runtime computes. A check is its kernel (per front end), its queries, the comparison of
// the device's results with the runtime, and the words a report uses; each lives in one file of
// src/validate/. DeviceValidator::run (device_validator.h) runs any check from GLSL and HLSL, and
// `matc validate`, `matc --validate` and the tests walk the same checks: material_check() for each
// material, shared_file_checks() for what the build's shared files carry.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "compile/compile.h"
#include "emit/build.h"
#include "emit/shader_literals.h"
#include "spirv/shader_compiler.h"

namespace matc {

// Largest differences allowed between device and CPU (docs/validation.md says why these).
struct ValidationTolerance {
  // F(mu): float32 arithmetic on the same polynomial and coefficients.
  double fresnel = 1e-5;
  // Fbar through the device's sampler: hardware bilinear weights may carry as few as 8 bits (the
  // coefficient-table and area-light paths, which sample, take this one too).
  double preintegrated = 1e-4;
  // Fbar from the embedded table: bilinear filtering in float32 shader code.
  double embedded = 1e-5;
  // Fbar from the closed form: float32 Chebyshev sums (coefficients below ~1).
  double analytic = 1e-5;
};

// One compared quantity of one front end's run ("F", "Fbar(r, g)", "L").
struct CheckedQuantity {
  std::string label;
  double tolerance = 0.0;
  // The largest |device - CPU| over the queries and channels (infinite for a NaN), and at which
  // query.
  double max_abs = 0.0;
  std::size_t worst_query = 0;
  bool passed() const { return max_abs <= tolerance; }
};

struct PathResult {
  ShaderLanguage language = ShaderLanguage::glsl;
  std::vector<CheckedQuantity> quantities;
  bool passed() const;
  // The quantity of this label (throws std::out_of_range for another).
  const CheckedQuantity& quantity(std::string_view label) const;
};

struct CheckResult {
  std::string subject;
  std::vector<PathResult> paths;  // GLSL, then HLSL
  bool passed() const;
};

// The tables a kernel samples besides the preintegrated one.
struct KernelTables {
  bool coefficient_table = false;  // binding 4
  bool ltc = false;                // binding 5
  std::vector<float> film;         // binding 6: a filmed metal's table (film_table_texels)
};

class DeviceCheck {
 public:
  virtual ~DeviceCheck() = default;
  // What a report line names: a material, "coefficient table", "area lights (LTC)".
  virtual std::string subject() const = 0;
  virtual SpirvWords kernel(ShaderLanguage language) const = 0;
  virtual KernelTables tables() const { return {}; }
  virtual std::size_t query_count() const = 0;
  // The queries as the kernel reads them (vec4s, query after query).
  virtual std::vector<float> packed_queries() const = 0;
  virtual std::size_t result_vec4s_per_query() const = 0;
  // One front end's results (query_count() * result_vec4s_per_query() vec4s) against the CPU.
  virtual std::vector<CheckedQuantity> compare(std::span<const float> results) const = 0;
  // Where query `index` lies, as a report says it when `label` fails there ("mu 0.1250").
  virtual std::string describe_query(std::size_t index, std::string_view label) const = 0;
};

// One material's generated code: F, Fbar through the sampler, from the embedded table (with one),
// and from the closed form, over validation_queries().
std::unique_ptr<DeviceCheck> material_check(const Build& build, const CompiledMaterial& compiled,
                                            const ValidationTolerance& tolerance);
// The textured-metal paths (coefficient table, n and k, baked coefficients), over
// table_validation_queries().
std::unique_ptr<DeviceCheck> coefficient_table_check(const Build& build,
                                                     const ValidationTolerance& tolerance);
// The area-light functions (LTC quad, disk and sphere lights), over
// area_light_validation_queries().
std::unique_ptr<DeviceCheck> area_light_check(const Build& build,
                                              const ValidationTolerance& tolerance);
// The checks of what a build's shared files carry: the coefficient-table path when it emits the
// coefficient table, the area lights when it emits the LTC table.
std::vector<std::unique_ptr<DeviceCheck>> shared_file_checks(const Build& build,
                                                             const ValidationTolerance& tolerance);

}  // namespace matc
