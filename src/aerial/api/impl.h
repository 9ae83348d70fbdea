#pragma once
// What the public classes of include/aerial/ hold: aerial's side of the API. aerial's own code
// that works from the public objects (the renderer, the exporters, the command line) reaches the
// Vulkan layer through these; a caller never sees them.
#include <memory>

#include "aerial/device.h"
#include "aerial/froxels.h"
#include "aerial/precompute/table_store.h"
#include "aerial/render/renderer.h"
#include "aerial/renderer.h"
#include "aerial/tables.h"
#include "aerial/vk/context.h"
#include "froxel/froxel_volume.h"

namespace aerial {

// The public classes have no accessor for their Impl: aerial's own code (and its tests) reach it
// through this friend of each, as ImplOf(tables).
struct ImplAccess {
  template <typename Public>
  static const typename Public::Impl& Of(const Public& object) { return *object.impl_; }
  template <typename Public>
  static typename Public::Impl& Of(Public& object) { return *object.impl_; }
  template <typename Public>
  static Public Make(std::unique_ptr<typename Public::Impl> impl) { return Public(std::move(impl)); }
};
template <typename Public>
decltype(auto) ImplOf(Public& object) { return ImplAccess::Of(object); }

struct Device::Impl {
  std::unique_ptr<vk::Context> context;
};

struct Tables::Impl {
  LoadedTables loaded;
  const AtmosphereTables& tables() const { return *loaded.tables; }
};

struct TableSnapshot::Impl {
  AtmosphereParameters atmosphere;
  PrecomputeOptions options;
  TableCache texels;
};

struct Froxels::Impl {
  Impl(const vk::Context& context, const FroxelGrid& grid);
  FroxelVolume volume;
  vk::Buffer frame_block;  // written by the command buffer (RecordedUniformBufferInfo)
  ::vk::raii::Sampler sampler;  // linear, clamped to the edge, as aerial's passes read froxels
};

struct SceneRenderer::Impl {
  const Tables& tables;
  Renderer renderer;
};

// The public form of an image of aerial's, with the sampler shaders read it through.
SampledImage ToSampledImage(const vk::SampledImageSlot& sampled);
// An image (a table, a frame's) with the tables' sampler: linear, clamped to the edge.
SampledImage SampledLikeTheTables(const AtmosphereTables& tables, const vk::Image& image);

}  // namespace aerial
