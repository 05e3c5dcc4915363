#include "engine/gpu/compute_pipeline.h"

#include <span>
#include <stdexcept>

#include "engine/gpu/vk_check.h"

namespace qlight::shaders {
std::span<const uint32_t> findSpirv(std::string_view name);
}

namespace qlight::gpu {

ComputePipeline::ComputePipeline(const Context& ctx, const std::string& shaderName,
                                 std::vector<uint32_t> specialization)
    : objects_(ctx.pipelines().get(shaderName, specialization)) {}

const PipelineObjects& ComputePipeline::objects() const {
  static const PipelineObjects kNone;
  return objects_ ? *objects_ : kNone;
}

std::shared_ptr<const PipelineObjects> buildComputePipeline(
    const Context& ctx, const std::string& shaderName,
    const std::vector<uint32_t>& specialization) {
  std::span<const uint32_t> spirv = shaders::findSpirv(shaderName);
  if (spirv.empty()) throw std::runtime_error("no embedded shader named " + shaderName);
  auto out = std::make_shared<PipelineObjects>();
  out->name = shaderName;
  out->reflection = reflectSpirv(spirv);
  for (int i = 0; i < 3; ++i) out->localSize[i] = out->reflection.localSize[i];
  // local_size_x_id = 0..2 convention: specialization constants 0..2 are the workgroup size.
  for (size_t i = 0; i < specialization.size() && i < 3; ++i)
    if (specialization[i]) out->localSize[i] = specialization[i];

  VkDevice device = ctx.device();
  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = spirv.size_bytes();
  moduleInfo.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  QL_VK(vkCreateShaderModule(device, &moduleInfo, nullptr, &module));
  out->module = Unique<VkShaderModule>(
      module, [device](VkShaderModule m) { vkDestroyShaderModule(device, m, nullptr); });

  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const ReflectedBinding& b : out->reflection.bindings) {
    if (b.set != 0)
      throw std::runtime_error("shader " + shaderName + ": binding " + b.name + " uses set " +
                               std::to_string(b.set) + "; qlight uses set 0 only");
    bindings.push_back({b.binding, b.type, b.count, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  }
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  setInfo.bindingCount = uint32_t(bindings.size());
  setInfo.pBindings = bindings.data();
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  QL_VK(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout));
  out->setLayout = Unique<VkDescriptorSetLayout>(setLayout, [device](VkDescriptorSetLayout l) {
    vkDestroyDescriptorSetLayout(device, l, nullptr);
  });

  VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, kMaxPushConstantBytes};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &range;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  QL_VK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
  out->layout = Unique<VkPipelineLayout>(
      layout, [device](VkPipelineLayout l) { vkDestroyPipelineLayout(device, l, nullptr); });

  std::vector<VkSpecializationMapEntry> entries;
  for (uint32_t i = 0; i < specialization.size(); ++i)
    entries.push_back({i, uint32_t(i * sizeof(uint32_t)), sizeof(uint32_t)});
  VkSpecializationInfo spec{uint32_t(entries.size()), entries.data(),
                            specialization.size() * sizeof(uint32_t), specialization.data()};

  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = specialization.empty() ? nullptr : &spec;
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  QL_VK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  out->pipeline = Unique<VkPipeline>(
      pipeline, [device](VkPipeline p) { vkDestroyPipeline(device, p, nullptr); });
  ctx.setName(uint64_t(pipeline), VK_OBJECT_TYPE_PIPELINE, shaderName);
  return out;
}

}  // namespace qlight::gpu
