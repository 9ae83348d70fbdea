#include "aerial/viewer/camera_path.h"

#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "aerial/error.h"

namespace aerial::viewer {
namespace {

constexpr double kR = 6360e3;

const char* kPath = R"(
[[keyframe]]
time_s = 0.0
position_m = [0.0, 0.0, 30.0]
yaw_deg = 350.0
pitch_deg = 4.0

[[keyframe]]
time_s = 2.0
position_m = [0.0, 2000.0, 230.0]
yaw_deg = 370.0
pitch_deg = 0.0
)";

TEST(CameraPath, InterpolatesLinearlyAndHoldsTheEnds) {
  CameraPath path = CameraPath::Parse(kPath, "path.toml", kR);
  ASSERT_EQ(path.keyframes().size(), 2u);
  EXPECT_DOUBLE_EQ(path.duration_s(), 2.0);
  Camera camera;
  camera.vertical_fov_deg = 42.0;
  path.Apply(0.5, camera);
  EXPECT_NEAR(camera.position.y, 500.0, 1e-9);
  EXPECT_NEAR(camera.position.z, 80.0, 1e-9);
  EXPECT_NEAR(camera.yaw_deg, 355.0, 1e-9);  // as written: 350 -> 370, no wrap to 10
  EXPECT_NEAR(camera.pitch_deg, 3.0, 1e-9);
  EXPECT_EQ(camera.vertical_fov_deg, 42.0);  // not part of a path
  path.Apply(-1.0, camera);
  EXPECT_EQ(camera.position.z, 30.0);
  path.Apply(60 * kFrameStepS + 1.0, camera);
  EXPECT_EQ(camera.position.y, 2000.0);
  EXPECT_EQ(camera.yaw_deg, 370.0);
}

// A frame step lands exactly on keyframes: frame 60 of a 2 s path is its last keyframe.
TEST(CameraPath, FrameStepIsThirtyPerSecond) {
  CameraPath path = CameraPath::Parse(kPath, "path.toml", kR);
  Camera camera;
  path.Apply(60 * kFrameStepS, camera);
  EXPECT_NEAR(camera.position.y, 2000.0, 1e-6);
}

struct BadPath {
  std::string text;
  std::string field;
};

// CTest lists each case by the field it expects named, not by the struct's bytes.
void PrintTo(const BadPath& bad, std::ostream* out) { *out << bad.field; }

class CameraPathRejects : public ::testing::TestWithParam<BadPath> {};

TEST_P(CameraPathRejects, NamingTheField) {
  try {
    CameraPath::Parse(GetParam().text, "path.toml", kR);
    FAIL() << "accepted:\n" << GetParam().text;
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), GetParam().field) << e.what();
    EXPECT_NE(e.where().find("path.toml"), std::string::npos) << e.what();
  }
}

// The missing key is named with what it should be, not shown as its table ("(a table)").
TEST(CameraPath, MissingKeyIsNamedWithItsForm) {
  try {
    std::string third = "[[keyframe]]\ntime_s = 3.0\nposition_m = [0.0, 0.0, 30.0]\npitch_deg = 0.0\n";
    CameraPath::Parse(kPath + third, "path.toml", kR);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "keyframe[2].yaw_deg");
    EXPECT_EQ(e.value(), "missing");
    EXPECT_EQ(e.allowed(), "a number (degrees) (every keyframe key is required)");
    EXPECT_EQ(e.where(), "path.toml:13:1") << "the keyframe's line";
  }
}

const char* kSunPath = R"(
[[keyframe]]
time_s = 0.0
position_m = [0.0, 0.0, 30.0]
yaw_deg = 0.0
pitch_deg = 4.0
sun_zenith_deg = 60.0
sun_azimuth_deg = 250.0

[[keyframe]]
time_s = 2.0
position_m = [0.0, 0.0, 30.0]
yaw_deg = 0.0
pitch_deg = 4.0
sun_zenith_deg = 88.0
sun_azimuth_deg = 260.0
)";

TEST(CameraPath, SunKeysMoveTheSunLikeTheCamera) {
  CameraPath path = CameraPath::Parse(kSunPath, "path.toml", kR);
  ASSERT_TRUE(path.moves_sun());
  Sun sun;
  path.ApplySun(0.5, sun);
  EXPECT_NEAR(sun.zenith_deg, 67.0, 1e-9);
  EXPECT_NEAR(sun.azimuth_deg, 252.5, 1e-9);
  path.ApplySun(5.0, sun);  // after the last keyframe: held there
  EXPECT_NEAR(sun.zenith_deg, 88.0, 1e-9);
}

TEST(CameraPath, WithoutSunKeysTheSunStays) {
  CameraPath path = CameraPath::Parse(kPath, "path.toml", kR);
  EXPECT_FALSE(path.moves_sun());
  Sun sun{.zenith_deg = 45.0, .azimuth_deg = 100.0};
  path.ApplySun(1.0, sun);
  EXPECT_EQ(sun, (Sun{.zenith_deg = 45.0, .azimuth_deg = 100.0}));
}

// Two keyframes, each at a valid altitude, whose straight line between them runs through the
// planet: keyframe[1] stands at the antipode of keyframe[0] (0 m up on the far side), so the
// camera would cross the planet's center at t = 0.5 s. Before, the path loaded and the viewer drew
// from inside the planet (a black frame), positions `render` refuses.
TEST(CameraPath, ASegmentThroughThePlanetIsRefusedNamingItsKeyframes) {
  const std::string path = "[[keyframe]]\ntime_s = 0.0\nposition_m = [0.0, 0.0, 0.0]\nyaw_deg = 0.0\n"
                           "pitch_deg = 0.0\n[[keyframe]]\ntime_s = 1.0\nposition_m = [0.0, 0.0, -12720000.0]\n"
                           "yaw_deg = 0.0\npitch_deg = 0.0\n";
  try {
    CameraPath::Parse(path, "path.toml", kR);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "keyframe[0] to keyframe[1]");
    EXPECT_EQ(e.value(), "[0, 0, -6360000] (altitude -6360000 m)");
    EXPECT_NE(e.allowed().find("at t = 0.5 s"), std::string::npos) << e.what();
    EXPECT_EQ(e.where(), "path.toml:8:14") << "keyframe[1].position_m";
  }
  // A segment 100 km long with its ends 227 m up passes 30 m over the ground at its middle: allowed.
  const std::string chord = "[[keyframe]]\ntime_s = 0.0\nposition_m = [-50000.0, 0.0, 30.0]\nyaw_deg = 0.0\n"
                            "pitch_deg = 0.0\n[[keyframe]]\ntime_s = 1.0\nposition_m = [50000.0, 0.0, 30.0]\n"
                            "yaw_deg = 0.0\npitch_deg = 0.0\n";
  EXPECT_NO_THROW(CameraPath::Parse(chord, "path.toml", kR));
}

// "x.x...x", parts parts.
std::string DottedKey(int parts) {
  std::string key = "x";
  for (int i = 1; i < parts; ++i) key += ".x";
  return key;
}

const std::string kFirst = "[[keyframe]]\ntime_s = 0.0\nposition_m = [0.0, 0.0, 30.0]\nyaw_deg = 0.0\npitch_deg = 0.0\n";

INSTANTIATE_TEST_SUITE_P(
    BadFiles, CameraPathRejects,
    ::testing::Values(
        BadPath{"", "keyframe"},
        BadPath{kFirst, "keyframe"},
        BadPath{kFirst + "[[keyframe]]\ntime_s = 1.0\nposition_m = [0.0, 0.0, 30.0]\npitch_deg = 0.0\n",
                "keyframe[1].yaw_deg"},
        BadPath{kFirst + "[[keyframe]]\ntime_s = 0.0\nposition_m = [0.0, 0.0, 30.0]\nyaw_deg = 0.0\npitch_deg = 0.0\n",
                "keyframe[1].time_s"},
        BadPath{kFirst + "[[keyframe]]\ntime_s = 1.0\nposition_m = [0.0, 30.0]\nyaw_deg = 0.0\npitch_deg = 0.0\n",
                "keyframe[1].position_m"},
        BadPath{kFirst + "[[keyframe]]\ntime_s = 1.0\nposition_m = [0.0, 0.0, 2e5]\nyaw_deg = 0.0\npitch_deg = 0.0\n",
                "keyframe[1].position_m"},
        BadPath{kFirst + "[[keyframe]]\ntime_s = 1.0\nposition_m = [0.0, 0.0, 30.0]\nyaw_deg = 0.0\npitch_deg = 95.0\n",
                "keyframe[1].pitch_deg"},
        BadPath{kFirst + "[[keyframe]]\ntime_s = 1.0\nposition_m = [0.0, 0.0, 30.0]\nyaw_deg = 0.0\npitch_deg = 0.0\nroll_deg = 1.0\n",
                "keyframe[1].roll_deg"},
        BadPath{kFirst + "[[keyframe]]\ntime_s = \"soon\"\nposition_m = [0.0, 0.0, 30.0]\nyaw_deg = 0.0\npitch_deg = 0.0\n",
                "keyframe[1].time_s"},
        // A finite yaw large enough that the interpolation's arithmetic overflows to NaN frames.
        BadPath{kFirst + "[[keyframe]]\ntime_s = 1.0\nposition_m = [0.0, 0.0, 30.0]\nyaw_deg = 1.7e308\npitch_deg = 0.0\n",
                "keyframe[1].yaw_deg"},
        // 40,000 dotted parts, which overflow toml++'s recursion stack unless the depth is bounded first.
        BadPath{DottedKey(40000) + " = 1\n", "TOML nesting"},
        // The sun's keys: a pair, in every keyframe or in none, each in its range.
        BadPath{kFirst + "sun_zenith_deg = 60.0\n[[keyframe]]\ntime_s = 1.0\nposition_m = [0.0, 0.0, 30.0]\nyaw_deg = 0.0\npitch_deg = 0.0\n",
                "keyframe[0].sun_azimuth_deg"},
        BadPath{kFirst + "sun_zenith_deg = 60.0\nsun_azimuth_deg = 0.0\n[[keyframe]]\ntime_s = 1.0\nposition_m = [0.0, 0.0, 30.0]\nyaw_deg = 0.0\npitch_deg = 0.0\n",
                "keyframe[1].sun_zenith_deg"},
        BadPath{kFirst + "[[keyframe]]\ntime_s = 1.0\nposition_m = [0.0, 0.0, 30.0]\nyaw_deg = 0.0\npitch_deg = 0.0\nsun_zenith_deg = 60.0\nsun_azimuth_deg = 0.0\n",
                "keyframe[1].sun_zenith_deg"},
        BadPath{kFirst + "sun_zenith_deg = 200.0\nsun_azimuth_deg = 0.0\n" + kFirst, "keyframe[0].sun_zenith_deg"}),
    [](const ::testing::TestParamInfo<BadPath>& info) { return "case" + std::to_string(info.index); });

}  // namespace
}  // namespace aerial::viewer
