// The per-frame compute passes read the atmosphere's and the frame's blocks at an index their
// compiler cannot see (shaders/include/blocks_not_inlined.glsl), so that lavapipe finds no uniform
// value to inline and compiles them once, not at every bind. Checked on the embedded SPIR-V: every
// access chain into those blocks takes its array index from an instruction, not from a constant;
// the other shaders keep the constant 0, which the same walk must tell apart.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <set>
#include <span>
#include <string>

#include "aerial/vk/shader_registry.h"

namespace aerial {
namespace {

// Opcodes of the SPIR-V specification, section 3.52.
enum Op : uint32_t {
  kOpName = 5, kOpTypePointer = 32, kOpConstant = 43, kOpSpecConstant = 50, kOpVariable = 59,
  kOpAccessChain = 65, kOpInBoundsAccessChain = 66,
};
constexpr size_t kHeaderWords = 5;

std::string LiteralString(std::span<const uint32_t> words) {
  std::string text;
  for (uint32_t word : words)
    for (int byte = 0; byte < 4; ++byte) {
      char c = char((word >> (8 * byte)) & 0xff);
      if (c == '\0') return text;
      text.push_back(c);
    }
  return text;
}

struct BlockIndices {
  int constant = 0;  // access chains into the blocks whose array index is a constant
  int computed = 0;  // and those whose index an instruction computes
};

// The access chains into AtmosphereBlock and FrameBlock variables: `parameters` (member 0), then
// the array index, which is the chain's second index.
BlockIndices CountBlockIndices(std::span<const uint32_t> spirv) {
  std::map<uint32_t, std::string> names;
  std::map<uint32_t, uint32_t> pointee, variable_type;
  std::set<uint32_t> constants;
  struct Chain { uint32_t base; std::span<const uint32_t> indices; };
  std::vector<Chain> chains;
  for (size_t i = kHeaderWords; i < spirv.size();) {
    uint32_t count = spirv[i] >> 16, op = spirv[i] & 0xffff;
    if (count == 0 || i + count > spirv.size()) break;
    std::span<const uint32_t> w = spirv.subspan(i, count);
    switch (op) {
      case kOpName: names[w[1]] = LiteralString(w.subspan(2)); break;
      case kOpTypePointer: pointee[w[1]] = w[3]; break;
      case kOpConstant:
      case kOpSpecConstant: constants.insert(w[2]); break;
      case kOpVariable: variable_type[w[2]] = pointee[w[1]]; break;
      case kOpAccessChain:
      case kOpInBoundsAccessChain: chains.push_back({w[3], w.subspan(4)}); break;
      default: break;
    }
    i += count;
  }
  BlockIndices result;
  for (const Chain& chain : chains) {
    auto type = variable_type.find(chain.base);
    if (type == variable_type.end()) continue;
    const std::string& block = names[type->second];
    if (block != "AtmosphereBlock" && block != "FrameBlock") continue;
    if (chain.indices.size() < 2) continue;  // the whole array: no element chosen
    ++(constants.contains(chain.indices[1]) ? result.constant : result.computed);
  }
  return result;
}

TEST(ShaderBlockIndex, PerFramePassesReadTheBlocksAtAComputedIndex) {
  for (const char* pass : {"frame/froxel.comp", "frame/sky_view.comp", "frame/sky_view_correction.comp"}) {
    SCOPED_TRACE(pass);
    std::span<const uint32_t> spirv = shaders::Find(pass);
    ASSERT_FALSE(spirv.empty());
    BlockIndices indices = CountBlockIndices(spirv);
    EXPECT_GT(indices.computed, 0);
    EXPECT_EQ(indices.constant, 0);
  }
}

TEST(ShaderBlockIndex, OtherShadersKeepTheConstantIndex) {
  // The sky's fragments and a precompute pass read the same blocks at the constant 0.
  for (const char* shader : {"frame/sky.frag", "precompute/single_scattering.comp"}) {
    SCOPED_TRACE(shader);
    std::span<const uint32_t> spirv = shaders::Find(shader);
    ASSERT_FALSE(spirv.empty());
    BlockIndices indices = CountBlockIndices(spirv);
    EXPECT_GT(indices.constant, 0);
    EXPECT_EQ(indices.computed, 0);
  }
}

}  // namespace
}  // namespace aerial
