// The runner's Vulkan backend on lavapipe: a compute shader compiled by
// glslang writes what an independent C++ loop computes, a sampled image reads
// back its texels, and a machine without a Vulkan driver gets an error that
// says what to install (never a skip, never an abort).
#include <snell/gpu/process.hpp>
#include <snell/gpu/vulkan_compute.hpp>

#include "support/temp_dir.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using snell::gpu::Error;
using snell::gpu::VulkanCompute;

// GLSL compiled to SPIR-V by glslang, as the parity runner does.
std::vector<std::uint32_t> compile(const std::string& source) {
  snell_test::TempDir dir;
  const auto file = dir.write("k.comp", source);
  const auto spv = dir.path() / "k.spv";
  const snell::gpu::ToolResult r =
      snell::gpu::runTool("glslangValidator", {"-V", "-o", spv.string(), file.string()}, "glslang-tools");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  const std::string bytes = snell::gpu::detail::readTextFile(spv);
  std::vector<std::uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  return words;
}

TEST(VulkanCompute, AffineKernelAndSampledImage) {
  const VulkanCompute vk;
  EXPECT_NE(vk.description().find("Vulkan 1."), std::string::npos) << vk.description();
  const std::vector<std::uint32_t> spirv = compile(R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Out { vec4 v[]; };
layout(binding = 5) uniform sampler2D tex;
layout(push_constant) uniform P { float a; float b; int n; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(n)) return;
  v[i] = vec4(a * float(i) + b, texelFetch(tex, ivec2(int(i) % 3, 1), 0).x, textureSize(tex, 0));
}
)");
  snell::Image img(3, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) img.at(x, y) = snell::vec4(10.0f * static_cast<float>(y) + static_cast<float>(x));
  const snell::Texture2D tex(img);
  const int n = 1000;
  const VulkanCompute::Buffer out(vk, n * sizeof(snell::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  const VulkanCompute::Image image(vk, tex);
  struct {
    float a, b;
    int n;
  } push{0.5f, 3.0f, n};
  std::vector<std::uint8_t> bytes(sizeof push);
  std::memcpy(bytes.data(), &push, sizeof push);
  vk.dispatch(spirv, {{0, &out, nullptr}, {5, nullptr, &image}}, bytes, (n + 63) / 64);
  const auto* v = static_cast<const snell::vec4*>(out.data());
  for (int i = 0; i < n; ++i) {
    ASSERT_EQ(v[i].x, 0.5f * static_cast<float>(i) + 3.0f) << i;
    ASSERT_EQ(v[i].y, 10.0f + static_cast<float>(i % 3)) << i;  // row 1 of the image: the second row stored
    ASSERT_EQ(v[i].z, 3.0f);
    ASSERT_EQ(v[i].w, 2.0f);
  }
}

// Without a driver the loader finds no device: the error names what to install.
TEST(VulkanCompute, NoDriverIsAClearError) {
  snell_test::TempDir dir;
  const std::string none = (dir.path() / "no_such_icd.json").string();
  const char* old = std::getenv("VK_ICD_FILENAMES");
  const std::string saved = old ? old : "";
  setenv("VK_ICD_FILENAMES", none.c_str(), 1);
  std::string message;
  try {
    const VulkanCompute vk;
    ADD_FAILURE() << "a Vulkan device without a driver: " << vk.description();
  } catch (const Error& e) {
    message = e.what();
  }
  if (old) setenv("VK_ICD_FILENAMES", saved.c_str(), 1); else unsetenv("VK_ICD_FILENAMES");
  EXPECT_NE(message.find("mesa-vulkan-drivers"), std::string::npos) << message;
  EXPECT_EQ(message.rfind("Vulkan: ", 0), 0u) << message;
}

}  // namespace
