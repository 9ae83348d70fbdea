// The horizon that culls hidden terrain chunks on the GPU (render/gpu_chunk_selection.h).
//
// Around the camera's local vertical, a view ray has an azimuth and an elevation, kept as its
// tangent: height over horizontal distance. The vertical plane of an azimuth holds the local
// vertical of every point on it, so a ray that passes under one point of the plane passes under
// the ground there, and sees nothing beyond (the camera is above the ground). The horizon keeps, per
// azimuth bin and per band of horizontal distance, the highest tangent below which every ray of the
// bin is known to be under the ground within that distance: occlusion horizons in the camera's own
// vertical frame (Downs, Möller and Séquin, I3D 2001; Lloyd and Egbert, IEEE Visualization 2002).
// Unlike a horizon on the screen, no occluder needs another beneath it, so every chunk adds its
// occluders at once, in parallel, and a chunk is tested only against the bands wholly in front of it.
// Chunks left out add theirs too: a ray under a hidden chunk's ground crossed the ground in front
// of it, and, by induction over the bands from the camera out, that crossing is on ground drawn.

const int kHorizonAzimuths = 1024;  // 0.35 degrees each, about 5 px of a 720p frame
const int kHorizonBands = 48;       // 32 m to 1,160 km, each 1.25 times the last
const float kHorizonNearestM = 32.0;
const float kHorizonBandRatio = 1.25;
const float kTwoPi = 6.283185307179586;

// Band k holds what lies within kHorizonNearestM * kHorizonBandRatio^k of the camera's vertical.
float HorizonBandEdge(int k) { return kHorizonNearestM * pow(kHorizonBandRatio, float(k)); }

// The first band that reaches out to a horizontal distance (kHorizonBands if none does).
int HorizonBandReaching(float distance_m) {
  int k = max(0, int(ceil(log(distance_m / kHorizonNearestM) / log(kHorizonBandRatio))) - 1);
  while (k < kHorizonBands && HorizonBandEdge(k) < distance_m) ++k;
  return k;
}

// The last band that ends within a horizontal distance (-1 if none does).
int HorizonBandWithin(float distance_m) {
  int k = min(kHorizonBands - 1, int(floor(log(distance_m / kHorizonNearestM) / log(kHorizonBandRatio))) + 1);
  while (k >= 0 && HorizonBandEdge(k) > distance_m) --k;
  return k;
}

// An azimuth (radians) in bins, within [-kHorizonAzimuths / 2, kHorizonAzimuths / 2].
float AzimuthInBins(float azimuth) { return azimuth * (float(kHorizonAzimuths) / kTwoPi); }

// `bins` moved by whole turns to within half a turn of `reference`: angles over less than half a
// turn compare without wrapping.
float UnwrapBins(float bins, float reference) {
  return bins - float(kHorizonAzimuths) * round((bins - reference) / float(kHorizonAzimuths));
}

uint HorizonIndex(int band, int bin) {
  return uint(band * kHorizonAzimuths + ((bin % kHorizonAzimuths) + kHorizonAzimuths) % kHorizonAzimuths);
}

// Floats as unsigned integers in the same order, for atomicMax; 0 stands below every float
// (nothing known).
uint OrderedBits(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float FromOrderedBits(uint u) { return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7fffffffu : ~u); }
