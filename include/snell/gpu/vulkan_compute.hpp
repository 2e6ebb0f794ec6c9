// A Vulkan compute device for running snell's GLSL compiled to SPIR-V: the
// runner's Vulkan backend (instance, device, buffers, sampled images,
// dispatch, read-back), as the parity suite uses it on lavapipe (Debian's
// mesa-vulkan-drivers). The loader (libvulkan.so.1, Debian's libvulkan1) is
// dlopen()ed like the GL backends, so snell::gpu links nothing new; every
// failure is an Error naming the call and its VkResult ("no Vulkan device"
// included), never an abort.
//
//   snell::gpu::VulkanCompute vk;                        // the first device (SNELL_VULKAN_DEVICE=name picks one)
//   std::vector<snell::gpu::VulkanCompute::Binding> b = {{0, &inBuffer}, {1, &outBuffer}, {16, &image}};
//   vk.dispatch(spirvWords, b, pushConstants, groups);
#pragma once

#define VK_NO_PROTOTYPES
#include <vulkan/vulkan.h>

#include <snell/bridge.hpp>

#include "dynamic_library.hpp"
#include "error.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace snell::gpu {

namespace detail {

inline const char* vkResultName(VkResult r) {
  switch (r) {
    case VK_SUCCESS: return "VK_SUCCESS";
    case VK_NOT_READY: return "VK_NOT_READY";
    case VK_TIMEOUT: return "VK_TIMEOUT";
    case VK_INCOMPLETE: return "VK_INCOMPLETE";
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER (no Vulkan driver: install mesa-vulkan-drivers)";
    case VK_ERROR_TOO_MANY_OBJECTS: return "VK_ERROR_TOO_MANY_OBJECTS";
    case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
    default: return "an unlisted VkResult";
  }
}

}  // namespace detail

// The Vulkan functions the runner calls, loaded through vkGetInstanceProcAddr.
#define SNELL_VK_INSTANCE_FUNCTIONS(X)                                                                       \
  X(vkDestroyInstance) X(vkEnumeratePhysicalDevices) X(vkGetPhysicalDeviceProperties)                      \
  X(vkGetPhysicalDeviceQueueFamilyProperties) X(vkGetPhysicalDeviceMemoryProperties) X(vkCreateDevice)     \
  X(vkGetDeviceProcAddr)
#define SNELL_VK_DEVICE_FUNCTIONS(X)                                                                         \
  X(vkDestroyDevice) X(vkGetDeviceQueue) X(vkCreateBuffer) X(vkDestroyBuffer)                              \
  X(vkGetBufferMemoryRequirements) X(vkAllocateMemory) X(vkFreeMemory) X(vkBindBufferMemory) X(vkMapMemory) \
  X(vkUnmapMemory) X(vkCreateImage) X(vkDestroyImage) X(vkGetImageMemoryRequirements) X(vkBindImageMemory) \
  X(vkCreateImageView) X(vkDestroyImageView) X(vkCreateSampler) X(vkDestroySampler)                        \
  X(vkCreateShaderModule) X(vkDestroyShaderModule) X(vkCreateDescriptorSetLayout)                          \
  X(vkDestroyDescriptorSetLayout) X(vkCreatePipelineLayout) X(vkDestroyPipelineLayout)                     \
  X(vkCreateComputePipelines) X(vkDestroyPipeline) X(vkCreateDescriptorPool) X(vkDestroyDescriptorPool)    \
  X(vkAllocateDescriptorSets) X(vkUpdateDescriptorSets) X(vkCreateCommandPool) X(vkDestroyCommandPool)     \
  X(vkAllocateCommandBuffers) X(vkFreeCommandBuffers) X(vkBeginCommandBuffer) X(vkEndCommandBuffer)        \
  X(vkCmdBindPipeline) X(vkCmdBindDescriptorSets) X(vkCmdPushConstants) X(vkCmdDispatch)                   \
  X(vkCmdPipelineBarrier) X(vkCmdCopyBufferToImage) X(vkQueueSubmit) X(vkQueueWaitIdle)                    \
  X(vkDeviceWaitIdle)

class VulkanCompute {
 public:
  // A host-visible buffer (lavapipe's memory is all host-visible).
  class Buffer {
   public:
    Buffer(const VulkanCompute& vk, std::size_t bytes, VkBufferUsageFlags usage) : vk_(&vk), bytes_(bytes) {
      VkBufferCreateInfo info{};
      info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
      info.size = std::max<std::size_t>(bytes, 16);
      info.usage = usage;
      info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
      vk.check(vk.vkCreateBuffer(vk.device_, &info, nullptr, &buffer_), "vkCreateBuffer");
      VkMemoryRequirements req{};
      vk.vkGetBufferMemoryRequirements(vk.device_, buffer_, &req);
      memory_ = vk.allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
      vk.check(vk.vkBindBufferMemory(vk.device_, buffer_, memory_, 0), "vkBindBufferMemory");
      vk.check(vk.vkMapMemory(vk.device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
    }
    ~Buffer() {
      if (mapped_ != nullptr) vk_->vkUnmapMemory(vk_->device_, memory_);
      if (buffer_ != VK_NULL_HANDLE) vk_->vkDestroyBuffer(vk_->device_, buffer_, nullptr);
      if (memory_ != VK_NULL_HANDLE) vk_->vkFreeMemory(vk_->device_, memory_, nullptr);
    }
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;
    void* data() const { return mapped_; }
    std::size_t bytes() const { return bytes_; }
    VkBuffer handle() const { return buffer_; }

   private:
    const VulkanCompute* vk_;
    std::size_t bytes_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    void* mapped_ = nullptr;
  };

  // A snell::Texture2D as a sampled RGBA32F image with all its levels and a
  // sampler with its filters and clamp-to-edge, as snell::gpu::Texture sets up GL.
  class Image {
   public:
    Image(const VulkanCompute& vk, const snell::Texture2D& tex) : vk_(&vk) {
      const int levels = tex.levelCount();
      if (levels < 1) throw Error("Vulkan image: the texture has no level");
      VkImageCreateInfo info{};
      info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
      info.imageType = VK_IMAGE_TYPE_2D;
      info.format = VK_FORMAT_R32G32B32A32_SFLOAT;
      info.extent = {static_cast<std::uint32_t>(tex.level(0).width), static_cast<std::uint32_t>(tex.level(0).height), 1};
      info.mipLevels = static_cast<std::uint32_t>(levels);
      info.arrayLayers = 1;
      info.samples = VK_SAMPLE_COUNT_1_BIT;
      info.tiling = VK_IMAGE_TILING_OPTIMAL;
      info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
      info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
      info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
      vk.check(vk.vkCreateImage(vk.device_, &info, nullptr, &image_), "vkCreateImage");
      VkMemoryRequirements req{};
      vk.vkGetImageMemoryRequirements(vk.device_, image_, &req);
      memory_ = vk.allocate(req, 0);
      vk.check(vk.vkBindImageMemory(vk.device_, image_, memory_, 0), "vkBindImageMemory");

      // Every level through one staging buffer, rows as stored (row 0 at v = 0, as GL).
      std::size_t total = 0;
      for (int l = 0; l < levels; ++l) total += tex.level(l).texels.size() * sizeof(vec4);
      Buffer staging(vk, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
      std::vector<VkBufferImageCopy> copies;
      std::size_t offset = 0;
      for (int l = 0; l < levels; ++l) {
        const snell::Image& img = tex.level(l);
        std::memcpy(static_cast<char*>(staging.data()) + offset, img.texels.data(), img.texels.size() * sizeof(vec4));
        VkBufferImageCopy c{};
        c.bufferOffset = offset;
        c.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, static_cast<std::uint32_t>(l), 0, 1};
        c.imageExtent = {static_cast<std::uint32_t>(img.width), static_cast<std::uint32_t>(img.height), 1};
        copies.push_back(c);
        offset += img.texels.size() * sizeof(vec4);
      }
      vk.submit([&](VkCommandBuffer cmd) {
        VkImageMemoryBarrier b{};
        b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = image_;
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, static_cast<std::uint32_t>(levels), 0, 1};
        b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        vk.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                                nullptr, 1, &b);
        vk.vkCmdCopyBufferToImage(cmd, staging.handle(), image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                  static_cast<std::uint32_t>(copies.size()), copies.data());
        b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        b.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        b.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
        vk.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr,
                                0, nullptr, 1, &b);
      });

      VkImageViewCreateInfo view{};

      view.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
      view.image = image_;
      view.viewType = VK_IMAGE_VIEW_TYPE_2D;
      view.format = VK_FORMAT_R32G32B32A32_SFLOAT;
      view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, static_cast<std::uint32_t>(levels), 0, 1};
      vk.check(vk.vkCreateImageView(vk.device_, &view, nullptr, &view_), "vkCreateImageView");

      const auto filter = [](snell::Filter f) { return f == snell::Filter::Linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST; };
      VkSamplerCreateInfo s{};
      s.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
      s.magFilter = filter(tex.magFilter);
      s.minFilter = filter(tex.minFilter);
      s.mipmapMode = tex.mipFilter == snell::MipFilter::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
      s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
      s.minLod = 0.0f;
      // GL without mips reads level 0 only (GL_NEAREST / GL_LINEAR minification): a
      // Vulkan sampler does that with maxLod 0.25, which keeps a positive LOD
      // positive (so minification picks minFilter, as in GL) while nearest-mip
      // selection stays on level 0.
      s.maxLod = tex.mipFilter == snell::MipFilter::None ? 0.25f : static_cast<float>(levels - 1);
      s.unnormalizedCoordinates = VK_FALSE;
      vk.check(vk.vkCreateSampler(vk.device_, &s, nullptr, &sampler_), "vkCreateSampler");
    }
    ~Image() {
      if (sampler_ != VK_NULL_HANDLE) vk_->vkDestroySampler(vk_->device_, sampler_, nullptr);
      if (view_ != VK_NULL_HANDLE) vk_->vkDestroyImageView(vk_->device_, view_, nullptr);
      if (image_ != VK_NULL_HANDLE) vk_->vkDestroyImage(vk_->device_, image_, nullptr);
      if (memory_ != VK_NULL_HANDLE) vk_->vkFreeMemory(vk_->device_, memory_, nullptr);
    }
    Image(const Image&) = delete;
    Image& operator=(const Image&) = delete;
    VkImageView view() const { return view_; }
    VkSampler sampler() const { return sampler_; }

   private:
    const VulkanCompute* vk_;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    VkSampler sampler_ = VK_NULL_HANDLE;
  };

  // A resource at a descriptor binding of set 0: a storage buffer or a combined image sampler.
  struct Binding {
    std::uint32_t binding;
    const Buffer* buffer = nullptr;
    const Image* image = nullptr;
  };

  VulkanCompute() {
    std::string whyNot;
    library_ = detail::openLibrary({"libvulkan.so.1", "libvulkan.so"}, whyNot);
    if (library_.handle == nullptr)
      throw Error("Vulkan: cannot load the Vulkan loader (" + whyNot + "): install libvulkan1 and mesa-vulkan-drivers");
    getInstanceProc_ =
        detail::requireSymbol<PFN_vkGetInstanceProcAddr>(library_, "vkGetInstanceProcAddr", "Vulkan");
    const auto createInstance =
        reinterpret_cast<PFN_vkCreateInstance>(getInstanceProc_(VK_NULL_HANDLE, "vkCreateInstance"));
    if (createInstance == nullptr) throw Error("Vulkan: the loader has no vkCreateInstance");
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "snell";
    app.apiVersion = VK_API_VERSION_1_1;
    VkInstanceCreateInfo ici{};
    ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    ici.pApplicationInfo = &app;
    check(createInstance(&ici, nullptr, &instance_), "vkCreateInstance");
#define SNELL_VK_LOAD_INSTANCE(name) \
  name = reinterpret_cast<PFN_##name>(require(getInstanceProc_(instance_, #name), #name));
    SNELL_VK_INSTANCE_FUNCTIONS(SNELL_VK_LOAD_INSTANCE)
#undef SNELL_VK_LOAD_INSTANCE
    pickDevice();
#define SNELL_VK_LOAD_DEVICE(name) name = reinterpret_cast<PFN_##name>(require(vkGetDeviceProcAddr(device_, #name), #name));
    SNELL_VK_DEVICE_FUNCTIONS(SNELL_VK_LOAD_DEVICE)
#undef SNELL_VK_LOAD_DEVICE
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
    VkCommandPoolCreateInfo pool{};
    pool.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = queueFamily_;
    check(vkCreateCommandPool(device_, &pool, nullptr, &commandPool_), "vkCreateCommandPool");
  }

  ~VulkanCompute() {
    if (device_ != VK_NULL_HANDLE) {
      vkDeviceWaitIdle(device_);
      if (commandPool_ != VK_NULL_HANDLE) vkDestroyCommandPool(device_, commandPool_, nullptr);
      vkDestroyDevice(device_, nullptr);
    }
    if (instance_ != VK_NULL_HANDLE && vkDestroyInstance != nullptr) vkDestroyInstance(instance_, nullptr);
    // The loader stays loaded, as the GL backends' libraries do (dynamic_library.hpp).
  }
  VulkanCompute(const VulkanCompute&) = delete;
  VulkanCompute& operator=(const VulkanCompute&) = delete;

  // "llvmpipe (LLVM 15.0.6, 256 bits), Vulkan 1.3.230"
  const std::string& description() const { return description_; }
  const VkPhysicalDeviceLimits& limits() const { return limits_; }

  // Runs the compute shader `spirv` (entry "main") once with `bindings` in
  // descriptor set 0, `push` as its push constants, `groups` work groups in x.
  void dispatch(const std::vector<std::uint32_t>& spirv, const std::vector<Binding>& bindings,
                const std::vector<std::uint8_t>& push, std::uint32_t groups) const {
    Pipeline p(*this, spirv, bindings, static_cast<std::uint32_t>(push.size()));
    p.run(bindings, push, groups);
  }

  // A compiled compute pipeline with its descriptor layout, reusable across dispatches.
  class Pipeline {
   public:
    Pipeline(const VulkanCompute& vk, const std::vector<std::uint32_t>& spirv, const std::vector<Binding>& bindings,
             std::uint32_t pushBytes)
        : vk_(&vk), pushBytes_(pushBytes) {
      VkShaderModuleCreateInfo sm{};
      sm.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
      sm.codeSize = spirv.size() * sizeof(std::uint32_t);
      sm.pCode = spirv.data();
      vk.check(vk.vkCreateShaderModule(vk.device_, &sm, nullptr, &module_), "vkCreateShaderModule");
      std::vector<VkDescriptorSetLayoutBinding> layout;
      for (const Binding& b : bindings) {
        VkDescriptorSetLayoutBinding l{};
        l.binding = b.binding;
        l.descriptorType = b.image ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        l.descriptorCount = 1;
        l.stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
        layout.push_back(l);
      }
      VkDescriptorSetLayoutCreateInfo dl{};
      dl.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
      dl.bindingCount = static_cast<std::uint32_t>(layout.size());
      dl.pBindings = layout.data();
      vk.check(vk.vkCreateDescriptorSetLayout(vk.device_, &dl, nullptr, &setLayout_), "vkCreateDescriptorSetLayout");
      VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes};
      VkPipelineLayoutCreateInfo pl{};
      pl.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
      pl.setLayoutCount = 1;
      pl.pSetLayouts = &setLayout_;
      pl.pushConstantRangeCount = pushBytes > 0 ? 1 : 0;
      pl.pPushConstantRanges = &range;
      vk.check(vk.vkCreatePipelineLayout(vk.device_, &pl, nullptr, &pipelineLayout_), "vkCreatePipelineLayout");
      VkComputePipelineCreateInfo cp{};
      cp.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
      cp.stage = VkPipelineShaderStageCreateInfo{};
      cp.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
      cp.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
      cp.stage.module = module_;
      cp.stage.pName = "main";
      cp.layout = pipelineLayout_;
      vk.check(vk.vkCreateComputePipelines(vk.device_, VK_NULL_HANDLE, 1, &cp, nullptr, &pipeline_),
               "vkCreateComputePipelines");
      std::uint32_t buffers = 0, images = 0;
      for (const Binding& b : bindings) (b.image ? images : buffers) += 1;
      std::vector<VkDescriptorPoolSize> sizes;
      if (buffers > 0) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers});
      if (images > 0) sizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, images});
      VkDescriptorPoolCreateInfo dp{};
      dp.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
      dp.flags = 0;
      dp.maxSets = 1;
      dp.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
      dp.pPoolSizes = sizes.data();
      vk.check(vk.vkCreateDescriptorPool(vk.device_, &dp, nullptr, &pool_), "vkCreateDescriptorPool");
      VkDescriptorSetAllocateInfo da{};
      da.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
      da.descriptorPool = pool_;
      da.descriptorSetCount = 1;
      da.pSetLayouts = &setLayout_;
      vk.check(vk.vkAllocateDescriptorSets(vk.device_, &da, &set_), "vkAllocateDescriptorSets");
    }
    ~Pipeline() {
      const VulkanCompute& vk = *vk_;
      if (pool_ != VK_NULL_HANDLE) vk.vkDestroyDescriptorPool(vk.device_, pool_, nullptr);
      if (pipeline_ != VK_NULL_HANDLE) vk.vkDestroyPipeline(vk.device_, pipeline_, nullptr);
      if (pipelineLayout_ != VK_NULL_HANDLE) vk.vkDestroyPipelineLayout(vk.device_, pipelineLayout_, nullptr);
      if (setLayout_ != VK_NULL_HANDLE) vk.vkDestroyDescriptorSetLayout(vk.device_, setLayout_, nullptr);
      if (module_ != VK_NULL_HANDLE) vk.vkDestroyShaderModule(vk.device_, module_, nullptr);
    }
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    // Points the descriptors at `bindings` (the layout's, in the same order), dispatches and waits.
    void run(const std::vector<Binding>& bindings, const std::vector<std::uint8_t>& push, std::uint32_t groups) const {
      const VulkanCompute& vk = *vk_;
      if (push.size() != pushBytes_) throw Error("Vulkan dispatch: push constants of the wrong size");
      std::vector<VkDescriptorBufferInfo> bufferInfos(bindings.size());
      std::vector<VkDescriptorImageInfo> imageInfos(bindings.size());
      std::vector<VkWriteDescriptorSet> writes;
      for (std::size_t i = 0; i < bindings.size(); ++i) {
        VkWriteDescriptorSet w{};
        w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        w.dstSet = set_;
        w.dstBinding = bindings[i].binding;
        w.descriptorCount = 1;
        if (bindings[i].image != nullptr) {
          imageInfos[i] = {bindings[i].image->sampler(), bindings[i].image->view(),
                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
          w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
          w.pImageInfo = &imageInfos[i];
        } else {
          bufferInfos[i] = {bindings[i].buffer->handle(), 0, VK_WHOLE_SIZE};
          w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
          w.pBufferInfo = &bufferInfos[i];
        }
        writes.push_back(w);
      }
      vk.vkUpdateDescriptorSets(vk.device_, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
      vk.submit([&](VkCommandBuffer cmd) {
        vk.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
        vk.vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_, 0, 1, &set_, 0, nullptr);
        if (!push.empty())
          vk.vkCmdPushConstants(cmd, pipelineLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0,
                                static_cast<std::uint32_t>(push.size()), push.data());
        vk.vkCmdDispatch(cmd, groups, 1, 1);
        VkMemoryBarrier m{};
        m.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
        m.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        m.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vk.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &m, 0,
                                nullptr, 0, nullptr);
      });
    }

   private:
    const VulkanCompute* vk_;
    std::uint32_t pushBytes_;
    VkShaderModule module_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
  };

  void check(VkResult r, const char* what) const {
    if (r != VK_SUCCESS) throw Error(std::string("Vulkan: ") + what + " failed: " + detail::vkResultName(r));
  }

 private:
  detail::DynamicLibrary library_{};
  PFN_vkGetInstanceProcAddr getInstanceProc_ = nullptr;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  std::uint32_t queueFamily_ = 0;
  VkPhysicalDeviceMemoryProperties memory_{};
  VkPhysicalDeviceLimits limits_{};
  std::string description_;

 public:
#define SNELL_VK_DECLARE(name) PFN_##name name = nullptr;
  SNELL_VK_INSTANCE_FUNCTIONS(SNELL_VK_DECLARE)
  SNELL_VK_DEVICE_FUNCTIONS(SNELL_VK_DECLARE)
#undef SNELL_VK_DECLARE

 private:
  static void* require(PFN_vkVoidFunction f, const char* name) {
    if (f == nullptr) throw Error(std::string("Vulkan: the driver has no ") + name);
    return reinterpret_cast<void*>(f);
  }

  // The first device with a compute queue, or the one SNELL_VULKAN_DEVICE names (a substring of its name).
  void pickDevice() {
    std::uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices");
    if (count == 0) throw Error("Vulkan: no Vulkan device (install mesa-vulkan-drivers for lavapipe, a CPU device)");
    std::vector<VkPhysicalDevice> devices(count);
    check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()), "vkEnumeratePhysicalDevices");
    const char* wanted = std::getenv("SNELL_VULKAN_DEVICE");
    std::string seen;
    for (VkPhysicalDevice d : devices) {
      VkPhysicalDeviceProperties props{};
      vkGetPhysicalDeviceProperties(d, &props);
      seen += std::string(seen.empty() ? "" : ", ") + props.deviceName;
      if (wanted != nullptr && *wanted != '\0' && std::string(props.deviceName).find(wanted) == std::string::npos) continue;
      std::uint32_t families = 0;
      vkGetPhysicalDeviceQueueFamilyProperties(d, &families, nullptr);
      std::vector<VkQueueFamilyProperties> fam(families);
      vkGetPhysicalDeviceQueueFamilyProperties(d, &families, fam.data());
      for (std::uint32_t f = 0; f < families; ++f) {
        if ((fam[f].queueFlags & VK_QUEUE_COMPUTE_BIT) == 0) continue;
        physical_ = d;
        queueFamily_ = f;
        limits_ = props.limits;
        description_ = std::string(props.deviceName) + ", Vulkan " + std::to_string(VK_API_VERSION_MAJOR(props.apiVersion)) +
                       "." + std::to_string(VK_API_VERSION_MINOR(props.apiVersion)) + "." +
                       std::to_string(VK_API_VERSION_PATCH(props.apiVersion));
        break;
      }
      if (physical_ != VK_NULL_HANDLE) break;
    }
    if (physical_ == VK_NULL_HANDLE)
      throw Error(std::string("Vulkan: no device with a compute queue") +
                  (wanted ? std::string(" named like SNELL_VULKAN_DEVICE=") + wanted : std::string()) +
                  " (devices: " + seen + ")");
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo q{};
    q.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    q.queueFamilyIndex = queueFamily_;
    q.queueCount = 1;
    q.pQueuePriorities = &priority;
    VkDeviceCreateInfo dci{};
    dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &q;
    check(vkCreateDevice(physical_, &dci, nullptr, &device_), "vkCreateDevice");
  }

  VkDeviceMemory allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags wanted) const {
    for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
      if ((req.memoryTypeBits & (1u << i)) == 0) continue;
      if ((memory_.memoryTypes[i].propertyFlags & wanted) != wanted) continue;
      VkMemoryAllocateInfo a{};
      a.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
      a.allocationSize = req.size;
      a.memoryTypeIndex = i;
      VkDeviceMemory m = VK_NULL_HANDLE;
      check(vkAllocateMemory(device_, &a, nullptr, &m), "vkAllocateMemory");
      return m;
    }
    throw Error("Vulkan: no memory type for a buffer or image of " + std::to_string(req.size) + " bytes");
  }

  // Records commands with `record`, submits them and waits for the queue.
  template <class Record>
  void submit(Record record) const {
    VkCommandBufferAllocateInfo a{};
    a.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    a.commandPool = commandPool_;
    a.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    a.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    check(vkAllocateCommandBuffers(device_, &a, &cmd), "vkAllocateCommandBuffers");
    struct Free {
      const VulkanCompute* vk;
      VkCommandBuffer cmd;
      ~Free() { vk->vkFreeCommandBuffers(vk->device_, vk->commandPool_, 1, &cmd); }
    } freeLater{this, cmd};
    VkCommandBufferBeginInfo b{};
    b.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    b.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd, &b), "vkBeginCommandBuffer");
    record(cmd);
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    VkSubmitInfo s{};
    s.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    s.commandBufferCount = 1;
    s.pCommandBuffers = &cmd;
    check(vkQueueSubmit(queue_, 1, &s, VK_NULL_HANDLE), "vkQueueSubmit");
    check(vkQueueWaitIdle(queue_), "vkQueueWaitIdle");
  }
};

}  // namespace snell::gpu
