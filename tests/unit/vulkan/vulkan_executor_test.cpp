// The Vulkan executor on lavapipe (or whatever device the loader finds), with the Khronos
// validation layer on: every test also fails if the layer reports anything.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "lut/preintegrate.h"
#include "matc/runtime/lut.h"
#include "matc/vulkan/buffer.h"
#include "matc/vulkan/compute_kernel.h"
#include "matc/vulkan/context.h"
#include "matc/vulkan/fullscreen_pass.h"
#include "matc/vulkan/image.h"
#include "matc/vulkan/sampler.h"
#include "spirv/shader_compiler.h"

namespace {

using matc::vulkan::Binding;

matc::SpirvWords compile(const std::string& text, matc::ShaderStage stage) {
  return matc::compile_to_spirv(
      {matc::ShaderLanguage::glsl, text, "vulkan_executor_test", "main", false, stage});
}

class VulkanExecutor : public testing::Test {
 protected:
  void TearDown() override {
    for (const std::string& message : context_.validation_messages())
      ADD_FAILURE() << "validation layer: " << message;
  }
  matc::vulkan::Context context_{matc::vulkan::ContextOptions{true, ""}};
};

TEST_F(VulkanExecutor, ComputeKernelReadsAndWritesStorageBuffers) {
  const auto module = compile(R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Values { float values[]; };
void main() { uint i = gl_GlobalInvocationID.x; values[i] = values[i] * values[i] + 1.0; })",
                              matc::ShaderStage::compute);
  std::vector<float> input(256);
  for (std::size_t i = 0; i < input.size(); ++i)
    input[i] = static_cast<float>(i) * 0.5f;
  matc::vulkan::Buffer buffer(context_, input.size() * sizeof(float),
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  buffer.write<float>(input);
  const std::array bindings = {Binding::storage_buffer(0, buffer)};
  const matc::vulkan::ComputeKernel kernel(context_, module, bindings);
  kernel.dispatch(4);
  const std::vector<float> output = buffer.read<float>(input.size());
  for (std::size_t i = 0; i < input.size(); ++i)
    EXPECT_EQ(output[i], input[i] * input[i] + 1.0f) << i;
}

// The device's sampler with LutSampler's settings reads the table where runtime::sample_lut
// says (the CPU mirror the validation compares with).
TEST_F(VulkanExecutor, LutSamplerMatchesTheCpuBilinearSample) {
  matc::Lut lut;
  lut.size = 8;
  lut.texels.resize(8 * 8 * 4);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (float& texel : lut.texels)
    texel = unit(random);
  const auto module = compile(R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Points { vec2 points[]; };
layout(std430, binding = 1) writeonly buffer Samples { vec4 samples[]; };
layout(binding = 2) uniform texture2D lut;
layout(binding = 3) uniform sampler lut_sampler;
void main() {
  uint i = gl_GlobalInvocationID.x;
  vec2 axes = vec2(sqrt(points[i].x), points[i].y);
  samples[i] = textureLod(sampler2D(lut, lut_sampler), (axes * 7.0 + 0.5) / 8.0, 0.0);
})",
                              matc::ShaderStage::compute);
  std::vector<float> points(2 * 256);
  for (float& value : points)
    value = unit(random);
  matc::vulkan::Buffer point_buffer(context_, points.size() * sizeof(float),
                                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  point_buffer.write<float>(points);
  matc::vulkan::Buffer samples(context_, 256 * 4 * sizeof(float),
                               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  const matc::vulkan::Image image(context_, 8, 8, lut.texels);
  const matc::vulkan::LutSampler sampler(context_);
  const std::array bindings = {
      Binding::storage_buffer(0, point_buffer), Binding::storage_buffer(1, samples),
      Binding::sampled_image(2, image), Binding::separate_sampler(3, sampler)};
  matc::vulkan::ComputeKernel(context_, module, bindings).dispatch(4);
  const std::vector<float> device = samples.read<float>(256 * 4);
  // Exact on lavapipe (float weights); a GPU with 8 sub-texel bits would be off by up to ~2e-3
  // here, since neighbouring random texels differ by up to 1.
  const double tolerance = context_.properties().limits.subTexelPrecisionBits >= 8 &&
                                   context_.device_name().find("llvmpipe") != std::string::npos
                               ? 1e-6
                               : 4e-3;
  for (std::size_t i = 0; i < 256; ++i) {
    const auto expected = matc::runtime::sample_lut(lut.view(), points[2 * i], points[2 * i + 1]);
    for (std::size_t c = 0; c < 4; ++c)
      EXPECT_NEAR(device[4 * i + c], expected[c], tolerance) << i << " " << c;
  }
}

// Pixels come back top row first; push constants reach the fragment shader.
TEST_F(VulkanExecutor, FullscreenPassDrawsEveryPixelAndReadsThemBack) {
  const auto vertex = compile(R"(#version 450
void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
})",
                              matc::ShaderStage::vertex);
  const auto fragment = compile(R"(#version 450
layout(push_constant) uniform Constants { float value; } constants;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(gl_FragCoord.xy, constants.value, 1.0); })",
                                matc::ShaderStage::fragment);
  matc::vulkan::FullscreenPass pass(context_, vertex, fragment, {}, 40, 24, sizeof(float));
  EXPECT_THROW(pass.read_pixels(), matc::vulkan::VulkanError);
  const float value = 3.25f;
  const matc::vulkan::FrameTime time = pass.draw(std::as_bytes(std::span(&value, 1)));
  EXPECT_GT(time.wall_ms, 0.0);
  const std::vector<float> pixels = pass.read_pixels();
  ASSERT_EQ(pixels.size(), 40u * 24u * 4u);
  for (std::size_t y = 0; y < 24; ++y) {
    for (std::size_t x = 0; x < 40; ++x) {
      const float* pixel = &pixels[(y * 40 + x) * 4];
      EXPECT_EQ(pixel[0], static_cast<float>(x) + 0.5f);
      EXPECT_EQ(pixel[1], static_cast<float>(y) + 0.5f);
      EXPECT_EQ(pixel[2], value);
    }
  }
}

// The layer really is listening: a storage-buffer binding on a buffer made without that usage is
// reported (and cleared so that TearDown does not fail this test).
TEST(VulkanValidationLayer, ReportsMisuse) {
  const matc::vulkan::Context context(matc::vulkan::ContextOptions{true, ""});
  const matc::vulkan::Buffer buffer(context, 64, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  const std::array bindings = {Binding::storage_buffer(0, buffer)};
  const matc::vulkan::DescriptorSet set(context, bindings, VK_SHADER_STAGE_COMPUTE_BIT);
  const auto messages = context.validation_messages();
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages.front().find("error:"), std::string::npos) << messages.front();
}

TEST(VulkanContext, NamesTheDevicesWhenNoneMatches) {
  try {
    const matc::vulkan::Context context(matc::vulkan::ContextOptions{false, "no such device"});
    FAIL() << "expected NoDeviceError";
  } catch (const matc::vulkan::NoDeviceError& error) {
    EXPECT_NE(std::string(error.what()).find("devices found"), std::string::npos) << error.what();
  }
}

}  // namespace
