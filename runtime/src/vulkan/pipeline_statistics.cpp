#include "matc/vulkan/pipeline_statistics.h"

#include <string>
#include <vector>

#include "fullscreen_pipeline.h"
#include "shader_module.h"

namespace matc::vulkan {
namespace {

// Destroys what it holds when the scope ends, however it ends.
struct PipelineObjects {
  VkDevice device;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  ~PipelineObjects() {
    vkDestroyPipeline(device, pipeline, nullptr);
    vkDestroyRenderPass(device, render_pass, nullptr);
    vkDestroyPipelineLayout(device, layout, nullptr);
    vkDestroyDescriptorSetLayout(device, set_layout, nullptr);
  }
};

template <typename Function>
Function device_function(VkDevice device, const char* name) {
  auto function = reinterpret_cast<Function>(vkGetDeviceProcAddr(device, name));
  if (function == nullptr) {
    throw VulkanError(std::string(name) +
                      " is not available: create the Context with pipeline_statistics");
  }
  return function;
}

// Vulkan's two-call enumeration: the count, then the items (each with its sType set).
template <typename Item, typename Call>
std::vector<Item> enumerate(VkStructureType type, const char* what, const Call& call) {
  std::uint32_t count = 0;
  check(call(&count, nullptr), what);
  std::vector<Item> items(count, Item{type});
  check(call(&count, items.data()), what);
  return items;
}

std::uint64_t as_integer(const VkPipelineExecutableStatisticKHR& statistic) {
  switch (statistic.format) {
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR:
      return statistic.value.b32;
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR:
      return static_cast<std::uint64_t>(statistic.value.i64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR:
      return statistic.value.u64;
    default:  // FLOAT64: none of the counts we read
      return static_cast<std::uint64_t>(statistic.value.f64);
  }
}

}  // namespace

std::optional<std::uint64_t> ExecutableStatistics::value(std::string_view statistic) const {
  for (const auto& [label, number] : values)
    if (label == statistic) return number;
  return std::nullopt;
}

ExecutableStatistics fullscreen_fragment_statistics(const Context& context,
                                                    std::span<const std::uint32_t> vertex_spirv,
                                                    std::span<const std::uint32_t> fragment_spirv,
                                                    std::span<const DescriptorSlot> slots,
                                                    bool capture_representations) {
  const VkDevice device = context.device();
  const auto get_properties = device_function<PFN_vkGetPipelineExecutablePropertiesKHR>(
      device, "vkGetPipelineExecutablePropertiesKHR");
  const auto get_statistics = device_function<PFN_vkGetPipelineExecutableStatisticsKHR>(
      device, "vkGetPipelineExecutableStatisticsKHR");
  const auto get_representations =
      device_function<PFN_vkGetPipelineExecutableInternalRepresentationsKHR>(
          device, "vkGetPipelineExecutableInternalRepresentationsKHR");

  PipelineObjects objects{device};
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const DescriptorSlot& slot : slots)
    bindings.push_back({slot.binding, slot.type, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = static_cast<std::uint32_t>(bindings.size());
  set_info.pBindings = bindings.data();
  check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &objects.set_layout),
        "vkCreateDescriptorSetLayout");
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &objects.set_layout;
  check(vkCreatePipelineLayout(device, &layout_info, nullptr, &objects.layout),
        "vkCreatePipelineLayout");
  objects.render_pass = create_fullscreen_render_pass(device);
  const ShaderModule vertex(device, vertex_spirv);
  const ShaderModule fragment(device, fragment_spirv);
  VkPipelineCreateFlags capture = VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR;
  if (capture_representations)
    capture |= VK_PIPELINE_CREATE_CAPTURE_INTERNAL_REPRESENTATIONS_BIT_KHR;
  // The size only sets the viewport state, which does not change the code.
  objects.pipeline =
      create_fullscreen_pipeline(device, objects.render_pass, objects.layout, vertex.handle(),
                                 fragment.handle(), 64, 64, capture);

  VkPipelineInfoKHR pipeline_info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
  pipeline_info.pipeline = objects.pipeline;
  const auto executables = enumerate<VkPipelineExecutablePropertiesKHR>(
      VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR, "vkGetPipelineExecutablePropertiesKHR",
      [&](std::uint32_t* count, VkPipelineExecutablePropertiesKHR* items) {
        return get_properties(device, &pipeline_info, count, items);
      });
  for (std::uint32_t index = 0; index < executables.size(); ++index) {
    if ((executables[index].stages & VK_SHADER_STAGE_FRAGMENT_BIT) == 0) continue;
    VkPipelineExecutableInfoKHR executable{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
    executable.pipeline = objects.pipeline;
    executable.executableIndex = index;
    const auto statistics = enumerate<VkPipelineExecutableStatisticKHR>(
        VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR, "vkGetPipelineExecutableStatisticsKHR",
        [&](std::uint32_t* count, VkPipelineExecutableStatisticKHR* items) {
          return get_statistics(device, &executable, count, items);
        });
    ExecutableStatistics result{executables[index].name, executables[index].stages, {}};
    for (const VkPipelineExecutableStatisticKHR& statistic : statistics)
      result.values.emplace_back(statistic.name, as_integer(statistic));
    if (capture_representations) {
      const auto call = [&](std::uint32_t* count,
                            VkPipelineExecutableInternalRepresentationKHR* items) {
        return get_representations(device, &executable, count, items);
      };
      // Sizes first, then the text into buffers of those sizes.
      auto forms = enumerate<VkPipelineExecutableInternalRepresentationKHR>(
          VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INTERNAL_REPRESENTATION_KHR,
          "vkGetPipelineExecutableInternalRepresentationsKHR", call);
      std::vector<std::string> texts(forms.size());
      for (std::size_t i = 0; i < forms.size(); ++i) {
        texts[i].assign(forms[i].dataSize, '\0');
        forms[i].pData = texts[i].data();
      }
      auto count = static_cast<std::uint32_t>(forms.size());
      check(call(&count, forms.data()), "vkGetPipelineExecutableInternalRepresentationsKHR");
      for (std::size_t i = 0; i < forms.size(); ++i) {
        if (!forms[i].isText) continue;
        std::string text = texts[i].substr(0, texts[i].find('\0'));  // the size counts the NUL
        result.representations.emplace_back(forms[i].name, std::move(text));
      }
    }
    return result;
  }
  throw VulkanError("the driver reported no fragment-shader executable for the pipeline");
}

}  // namespace matc::vulkan
