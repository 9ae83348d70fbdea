#pragma once
// The terrain's level-of-detail selection made by the GPU (shaders/frame/terrain_select.comp):
// the rule of terrain/lod_selection.h (frustum culling, Ulrich's screen-space error bound, a chunk
// drawn in its children's place until they are built, skirts where a neighbour is drawn at another
// level, front-to-back order), walked on the GPU over the chunks built so far, written as indexed
// indirect draws. Chunks that nearer terrain hides are left out by a horizon around the camera's
// vertical (shaders/include/terrain_horizon.glsl, terrain_occluders.comp), to which every chunk
// the walk keeps adds its cells at once: unlike the CPU's horizon on the screen, no chunk waits
// for those in front of it. Each is then tested against it block by block of its cells, at their
// highest (terrain_hidden.comp), and against the frustum by the ground over the block, which the
// chunk's bounds overstate: a chunk whose blocks are all hidden or outside the view is left out,
// and one seen in part draws without the blocks unseen that come last in one of four block orders
// (rows or columns, from either side; terrain::ChunkBlockIndexRange), as GPU-driven renderers cull
// clusters of a mesh (Wihlidal, "Optimizing the Graphics Pipeline with Compute", GDC 2016). The
// CPU's part no longer grows with the terrain: it keeps the tree of built chunks (a few links per
// chunk built or dropped) and builds the chunks the GPU asks for.
//
// The tree is the chunk slots' table: per slot, the chunk's bounds and error, its blocks' lowest and
// highest heights, and the slots of its children and of its level's neighbours. Its changes reach the GPU
// in the next recorded selection's commands, so each selection in flight walks the tree as it was
// when it was recorded. A removed chunk's slot may be drawn by the selections recorded before the
// removal: its vertices may be overwritten once those have completed.
//
// The drawn chunks come in two lists, as the renderer draws them: those that read the froxels per
// pixel, then those that read them per vertex (render/surface_reads.h), each front to back.
//
// Like the CPU's, it finds how far the camera may move before a refinement test would come out
// otherwise (terrain::Selection::camera_slack_m), in single precision. For a caller that keeps
// what the chunks drew (a shadow map's tile), it can also report whether they changed (Compare).
#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "aerial/terrain/lod_selection.h"
#include "aerial/vk/compute_pipeline.h"
#include "aerial/vk/resources.h"

namespace aerial {

class GpuChunkSelection {
 public:
  // slots: how many chunks the tree holds (the chunk cache's slots, at most 2^24);
  // vertices_per_slot: where slot s's vertices begin (s times it) in the vertex buffer the draws
  // read; first_instance: the draws' first instance; feedbacks: how many selections may be in
  // flight at once, each with its own copy of what it tells the CPU (ReadFeedback);
  // occlusion_culling: whether its views may leave out hidden chunks
  // (terrain::LodView::occlusion_culling), for which it holds the horizon, the blocks' heights and
  // the blocks as targets.
  GpuChunkSelection(const vk::Context& context, uint32_t slots, uint32_t vertices_per_slot, uint32_t first_instance,
                    uint32_t feedbacks = 1, bool occlusion_culling = true);
  // The device memory such a selection holds.
  static uint64_t MemoryBytes(uint32_t slots, uint32_t feedbacks, bool occlusion_culling);

  // The chunk `id`, built, is in `slot` (a free one) / is no longer there. It reads the froxels
  // per pixel while its bounds are within per_pixel_reads_within_m of the camera
  // (PerPixelReadsWithinM), per vertex beyond.
  void Insert(uint32_t slot, const terrain::ChunkId& id, const terrain::ChunkInfo& info,
              double per_pixel_reads_within_m);
  void Remove(uint32_t slot);
  std::optional<uint32_t> SlotOf(const terrain::ChunkId& id) const;

  // Whether the tree changed since the last selection was recorded: if not, a selection of the
  // same view draws what that one drew.
  bool tree_changed() const { return !changed_nodes_.empty() || !inserted_.empty(); }
  uint32_t generation() const { return generation_; }  // of the last selection recorded (0: none)

  // For a caller that draws into an image that keeps what it drew (a shadow map's tile): whether
  // a selection compares the chunks it draws (their slots, which chunk fills each, their skirts)
  // with those of the last selection that compared, to report them changed or not (BeginIfChanged),
  // or reports them changed whatever they are (the caller redraws regardless).
  enum class Compare { kNothing, kWithTheLast, kRedrawn };

  // Records the selection of view's chunks (LodView::front_to_back is not read: the order is
  // always front to back), and the copy of its feedback (< feedbacks) for the CPU.
  void Record(const vk::CommandBuffer& cmd, const terrain::LodView& view, uint32_t feedback = 0,
              Compare compare = Compare::kNothing);

  // What a selection tells the CPU, without the list of its chunks: copied into the feedback it was
  // recorded with, so that it may be read once that selection completed whatever was recorded
  // after it.
  struct Feedback {
    uint32_t generation = 0;  // which selection wrote it, later ones higher; 0: none yet
    size_t per_pixel = 0, per_vertex = 0;  // chunks drawn, by where they read the froxels
    size_t indices = 0;                    // of the chunks drawn, skirts included
    // terrain::Selection's; hidden also counts the chunks whose ground lies outside the view
    int deferred = 0, hidden = 0;
    double camera_slack_m = 0.0;           // terrain::Selection's, in single precision
    std::vector<terrain::ChunkId> requested;  // the first kFedBackRequests children to build
    std::vector<uint32_t> drawn_slots;        // the slots of the chunks drawn
  };
  static constexpr uint32_t kFedBackRequests = 1024;
  Feedback ReadFeedback(uint32_t feedback) const;

  // What the last recorded selection wrote, once its commands have completed.
  struct Result {
    // With their skirts: those that read the froxels per pixel, front to back, then the others.
    std::vector<terrain::SelectedChunk> chunks;
    // Per chunk, a bit per block of its cells (terrain::kBlocksPerChunk) that its draw leaves out,
    // nearer terrain hiding it or its ground lying outside the view.
    std::vector<uint32_t> blocks_left_out;
    size_t per_pixel = 0;                        // how many of chunks read them per pixel
    std::vector<terrain::ChunkId> requested;     // children to build
    int deferred = 0;                            // terrain::Selection::deferred
    int hidden = 0;                              // Feedback::hidden
    double camera_slack_m = 0.0;                 // terrain::Selection's, in single precision
    bool changed = false;                        // what it reported (Compare)
  };
  Result Read() const;

  // Records the draws of the last selection recorded (one vkCmdDrawIndexedIndirectCount per
  // list, with the index and vertex buffers the caller bound): the chunks that read the froxels
  // per pixel (per_pixel true), per vertex (false), or both lists (nullopt). Returns the draws.
  int Draw(const vk::CommandBuffer& cmd, std::optional<bool> per_pixel) const;
  // Begins conditional rendering (VK_EXT_conditional_rendering) on whether the last selection,
  // recorded with Compare::kWithTheLast or kRedrawn, reported its chunks changed.
  void BeginIfChanged(const vk::CommandBuffer& cmd) const;

  // The draws' buffer, for the tests: the count of the chunks that read per pixel (uint32) at
  // offset 0, their VkDrawIndexedIndirectCommands from kDrawsOffset.
  const vk::Buffer& draws() const { return draws_; }
  static constexpr ::vk::DeviceSize kDrawsOffset = 32;

 private:
  // Those that read per vertex: their count at kPerVertexCountOffset, their commands from
  // per_vertex_draws_offset(); at most slots_ in each list.
  static constexpr ::vk::DeviceSize kPerVertexCountOffset = 16, kChangedOffset = 28;
  ::vk::DeviceSize per_vertex_draws_offset() const;

  // terrain_select.comp's ChunkNode (std430).
  struct Node {
    glm::vec4 lower;  // w: geometric error
    glm::vec4 upper;  // w: the distance within which it reads the froxels per pixel
    glm::ivec4 children, neighbours, id;
  };
  struct BufferBytes;
  BufferBytes bytes() const;
  Node& Change(uint32_t slot);  // the slot's node, to be written in the next selection's commands
  void Link(const terrain::ChunkId& id, int32_t slot);

  uint32_t slots_;
  bool occlusion_culling_;
  uint32_t vertices_per_slot_, first_instance_;
  uint32_t generation_ = 0;
  uint32_t fills_ = 0;  // chunks inserted so far
  std::unordered_map<terrain::ChunkId, uint32_t, terrain::ChunkIdHash> slot_of_;
  std::vector<terrain::ChunkId> id_in_slot_;
  std::vector<Node> nodes_;
  std::vector<std::array<glm::vec2, terrain::kBlocksPerChunk>> block_heights_m_;
  std::vector<bool> node_changed_;
  std::vector<uint32_t> changed_nodes_, inserted_;  // since the last selection recorded
  vk::Buffer tree_, block_heights_, view_, queues_, stamps_, keys_, draws_, requests_, block_groups_, horizon_;
  vk::Buffer block_targets_;  // terrain_occluders.comp's BlockTargets
  vk::Buffer content_;        // terrain_select.comp's TileContent
  uint32_t workgroup_size_;  // terrain_select.comp's
  vk::ComputePipeline walk_, occluders_, cumulative_horizon_, hidden_, finish_;
  std::vector<uint32_t> feedback_generations_;
  std::vector<vk::Buffer> feedbacks_;  // the draws' header, kFedBackRequests requests, the stamps
};

}  // namespace aerial
