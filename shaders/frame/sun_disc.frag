#version 450
#extension GL_GOOGLE_include_directive : require
// The sun's disc, added to the sky pass's pixels around it (froxel mode): the disc's radiance,
// limb-darkened, through the air of the pixel's own ray, whose transmittance the sky-view table's
// background holds above the horizon (sky_view.comp). Where the ray meets the ground the sky pass
// drew the bare planet, and the disc adds nothing. Blended additively (alpha 0), drawn only where
// the sky was (the depth test of the sky's pass).
#include "sky_view.glsl"
#include "surface.glsl"
layout(set = 0, binding = 2) uniform sampler2D background_sky;
layout(location = 0) out vec4 color;

void main() {
  vec3 ray = ViewRayFromScreen(gl_FragCoord.xy / AERIAL_FRAME.viewport.xy);
  float r, mu, mu_s, nu;
  GetCameraRayParameters(ray, r, mu, mu_s, nu);
  vec3 up, toward_sun, side;
  GetSkyViewFrame(up, toward_sun, side);
  // The table's rows are laid out for its own horizon (its alpha, sky_view.comp); the ground hides
  // the disc below the camera's.
  float table_horizon = texelFetch(background_sky, ivec2(0), 0).a;
  vec2 uv = GetSkyViewUvOfRay(ray, mu, up, toward_sun, table_horizon, textureSize(background_sky, 0));
  vec3 disc = ShadeBackground(textureLod(background_sky, uv, 0.0).rgb, false, ray);
  color = vec4(mu < cos(HorizonZenithAngle(r)) ? vec3(0.0) : disc, 0.0);
}
