#pragma once
// The CPU reference (aerial/reference, double precision) at a sparse grid of pixel centers of a
// rendered view. Each pixel's ray is rebuilt exactly as the composite shaders build it
// (shaders/include/frame.glsl: ViewRayFromScreen, GetCameraRayParameters), from the frame's own
// uniforms (Renderer::frame_uniforms), in double precision. What each pixel is compared with:
//   sky pixels (no geometry): the sky radiance along the whole view ray, of the orders the tables
//     stand for (PrecomputeOptions::RepresentedOrders): L = S. Where the ray meets the bare
//     planet the renderer adds the ground's Lambertian reflection, so the reference adds
//     T albedo / pi (E_sun + E_sky) of the ground, lit as lambertian_radiance.h lights a surface
//     facing up.
//   opaque pixels: L = S + T L_surface over the segment to the surface, the surface lit by the
//     reference itself (lambertian_radiance.h: sun and tilted-sky irradiance of the same orders, no
//     shadows) at the point, normal and albedo the scene has there (aerial/scene_surface.h). The
//     renderer's surface image (Renderer::ReadSurface) only gives the depth and tells sky from
//     geometry: its lighting is what is checked, with the aerial perspective.
// Pixels that see the sun disc are left out (the disc is not a scattering quantity), and opaque
// pixels where the scene has no surface at the renderer's depth (aerial/scene_surface.h).
#include <array>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "aerial/image.h"
#include "aerial/reference/reference.h"
#include "aerial/scene.h"
#include "aerial/shader_abi/frame_geometry.h"
#include "aerial/spectrum/spectral_sampling.h"
#include "aerial/validation/image_metrics.h"

namespace aerial::validation {

struct ReferencePixel {
  int x = 0, y = 0;
  bool sky = false;
  Spectrum inscatter{};      // S: the whole ray (sky) or the segment to the surface (opaque)
  Spectrum transmittance{};  // T over the same ray or segment
  // Radiance leaving what ends the ray: the lit surface (opaque pixels), the lit ground (sky
  // pixels meeting the planet), else 0.
  Spectrum surface{};
  Spectrum std_error{};  // Monte Carlo standard error of the expected radiance
  Spectrum Expected() const;  // S + T surface
};

struct ReferenceSampling {
  int columns = 16, rows = 9;
  int orders = 4;  // or reference::kAllOrders
  reference::MonteCarloOptions monte_carlo;
  // The renderer's terrain error bound (RenderOptions::terrain_error_px): how far its terrain may
  // lie from the height function's surface (aerial/scene_surface.h).
  double terrain_error_px = 0.0;
  // The scene surfaces' albedo as the reference lights them, from the scene's (empty: as given).
  // The spectral reference maps it to each group's wavelengths.
  std::function<Spectrum(const Spectrum&)> scene_albedo;
};

struct ViewReference {
  std::vector<ReferencePixel> pixels;
  int sun_pixels = 0;  // grid pixels left out because they see the sun disc
  // Opaque grid pixels left out because the scene has no surface at the renderer's depth there.
  int unmatched_pixels = 0;
  // Median over the pixels of the largest relative standard error of a channel (relative to the
  // expected radiance): the noise floor of the comparisons against this reference.
  double median_relative_std_error = 0.0;
};

// The scene with its transparent meshes removed, so that every pixel is sky or an opaque surface
// the reference can light.
Scene OpaqueScene(const Scene& scene);

// The unit view ray (camera-relative world frame) through the center of pixel (x, y), row 0 at
// the top, as ViewRayFromScreen computes it: the clip-space point (uv * 2 - 1, 0.5, 1) through the
// frame's inverse view-projection.
glm::dvec3 PixelRay(const FrameUniforms& frame, int x, int y);

// The pixels of a columns x rows grid of cells over a width x height image: each cell's center
// pixel.
std::vector<std::array<int, 2>> GridPixels(int width, int height, int columns, int rows);

// scene: what was rendered (its camera, meshes and terrain); frame and surface: the view's
// Renderer::frame_uniforms and Renderer::ReadSurface (distances; sky where alpha < 0). on_pixel
// (may be empty) is called after each grid pixel.
ViewReference SampleReference(const reference::Reference& model, const Scene& scene, const FrameUniforms& frame,
                              const ImageRgbF& surface, const ReferenceSampling& sampling,
                              const std::function<void()>& on_pixel);

// SampleReference in colour: at every group of three wavelengths of `spectral_sampling` (the
// atmosphere extended as the spectral precompute extends it, SpectralAtmosphere), each scene
// surface's linear sRGB albedo taken as the reflectance spectrum that reflects sunlight as the
// albedo does its colour (SpectralAtmosphere::ReflectanceForSunlight, as the renderer multiplies
// light by it), converted to linear sRGB by the sampling's conversion and summed. A pixel's
// `transmittance` is then the sunlight-weighted one (LinearSrgb(E T) / LinearSrgb(E), as
// spectral_reference.h's) and its `surface` what makes
// Expected() the converted S + T L_surface; standard errors are the converted values' own
// (LinearSrgbStdError, probe/spectral_reference.h), S's and T L_surface's added as independent ones.
ViewReference SampleSpectralReference(const AtmosphereParameters& atmosphere,
                                      const spectrum::SpectralSampling& spectral_sampling, const Scene& scene,
                                      const FrameUniforms& frame, const ImageRgbF& surface,
                                      const ReferenceSampling& sampling, const std::function<void()>& on_pixel);

// The reference's pixels of one class against a rendered image.
std::vector<PixelSample> ReferenceSamples(const ViewReference& reference, const ImageRgbF& rendered,
                                          PixelClass pixels);

}  // namespace aerial::validation
