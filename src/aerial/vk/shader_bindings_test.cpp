#include "aerial/vk/shader_bindings.h"

#include <gtest/gtest.h>

#include "aerial/error.h"
#include "aerial/vk/compute_pipeline.h"
#include "aerial/vk/descriptors.h"
#include "aerial/vk/shader_registry.h"

namespace aerial::vk {
namespace {

using ::vk::DescriptorType;

// The froxel pass's bindings as shaders/frame/froxel.comp declares them (written out here from
// the GLSL, not from the reflection under test): blocks by their type's name, images by theirs.
const SlotLayout kFroxelBindings = {
    {"AtmosphereBlock", kUniform},        {"FrameBlock", kUniform},
    {"transmittance_texture", kSampled},  {"multiple_density_texture", kSampled},
    {"rayleigh_froxels", kStorageImage},  {"mie_froxels", kStorageImage},
    {"transmittance_froxels", kStorageImage}, {"ShadowBlock", kUniform},
    {"shadow_map", kSampled}};

TEST(ShaderBindings, ReflectionFindsEveryBindingByNameAndType) {
  std::vector<ShaderBinding> found = ReflectShaderBindings(shaders::Find("frame/froxel.comp"));
  ASSERT_EQ(found.size(), kFroxelBindings.size());
  for (const ShaderBinding& b : found) {
    SCOPED_TRACE(b.name);
    ASSERT_LT(b.binding, kFroxelBindings.size());
    EXPECT_EQ(b.set, 0u);
    EXPECT_EQ(b.name, kFroxelBindings[b.binding].name);
    EXPECT_EQ(b.type, kFroxelBindings[b.binding].type);
  }
  // Storage buffers: the probe's queries and results (std430 blocks).
  std::vector<ShaderBinding> probe = ReflectShaderBindings(shaders::Find("probe/probe.comp"));
  ASSERT_EQ(probe.size(), 9u);
  EXPECT_EQ(probe.back().name, "Results");
  EXPECT_EQ(probe.back().type, DescriptorType::eStorageBuffer);
}

// A layout that names the shader's bindings passes, with slots the shader does not use after
// them; a swapped name, a wrong type or a missing slot is refused, naming the shader and binding.
TEST(ShaderBindings, CheckRefusesSwappedNamesWrongTypesAndMissingSlots) {
  std::span<const uint32_t> froxel = shaders::Find("frame/froxel.comp");
  SlotLayout layout = kFroxelBindings;
  layout.push_back({"unused_by_this_shader", kSampled});
  EXPECT_NO_THROW(CheckShaderBindings("frame/froxel.comp", froxel, layout));

  auto refusal = [&](const SlotLayout& slots) {
    try {
      CheckShaderBindings("frame/froxel.comp", froxel, slots);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  SlotLayout swapped = kFroxelBindings;
  std::swap(swapped[2].name, swapped[3].name);
  EXPECT_NE(refusal(swapped).find("frame/froxel.comp binding 2 (transmittance_texture)"), std::string::npos)
      << refusal(swapped);
  SlotLayout wrong_type = kFroxelBindings;
  wrong_type[4].type = kSampled;
  EXPECT_NE(refusal(wrong_type).find("binding 4 (rayleigh_froxels) type"), std::string::npos) << refusal(wrong_type);
  SlotLayout missing(kFroxelBindings.begin(), kFroxelBindings.end() - 1);
  EXPECT_NE(refusal(missing).find("binding 8 (shadow_map)"), std::string::npos) << refusal(missing);
}

// At dispatch, a resource of the wrong kind for its slot (an image to write where the shader
// samples one) is refused by slot number and name before anything reaches the device.
TEST(ShaderBindings, DispatchRefusesAResourceOfTheWrongKind) {
  Context context({.validation = true});
  const int before = Context::ValidationMessageCount();
  Image image(context, {.extent = {4, 1, 1}});
  ::vk::raii::Sampler sampler = CreateLinearClampSampler(context);
  ComputePipeline pipeline(context, "test/tone_map.comp",
                           {{"radiance_image", kSampled}, {"display_values", kStorageImage}});
  try {
    context.Submit([&](const CommandBuffer& cmd) {
      pipeline.Dispatch(cmd, {StorageImageSlot{&image}, SampledImageSlot{&image, *sampler}}, {4, 1, 1}, {4, 1, 1});
    });
    FAIL() << "a storage image was pushed to a sampled slot";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "test/tone_map.comp slot 0 (radiance_image)");
  }
  EXPECT_EQ(Context::ValidationMessageCount(), before);
}

}  // namespace
}  // namespace aerial::vk
