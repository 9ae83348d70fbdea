// The viewer's debug views of a real frame (noon preset, small tables): each view shows what it
// says, with numbers the physics fixes, and the final view is the PNG encoder's output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "aerial/api/impl.h"
#include "aerial/image.h"
#include "aerial/scene.h"
#include "aerial/viewer/display_passes.h"
#include "display_target.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

constexpr int kWidth = 160, kHeight = 90;
constexpr float kExposure = 8.0f;
constexpr ::vk::Extent2D kExtent{kWidth, kHeight};

struct Display {
  std::vector<uint8_t> rgba;
  const uint8_t* pixel(int x, int y) const { return rgba.data() + 4 * (size_t(y) * kWidth + x); }
};

class ViewerDebugViews : public GpuTest {
 protected:
  // One frame for the whole suite: building the scene and the renderer is most of the time.
  static void SetUpTestSuite() {
    scene_ = new Scene(BuildPreset("noon", SmallPublicTables().atmosphere().bottom_radius_m));
    renderer_ = new SceneRenderer(SmallPublicTables(), *scene_, RenderOptions{.width = kWidth, .height = kHeight});
    renderer_->Render(*scene_);
    target_ = new DisplayTarget(SharedContext(), kWidth, kHeight);
    passes_ = new viewer::DisplayPasses(SharedContext(), target_->render_pass(), ::vk::Format::eR8G8B8A8Unorm);
  }
  static void TearDownTestSuite() {
    delete passes_;
    delete target_;
    delete renderer_;
    delete scene_;
  }

  template <typename Record>
  Display Show(Record record) {
    return Display{target_->Draw(record)};
  }
  Display ShowTerm(viewer::DisplayPasses::Term term) {
    return Show([&](const auto& cmd) { passes_->RecordTerm(cmd, kExtent, *renderer_, 0, term, kExposure); });
  }

  static inline Scene* scene_ = nullptr;
  static inline SceneRenderer* renderer_ = nullptr;
  static inline DisplayTarget* target_ = nullptr;
  static inline viewer::DisplayPasses* passes_ = nullptr;
};

// What the window shows is what a PNG of the frame holds: the same curve (viewer_present_test.cpp)
// on the renderer's own output image, at most one 8-bit step apart where rounding straddles.
TEST_F(ViewerDebugViews, FinalViewIsThePngOfTheFrame) {
  Display shown = Show([&](const auto& cmd) { passes_->RecordToneMap(cmd, kExtent, renderer_->output(), kExposure); });
  std::vector<uint8_t> png = ToneMapToSrgb8(renderer_->ReadOutput(), {.exposure = kExposure});
  int worst = 0;
  for (size_t i = 0; i < png.size(); ++i)
    if (i % 4 != 3) worst = std::max(worst, std::abs(int(shown.rgba[i]) - int(png[i])));
  EXPECT_LE(worst, 1);
}

// Rayleigh scattering goes as lambda^-4 (440 nm scatters 5.7x more than 680 nm), Mie scattering is
// grey in this atmosphere: in the sky straight above the image center the Rayleigh view is blue
// and the Mie view close to grey.
TEST_F(ViewerDebugViews, RayleighIsBlueAndMieIsGrey) {
  Display rayleigh = ShowTerm(viewer::DisplayPasses::Term::kRayleigh);
  Display mie = ShowTerm(viewer::DisplayPasses::Term::kMie);
  const uint8_t* r = rayleigh.pixel(kWidth / 2, 2);
  const uint8_t* m = mie.pixel(kWidth / 2, 2);
  EXPECT_GT(r[2], r[0] + 40) << "Rayleigh view, top center: " << int(r[0]) << " " << int(r[2]);
  EXPECT_GT(m[0], 0);
  // Only the transmittance on the way colors Mie inscatter; its channels stay within 1.5x.
  EXPECT_LT(std::max(m[0], m[2]), 1.5 * std::min(m[0], m[2])) << int(m[0]) << " " << int(m[2]);
}

// Transmittance: 1 at the camera, lower with distance, lowest in blue. The froxel slice view's
// transmittance column is ~1 in the first slice (12 m at 32 slices to 128 km) and lower in the last
// (128 km); the sky's whole-ray transmittance is below a near landmark's.
TEST_F(ViewerDebugViews, TransmittanceFallsWithDistance) {
  Display first = Show([&](const auto& cmd) { passes_->RecordFroxelSlice(cmd, kExtent, *renderer_, 0, kExposure); });
  Display last = Show([&](const auto& cmd) { passes_->RecordFroxelSlice(cmd, kExtent, *renderer_, 31, kExposure); });
  const uint8_t* near = first.pixel(kWidth * 5 / 6, kHeight / 2);  // the third column
  const uint8_t* far = last.pixel(kWidth * 5 / 6, kHeight / 2);
  EXPECT_GE(near[2], 254);
  EXPECT_LT(far[2], near[2] - 30) << int(far[2]);
  EXPECT_LT(far[2], far[0]) << "blue is attenuated most";

  Display transmittance = ShowTerm(viewer::DisplayPasses::Term::kTransmittance);
  ImageRgbF surface = ImplOf(*renderer_).renderer.ReadSurface();
  int sky = -1, ground = -1;  // a pixel of sky, and one of geometry within 2 km
  for (int i = 0; i < kWidth * kHeight; ++i) {
    float distance = surface.rgba[4 * i + 3];
    if (distance < 0.0f && sky < 0) sky = i;
    if (distance > 0.0f && distance < 2000.0f && ground < 0) ground = i;
  }
  ASSERT_GE(sky, 0);
  ASSERT_GE(ground, 0);
  EXPECT_LT(transmittance.rgba[4 * sky + 2], transmittance.rgba[4 * ground + 2]);
}

// The frame against a copy of it 2% brighter in its left half: there the relative difference is
// 0.02, 0.4 of the full scale 0.05, which the hot map shows as (1, 0.2, 0) before the sRGB
// encoding (green 0.2 -> 124 of 255); the right half, the frame against itself, is black.
TEST_F(ViewerDebugViews, DifferenceShowsAKnownDifferenceAndBlackWhereFramesAgree) {
  ImageRgbF frame = renderer_->ReadOutput();
  ImageRgbF brighter = frame;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth / 2; ++x)
      for (int c = 0; c < 3; ++c) brighter.rgba[4 * (size_t(y) * kWidth + x) + c] *= 1.02f;
  vk::Image first = Upload(frame), second = Upload(brighter);
  Display shown = Show([&](const auto& cmd) {
    passes_->RecordDifference(cmd, kExtent, ToSampledImage({&first, VK_NULL_HANDLE}),
                              ToSampledImage({&second, VK_NULL_HANDLE}), 0.05f);
  });
  const int green = int(std::lround(255 * (1.055 * std::pow(0.2, 1 / 2.4) - 0.055)));
  int wrong_left = 0, lit_right = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const uint8_t* p = shown.pixel(x, y);
      if (x < kWidth / 2)
        wrong_left += p[0] != 255 || std::abs(p[1] - green) > 1 || p[2] != 0;
      else
        lit_right += p[0] != 0 || p[1] != 0 || p[2] != 0;
    }
  EXPECT_EQ(wrong_left, 0) << "expected (255, " << green << ", 0); top left: " << int(shown.pixel(0, 0)[0])
                           << " " << int(shown.pixel(0, 0)[1]) << " " << int(shown.pixel(0, 0)[2]);
  EXPECT_EQ(lit_right, 0);
}

}  // namespace
}  // namespace aerial::testing
