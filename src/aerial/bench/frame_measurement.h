#pragma once
// Frames of several renderers of one scene, interleaved (frame i: every renderer in turn, from
// renderer i modulo their number) so that all see the same machine noise and none always follows
// the same other one, after warm-up frames: lavapipe compiles each pipeline on its
// first use, so the first frame of a renderer costs far more than the next ones. Each frame has
// its GPU pass times, its wall-clock time (SceneRenderer::Render from the call to the end of the wait,
// the CPU's part: terrain selection, sorting, recording, submitting, included), the process's
// CPU time over it, and the calling thread's (that CPU part alone).
#include <ctime>
#include <functional>
#include <limits>
#include <vector>

#include "aerial/bench/pass_stats.h"
#include "aerial/renderer.h"

namespace aerial::bench {

// The passes timed by the renderer that the frame statistics name (renderer.cpp).
inline constexpr const char* kFroxelBuildPass = "froxel build";
// The sun's shadow map: the tiles a frame redraws (a moving sun: all of them; a still view: none).
inline constexpr const char* kShadowMapPass = "shadow map";

// A moving camera makes each frame rebuild what the renderer keeps for a still one (the froxel
// volume, and the sky-view table past 10 m of altitude): frame i turns the camera by i x 0.1
// degrees of yaw and lifts it by 12 m on odd frames, so every frame pays for both. A still view
// measures what a frame costs when nothing moves. A moving sun (frame i: the sun's zenith angle
// i x 0.02 degrees larger, a sunset 15 times faster than the Earth's at 60 frames per second)
// under a still camera redraws the shadow map and rebuilds the froxel volume and the sky-view
// table every frame. Frames are drawn as the viewer draws them, not complete (SceneRenderer::Record):
// a sky-view table made within 10 m of altitude is kept.
enum class Motion { kCamera, kStill, kSun };

// The scene of frame i under the motion.
Scene Moved(const Scene& scene, Motion motion, int frame);

// A CPU clock (CLOCK_PROCESS_CPUTIME_ID, CLOCK_THREAD_CPUTIME_ID) in milliseconds.
double CpuClockMs(clockid_t clock);

struct FrameSource {
  SceneRenderer* renderer;
  Motion motion = Motion::kCamera;
  // At most this many measured frames: a source that costs seconds a frame stops early, while the
  // others go on (its warm-up frames are rendered in full).
  int max_frames = std::numeric_limits<int>::max();
};

// frames[r] holds source r's measured frames, in order. on_frame (may be empty) is called with r
// after every frame of source r, warm-up included.
std::vector<std::vector<RunResult>> MeasureFrames(const std::vector<FrameSource>& sources, const Scene& scene,
                                                  int warmup, int frames,
                                                  const std::function<void(size_t source)>& on_frame);

// The pixels that the renderer's last frame's opaque surfaces cover (the rest is sky), from its
// surface image (Renderer::ReadSurface).
size_t CoveredPixels(const SceneRenderer& renderer);

}  // namespace aerial::bench
