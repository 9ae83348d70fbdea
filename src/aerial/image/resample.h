#pragma once
// Resampling an image to another size.
#include "aerial/image.h"

namespace aerial {

// Bilinear, with texel centers at (i + 0.5) / size on both images and clamping at the edges: what
// a GPU's linear sampler with clamp-to-edge returns, so that `aerial render --render-scale` and
// the viewer's display upscale a frame the same way.
ImageRgbF ResizeBilinear(const ImageRgbF& image, int width, int height);

// The mean of each factor x factor block of radiance (and coverage): an image rendered `factor`
// times larger on each side, filtered down to the size asked for (what tests compare `render`'s
// jittered supersampling with). The sides must be multiples of factor (>= 1); throws
// Error("image size") otherwise.
ImageRgbF DownsampleBox(const ImageRgbF& image, int factor);

}  // namespace aerial
