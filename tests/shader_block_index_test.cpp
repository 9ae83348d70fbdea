// The per-frame compute passes read the atmosphere's and the frame's blocks at an index their
// compiler cannot see (shaders/include/blocks_not_inlined.glsl), so that lavapipe finds no uniform
// value to inline and compiles them once, not at every bind. Checked on the embedded SPIR-V: every
// access chain into those blocks takes its array index from an instruction, not from a constant;
// the other shaders keep the constant 0, which the same walk must tell apart.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <span>
#include <vector>

#include "aerial/vk/shader_bindings.h"
#include "aerial/vk/shader_registry.h"

namespace aerial {
namespace {

// Opcodes and decorations of the SPIR-V specification, sections 3.20 and 3.52.
enum Op : uint32_t {
  kOpConstant = 43, kOpSpecConstant = 50, kOpDecorate = 71, kOpAccessChain = 65, kOpInBoundsAccessChain = 66,
};
constexpr uint32_t kBinding = 33;
constexpr size_t kHeaderWords = 5;

struct BlockIndices {
  int constant = 0;  // access chains into the blocks whose array index is a constant
  int computed = 0;  // and those whose index an instruction computes
};

// The access chains into the AtmosphereBlock and FrameBlock variables (found by their bindings,
// as the module's reflection names them): `parameters` (member 0), then the array index, which is
// the chain's second index.
BlockIndices CountBlockIndices(std::span<const uint32_t> spirv) {
  std::set<uint32_t> block_bindings;
  for (const vk::ShaderBinding& b : vk::ReflectShaderBindings(spirv))
    if (b.name == "AtmosphereBlock" || b.name == "FrameBlock") block_bindings.insert(b.binding);
  std::set<uint32_t> blocks, constants;
  struct Chain { uint32_t base; std::span<const uint32_t> indices; };
  std::vector<Chain> chains;
  for (size_t i = kHeaderWords; i < spirv.size();) {
    uint32_t count = spirv[i] >> 16, op = spirv[i] & 0xffff;
    if (count == 0 || i + count > spirv.size()) break;
    std::span<const uint32_t> w = spirv.subspan(i, count);
    if (op == kOpDecorate && w[2] == kBinding && block_bindings.contains(w[3])) blocks.insert(w[1]);
    if (op == kOpConstant || op == kOpSpecConstant) constants.insert(w[2]);
    if (op == kOpAccessChain || op == kOpInBoundsAccessChain) chains.push_back({w[3], w.subspan(4)});
    i += count;
  }
  BlockIndices result;
  for (const Chain& chain : chains)
    if (blocks.contains(chain.base) && chain.indices.size() >= 2)  // fewer: no element chosen
      ++(constants.contains(chain.indices[1]) ? result.constant : result.computed);
  return result;
}

TEST(ShaderBlockIndex, PerFramePassesReadTheBlocksAtAComputedIndexOthersAtTheConstant) {
  struct Case {
    const char* shader;
    bool computed;
  };
  // The three per-frame compute passes; the sky's fragments and a precompute pass, which read the
  // same blocks at the constant 0.
  for (Case c : {Case{"frame/froxel.comp", true}, Case{"frame/sky_view.comp", true},
                 Case{"frame/sky_view_correction.comp", true}, Case{"frame/sky.frag", false},
                 Case{"precompute/single_scattering.comp", false}}) {
    SCOPED_TRACE(c.shader);
    std::span<const uint32_t> spirv = shaders::Find(c.shader);
    ASSERT_FALSE(spirv.empty());
    BlockIndices indices = CountBlockIndices(spirv);
    EXPECT_GT(c.computed ? indices.computed : indices.constant, 0);
    EXPECT_EQ(c.computed ? indices.constant : indices.computed, 0);
  }
}

}  // namespace
}  // namespace aerial
