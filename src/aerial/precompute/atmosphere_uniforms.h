#pragma once
// The atmosphere's uniform block (shader_abi/atmosphere_block.h) filled from its parameters and
// the tables' options: for spectral tables, the render-time atmosphere in linear sRGB
// (ShaderAtmosphere) and the sunlight's terms per wavelength (spectrum/spectral_sunlight.h).
#include "aerial/atmosphere.h"
#include "aerial/shader_abi/atmosphere_block.h"
#include "aerial/table_options.h"

namespace aerial {

AtmosphereUniforms MakeAtmosphereUniforms(const AtmosphereParameters& atmosphere,
                                          const PrecomputeOptions& options);

}  // namespace aerial
