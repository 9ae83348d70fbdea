// The uniform blocks shared by C++ and GLSL are written twice, as C++ structs
// (AtmosphereUniforms, FrameUniforms, ShadowUniforms) and as GLSL blocks (AtmosphereBlock in
// definitions.glsl, FrameBlock in frame.glsl, ShadowBlock in shadow.glsl). This checks every
// member's offset and each block's size as the GLSL compiler lays them out (glslangValidator's
// reflection, --reflect-all-block-variables, on shaders/frame/froxel.comp, which binds all three)
// against offsetof and sizeof in C++: a member added, moved or retyped on one side only fails here.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstdio>
#include <map>
#include <memory>
#include <regex>
#include <string>

#include "aerial/shader_abi/atmosphere_block.h"
#include "aerial/shader_abi/frame_block.h"
#include "aerial/shader_abi/shadow_block.h"

namespace aerial {
namespace {

struct Reflection {
  std::map<std::string, long> member_offsets;  // "Block.member" -> byte offset
  std::map<std::string, long> block_sizes;     // "Block" -> bytes
};

Reflection ReflectFroxelShader() {
  std::string command = std::string(GLSLANG_VALIDATOR) + " -q --reflect-all-block-variables -V " +
                        "--target-env vulkan1.2 -I" AERIAL_SOURCE_DIR "/shaders/include " +
                        AERIAL_SOURCE_DIR "/shaders/frame/froxel.comp -o /dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return {};
  std::string output;
  std::array<char, 4096> buffer;
  while (size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe.get())) output.append(buffer.data(), n);
  Reflection reflection;
  // "FrameBlock.viewport: offset 208, type ..." and "FrameBlock: offset -1, type ffffffff, size 224, ..."
  std::regex member(R"(^(\w+Block\.[\w\.\[\]]+): offset (\d+),)");
  std::regex block(R"(^(\w+Block): offset -1, type \w+, size (\d+),)");
  // The atmosphere's and the frame's members sit in the block's array of one struct
  // (definitions.glsl, AERIAL_BLOCK_INDEX): "AtmosphereBlock.parameters[0].top_radius", and
  // "AtmosphereBlock.parameters.top_radius" where a shader reads it at a computed index.
  std::regex parameters(R"(\.parameters(\[0\])?)");
  std::smatch m;
  size_t start = 0;
  while (start < output.size()) {
    size_t end = output.find('\n', start);
    std::string line = output.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (std::regex_search(line, m, member))
      reflection.member_offsets[std::regex_replace(m[1].str(), parameters, "")] = std::stol(m[2]);
    else if (std::regex_search(line, m, block)) reflection.block_sizes[m[1]] = std::stol(m[2]);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return reflection;
}

// The C++ side, member by member, named as in GLSL.
std::map<std::string, long> CppOffsets() {
  std::map<std::string, long> offsets;
#define AERIAL_MEMBER(block, type, member) offsets[#block "." #member] = offsetof(type, member)
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, solar_irradiance);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, rayleigh_scattering);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, mie_scattering);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, mie_extinction);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, absorption_extinction);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, ground_albedo);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, bottom_radius);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, top_radius);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, sun_angular_radius);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, mie_phase_g);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, mu_s_min);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, multiple_density_scale);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, pad1);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, pad2);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, transmittance_size);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, irradiance_size);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, scattering_size);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, density_size);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, density_directions);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, sample_counts);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, multiple_scattering_steps);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, multiple_density_size);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, spectral_sunlight_terms);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, spectral_sunlight_exponent);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, spectral_sunlight_rayleigh);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, spectral_sunlight_mie);
  AERIAL_MEMBER(AtmosphereBlock, AtmosphereUniforms, spectral_sunlight_direct);
  AERIAL_MEMBER(FrameBlock, FrameUniforms, view_projection);
  AERIAL_MEMBER(FrameBlock, FrameUniforms, inverse_view_projection);
  AERIAL_MEMBER(FrameBlock, FrameUniforms, camera_scene_position);
  AERIAL_MEMBER(FrameBlock, FrameUniforms, camera_planet_position);
  AERIAL_MEMBER(FrameBlock, FrameUniforms, sun_direction);
  AERIAL_MEMBER(FrameBlock, FrameUniforms, froxel_size);
  AERIAL_MEMBER(FrameBlock, FrameUniforms, froxel_depth);
  AERIAL_MEMBER(FrameBlock, FrameUniforms, viewport);
  AERIAL_MEMBER(FrameBlock, FrameUniforms, froxel_rows);
  AERIAL_MEMBER(FrameBlock, FrameUniforms, froxel_columns);
  AERIAL_MEMBER(ShadowBlock, ShadowUniforms, toward_sun);
  AERIAL_MEMBER(ShadowBlock, ShadowUniforms, cascade_right);
  AERIAL_MEMBER(ShadowBlock, ShadowUniforms, cascade_up);
  AERIAL_MEMBER(ShadowBlock, ShadowUniforms, cascade_toward_sun);
  AERIAL_MEMBER(ShadowBlock, ShadowUniforms, view_forward);
  AERIAL_MEMBER(ShadowBlock, ShadowUniforms, cascade_far_m);
  AERIAL_MEMBER(ShadowBlock, ShadowUniforms, cascade_origin);
  AERIAL_MEMBER(ShadowBlock, ShadowUniforms, cascade_scale);
  AERIAL_MEMBER(ShadowBlock, ShadowUniforms, cascades);
  AERIAL_MEMBER(ShadowBlock, ShadowUniforms, casters);
#undef AERIAL_MEMBER
  // The density profiles: GLSL's DensityProfile { DensityProfileLayer layers[2]; }.
  const std::pair<const char*, size_t> profiles[] = {
      {"rayleigh_density", offsetof(AtmosphereUniforms, rayleigh_density)},
      {"mie_density", offsetof(AtmosphereUniforms, mie_density)},
      {"absorption_density", offsetof(AtmosphereUniforms, absorption_density)}};
  const std::pair<const char*, size_t> layer_members[] = {
      {"width", offsetof(GpuDensityLayer, width)},
      {"exp_term", offsetof(GpuDensityLayer, exp_term)},
      {"exp_scale", offsetof(GpuDensityLayer, exp_scale)},
      {"linear_term", offsetof(GpuDensityLayer, linear_term)},
      {"constant_term", offsetof(GpuDensityLayer, constant_term)},
      {"pad0", offsetof(GpuDensityLayer, pad0)},
      {"pad1", offsetof(GpuDensityLayer, pad1)},
      {"pad2", offsetof(GpuDensityLayer, pad2)}};
  for (const auto& [profile, profile_offset] : profiles)
    for (int layer = 0; layer < 2; ++layer)
      for (const auto& [name, member_offset] : layer_members)
        offsets[std::string("AtmosphereBlock.") + profile + ".layers[" + std::to_string(layer) + "]." + name] =
            long(profile_offset + layer * sizeof(GpuDensityLayer) + member_offset);
  return offsets;
}

TEST(UniformLayout, GlslBlocksMatchTheCppStructs) {
  Reflection reflection = ReflectFroxelShader();
  std::map<std::string, long> cpp = CppOffsets();
  ASSERT_EQ(cpp.size(), 47u + 3 * 2 * 8);  // every member of the three blocks, once
  // Every member on each side, at the same offset: 95 members.
  EXPECT_EQ(reflection.member_offsets.size(), cpp.size());
  for (const auto& [name, offset] : cpp) {
    auto it = reflection.member_offsets.find(name);
    ASSERT_NE(it, reflection.member_offsets.end()) << name << " is in C++ but not in the GLSL block";
    EXPECT_EQ(it->second, offset) << name;
  }
  for (const auto& [name, offset] : reflection.member_offsets)
    EXPECT_TRUE(cpp.count(name)) << name << " is in the GLSL block but not in C++";
  EXPECT_EQ(reflection.block_sizes["AtmosphereBlock"], long(sizeof(AtmosphereUniforms)));
  EXPECT_EQ(reflection.block_sizes["FrameBlock"], long(sizeof(FrameUniforms)));
  EXPECT_EQ(reflection.block_sizes["ShadowBlock"], long(sizeof(ShadowUniforms)));
}

}  // namespace
}  // namespace aerial
