#pragma once
// The CPU reference (aerial/reference, double precision) at a sparse grid of pixel centers of a
// rendered view. Each pixel's ray is rebuilt exactly as the composite shaders build it
// (shaders/include/frame.glsl: ViewRayFromScreen, GetCameraRayParameters), from the frame's own
// uniforms (Renderer::frame_uniforms), in double precision. What each pixel is compared with:
//   sky pixels (no geometry): the sky radiance along the whole view ray, of the orders the tables
//     stand for (PrecomputeOptions::RepresentedOrders): L = S. Where the ray meets the bare
//     planet the renderer adds the ground's Lambertian reflection, so the reference adds
//     T albedo / pi (E_sun + E_sky) at the ground point, E_sky of the same orders.
//   opaque pixels: aerial perspective over the segment to the surface, L = L_surface T + S, with
//     the renderer's own L_surface (Renderer::ReadSurface), so only aerial perspective differs.
// Pixels that see the sun disc are left out: the disc is not a scattering quantity.
#include <array>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "aerial/bench/image_metrics.h"
#include "aerial/image/image.h"
#include "aerial/reference/reference.h"
#include "aerial/render/frame_uniforms.h"

namespace aerial::bench {

struct ReferencePixel {
  int x = 0, y = 0;
  bool sky = false;
  Spectrum inscatter{};      // S: the whole ray (sky) or the segment to the surface (opaque)
  Spectrum transmittance{};  // T over the same ray or segment
  Spectrum ground{};         // sky pixels meeting the planet: radiance leaving the ground
  Spectrum std_error{};      // Monte Carlo standard error of the expected radiance
  // The expected radiance; surface_rgba is the renderer's surface pixel (used for opaque pixels).
  Spectrum Expected(const float* surface_rgba) const;
};

struct ReferenceSampling {
  int columns = 16, rows = 9;
  int orders = 4;  // or reference::kAllOrders
  reference::MonteCarloOptions monte_carlo;
};

struct ViewReference {
  std::vector<ReferencePixel> pixels;
  int sun_pixels = 0;  // grid pixels left out because they see the sun disc
  // Median over the pixels of the largest relative standard error of a channel (relative to the
  // expected radiance): the noise floor of the comparisons against this reference.
  double median_relative_std_error = 0.0;
};

// The unit view ray (camera-relative world frame) through the center of pixel (x, y), row 0 at
// the top, as ViewRayFromScreen computes it: the clip-space point (uv * 2 - 1, 0.5, 1) through the
// frame's inverse view-projection.
glm::dvec3 PixelRay(const FrameUniforms& frame, int x, int y);

// The pixels of a columns x rows grid of cells over a width x height image: each cell's center
// pixel.
std::vector<std::array<int, 2>> GridPixels(int width, int height, int columns, int rows);

// surface: the view's Renderer::ReadSurface (distances; sky where alpha < 0). on_pixel (may be
// empty) is called after each grid pixel.
ViewReference SampleReference(const reference::Reference& model, const FrameUniforms& frame,
                              const ImageRgbF& surface, const ReferenceSampling& sampling,
                              const std::function<void()>& on_pixel);

// The reference's pixels of one class against a rendered image (and that renderer's surface).
std::vector<PixelSample> ReferenceSamples(const ViewReference& reference, const ImageRgbF& rendered,
                                          const ImageRgbF& surface, PixelClass pixels);

}  // namespace aerial::bench
