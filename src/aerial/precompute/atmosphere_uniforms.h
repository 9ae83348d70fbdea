#pragma once
// The atmosphere's uniform block (shader_abi/atmosphere_block.h) filled from its parameters and
// the tables' options.
#include "aerial/atmosphere.h"
#include "aerial/shader_abi/atmosphere_block.h"
#include "aerial/table_options.h"

namespace aerial {

AtmosphereUniforms MakeAtmosphereUniforms(const AtmosphereParameters& atmosphere,
                                          const PrecomputeOptions& options);

}  // namespace aerial
