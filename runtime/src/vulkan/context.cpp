#include "matc/vulkan/context.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <mutex>
#include <optional>

namespace matc::vulkan {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

struct MessageLog {
  std::mutex mutex;
  std::vector<std::string> messages;
};

VKAPI_ATTR VkBool32 VKAPI_CALL record_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void* user_data) {
  auto* log = static_cast<MessageLog*>(user_data);
  const char* level =
      (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0 ? "error" : "warning";
  const std::lock_guard lock(log->mutex);
  log->messages.push_back(std::string(level) + ": " + (data->pMessage ? data->pMessage : ""));
  return VK_FALSE;
}

bool has_layer(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& layer) {
    return std::strcmp(layer.layerName, name) == 0;
  });
}

bool has_device_extension(VkPhysicalDevice device, const char* name) {
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& e) {
    return std::strcmp(e.extensionName, name) == 0;
  });
}

// Lower is better: discrete, integrated, virtual, CPU, other.
int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 3;
    default:
      return 4;
  }
}

std::optional<std::uint32_t> graphics_compute_family(VkPhysicalDevice device) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  constexpr VkQueueFlags kNeeded = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  for (std::uint32_t i = 0; i < count; ++i) {
    if ((families[i].queueFlags & kNeeded) == kNeeded) return i;
  }
  return std::nullopt;
}

}  // namespace

const char* result_name(VkResult result) {
  switch (result) {
#define MATC_RESULT_NAME(name) \
  case name:                   \
    return #name;
    MATC_RESULT_NAME(VK_SUCCESS)
    MATC_RESULT_NAME(VK_NOT_READY)
    MATC_RESULT_NAME(VK_TIMEOUT)
    MATC_RESULT_NAME(VK_INCOMPLETE)
    MATC_RESULT_NAME(VK_ERROR_OUT_OF_HOST_MEMORY)
    MATC_RESULT_NAME(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    MATC_RESULT_NAME(VK_ERROR_INITIALIZATION_FAILED)
    MATC_RESULT_NAME(VK_ERROR_DEVICE_LOST)
    MATC_RESULT_NAME(VK_ERROR_MEMORY_MAP_FAILED)
    MATC_RESULT_NAME(VK_ERROR_LAYER_NOT_PRESENT)
    MATC_RESULT_NAME(VK_ERROR_EXTENSION_NOT_PRESENT)
    MATC_RESULT_NAME(VK_ERROR_FEATURE_NOT_PRESENT)
    MATC_RESULT_NAME(VK_ERROR_INCOMPATIBLE_DRIVER)
    MATC_RESULT_NAME(VK_ERROR_TOO_MANY_OBJECTS)
    MATC_RESULT_NAME(VK_ERROR_FORMAT_NOT_SUPPORTED)
    MATC_RESULT_NAME(VK_ERROR_OUT_OF_POOL_MEMORY)
    MATC_RESULT_NAME(VK_ERROR_INVALID_SHADER_NV)
#undef MATC_RESULT_NAME
    default:
      return "VkResult (unknown)";
  }
}

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) {
    throw VulkanError(std::string(what) + " failed: " + result_name(result) + " (" +
                      std::to_string(static_cast<int>(result)) + ")");
  }
}

struct Context::State {
  MessageLog log;
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties{};
  VkPhysicalDeviceMemoryProperties memory{};
  std::uint32_t queue_family = 0;
  std::uint32_t timestamp_bits = 0;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool command_pool = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;

  ~State() {
    if (device != VK_NULL_HANDLE) {
      // Without a fence nothing was ever submitted (and the null device cannot wait).
      if (fence != VK_NULL_HANDLE) vkDeviceWaitIdle(device);
      if (fence != VK_NULL_HANDLE) vkDestroyFence(device, fence, nullptr);
      if (command_pool != VK_NULL_HANDLE) vkDestroyCommandPool(device, command_pool, nullptr);
      vkDestroyDevice(device, nullptr);
    }
    if (messenger != VK_NULL_HANDLE) {
      auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
      if (destroy) destroy(instance, messenger, nullptr);
    }
    if (instance != VK_NULL_HANDLE) vkDestroyInstance(instance, nullptr);
  }

  void create_instance(bool validation) {
    VkApplicationInfo application{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    application.pApplicationName = "matc";
    application.pEngineName = "matc";
    application.apiVersion = VK_API_VERSION_1_1;  // matc's SPIR-V is 1.3

    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    VkDebugUtilsMessengerCreateInfoEXT messenger_info{
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger_info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                     VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger_info.pfnUserCallback = record_message;
    messenger_info.pUserData = &log;
    if (validation) {
      if (!has_layer(kValidationLayer)) {
        throw VulkanError(std::string(kValidationLayer) +
                          " is not installed (Debian: apt-get install vulkan-validationlayers)");
      }
      layers.push_back(kValidationLayer);
      extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pNext = validation ? &messenger_info : nullptr;  // also reports instance creation
    info.pApplicationInfo = &application;
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    const VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER) {
      throw NoDeviceError(
          "no Vulkan driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER); "
          "Mesa's CPU driver lavapipe comes with the Debian package mesa-vulkan-drivers");
    }
    check(result, "vkCreateInstance");
    if (validation) {
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
      if (!create) throw VulkanError("vkCreateDebugUtilsMessengerEXT is not available");
      check(create(instance, &messenger_info, nullptr, &messenger),
            "vkCreateDebugUtilsMessengerEXT");
    }
  }

  void pick_device(const std::string& wanted_name) {
    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    std::string seen;
    int best_rank = 1 << 30;
    for (VkPhysicalDevice candidate : devices) {
      VkPhysicalDeviceProperties candidate_properties;
      vkGetPhysicalDeviceProperties(candidate, &candidate_properties);
      const std::string name = candidate_properties.deviceName;
      seen += (seen.empty() ? "" : ", ") + name;
      const auto family = graphics_compute_family(candidate);
      if (!family || candidate_properties.apiVersion < VK_API_VERSION_1_1) continue;
      if (!wanted_name.empty() && name.find(wanted_name) == std::string::npos) continue;
      const int rank = type_rank(candidate_properties.deviceType);
      if (rank >= best_rank) continue;
      best_rank = rank;
      physical_device = candidate;
      properties = candidate_properties;
      queue_family = *family;
    }
    if (physical_device == VK_NULL_HANDLE) {
      std::string message = "no Vulkan 1.1 device with a graphics and compute queue";
      if (!wanted_name.empty()) message += " whose name contains '" + wanted_name + "'";
      message += seen.empty() ? " (no device at all; lavapipe, Mesa's CPU driver, comes with the "
                                "Debian package mesa-vulkan-drivers)"
                              : " (devices found: " + seen + ")";
      throw NoDeviceError(message);
    }
    vkGetPhysicalDeviceMemoryProperties(physical_device, &memory);
    std::uint32_t family_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &family_count, nullptr);
    std::vector<VkQueueFamilyProperties> families(family_count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &family_count, families.data());
    timestamp_bits = families[queue_family].timestampValidBits;
  }

  void create_device(bool pipeline_statistics) {
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue_info.queueFamilyIndex = queue_family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue_info;
    VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR executable_info{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
    const char* executable_extension = VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME;
    if (pipeline_statistics) {
      if (!has_device_extension(physical_device, executable_extension)) {
        throw NoDeviceError(std::string(properties.deviceName) + " does not report " +
                            executable_extension + " (pipeline statistics)");
      }
      executable_info.pipelineExecutableInfo = VK_TRUE;
      info.pNext = &executable_info;
      info.enabledExtensionCount = 1;
      info.ppEnabledExtensionNames = &executable_extension;
    }
    check(vkCreateDevice(physical_device, &info, nullptr, &device), "vkCreateDevice");
    vkGetDeviceQueue(device, queue_family, 0, &queue);

    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    const VkResult fence_result = vkCreateFence(device, &fence_info, nullptr, &fence);
    // RADV's null device (RADV_FORCE_FAMILY without an AMD GPU) compiles pipelines but can run
    // nothing: a statistics context goes on without a fence or command pool, and submit() refuses.
    if (pipeline_statistics && fence_result != VK_SUCCESS) {
      fence = VK_NULL_HANDLE;
      return;
    }
    check(fence_result, "vkCreateFence");
    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool_info.queueFamilyIndex = queue_family;
    check(vkCreateCommandPool(device, &pool_info, nullptr, &command_pool), "vkCreateCommandPool");
  }
};

Context::Context(const ContextOptions& options) : state_(std::make_unique<State>()) {
  state_->create_instance(options.validation);
  state_->pick_device(options.device_name);
  state_->create_device(options.pipeline_statistics);
}

Context::~Context() = default;

VkDevice Context::device() const {
  return state_->device;
}
VkPhysicalDevice Context::physical_device() const {
  return state_->physical_device;
}
const VkPhysicalDeviceProperties& Context::properties() const {
  return state_->properties;
}
std::string Context::device_name() const {
  return state_->properties.deviceName;
}
bool Context::has_timestamps() const {
  return state_->timestamp_bits > 0 && state_->properties.limits.timestampPeriod > 0.0f;
}

std::uint32_t Context::memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags) const {
  const VkPhysicalDeviceMemoryProperties& memory = state_->memory;
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if ((type_bits & (1u << i)) != 0 && (memory.memoryTypes[i].propertyFlags & flags) == flags)
      return i;
  }
  throw VulkanError("no memory type with the required properties on " + device_name());
}

VkDeviceMemory Context::allocate_memory(const VkMemoryRequirements& requirements,
                                        VkMemoryPropertyFlags flags) const {
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  allocate.allocationSize = requirements.size;
  allocate.memoryTypeIndex = memory_type(requirements.memoryTypeBits, flags);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  check(vkAllocateMemory(state_->device, &allocate, nullptr, &memory), "vkAllocateMemory");
  return memory;
}

void Context::submit(const std::function<void(VkCommandBuffer)>& record) const {
  if (state_->fence == VK_NULL_HANDLE)
    throw VulkanError(device_name() + " compiles pipelines but cannot run them (no fence)");
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = state_->command_pool;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(state_->device, &allocate, &commands), "vkAllocateCommandBuffers");
  struct Release {
    const State& state;
    VkCommandBuffer commands;
    ~Release() { vkFreeCommandBuffers(state.device, state.command_pool, 1, &commands); }
  } release{*state_, commands};

  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer");
  record(commands);
  check(vkEndCommandBuffer(commands), "vkEndCommandBuffer");

  VkSubmitInfo submit_info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit_info.commandBufferCount = 1;
  submit_info.pCommandBuffers = &commands;
  check(vkResetFences(state_->device, 1, &state_->fence), "vkResetFences");
  check(vkQueueSubmit(state_->queue, 1, &submit_info, state_->fence), "vkQueueSubmit");
  check(vkWaitForFences(state_->device, 1, &state_->fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

std::vector<std::string> Context::validation_messages() const {
  const std::lock_guard lock(state_->log.mutex);
  return state_->log.messages;
}

}  // namespace matc::vulkan
