#pragma once
// What a frame's raster passes recorded: draw calls, and pipeline binds (each with its descriptors
// pushed). A CPU-bound frame on a real GPU pays for each; FrameInfo::draws and ::draw_binds
// report them.

namespace aerial {

struct RecordedDraws {
  int draws = 0, binds = 0;
  RecordedDraws& operator+=(const RecordedDraws& other) {
    draws += other.draws;
    binds += other.binds;
    return *this;
  }
};

}  // namespace aerial
