#pragma once
// What the viewer's panel edits. The frame options (froxels, aerial mode) become the Renderer's
// RenderOptions, the table options a table request; the rest only steers the display passes.
#include "aerial/froxel_grid.h"
#include "aerial/renderer.h"
#include "aerial/table_options.h"
#include "aerial/viewer/atmosphere_knobs.h"

namespace aerial::viewer {

enum class DebugView {
  kFinal,          // the renderer's frame, tone mapped
  kRayleigh,       // the aerial perspective's terms alone (display_passes.h)
  kMie,
  kTransmittance,
  kFroxelSlice,    // one depth slice of the froxel volume
  kDifference,     // the frames of the 3D and 4D tables, relative difference
};

struct ViewSettings {
  // Tables: changing these asks the table worker for a new set.
  LutVariant variant = LutVariant::k4D;
  AtmosphereKnobs knobs;
  // Frame: changing these recreates the renderer (the aerial mode and the shadows are
  // specialization constants).
  FroxelGrid froxels;
  AerialMode mode = AerialMode::kFroxel;
  float render_scale = 1.0f;
  bool shadows = true;
  // Changes from frame to frame without a new renderer (only the terrain's selection uses it).
  float terrain_error_px = 4.0f;
  // Display.
  // Exposure (aerial/image/exposure.h): metered and adapted every frame, or the EV100 set here.
  bool auto_exposure = true;
  float ev100 = 14.0f;
  DebugView view = DebugView::kFinal;
  int froxel_slice = 8;
  float difference_full_scale = 0.05f;  // relative difference shown white
  // Sun clock (sun_control.h); the sun follows it only when the time slider moves.
  float solar_time_h = 12.0f;
  float latitude_deg = 45.0f;
  float declination_deg = 0.0f;
};

}  // namespace aerial::viewer
