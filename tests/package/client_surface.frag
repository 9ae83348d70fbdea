#version 450
#extension GL_GOOGLE_include_directive : require
// A client's own fragment shader using aerial's installed GLSL (share/aerial/glsl,
// aerial_perspective.glsl): its own bindings for aerial's tables and froxels, aerial's two
// uniform blocks where the contract puts them (set 0, bindings 0 and 1). run.sh compiles it
// against the installed include directory.
#include "aerial_perspective.glsl"
layout(set = 0, binding = 4) uniform sampler3D client_rayleigh;
layout(set = 0, binding = 5) uniform sampler3D client_mie;
layout(set = 0, binding = 6) uniform sampler3D client_transmittance;
layout(set = 0, binding = 7) uniform sampler2D client_transmittance_table;
layout(set = 0, binding = 8) uniform sampler3D client_rayleigh_table;
layout(set = 0, binding = 9) uniform sampler3D client_mie_table;
layout(set = 0, binding = 10) uniform sampler3D client_multiple_table;
layout(set = 0, binding = 11) uniform sampler2D client_irradiance_table;
layout(location = 0) in vec3 relative_position;  // camera-relative world, as aerial's
layout(location = 1) in vec3 lit_radiance;       // the client's own surface lighting
layout(location = 2) flat in int is_sky;
layout(location = 0) out vec4 color;

void main() {
  if (is_sky == 1) {
    color = vec4(GetSkyRadianceAlongRay(client_transmittance_table, client_rayleigh_table, client_mie_table,
                                        client_multiple_table, client_irradiance_table, normalize(relative_position)),
                 1.0);
    return;
  }
  Inscatter segment = GetAerialPerspective(client_rayleigh, client_mie, client_transmittance,
                                           gl_FragCoord.xy / AERIAL_FRAME.viewport.xy, length(relative_position));
  color = vec4(ApplyAerialPerspective(lit_radiance, segment, ViewSunCosine(relative_position)), 1.0);
}
