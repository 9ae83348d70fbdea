// Included first by the compute passes that run at every moving frame (the froxel build, the
// sky-view table and its correction lattice): they read the atmosphere's and the frame's blocks
// (definitions.glsl) at an index their compiler cannot see, a zero for any dispatch of fewer than
// 2^30 workgroups along x.
//
// Why: lavapipe (Mesa 22.3) inlines into a shader the uniform values that decide a branch or bound
// a loop, then compiles the pipeline anew at every bind, keeping no variant (lvp_execute.c,
// update_inline_shader_state). The three passes held such branches (the tables' sizes, the sunlight
// terms, the froxel grid's depth), so a moving frame compiled all three: a third of its wall clock
// on a 2-core machine (docs/speed.md, "No pipeline compiled per frame"). A uniform read at an offset that
// is not a constant is never inlined. A GPU driver reads the same values from the block either way.
#ifndef AERIAL_BLOCKS_NOT_INLINED_GLSL
#define AERIAL_BLOCKS_NOT_INLINED_GLSL
#ifdef AERIAL_DEFINITIONS_GLSL
#error "include blocks_not_inlined.glsl before definitions.glsl and every file that includes it"
#endif
#define AERIAL_BLOCK_INDEX int(gl_NumWorkGroups.x >> 30u)
#endif
