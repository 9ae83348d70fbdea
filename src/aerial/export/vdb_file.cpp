// The one translation unit that includes OpenVDB (see vdb_file.h).
#include "aerial/export/vdb_file.h"

#include <cmath>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

#include <openvdb/openvdb.h>

#include "aerial/core/atomic_file.h"
#include "aerial/core/format_number.h"
#include "aerial/error.h"

namespace aerial {
namespace {

void InitializeOpenVdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

void InsertMetadata(openvdb::MetaMap& map, const VdbMetadata& metadata) {
  for (const auto& [name, value] : metadata) {
    std::visit(
        [&, name = name](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, std::string>) {
            map.insertMeta(name, openvdb::StringMetadata(v));
          } else if constexpr (std::is_same_v<T, double>) {
            map.insertMeta(name, openvdb::DoubleMetadata(v));
          } else if constexpr (std::is_same_v<T, int64_t>) {
            map.insertMeta(name, openvdb::Int64Metadata(v));
          } else if constexpr (std::is_same_v<T, bool>) {
            map.insertMeta(name, openvdb::BoolMetadata(v));
          } else if constexpr (std::is_same_v<T, std::array<double, 3>>) {
            map.insertMeta(name, openvdb::Vec3DMetadata(openvdb::Vec3d(v[0], v[1], v[2])));
          } else {
            map.insertMeta(name, openvdb::Vec3IMetadata(openvdb::Vec3i(v[0], v[1], v[2])));
          }
        },
        value);
  }
}

// Every metadata type aerial writes, plus the ones OpenVDB adds (float, int32, vec3s widen).
VdbMetadata ExtractMetadata(const openvdb::MetaMap& map) {
  VdbMetadata metadata;
  for (auto it = map.beginMeta(); it != map.endMeta(); ++it) {
    const openvdb::Metadata& meta = *it->second;
    const std::string& name = it->first;
    if (auto* s = dynamic_cast<const openvdb::StringMetadata*>(&meta)) {
      metadata[name] = s->value();
    } else if (auto* d = dynamic_cast<const openvdb::DoubleMetadata*>(&meta)) {
      metadata[name] = d->value();
    } else if (auto* f = dynamic_cast<const openvdb::FloatMetadata*>(&meta)) {
      metadata[name] = double(f->value());
    } else if (auto* i = dynamic_cast<const openvdb::Int64Metadata*>(&meta)) {
      metadata[name] = int64_t(i->value());
    } else if (auto* i32 = dynamic_cast<const openvdb::Int32Metadata*>(&meta)) {
      metadata[name] = int64_t(i32->value());
    } else if (auto* b = dynamic_cast<const openvdb::BoolMetadata*>(&meta)) {
      metadata[name] = b->value();
    } else if (auto* v = dynamic_cast<const openvdb::Vec3DMetadata*>(&meta)) {
      metadata[name] = std::array<double, 3>{v->value()[0], v->value()[1], v->value()[2]};
    } else if (auto* vs = dynamic_cast<const openvdb::Vec3SMetadata*>(&meta)) {
      metadata[name] = std::array<double, 3>{vs->value()[0], vs->value()[1], vs->value()[2]};
    } else if (auto* vi = dynamic_cast<const openvdb::Vec3IMetadata*>(&meta)) {
      metadata[name] = std::array<int32_t, 3>{vi->value()[0], vi->value()[1], vi->value()[2]};
    }
  }
  return metadata;
}

// The archive format openvdb::io::File writes (seekable: grid offsets recorded, so readers can
// load grids one by one), encoded into a string instead of a file stream.
class VdbArchive : public openvdb::io::Archive {
 public:
  // Throws openvdb::Exception for what OpenVDB cannot encode, and when the string stream failed
  // (only for want of memory).
  std::string Encode(const openvdb::GridPtrVec& grids, const openvdb::MetaMap& metadata) const {
    std::ostringstream out(std::ios_base::out | std::ios_base::binary);
    write(out, grids, /*seekable=*/true, metadata);
    if (!out) OPENVDB_THROW(openvdb::IoError, "out of memory while encoding");
    return std::move(out).str();
  }
};

void CheckFrustum(const VdbFrustum& frustum) {
  if (!(frustum.taper > 0.0 && frustum.taper <= 1.0))
    throw Error("VDB frustum taper", std::to_string(frustum.taper), "in (0, 1] (near width / far width)");
  if (!(frustum.depth > 0.0 && std::isfinite(frustum.depth)))
    throw Error("VDB frustum depth", std::to_string(frustum.depth), "finite and > 0");
  for (int axis = 0; axis < 3; ++axis)
    if (!(frustum.index_max[axis] > frustum.index_min[axis] && std::isfinite(frustum.index_min[axis]) &&
          std::isfinite(frustum.index_max[axis])))
      throw Error("VDB frustum index box", std::to_string(frustum.index_max[axis] - frustum.index_min[axis]),
                  "a finite, non-empty extent on every axis");
  for (double m : frustum.second_map)
    if (!std::isfinite(m)) throw Error("VDB frustum second map", std::to_string(m), "finite entries");
}

void CheckVolume(const VdbVolume& volume) {
  if (volume.frustum) {
    CheckFrustum(*volume.frustum);
  } else {
    if (!(volume.voxel_size_m > 0.0 && std::isfinite(volume.voxel_size_m)))
      throw Error("VDB voxel size", FormatNumber(volume.voxel_size_m), "a finite size > 0");
    for (double o : volume.origin_m)
      if (!std::isfinite(o)) throw Error("VDB origin", std::to_string(o), "finite meters");
  }
  std::set<std::string> names;
  for (const VdbVolume::Grid& grid : volume.grids) {
    if (grid.name.empty() || !names.insert(grid.name).second)
      throw Error("VDB grid name", grid.name, "a unique, non-empty name");
    if (grid.components != 1 && grid.components != 3)
      throw Error("VDB grid components", std::to_string(grid.components), "1 or 3", grid.name);
    if (grid.values.size() != volume.voxels.size() * size_t(grid.components))
      throw Error("VDB grid values", std::to_string(grid.values.size()),
                  std::to_string(volume.voxels.size() * grid.components) + " (components x voxels)",
                  grid.name);
    if (!std::isfinite(grid.background))
      throw Error("VDB grid background", FormatNumber(grid.background), "a finite value", grid.name);
  }
}

// The volume's transform: linear, or OpenVDB's frustum map (see VdbFrustum). Throws
// openvdb::Exception for a second map it cannot invert.
openvdb::math::Transform::Ptr MakeTransform(const VdbVolume& volume) {
  if (!volume.frustum) {
    openvdb::math::Transform::Ptr transform =
        openvdb::math::Transform::createLinearTransform(volume.voxel_size_m);
    transform->postTranslate(openvdb::Vec3d(volume.origin_m[0], volume.origin_m[1], volume.origin_m[2]));
    return transform;
  }
  const VdbFrustum& frustum = *volume.frustum;
  // OpenVDB multiplies row vectors, world = (x, y, z, 1) m: m is second_map transposed.
  openvdb::Mat4d m = openvdb::Mat4d::identity();
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column) m(column, row) = frustum.second_map[row * 4 + column];
  auto second_map = std::make_shared<openvdb::math::AffineMap>(m);
  openvdb::BBoxd box(openvdb::Vec3d(frustum.index_min.data()), openvdb::Vec3d(frustum.index_max.data()));
  auto map = std::make_shared<openvdb::math::NonlinearFrustumMap>(box, frustum.taper, frustum.depth, second_map);
  return std::make_shared<openvdb::math::Transform>(map);
}

template <typename GridType, typename Value>
openvdb::GridBase::Ptr MakeGrid(const VdbVolume& volume, const VdbVolume::Grid& source,
                                const openvdb::math::Transform::Ptr& transform, Value make_value) {
  typename GridType::Ptr grid = GridType::create(typename GridType::ValueType(source.background));
  grid->setName(source.name);
  grid->setTransform(transform);
  grid->setGridClass(source.grid_class == VdbGridClass::kFogVolume ? openvdb::GRID_FOG_VOLUME
                                                                   : openvdb::GRID_UNKNOWN);
  auto accessor = grid->getAccessor();
  const float* values = source.values.data();
  for (size_t n = 0; n < volume.voxels.size(); ++n, values += source.components) {
    const auto& v = volume.voxels[n];
    // setValueOn keeps the voxel active even when its value equals the background.
    accessor.setValueOn(openvdb::Coord(v[0], v[1], v[2]), make_value(values));
  }
  InsertMetadata(*grid, volume.grid_metadata);
  InsertMetadata(*grid, source.metadata);
  return grid;
}

template <typename GridType>
void ReadValues(const GridType& grid, VdbGridData& data, int components) {
  auto store = [&](const openvdb::Coord& c, const typename GridType::ValueType& value) {
    int64_t offset = data.Offset(c.x(), c.y(), c.z());
    if (offset < 0) return;
    data.active[offset] = 1;
    for (int k = 0; k < components; ++k) {
      if constexpr (std::is_same_v<typename GridType::ValueType, float>) {
        data.values[offset * components + k] = value;
      } else {
        data.values[offset * components + k] = value[k];
      }
    }
  };
  for (auto it = grid.cbeginValueOn(); it; ++it) {
    if (it.isVoxelValue()) {
      store(it.getCoord(), *it);
    } else {
      // A tile: aerial never writes one, but a file from elsewhere may hold them.
      openvdb::CoordBBox box;
      it.getBoundingBox(box);
      for (auto c = box.begin(); c; ++c) store(*c, *it);
    }
  }
}

}  // namespace

void WriteVdb(const std::filesystem::path& path, const VdbVolume& volume) {
  CheckVolume(volume);
  InitializeOpenVdb();
  // Encoded in memory, then written with write(2), whose every error is checked: openvdb::io::File
  // writes through an std::ofstream and never looks at its state, so a full disk gave a truncated
  // file and no error.
  std::string bytes;
  try {
    openvdb::math::Transform::Ptr transform = MakeTransform(volume);
    openvdb::GridPtrVec grids;
    for (const VdbVolume::Grid& source : volume.grids) {
      if (source.components == 3) {
        grids.push_back(MakeGrid<openvdb::Vec3SGrid>(
            volume, source, transform, [](const float* v) { return openvdb::Vec3s(v[0], v[1], v[2]); }));
      } else {
        grids.push_back(
            MakeGrid<openvdb::FloatGrid>(volume, source, transform, [](const float* v) { return *v; }));
      }
    }
    openvdb::MetaMap file_metadata;
    InsertMetadata(file_metadata, volume.file_metadata);
    bytes = VdbArchive().Encode(grids, file_metadata);
  } catch (const openvdb::Exception& e) {
    throw Error("file", path.string(), std::string("a VDB file we can encode (") + e.what() + ")");
  }
  WriteFileAtomically(path, bytes);
}

int64_t VdbGridData::Offset(int32_t i, int32_t j, int32_t k) const {
  if (i < min[0] || j < min[1] || k < min[2] || i > max[0] || j > max[1] || k > max[2]) return -1;
  int64_t sx = max[0] - min[0] + 1, sy = max[1] - min[1] + 1;
  return ((int64_t(k) - min[2]) * sy + (j - min[1])) * sx + (i - min[0]);
}

const VdbGridData* VdbFileData::Find(const std::string& name) const {
  for (const VdbGridData& grid : grids)
    if (grid.name == name) return &grid;
  return nullptr;
}

VdbFileData ReadVdb(const std::filesystem::path& path) {
  InitializeOpenVdb();
  VdbFileData data;
  try {
    openvdb::io::File file(path.string());
    file.open(/*delayLoad=*/false);
    data.metadata = ExtractMetadata(*file.getMetadata());
    openvdb::GridPtrVecPtr grids = file.getGrids();
    file.close();
    for (const openvdb::GridBase::Ptr& base : *grids) {
      VdbGridData grid;
      grid.name = base->getName();
      grid.type = base->valueType();
      grid.active_voxels = int64_t(base->activeVoxelCount());
      grid.metadata = ExtractMetadata(*base);
      grid.grid_class = openvdb::GridBase::gridClassToString(base->getGridClass());
      openvdb::math::Transform::ConstPtr transform = base->constTransformPtr();
      grid.map_type = transform->mapType();
      grid.to_world = [transform](double i, double j, double k) {
        openvdb::Vec3d world = transform->indexToWorld(openvdb::Vec3d(i, j, k));
        return std::array<double, 3>{world[0], world[1], world[2]};
      };
      grid.linear_transform = transform->isLinear();
      if (grid.linear_transform) {
        openvdb::Vec3d origin = transform->indexToWorld(openvdb::Vec3d(0, 0, 0));
        for (int axis = 0; axis < 3; ++axis) {
          openvdb::Vec3d unit(0, 0, 0);
          unit[axis] = 1;
          openvdb::Vec3d column = transform->indexToWorld(unit) - origin;
          for (int row = 0; row < 3; ++row) grid.index_to_world[row * 4 + axis] = column[row];
        }
        for (int row = 0; row < 3; ++row) grid.index_to_world[row * 4 + 3] = origin[row];
      }
      openvdb::CoordBBox box = base->evalActiveVoxelBoundingBox();
      if (grid.active_voxels > 0) {
        grid.min = {box.min().x(), box.min().y(), box.min().z()};
        grid.max = {box.max().x(), box.max().y(), box.max().z()};
      } else {
        grid.min = {0, 0, 0};
        grid.max = {-1, -1, -1};
      }
      size_t count = grid.active_voxels > 0 ? size_t(box.volume()) : 0;
      if (auto f = openvdb::GridBase::grid<openvdb::FloatGrid>(base)) {
        grid.components = 1;
        grid.background[0] = f->background();
        grid.values.assign(count, 0.0f);
        grid.active.assign(count, 0);
        ReadValues(*f, grid, 1);
      } else if (auto v = openvdb::GridBase::grid<openvdb::Vec3SGrid>(base)) {
        grid.components = 3;
        for (int c = 0; c < 3; ++c) grid.background[c] = v->background()[c];
        grid.values.assign(count * 3, 0.0f);
        grid.active.assign(count, 0);
        ReadValues(*v, grid, 3);
      } else {
        continue;
      }
      data.grids.push_back(std::move(grid));
    }
  } catch (const openvdb::Exception& e) {
    throw Error("file", path.string(), std::string("a readable VDB file (") + e.what() + ")");
  }
  return data;
}

}  // namespace aerial
