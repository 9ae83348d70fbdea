#pragma once
// The ground the exported volumes stop at: a voxel whose center lies below it is left inactive
// (no fog inside the terrain). The ground is the scene's terrain surface where the scene has the
// built-in terrain (scene/terrain.h: TerrainHeightM above the planet sphere, the surface the
// renderer draws), else the planet sphere (sea level). Meshes are not ground: they are objects
// standing in the air (landmarks, a balloon, a glTF model).
#include <glm/glm.hpp>

namespace aerial {

class Ground {
 public:
  Ground(bool terrain, double planet_radius_m) : terrain_(terrain), planet_radius_m_(planet_radius_m) {}

  // Whether the world point (scene frame, m) lies below the ground.
  bool Below(const glm::dvec3& point) const;

 private:
  bool terrain_;
  double planet_radius_m_;
};

}  // namespace aerial
