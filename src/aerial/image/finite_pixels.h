#pragma once
// A frame with a NaN or an infinity is an error, never a silent image: checked on the read-back
// before an image is written (one pass over floats already in memory, far cheaper than encoding).
#include "aerial/image.h"

namespace aerial {

// Throws Error("frame", "NaN or infinity at pixel (x, y)", ...) for the first non-finite red,
// green or blue value.
void CheckFinitePixels(const ImageRgbF& image);

}  // namespace aerial
