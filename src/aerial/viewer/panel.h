#pragma once
// The viewer's Dear ImGui panel: atmosphere, tables, froxels, aerial perspective, exposure, debug
// views, sun clock, timings. It edits ViewSettings and reports what the viewer must act on.
#include <string>
#include <vector>

#include "aerial/device.h"
#include "aerial/viewer/table_worker.h"
#include "aerial/viewer/view_settings.h"

namespace aerial::viewer {

struct PanelInfo {
  double fps = 0, frame_ms = 0;       // medians over the last frames
  std::vector<PassTime> passes;   // GPU time of each pass of the last finished frame
  size_t terrain_chunks = 0, terrain_triangles = 0;  // drawn in the last frame
  TableWorkStatus work;
  std::string tables;                 // the tables in use
  std::string message;                // the last screenshot, export or table error
  bool difference_ready = false;      // both variants' tables are loaded for this atmosphere
};

struct PanelEvents {
  bool tables_changed = false;  // atmosphere knobs (on release) or variant
  bool sun_clock_moved = false;
  bool screenshot = false;
  bool export_vdb = false;
};

PanelEvents DrawPanel(ViewSettings& settings, const PanelInfo& info);

// The keys' help (key_commands.h) in a window at the centre of the screen.
void DrawKeyHelp();

}  // namespace aerial::viewer
