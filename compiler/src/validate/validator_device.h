// What a DeviceValidator holds on the device (internal: shared by the per-material and the
// coefficient-table validations).
#pragma once

#include <cstdint>
#include <vector>

#include "matc/emit/validation_kernel.h"
#include "matc/fit/coefficient_table.h"
#include "matc/lut/preintegrate.h"
#include "matc/validate/device_validation.h"
#include "matc/vulkan/buffer.h"
#include "matc/vulkan/context.h"
#include "matc/vulkan/image.h"
#include "matc/vulkan/sampler.h"

namespace matc {

inline constexpr std::uint32_t kWorkgroupSize = 64;

struct DeviceValidator::Device {
  vulkan::Context context;
  vulkan::Image lut;
  vulkan::Image coefficient_table;
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
        sampler(context),
        queries(context, query_count * 4 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
        results(context, query_count * kValidationResultsPerQuery * 4 * sizeof(float),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {}
};

}  // namespace matc
