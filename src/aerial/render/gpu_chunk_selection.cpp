#include "aerial/render/gpu_chunk_selection.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <string>

#include "aerial/error.h"

namespace aerial {
namespace {

using terrain::ChunkId;

constexpr int32_t kNotBuilt = -1, kOutsideTerrain = -2;  // terrain_select.comp's
constexpr uint32_t kHorizonAzimuths = 1024;  // terrain_horizon.glsl's
constexpr uint32_t kHorizonEntries = kHorizonAzimuths * 48;  // times its kHorizonBands
constexpr int32_t kWalk = 0, kFinish = 1;                    // terrain_select.comp's kStage
constexpr int32_t kCumulativeHorizon = 0, kHiddenChunks = 1;  // terrain_hidden.comp's kStage
constexpr uint32_t kHiddenWorkgroupSize = 64;                 // and its local size
// The draws' header: draws per pixel, deferred, requested, hidden, draws per vertex, indices, the
// camera's slack (float bits), changed.
using Header = std::array<uint32_t, 8>;
// A feedback's copy: the draws' header, the first requests, the stamps.
constexpr ::vk::DeviceSize kFeedbackRequestsOffset = GpuChunkSelection::kDrawsOffset;
constexpr ::vk::DeviceSize kFeedbackStampsOffset =
    kFeedbackRequestsOffset + GpuChunkSelection::kFedBackRequests * sizeof(glm::ivec4);

// terrain_select.comp's SelectionView (std140).
struct SelectionView {
  std::array<glm::vec4, 5> planes;
  glm::vec4 camera;  // w: pixels per radian
  glm::vec4 limits;  // error bound (px), resolved error (m), the camera's sea-level x and y
  glm::ivec4 root;   // root slot, generation, vertices per slot, first instance
  glm::vec4 vertical;  // w: the camera's height above the sea-level sphere (m)
  glm::vec4 east;      // w: the planet's radius (m)
  glm::vec4 north;     // w: unused (hidden chunks are left out by the passes recorded)
  glm::uvec4 compare;  // x: compare with the last selection's chunks; y: report them changed
  std::array<glm::uvec4, 16> index_ranges;
  std::array<glm::uvec4, 16> block_firsts;  // per skirt mask, per block order
};
static_assert(sizeof(SelectionView) == 704);
static_assert(terrain::kBlockOrders == 4);

// terrain_keys.glsl's: the slots a key's word holds.
constexpr uint32_t kMaxSlots = 1u << 24;

// The same level's chunks across a chunk's sides, in the order of the skirt mask's bits
// (terrain::ChunkSide: south, east, north, west).
std::array<ChunkId, 4> Neighbours(const ChunkId& c) {
  return {ChunkId{c.level, c.x, c.y - 1}, ChunkId{c.level, c.x + 1, c.y}, ChunkId{c.level, c.x, c.y + 1},
          ChunkId{c.level, c.x - 1, c.y}};
}
int Opposite(int side) { return (side + 2) % 4; }
// Which of its parent's children a chunk is (terrain::Children's order).
int ChildIndex(const ChunkId& id) { return (id.x & 1) + 2 * (id.y & 1); }

// terrain_select.comp's bindings.
vk::SlotLayout SelectSlots() {
  return {{"ChunkTree", vk::kStorageBuffer},         {"SelectionView", vk::kUniform},
          {"SelectionQueues", vk::kStorageBuffer},   {"SelectionStamps", vk::kStorageBuffer},
          {"SelectionKeys", vk::kStorageBuffer},     {"SelectionDraws", vk::kStorageBuffer},
          {"SelectionRequests", vk::kStorageBuffer}, {"BlockDispatch", vk::kStorageBuffer},
          {"TileContent", vk::kStorageBuffer}};
}

vk::SlotLayout OccluderSlots() {
  return {{"ChunkTree", vk::kStorageBuffer},        {"SelectionView", vk::kUniform},
          {"SelectionKeys", vk::kStorageBuffer},    {"SelectionDraws", vk::kStorageBuffer},
          {"ChunkBlockHeights", vk::kStorageBuffer}, {"TerrainHorizon", vk::kStorageBuffer},
          {"BlockTargets", vk::kStorageBuffer}};
}

vk::SlotLayout HiddenSlots() {
  return {{"SelectionKeys", vk::kStorageBuffer},
          {"SelectionDraws", vk::kStorageBuffer},
          {"BlockTargets", vk::kStorageBuffer},
          {"TerrainHorizon", vk::kStorageBuffer}};
}

vk::Buffer StorageBuffer(const vk::Context& context, ::vk::DeviceSize size, bool host_visible,
                         ::vk::BufferUsageFlags usage = {}) {
  return vk::Buffer(context, {.size = size, .usage = ::vk::BufferUsageFlagBits::eStorageBuffer | usage,
                              .host_visible = host_visible});
}

uint32_t CheckedSlots(uint32_t slots) {
  if (slots > kMaxSlots)
    throw Error("terrain selection slots", std::to_string(slots), "at most " + std::to_string(kMaxSlots));
  return slots;
}

// The invocations of terrain_select.comp's one workgroup. A CPU rasterizer (llvmpipe) runs a
// workgroup on one thread, a SIMD group of 8 at a time, switching between its groups at every
// barrier: there 256 invocations spend more of a selection switching than working, and 32 take
// far less time (aerial_bench_terrain_selection; docs/speed.md). A GPU runs them side by side:
// 256 keeps its loops over a level's chunks and the sort's stages short.
uint32_t SelectionWorkgroupSize(const vk::Context& context) {
  return context.cpu_device() ? 32 : 256;
}

double CameraSlackM(uint32_t bits) { return double(std::bit_cast<float>(bits)); }

}  // namespace

// The bytes of each buffer a selection over `slots` chunk slots holds. One that never leaves out
// hidden chunks holds the horizon's buffers at a placeholder's size.
struct GpuChunkSelection::BufferBytes {
  BufferBytes(uint32_t slots, bool occlusion_culling) : slots(slots), culling(occlusion_culling) {}
  uint32_t slots;
  bool culling;
  ::vk::DeviceSize ForCulling(::vk::DeviceSize bytes) const { return culling ? bytes : sizeof(glm::vec4); }
  ::vk::DeviceSize tree() const { return slots * sizeof(Node); }
  ::vk::DeviceSize block_heights() const { return ForCulling(slots * terrain::kBlocksPerChunk * sizeof(glm::vec2)); }
  ::vk::DeviceSize queues() const { return 2 * slots * sizeof(int32_t); }
  ::vk::DeviceSize stamps() const { return slots * sizeof(uint32_t); }
  ::vk::DeviceSize keys() const { return std::bit_ceil(slots) * 2 * sizeof(uint32_t); }
  ::vk::DeviceSize draws() const {
    return kDrawsOffset + 2 * slots * sizeof(::vk::DrawIndexedIndirectCommand);
  }
  ::vk::DeviceSize requests() const { return 4 * slots * sizeof(glm::ivec4); }
  static constexpr ::vk::DeviceSize block_groups() { return sizeof(::vk::DispatchIndirectCommand); }
  ::vk::DeviceSize horizon() const { return ForCulling(kHorizonEntries * sizeof(uint32_t)); }
  ::vk::DeviceSize block_targets() const { return ForCulling(slots * terrain::kBlocksPerChunk * sizeof(glm::vec4)); }
  ::vk::DeviceSize content() const { return slots * sizeof(glm::uvec2); }
  ::vk::DeviceSize feedback() const { return kFeedbackStampsOffset + slots * sizeof(uint32_t); }
  ::vk::DeviceSize all(uint32_t feedbacks) const {
    return tree() + block_heights() + sizeof(SelectionView) + queues() + stamps() + keys() + draws() + requests() +
           block_groups() + horizon() + block_targets() + content() + feedbacks * feedback();
  }
};

GpuChunkSelection::BufferBytes GpuChunkSelection::bytes() const { return BufferBytes(slots_, occlusion_culling_); }

uint64_t GpuChunkSelection::MemoryBytes(uint32_t slots, uint32_t feedbacks, bool occlusion_culling) {
  return BufferBytes(slots, occlusion_culling).all(feedbacks);
}

GpuChunkSelection::GpuChunkSelection(const vk::Context& context, uint32_t slots, uint32_t vertices_per_slot,
                                     uint32_t first_instance, uint32_t feedbacks, bool occlusion_culling)
    : slots_(CheckedSlots(slots)),
      occlusion_culling_(occlusion_culling),
      vertices_per_slot_(vertices_per_slot),
      first_instance_(first_instance),
      id_in_slot_(slots),
      nodes_(slots),
      block_heights_m_(occlusion_culling ? slots : 0),
      node_changed_(slots, false),
      tree_(StorageBuffer(context, bytes().tree(), false, ::vk::BufferUsageFlagBits::eTransferDst)),
      block_heights_(StorageBuffer(context, bytes().block_heights(), false,
                                  ::vk::BufferUsageFlagBits::eTransferDst)),
      view_(context, vk::RecordedUniformBufferInfo(sizeof(SelectionView))),
      queues_(StorageBuffer(context, bytes().queues(), false)),
      stamps_(StorageBuffer(context, bytes().stamps(), true, ::vk::BufferUsageFlagBits::eTransferSrc)),
      keys_(StorageBuffer(context, bytes().keys(), false)),
      draws_(StorageBuffer(context, bytes().draws(), true,
                           ::vk::BufferUsageFlagBits::eIndirectBuffer | ::vk::BufferUsageFlagBits::eTransferSrc |
                               ::vk::BufferUsageFlagBits::eConditionalRenderingEXT)),
      requests_(StorageBuffer(context, bytes().requests(), true, ::vk::BufferUsageFlagBits::eTransferSrc)),
      block_groups_(StorageBuffer(context, BufferBytes::block_groups(), false,
                                  ::vk::BufferUsageFlagBits::eIndirectBuffer)),
      horizon_(StorageBuffer(context, bytes().horizon(), false,
                             ::vk::BufferUsageFlagBits::eTransferDst)),
      block_targets_(StorageBuffer(context, bytes().block_targets(), false)),
      content_(StorageBuffer(context, bytes().content(), true)),
      workgroup_size_(SelectionWorkgroupSize(context)),
      walk_(context, "frame/terrain_select.comp", SelectSlots(), 0, {kWalk, int32_t(workgroup_size_)}),
      occluders_(context, "frame/terrain_occluders.comp", OccluderSlots()),
      cumulative_horizon_(context, "frame/terrain_hidden.comp", HiddenSlots(), 0, {kCumulativeHorizon}),
      hidden_(context, "frame/terrain_hidden.comp", HiddenSlots(), 0, {kHiddenChunks}),
      finish_(context, "frame/terrain_select.comp", SelectSlots(), 0, {kFinish, int32_t(workgroup_size_)}),
      feedback_generations_(feedbacks, 0) {
  static_assert(sizeof(Node) == 80);
  std::memset(stamps_.mapped(), 0, stamps_.size());
  std::memset(content_.mapped(), 0, content_.size());
  for (uint32_t i = 0; i < feedbacks; ++i)
    feedbacks_.emplace_back(context, vk::BufferCreateInfo{.size = bytes().feedback(),
                                                    .usage = ::vk::BufferUsageFlagBits::eTransferDst,
                                                    .host_visible = true});
}

GpuChunkSelection::Node& GpuChunkSelection::Change(uint32_t slot) {
  if (!node_changed_[slot]) changed_nodes_.push_back(slot);
  node_changed_[slot] = true;
  return nodes_[slot];
}

std::optional<uint32_t> GpuChunkSelection::SlotOf(const ChunkId& id) const {
  auto it = slot_of_.find(id);
  if (it == slot_of_.end()) return std::nullopt;
  return it->second;
}

// Points the chunk's parent and neighbours at `slot` (kNotBuilt: at nothing).
void GpuChunkSelection::Link(const ChunkId& id, int32_t slot) {
  if (id.level > 0)
    if (std::optional<uint32_t> parent = SlotOf(terrain::Parent(id))) Change(*parent).children[ChildIndex(id)] = slot;
  const std::array<ChunkId, 4> neighbours = Neighbours(id);
  for (int side = 0; side < 4; ++side)
    if (std::optional<uint32_t> neighbour = SlotOf(neighbours[side]))
      Change(*neighbour).neighbours[Opposite(side)] = slot;
}

void GpuChunkSelection::Insert(uint32_t slot, const ChunkId& id, const terrain::ChunkInfo& info,
                               double per_pixel_reads_within_m) {
  Node node{.lower = glm::vec4(glm::vec3(info.bounds.min), float(info.geometric_error_m)),
            .upper = glm::vec4(glm::vec3(info.bounds.max), float(per_pixel_reads_within_m)),
            .id = glm::ivec4(id.level, id.x, id.y, int32_t(fills_++))};
  const std::array<ChunkId, 4> children = terrain::Children(id);
  for (int k = 0; k < 4; ++k) {
    if (id.level == terrain::kMaxChunkLevel || !terrain::WithinTerrain(children[k]))
      node.children[k] = kOutsideTerrain;
    else
      node.children[k] = int32_t(SlotOf(children[k]).value_or(kNotBuilt));
  }
  const std::array<ChunkId, 4> neighbours = Neighbours(id);
  for (int side = 0; side < 4; ++side) node.neighbours[side] = int32_t(SlotOf(neighbours[side]).value_or(kNotBuilt));
  Change(slot) = node;
  if (occlusion_culling_) block_heights_m_[slot] = terrain::BlockHeights(info.cell_lowest_m, info.cell_highest_m);
  inserted_.push_back(slot);
  slot_of_[id] = slot;
  id_in_slot_[slot] = id;
  Link(id, int32_t(slot));
}

void GpuChunkSelection::Remove(uint32_t slot) {
  const ChunkId id = id_in_slot_[slot];
  slot_of_.erase(id);
  Link(id, kNotBuilt);
}

void GpuChunkSelection::Record(const vk::CommandBuffer& cmd, const terrain::LodView& view, uint32_t feedback,
                               Compare compare) {
  if (feedback >= feedbacks_.size())
    throw Error("terrain selection feedback", std::to_string(feedback), "below " + std::to_string(feedbacks_.size()));
  if (view.occlusion_culling && !occlusion_culling_)
    throw Error("terrain selection view", "occlusion culling", "a selection built for it");
  if (++generation_ == 0) ++generation_;  // stamps start at 0: no selection has drawn a slot
  SelectionView block{};
  for (size_t i = 0; i < view.planes.size(); ++i) block.planes[i] = glm::vec4(view.planes[i]);
  // The sea-level point under the camera: the quadtree's order is taken from it.
  const glm::dvec3 center(0.0, 0.0, -view.planet_radius_m);
  const glm::dvec3 eye = center + view.planet_radius_m * glm::normalize(view.camera - center);
  block.camera = glm::vec4(glm::vec3(view.camera), float(view.pixels_per_radian));
  block.limits = glm::vec4(float(view.max_error_px), float(view.resolved_error_m), float(eye.x), float(eye.y));
  block.root = glm::ivec4(int32_t(SlotOf(ChunkId{}).value_or(kNotBuilt)), int32_t(generation_),
                          int32_t(vertices_per_slot_), int32_t(first_instance_));
  // The camera's vertical frame, for the horizon (terrain_horizon.glsl): azimuth 0 along the
  // scene's x made horizontal.
  const glm::dvec3 up = glm::normalize(view.camera - center);
  const glm::dvec3 east = glm::normalize(glm::dvec3(1.0, 0.0, 0.0) - up.x * up);
  block.vertical = glm::vec4(glm::vec3(up), float(glm::length(view.camera - center) - view.planet_radius_m));
  block.east = glm::vec4(glm::vec3(east), float(view.planet_radius_m));
  block.north = glm::vec4(glm::vec3(glm::cross(up, east)), 0.0f);
  block.compare = glm::uvec4(compare != Compare::kNothing, compare == Compare::kRedrawn, 0, 0);
  for (uint32_t mask = 0; mask < 16; ++mask) {
    terrain::IndexRange range = terrain::ChunkIndexRange(mask);
    block.index_ranges[mask] = glm::uvec4(range.first, range.count, 0, 0);
    for (int order = 0; order < terrain::kBlockOrders; ++order)
      block.block_firsts[mask][order] = terrain::ChunkBlockIndexRange(mask, order).first;
  }
  // The tree's changes and the view, in the commands: each selection sees them as they were when
  // it was recorded, whatever is in flight.
  vk::FullBarrier(cmd);
  for (uint32_t slot : changed_nodes_) {
    cmd.updateBuffer(tree_.handle(), slot * sizeof(Node), ::vk::ArrayProxy<const Node>(1, &nodes_[slot]));
    node_changed_[slot] = false;
  }
  if (occlusion_culling_) {
    for (uint32_t slot : inserted_)
      cmd.updateBuffer(block_heights_.handle(), slot * sizeof(block_heights_m_[slot]),
                       ::vk::ArrayProxy<const glm::vec2>(uint32_t(block_heights_m_[slot].size()), block_heights_m_[slot].data()));
  }
  changed_nodes_.clear();
  inserted_.clear();
  cmd.updateBuffer(view_.handle(), 0, ::vk::ArrayProxy<const SelectionView>(1, &block));
  const std::vector<vk::Slot> slots = {
      vk::StorageBufferSlot{&tree_},      vk::UniformBufferSlot{&view_},        vk::StorageBufferSlot{&queues_},
      vk::StorageBufferSlot{&stamps_},    vk::StorageBufferSlot{&keys_},        vk::StorageBufferSlot{&draws_},
      vk::StorageBufferSlot{&requests_},  vk::StorageBufferSlot{&block_groups_}, vk::StorageBufferSlot{&content_}};
  const std::vector<vk::Slot> occluder_slots = {
      vk::StorageBufferSlot{&tree_},  vk::UniformBufferSlot{&view_},         vk::StorageBufferSlot{&keys_},
      vk::StorageBufferSlot{&draws_}, vk::StorageBufferSlot{&block_heights_}, vk::StorageBufferSlot{&horizon_},
      vk::StorageBufferSlot{&block_targets_}};
  const std::vector<vk::Slot> hidden_slots = {vk::StorageBufferSlot{&keys_}, vk::StorageBufferSlot{&draws_},
                                              vk::StorageBufferSlot{&block_targets_},
                                              vk::StorageBufferSlot{&horizon_}};
  if (view.occlusion_culling) cmd.fillBuffer(horizon_.handle(), 0, VK_WHOLE_SIZE, 0u);  // nothing known
  vk::FullBarrier(cmd);
  walk_.Dispatch(cmd, slots, {workgroup_size_, 1, 1}, {workgroup_size_, 1, 1});
  vk::FullBarrier(cmd);
  if (view.occlusion_culling) {
    occluders_.DispatchIndirect(cmd, occluder_slots, block_groups_);
    vk::FullBarrier(cmd);
    cumulative_horizon_.Dispatch(cmd, hidden_slots, {kHorizonAzimuths, 1, 1}, {kHiddenWorkgroupSize, 1, 1});
    vk::FullBarrier(cmd);
    hidden_.DispatchIndirect(cmd, hidden_slots, block_groups_);
    vk::FullBarrier(cmd);
  }
  finish_.Dispatch(cmd, slots, {workgroup_size_, 1, 1}, {workgroup_size_, 1, 1});
  vk::FullBarrier(cmd);
  const ::vk::Buffer copy = feedbacks_[feedback].handle();
  cmd.copyBuffer(draws_.handle(), copy, ::vk::BufferCopy{0, 0, sizeof(Header)});
  cmd.copyBuffer(requests_.handle(), copy,
                 ::vk::BufferCopy{0, kFeedbackRequestsOffset, std::min(kFedBackRequests * sizeof(glm::ivec4), requests_.size())});
  cmd.copyBuffer(stamps_.handle(), copy, ::vk::BufferCopy{0, kFeedbackStampsOffset, slots_ * sizeof(uint32_t)});
  vk::FullBarrier(cmd);
  feedback_generations_[feedback] = generation_;
}

::vk::DeviceSize GpuChunkSelection::per_vertex_draws_offset() const {
  return kDrawsOffset + slots_ * sizeof(::vk::DrawIndexedIndirectCommand);
}

void GpuChunkSelection::BeginIfChanged(const vk::CommandBuffer& cmd) const {
  cmd.beginConditionalRenderingEXT(::vk::ConditionalRenderingBeginInfoEXT{.buffer = draws_.handle(), .offset = kChangedOffset});
}

int GpuChunkSelection::Draw(const vk::CommandBuffer& cmd, std::optional<bool> per_pixel) const {
  int draws = 0;
  auto draw_list = [&](::vk::DeviceSize count_offset, ::vk::DeviceSize draws_offset) {
    cmd.drawIndexedIndirectCount(draws_.handle(), draws_offset, draws_.handle(), count_offset, slots_,
                                 sizeof(::vk::DrawIndexedIndirectCommand));
    ++draws;
  };
  if (per_pixel.value_or(true)) draw_list(0, kDrawsOffset);
  if (!per_pixel.value_or(false)) draw_list(kPerVertexCountOffset, per_vertex_draws_offset());
  return draws;
}

GpuChunkSelection::Feedback GpuChunkSelection::ReadFeedback(uint32_t feedback) const {
  const std::byte* copy = feedbacks_.at(feedback).mapped();
  Header header;
  std::memcpy(header.data(), copy, sizeof(header));
  Feedback result{.generation = feedback_generations_[feedback]};
  if (result.generation == 0) return result;
  result.per_pixel = header[0];
  result.per_vertex = header[4];
  result.indices = header[5];
  result.deferred = int(header[1]);
  result.hidden = int(header[3]);
  result.camera_slack_m = CameraSlackM(header[6]);
  const auto* requests = reinterpret_cast<const glm::ivec4*>(copy + kFeedbackRequestsOffset);
  for (uint32_t i = 0; i < std::min(header[2], kFedBackRequests); ++i)
    result.requested.push_back({requests[i].x, requests[i].y, requests[i].z});
  const auto* stamps = reinterpret_cast<const uint32_t*>(copy + kFeedbackStampsOffset);
  for (uint32_t slot = 0; slot < slots_; ++slot)
    if (stamps[slot] == result.generation) result.drawn_slots.push_back(slot);
  return result;
}

GpuChunkSelection::Result GpuChunkSelection::Read() const {
  Header header;
  std::memcpy(header.data(), draws_.mapped(), sizeof(header));
  const auto* requests = reinterpret_cast<const glm::ivec4*>(requests_.mapped());
  Result result{.per_pixel = header[0],
                .deferred = int(header[1]),
                .hidden = int(header[3]),
                .camera_slack_m = CameraSlackM(header[6]),
                .changed = header[7] != 0};
  for (auto [offset, count] : {std::pair{kDrawsOffset, header[0]}, std::pair{per_vertex_draws_offset(), header[4]}}) {
    const auto* commands = reinterpret_cast<const ::vk::DrawIndexedIndirectCommand*>(draws_.mapped() + offset);
    for (uint32_t i = 0; i < count; ++i) {
      const uint32_t slot = uint32_t(commands[i].vertexOffset) / vertices_per_slot_;
      uint32_t skirts = 0, left_out = 0;
      for (uint32_t mask = 0; mask <= terrain::kAllSides; ++mask) {
        const terrain::IndexRange whole = terrain::ChunkIndexRange(mask);
        if (whole.first == commands[i].firstIndex) skirts = mask;
        for (int order = 0; order < terrain::kBlockOrders; ++order) {
          if (terrain::ChunkBlockIndexRange(mask, order).first != commands[i].firstIndex) continue;
          skirts = mask;
          // The order's last blocks, as many as the draw leaves out.
          for (uint32_t k = (whole.count - commands[i].indexCount) / terrain::kBlockIndices; k > 0; --k)
            left_out |= 1u << terrain::BlockAtPosition(order, terrain::kBlocksPerChunk - k);
        }
      }
      result.chunks.push_back({id_in_slot_[slot], skirts});
      result.blocks_left_out.push_back(left_out);
    }
  }
  for (uint32_t i = 0; i < header[2]; ++i) result.requested.push_back({requests[i].x, requests[i].y, requests[i].z});
  return result;
}

}  // namespace aerial
