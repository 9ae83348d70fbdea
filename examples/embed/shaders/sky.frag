#version 450
#extension GL_GOOGLE_include_directive : require
// The sky where no mesh was drawn (the depth test leaves only those pixels): the inscatter of the
// pixel's whole view ray from aerial's tables, with its phase functions, and behind it the sun's
// disc or the bare planet.
#include "aerial_perspective.glsl"
#include "bindings.glsl"
// rgb: radiance at the camera; a: the distance, infinite.
layout(location = 0) out vec4 color;

void main() {
  vec3 ray = ViewRayFromScreen(gl_FragCoord.xy / AERIAL_FRAME.viewport.xy);
  vec3 sky = GetSkyRadianceAlongRay(transmittance_texture, rayleigh_texture, mie_texture, multiple_texture,
                                    irradiance_texture, ray);
  color = vec4(sky, uintBitsToFloat(0x7f800000u));
}
