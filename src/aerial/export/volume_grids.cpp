#include "aerial/export/volume_grids.h"

#include "aerial/export/fog_density.h"

namespace aerial {
namespace {

struct GridText {
  const char* name;
  const char* units;
  const char* description;
};

constexpr GridText kRayleigh{"rayleigh_inscatter", "W/m^2/nm",
                             "Rayleigh inscatter from the camera to the point, without phase: times "
                             "the Rayleigh phase function (1/sr) it is radiance (W/m^2/sr/nm); "
                             "channels as `channels` says"};
constexpr GridText kMie{"mie_inscatter", "W/m^2/nm",
                        "Mie inscatter from the camera to the point, without phase: times the Mie "
                        "phase function (1/sr) it is radiance (W/m^2/sr/nm); channels as "
                        "`channels` says"};
constexpr GridText kTransmittance{"transmittance", "1",
                                  "transmittance from the camera to the point; channels as "
                                  "`channels` says; background 1 (clear air)"};
constexpr GridText kLuminance{"inscatter_luminance", "W/m^2/nm",
                              "0.2126 R + 0.7152 G + 0.0722 B of rayleigh_inscatter + "
                              "mie_inscatter (phase taken as 1): a scalar to look at the volume "
                              "with, not a photometric quantity"};
constexpr GridText kDensity{"density", "1/m",
                            "extinction coefficient of the air at the point (Rayleigh scattering, "
                            "Mie extinction and ozone absorption at its altitude), 0.2126 R + "
                            "0.7152 G + 0.0722 B of the channels: a fog volume's density"};

constexpr GridText kScattering{"scattering", "1/m",
                               "scattering coefficient of the air at the point, per channel (Rayleigh and Mie "
                               "scattering at its altitude); channels as `channels` says"};
constexpr GridText kAbsorption{"absorption", "1/m",
                               "absorption coefficient of the air at the point, per channel (Mie absorption and "
                               "ozone at its altitude); channels as `channels` says"};

VdbVolume::Grid MakeGrid(const GridText& text, int components, size_t voxels, float background = 0.0f,
                         VdbGridClass grid_class = VdbGridClass::kUnknown) {
  VdbVolume::Grid grid{.name = text.name, .components = components};
  grid.values.reserve(voxels * components);
  grid.metadata = {{"value_units", std::string(text.units)},
                   {"description", std::string(text.description)}};
  grid.background = background;
  grid.grid_class = grid_class;
  return grid;
}

// Rec. 709 luma of rayleigh + mie (the phase taken as 1): the scalar inscatter_luminance grid.
double InscatterLuminance(const float* rayleigh, const float* mie) {
  return Luma(glm::dvec3(double(rayleigh[0]) + mie[0], double(rayleigh[1]) + mie[1], double(rayleigh[2]) + mie[2]));
}

}  // namespace

VolumeGrids::VolumeGrids(size_t voxels)
    : rayleigh_(MakeGrid(kRayleigh, 3, voxels)),
      mie_(MakeGrid(kMie, 3, voxels)),
      transmittance_(MakeGrid(kTransmittance, 3, voxels, 1.0f)),
      luminance_(MakeGrid(kLuminance, 1, voxels)),
      density_(MakeGrid(kDensity, 1, voxels, 0.0f, VdbGridClass::kFogVolume)),
      scattering_(MakeGrid(kScattering, 3, voxels)),
      absorption_(MakeGrid(kAbsorption, 3, voxels)) {}

void VolumeGrids::Add(const FroxelTexels::Sample& sample, const AirCoefficients& air) {
  float r[3] = {}, m[3] = {};
  for (int c = 0; c < 3; ++c) {
    r[c] = float(sample.rayleigh[c]);
    m[c] = float(sample.mie[c]);
    rayleigh_.values.push_back(r[c]);
    mie_.values.push_back(m[c]);
    transmittance_.values.push_back(float(sample.transmittance[c]));
    scattering_.values.push_back(float(air.scattering[c]));
    absorption_.values.push_back(float(air.absorption[c]));
  }
  luminance_.values.push_back(float(InscatterLuminance(r, m)));
  density_.values.push_back(float(Luma(air.scattering + air.absorption)));
}

std::vector<VdbVolume::Grid> VolumeGrids::Take() && {
  std::vector<VdbVolume::Grid> grids;
  for (VdbVolume::Grid* grid :
       {&rayleigh_, &mie_, &transmittance_, &luminance_, &density_, &scattering_, &absorption_})
    grids.push_back(std::move(*grid));
  return grids;
}

}  // namespace aerial
