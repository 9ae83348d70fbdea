// The example's descriptor layout (scene_pass.cpp makes it). Set 0 holds aerial's two uniform
// blocks where aerial's GLSL declares them: the AtmosphereBlock at binding 0 (definitions.glsl)
// and the FrameBlock at binding 1 (frame.glsl). The tables and the froxel volume are plain
// sampled images, so the engine puts them where it likes: here, in a set of their own.
#ifndef EMBED_BINDINGS_GLSL
#define EMBED_BINDINGS_GLSL
layout(set = 1, binding = 0) uniform sampler2D transmittance_texture;  // aerial::Tables
layout(set = 1, binding = 1) uniform sampler2D irradiance_texture;
layout(set = 1, binding = 2) uniform sampler3D rayleigh_texture;
layout(set = 1, binding = 3) uniform sampler3D mie_texture;
layout(set = 1, binding = 4) uniform sampler3D multiple_texture;
layout(set = 1, binding = 5) uniform sampler3D rayleigh_froxels;  // aerial::Froxels
layout(set = 1, binding = 6) uniform sampler3D mie_froxels;
layout(set = 1, binding = 7) uniform sampler3D transmittance_froxels;
#endif
