// What a DeviceValidator holds on the device (internal: shared by the per-material and the
// coefficient-table validations).
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "matc/emit/validation_kernel.h"
#include "matc/fit/coefficient_table.h"
#include "matc/lut/preintegrate.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/ltc.h"
#include "matc/validate/device_validation.h"
#include "matc/vulkan/buffer.h"
#include "matc/vulkan/compute_kernel.h"
#include "matc/vulkan/context.h"
#include "matc/vulkan/image.h"
#include "matc/vulkan/sampler.h"

namespace matc {

inline constexpr std::uint32_t kWorkgroupSize = 64;

// Keeps the largest |actual - expected| over the three channels in `max_abs` and where it
// happened in `where` (a query or its index).
template <typename Where>
void record_largest(double& max_abs, Where& where, const runtime::Rgb& expected,
                    const float* actual, const Where& here) {
  for (std::size_t channel = 0; channel < 3; ++channel) {
    const double difference = std::abs(static_cast<double>(actual[channel]) - expected[channel]);
    // A NaN from the device must fail, not compare false and pass.
    if (std::isnan(difference) || difference > max_abs) {
      max_abs = std::isnan(difference) ? INFINITY : difference;
      where = here;
    }
  }
}

struct DeviceValidator::Device {
  vulkan::Context context;
  vulkan::Image lut;
  vulkan::Image coefficient_table;
  vulkan::Image ltc;
  vulkan::LutSampler sampler;
  vulkan::Buffer queries;
  vulkan::Buffer results;

  Device(const vulkan::ContextOptions& options, const Lut& table,
         const CoefficientTable& coefficients, std::size_t query_count)
      : context(options),
        lut(context, static_cast<std::uint32_t>(table.size), static_cast<std::uint32_t>(table.size),
            table.texels),
        coefficient_table(context, static_cast<std::uint32_t>(coefficients.size()),
                          static_cast<std::uint32_t>(coefficients.size()),
                          rgba_texels(coefficients)),
        ltc(context, static_cast<std::uint32_t>(runtime::shipped_ltc_table().size),
            static_cast<std::uint32_t>(runtime::shipped_ltc_table().size),
            runtime::shipped_ltc_table().texels),
        sampler(context),
        queries(context, query_count * 4 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
        results(context, query_count * kValidationResultsPerQuery * 4 * sizeof(float),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {}

  // Runs one query-kernel (the coefficient-table and area-light ones): `packed` queries at
  // binding 0, `result_floats` results read back from binding 1, the preintegrated table, the
  // sampler and the coefficient table at 2-4, and the LTC table at 5 when `with_ltc`; one
  // invocation per query, `query_count` a multiple of kWorkgroupSize.
  std::vector<float> run_queries(const SpirvWords& module, std::span<const float> packed,
                                 std::size_t query_count, std::size_t result_floats,
                                 bool with_ltc) const {
    vulkan::Buffer query_buffer(context, packed.size() * sizeof(float),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    query_buffer.write<float>(packed);
    vulkan::Buffer result_buffer(context, result_floats * sizeof(float),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::vector<vulkan::Binding> bindings = {vulkan::Binding::storage_buffer(0, query_buffer),
                                             vulkan::Binding::storage_buffer(1, result_buffer),
                                             vulkan::Binding::sampled_image(2, lut),
                                             vulkan::Binding::separate_sampler(3, sampler),
                                             vulkan::Binding::sampled_image(4, coefficient_table)};
    if (with_ltc) bindings.push_back(vulkan::Binding::sampled_image(5, ltc));
    const vulkan::ComputeKernel kernel(context, module, bindings);
    kernel.dispatch(static_cast<std::uint32_t>(query_count / kWorkgroupSize));
    return result_buffer.read<float>(result_floats);
  }
};

}  // namespace matc
