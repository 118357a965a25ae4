// What a driver's shader compiler says of a pipeline it compiled (VK_KHR_pipeline_executable_
// properties): instruction counts, registers and, on RADV, ACO's static latency and inverse-
// throughput estimates. On RADV's null device (RADV_FORCE_FAMILY, no AMD GPU needed) this is the
// instruction cost of a shader on a real GPU ISA, which lavapipe's timings hide.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "matc/vulkan/context.h"

namespace matc::vulkan {

// One executable of a pipeline (one shader stage, as the driver compiled it) and its statistics.
struct ExecutableStatistics {
  std::string name;  // the driver's name for it, e.g. "Fragment Shader"
  VkShaderStageFlags stages = 0;
  std::vector<std::pair<std::string, std::uint64_t>> values;  // in the driver's order
  // With capture_representations: the driver's text forms of the code, by name (on RADV "NIR
  // Shader(s)", "ACO IR" and "Assembly"; binary forms are left out).
  std::vector<std::pair<std::string, std::string>> representations;

  // The statistic called `statistic` (e.g. "Inverse Throughput"), if the driver reports it.
  std::optional<std::uint64_t> value(std::string_view statistic) const;
};

// A descriptor a shader declares in set 0: a layout-only binding (nothing is bound or run).
struct DescriptorSlot {
  std::uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
};

// Compiles the full-screen pass of FullscreenPass (the same render pass and pipeline state) with
// statistics captured and returns its fragment stage's. `context` must have been created with
// ContextOptions::pipeline_statistics; nothing is drawn. With capture_representations the
// driver also keeps the code's text forms (its disassembly among them).
ExecutableStatistics fullscreen_fragment_statistics(const Context& context,
                                                    std::span<const std::uint32_t> vertex_spirv,
                                                    std::span<const std::uint32_t> fragment_spirv,
                                                    std::span<const DescriptorSlot> slots,
                                                    bool capture_representations = false);

}  // namespace matc::vulkan
