#include "aerial/scene/terrain.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "aerial/scene/noise.h"

namespace aerial {
namespace {

double SmoothStep(double edge0, double edge1, double x) {
  double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Musgrave's ridged multifractal ("Texturing and Modeling", 3rd ed., ch. 16): 1 - |noise| turns
// the noise's zero crossings into sharp crests, squaring narrows them, and weighting each octave
// by the previous one puts fine detail on the crests and leaves the valleys smooth. Six octaves
// from an 18 km wavelength down to ~560 m, about the mesh spacing 30 km out. Each octave is
// rotated by 37 degrees so the lattices of successive octaves do not line up. Result in [0, 1].
double RidgedMultifractal(double x, double y) {
  constexpr int kOctaves = 6;
  constexpr double kGradientNoiseMax = 0.7071;  // sqrt(2)/2, the 2D extreme
  static const double c = std::cos(0.6458), s = std::sin(0.6458);
  double frequency = 1.0 / 18000.0, amplitude = 1.0, weight = 1.0, sum = 0.0, total = 0.0;
  for (int octave = 0; octave < kOctaves; ++octave) {
    double n = GradientNoise(x * frequency, y * frequency, 101 + octave) / kGradientNoiseMax;
    double ridge = 1.0 - std::min(std::fabs(n), 1.0);
    ridge *= ridge * weight;
    weight = std::clamp(2.0 * ridge, 0.0, 1.0);
    sum += ridge * amplitude;
    total += amplitude;
    double rotated_x = c * x - s * y;
    y = s * x + c * y;
    x = rotated_x;
    frequency *= 2.0;
    amplitude *= 0.5;
  }
  return sum / total;
}

// Where mountains may rise, in [0, 1]: not within 2.5 km of the camera's valley floor, fully from
// 7 km, fading out from 85 km to the terrain's edge, and held low in a corridor along +y (north,
// the default view direction) so the landmarks stand in the open and mountains close its far end
// at 50-60 km. The corridor half-width is 600 m + 0.1 y (about 6 degrees seen from the origin),
// its walls rise over 1.5 km + 0.1 y beyond that.
double MountainMask(double x, double y) {
  double d = std::hypot(x, y);
  double mask = SmoothStep(2500.0, 7000.0, d) * (1.0 - SmoothStep(85e3, kTerrainRadiusM, d));
  if (y > 0.0) {
    double half_width = 600.0 + 0.1 * y, wall = 1500.0 + 0.1 * y;
    double lateral = SmoothStep(half_width, half_width + wall, std::fabs(x));
    double far_end = SmoothStep(48e3, 60e3, y);
    mask *= std::max(lateral, far_end);
  }
  return mask;
}

// Linear sRGB albedos at visible wavelengths. Grass: the ColorChecker's "foliage" patch (X-Rite's
// published sRGB 87, 108, 67); lush and dry grass, bare soil and rock: the ECOSTRESS spectral
// library (Meerdink et al. 2019; green and dry grass, brown loam, granite and basalt at
// 450-650 nm); snow: aged snow, ~0.8 in the visible (Warren 1982, "Optical properties of snow").
constexpr glm::dvec3 kLushGrass{0.05, 0.09, 0.035}, kGrass{0.10, 0.14, 0.07}, kDryGrass{0.22, 0.20, 0.11},
    kSoil{0.17, 0.13, 0.09}, kGranite{0.27, 0.25, 0.23}, kDarkRock{0.09, 0.09, 0.08}, kSnow{0.75, 0.76, 0.80};

// Gradient noise in [-1, 1] with wavelength lambda_m.
double Noise(double x, double y, double lambda_m, uint32_t seed) {
  constexpr double kGradientNoiseMax = 0.7071;  // sqrt(2)/2, the 2D extreme
  return GradientNoise(x / lambda_m, y / lambda_m, seed) / kGradientNoiseMax;
}

// Meadows of lush, green and dry grass with bare soil on the slopes below the rocks; rock above
// ~1 km and on slopes steeper than ~37 degrees (cos slope < 0.8), in light and dark outcrops; snow
// above ~2.5 km where the slope holds it (cos slope > 0.7). Noise moves every boundary (the rock
// line by +-300 m, the snow line by +-250 m, the slope limits by +-0.05) so they wander like real
// ones. The patches are 1 km and larger: every grid the renderer draws near enough to show them
// samples them finely, so its level of detail and the fixed mesh agree on them (a finer detail,
// sampled per vertex, changes with the grid and so with the level of detail).
glm::dvec3 TerrainAlbedo(double x, double y, double height_m, double cos_slope) {
  double wander = Noise(x, y, 2000.0, 31), patches = Noise(x, y, 3000.0, 37) + 0.5 * Noise(x, y, 1000.0, 41);
  double slope = cos_slope + 0.05 * wander;
  glm::dvec3 grass = patches < 0.0 ? glm::mix(kGrass, kLushGrass, SmoothStep(-0.1, -0.6, patches))
                                   : glm::mix(kGrass, kDryGrass, SmoothStep(0.2, 0.7, patches));
  glm::dvec3 ground = glm::mix(grass, kSoil, SmoothStep(0.93, 0.85, slope));
  glm::dvec3 rock = glm::mix(kDarkRock, kGranite, SmoothStep(-0.2, 0.8, patches));
  double rocky = std::max(SmoothStep(600.0, 1600.0, height_m + 300.0 * wander), SmoothStep(0.85, 0.7, slope));
  double snow = SmoothStep(2400.0, 2700.0, height_m - 250.0 * wander) * SmoothStep(0.55, 0.75, slope);
  return glm::mix(glm::mix(ground, rock, rocky), kSnow, snow);
}

// The surface at p whose normal is across_x x across_y, with its albedo.
TerrainSurface SurfaceFromDifferences(const glm::dvec3& p, const glm::dvec3& across_x,
                                      const glm::dvec3& across_y, double planet_radius_m) {
  const glm::dvec3 center(0.0, 0.0, -planet_radius_m);
  glm::dvec3 normal = glm::normalize(glm::cross(across_x, across_y));
  glm::dvec3 up = glm::normalize(p - center);
  double height = glm::length(p - center) - planet_radius_m;
  glm::dvec3 sea_level = center + planet_radius_m * up;
  return {p, normal, TerrainAlbedo(sea_level.x, sea_level.y, height, glm::dot(normal, up))};
}

}  // namespace

glm::dvec3 TerrainPoint(double x, double y, double planet_radius_m) {
  return SurfacePoint(x, y, TerrainHeightM(x, y), planet_radius_m);
}

Vertex TerrainVertex(const glm::dvec3& p, const glm::dvec3& across_x, const glm::dvec3& across_y,
                     double planet_radius_m) {
  TerrainSurface s = SurfaceFromDifferences(p, across_x, across_y, planet_radius_m);
  return {glm::vec3(s.point), glm::vec3(s.normal), glm::vec3(s.albedo), 1.0f};
}

TerrainSurface TerrainSurfaceAt(double x, double y, double planet_radius_m) {
  const double h = kTerrainNormalStepM, R = planet_radius_m;
  return SurfaceFromDifferences(TerrainPoint(x, y, R), TerrainPoint(x + h, y, R) - TerrainPoint(x - h, y, R),
                                TerrainPoint(x, y + h, R) - TerrainPoint(x, y - h, R), R);
}

double TerrainHeightM(double x, double y) {
  double d = std::hypot(x, y);
  // The valley floor: flat at the camera, rising 4 m per km (faster than the planet's curvature
  // drop d / R = 0.16 m per km at 25 km) so the corridor floor stays above the camera's horizon,
  // with 30 m gentle hills from 300 m out.
  double hills = 30.0 * GradientNoise(x / 1500.0, y / 1500.0, 7) * SmoothStep(300.0, 3000.0, d);
  double floor = 0.004 * d + hills;
  double ridges = RidgedMultifractal(x, y);
  return floor + MountainMask(x, y) * 3000.0 * ridges * ridges;
}

glm::dvec3 SurfacePoint(double x, double y, double height_m, double planet_radius_m) {
  const double r = planet_radius_m;
  glm::dvec3 up{x / r, y / r, std::sqrt(std::max(0.0, r * r - x * x - y * y)) / r};
  return glm::dvec3(0.0, 0.0, -r) + (r + height_m) * up;
}

glm::dvec3 SeaLevelPoint(const glm::dvec3& p, double planet_radius_m) {
  const glm::dvec3 center(0.0, 0.0, -planet_radius_m);
  return center + planet_radius_m * glm::normalize(p - center);
}

double HeightAboveTerrainM(const glm::dvec3& p, double planet_radius_m) {
  glm::dvec3 sea_level = SeaLevelPoint(p, planet_radius_m);
  double altitude = glm::length(p - glm::dvec3(0.0, 0.0, -planet_radius_m)) - planet_radius_m;
  return altitude - TerrainHeightM(sea_level.x, sea_level.y);
}

GroundFrame GroundFrameAt(double x, double y, double planet_radius_m) {
  GroundFrame frame;
  frame.origin = TerrainPoint(x, y, planet_radius_m);
  frame.up = glm::normalize(frame.origin - glm::dvec3(0.0, 0.0, -planet_radius_m));
  frame.east = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), frame.up));
  frame.north = glm::cross(frame.up, frame.east);
  return frame;
}

Mesh BuildTerrainMesh(double planet_radius_m) {
  const double R = planet_radius_m;
  const double dtheta = 2.0 * std::numbers::pi / kTerrainSegments;
  std::vector<double> radii{0.0};
  while (radii.back() < kTerrainRadiusM)
    radii.push_back(std::min(kTerrainRadiusM,
                             radii.back() + std::max(kTerrainMinStepM, radii.back() * dtheta)));

  Mesh mesh;
  mesh.name = "terrain";
  auto add_vertex = [&](double x, double y, double step) {
    mesh.vertices.push_back(TerrainVertex(TerrainPoint(x, y, R),
                                          TerrainPoint(x + step, y, R) - TerrainPoint(x - step, y, R),
                                          TerrainPoint(x, y + step, R) - TerrainPoint(x, y - step, R),
                                          R));
  };
  add_vertex(0.0, 0.0, kTerrainMinStepM);
  for (size_t ring = 1; ring < radii.size(); ++ring) {
    double step = radii[ring] - radii[ring - 1];
    for (int j = 0; j < kTerrainSegments; ++j) {
      double azimuth = j * dtheta;  // compass: clockwise from north seen from above
      add_vertex(radii[ring] * std::sin(azimuth), radii[ring] * std::cos(azimuth), step);
    }
  }

  // Segment j to j + 1 runs clockwise seen from above (compass azimuth), so these orders are
  // counter-clockwise seen from above: the triangles face up, like their normals.
  auto index = [](size_t ring, int j) {
    return static_cast<uint32_t>(1 + (ring - 1) * kTerrainSegments + j % kTerrainSegments);
  };
  for (int j = 0; j < kTerrainSegments; ++j)
    mesh.indices.insert(mesh.indices.end(), {0u, index(1, j + 1), index(1, j)});
  for (size_t ring = 1; ring + 1 < radii.size(); ++ring) {
    for (int j = 0; j < kTerrainSegments; ++j) {
      uint32_t a = index(ring, j), b = index(ring, j + 1);
      uint32_t c = index(ring + 1, j), d = index(ring + 1, j + 1);
      mesh.indices.insert(mesh.indices.end(), {a, b, c, b, d, c});
    }
  }
  return mesh;
}

}  // namespace aerial
