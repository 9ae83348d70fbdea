#include "aerial/viewer/panel.h"

#include <algorithm>
#include <array>
#include <string>

#include <imgui.h>

#include "aerial/viewer/dynamic_resolution.h"
#include "aerial/viewer/key_commands.h"

namespace aerial::viewer {
namespace {

// A slider over a double shown in display units (value / unit); true once an edit is released,
// so a drag asks for one table set, not one per frame.
bool KnobSlider(const char* label, double& value, float min, float max, const char* format,
                double unit = 1.0, ImGuiSliderFlags flags = 0) {
  float shown = float(value / unit);
  if (ImGui::SliderFloat(label, &shown, min, max, format, flags)) value = double(shown) * unit;
  return ImGui::IsItemDeactivatedAfterEdit();
}

bool AtmosphereSection(AtmosphereKnobs& knobs) {
  bool changed = false;
  if (knobs.rayleigh_scale_height_m)
    changed |= KnobSlider("Rayleigh scale height", *knobs.rayleigh_scale_height_m, 2.0f, 16.0f,
                          "%.2f km", 1e3);
  if (knobs.mie_scale_height_m)
    changed |= KnobSlider("Mie scale height", *knobs.mie_scale_height_m, 0.3f, 6.0f, "%.2f km", 1e3);
  changed |= KnobSlider("Mie g", knobs.mie_g, 0.0f, 0.95f, "%.3f");
  changed |= KnobSlider("Ozone", knobs.ozone_scale, 0.0f, 3.0f, "%.2f x");
  changed |= KnobSlider("Ground albedo", knobs.ground_albedo, 0.0f, 1.0f, "%.2f");
  return changed;
}

void TablesStatus(const PanelInfo& info) {
  ImGui::TextWrapped("Tables: %s", info.tables.c_str());
  if (!info.work.busy) return;
  const TableWorkStatus& work = info.work;
  float fraction = work.total_steps > 0 ? float(work.done_steps) / float(work.total_steps) : 0.0f;
  std::string label = work.total_steps > 0 ? std::to_string(work.done_steps) + "/" +
                                                 std::to_string(work.total_steps) + " passes"
                                           : "loading";
  ImGui::ProgressBar(fraction, ImVec2(-1.0f, 0.0f), label.c_str());
  ImGui::TextWrapped("Computing %s in the background", info.work.description.c_str());
}

// Froxel grids offered in the combo, plus the command line's if it is another.
void FroxelSection(FroxelGrid& grid) {
  std::vector<std::string> grids = {"16x16x16", "32x32x32", "64x64x64", "32x32x64", "64x64x32"};
  std::string current = std::to_string(grid.width) + "x" + std::to_string(grid.height) + "x" +
                        std::to_string(grid.depth);
  if (std::find(grids.begin(), grids.end(), current) == grids.end()) grids.insert(grids.begin(), current);
  if (ImGui::BeginCombo("Froxels", current.c_str())) {
    for (const std::string& g : grids) {
      if (ImGui::Selectable(g.c_str(), g == current)) {
        FroxelGrid parsed = FroxelGrid::Parse(g);
        grid.width = parsed.width;
        grid.height = parsed.height;
        grid.depth = parsed.depth;
      }
    }
    ImGui::EndCombo();
  }
  // Only the renderer's distribution: slice k at far ((k + 0.5) / D)^2 (aerial/froxel_grid.h).
  KnobSlider("Froxel far distance", grid.far_m, 8.0f, 512.0f, "%.0f km", 1e3, ImGuiSliderFlags_Logarithmic);
  ImGui::TextDisabled("slices: quadratic, first at %.0f m", grid.SliceDistance(0.5));
}

void DebugSection(ViewSettings& s, const PanelInfo& info) {
  const std::array<const char*, 6> names = {"Final image", "Rayleigh only", "Mie only",
                                            "Transmittance", "Froxel slice", "3D vs 4D difference"};
  int view = int(s.view);
  if (ImGui::Combo("Debug view", &view, names.data(), int(names.size()))) s.view = DebugView(view);
  if (s.view == DebugView::kFroxelSlice) {
    s.froxel_slice = std::clamp(s.froxel_slice, 0, s.froxels.depth - 1);  // the grid may have changed
    ImGui::SliderInt("Slice", &s.froxel_slice, 0, s.froxels.depth - 1);
    ImGui::TextDisabled("at %.0f m; columns: Rayleigh, Mie (x 1/4pi), transmittance",
                        s.froxels.SliceDistance(s.froxel_slice + 0.5));
    if (s.mode != AerialMode::kFroxel) ImGui::TextWrapped("The per-pixel modes build no froxels.");
  }
  if (s.view == DebugView::kDifference) {
    ImGui::SliderFloat("White at", &s.difference_full_scale, 0.001f, 0.5f, "%.3f", ImGuiSliderFlags_Logarithmic);
    ImGui::TextDisabled("max |L3d - L4d| / max L4d per pixel, black-red-yellow-white");
    if (!info.difference_ready) ImGui::TextWrapped("Loading the other variant's tables...");
  }
}

bool SunSection(ViewSettings& s) {
  bool moved = ImGui::SliderFloat("Solar time", &s.solar_time_h, 0.0f, 24.0f, "%.2f h");
  moved |= ImGui::SliderFloat("Latitude", &s.latitude_deg, -90.0f, 90.0f, "%.1f deg");
  moved |= ImGui::SliderFloat("Declination", &s.declination_deg, -23.44f, 23.44f, "%.1f deg");
  ImGui::TextDisabled("arrow keys or left-drag: move the sun");
  return moved;
}

// A few render scales (each one makes a new renderer, so not a continuous slider).
void RenderScaleCombo(float& scale) {
  char current[16];
  std::snprintf(current, sizeof current, "%.2f", scale);
  if (ImGui::BeginCombo("Render scale", current)) {
    for (float choice : kRenderScales) {
      char label[16];
      std::snprintf(label, sizeof label, "%.2f", choice);
      if (ImGui::Selectable(label, choice == scale)) scale = choice;
    }
    ImGui::EndCombo();
  }
}

void Timings(const PanelInfo& info) {
  ImGui::Text("%.1f FPS, %.1f ms per frame", info.fps, info.frame_ms);
  ImGui::Text("terrain: %zu chunks, %zu triangles", info.terrain_chunks, info.terrain_triangles);
  double total = 0.0;
  for (const PassTime& pass : info.passes) {
    ImGui::Text("  %-20s %7.2f ms", pass.pass.c_str(), pass.milliseconds);
    total += pass.milliseconds;
  }
  ImGui::Text("  %-20s %7.2f ms", "GPU total", total);
}

}  // namespace

PanelEvents DrawPanel(ViewSettings& s, const PanelInfo& info) {
  PanelEvents events;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("aerial");
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 12);  // room for the longest label on the right
  if (ImGui::CollapsingHeader("Atmosphere", ImGuiTreeNodeFlags_DefaultOpen)) {
    events.tables_changed |= AtmosphereSection(s.knobs);
    int variant = s.variant == LutVariant::k4D ? 0 : 1;
    ImGui::Text("Tables");
    ImGui::SameLine();
    bool switched = ImGui::RadioButton("4D", &variant, 0);
    ImGui::SameLine();
    switched |= ImGui::RadioButton("3D", &variant, 1);
    if (switched) {
      s.variant = variant == 0 ? LutVariant::k4D : LutVariant::k3D;
      events.tables_changed = true;
    }
    TablesStatus(info);
  }
  if (ImGui::CollapsingHeader("Frame", ImGuiTreeNodeFlags_DefaultOpen)) {
    int mode = int(s.mode);
    ImGui::Text("Aerial perspective");
    ImGui::SameLine();
    ImGui::RadioButton("froxels", &mode, int(AerialMode::kFroxel));
    ImGui::SameLine();
    ImGui::RadioButton("per pixel", &mode, int(AerialMode::kPerPixel));
    ImGui::SameLine();
    ImGui::RadioButton("table difference", &mode, int(AerialMode::kTableDifference));
    s.mode = AerialMode(mode);
    ImGui::Checkbox("Sun shadows", &s.shadows);
    FroxelSection(s.froxels);
    RenderScaleCombo(s.render_scale);
    ImGui::SliderFloat("Terrain error", &s.terrain_error_px, 0.25f, 64.0f, "%.2f px",
                       ImGuiSliderFlags_Logarithmic);
    ImGui::Checkbox("Auto exposure", &s.auto_exposure);
    ImGui::SameLine();
    // Setting the EV100 by hand fixes it.
    if (ImGui::SliderFloat("EV100", &s.ev100, -4.0f, 20.0f, "%.1f")) s.auto_exposure = false;
    DebugSection(s, info);
  }
  if (ImGui::CollapsingHeader("Sun")) events.sun_clock_moved = SunSection(s);
  if (ImGui::CollapsingHeader("Timings", ImGuiTreeNodeFlags_DefaultOpen)) Timings(info);
  events.screenshot = ImGui::Button("Screenshot (F12, P)");
  ImGui::SameLine();
  events.export_vdb = ImGui::Button("Froxels to VDB (V)");
  if (!info.message.empty()) ImGui::TextWrapped("%s", info.message.c_str());
  ImGui::TextDisabled("WASD QE: fly, right-drag: look; F1: all keys, Tab: hide this panel");
  ImGui::PopItemWidth();
  ImGui::End();
  return events;
}

void DrawKeyHelp() {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x / 2, viewport->WorkPos.y + viewport->WorkSize.y / 2),
                          ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::Begin("Keys", nullptr,
               ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
  for (const char* line : KeyHelpLines()) ImGui::TextUnformatted(line);
  ImGui::End();
}

}  // namespace aerial::viewer
