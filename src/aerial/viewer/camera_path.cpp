#include "aerial/viewer/camera_path.h"

#include <algorithm>

#include "aerial/core/toml_reader.h"
#include "aerial/error.h"
#include "aerial/scene/scene_limits.h"

namespace aerial::viewer {
namespace {

// The keyframe's key; a missing one is named with what it should be, at the keyframe's line.
const toml::node& Required(const TomlReader& r, const toml::table& t, const toml::node& table_node,
                           const std::string& field, std::string_view key,
                           const std::string& allowed) {
  const toml::node* node = t.get(key);
  if (!node) {
    throw Error(TomlReader::Join(field, key), "missing",
                allowed + " (every keyframe key is required)", r.At(table_node));
  }
  return *node;
}

CameraKeyframe ReadKeyframe(TomlReader& r, const toml::node& node, const std::string& field,
                            double planet_radius_m) {
  const toml::table& t = r.Table(node, field);
  r.RejectUnknownKeys(t, field, {"time_s", "position_m", "yaw_deg", "pitch_deg", "sun_zenith_deg", "sun_azimuth_deg"});
  auto key = [&](std::string_view k) { return TomlReader::Join(field, k); };
  CameraKeyframe k;
  const toml::node& time = Required(r, t, node, field, "time_s", "a number (s)");
  k.time_s = r.Number(time, key("time_s"), "s");
  if (!(k.time_s >= 0.0 && std::isfinite(k.time_s))) r.Fail(time, key("time_s"), ">= 0 s and finite");
  const toml::node& position =
      Required(r, t, node, field, "position_m", "an array of 3 numbers (m)");
  std::vector<double> p = r.Numbers(position, key("position_m"), 3, 3, "m");
  k.position_m = {p[0], p[1], p[2]};
  CheckCameraPosition(k.position_m, planet_radius_m, key("position_m"), r.At(position));
  const toml::node& yaw = Required(r, t, node, field, "yaw_deg", "a number (degrees)");
  k.yaw_deg = r.Number(yaw, key("yaw_deg"), "degrees");
  CheckAzimuthDeg(k.yaw_deg, key("yaw_deg"), r.At(yaw));
  const toml::node& pitch = Required(r, t, node, field, "pitch_deg", "a number (degrees)");
  k.pitch_deg = r.Number(pitch, key("pitch_deg"), "degrees");
  CheckPitchDeg(k.pitch_deg, key("pitch_deg"), r.At(pitch));
  if (t.contains("sun_zenith_deg") || t.contains("sun_azimuth_deg")) {
    const toml::node& zenith = Required(r, t, node, field, "sun_zenith_deg", "a number (degrees), with sun_azimuth_deg");
    const toml::node& azimuth = Required(r, t, node, field, "sun_azimuth_deg", "a number (degrees), with sun_zenith_deg");
    Sun sun;
    sun.zenith_deg = r.Number(zenith, key("sun_zenith_deg"), "degrees");
    CheckZenithDeg(sun.zenith_deg, key("sun_zenith_deg"), r.At(zenith));
    sun.azimuth_deg = r.Number(azimuth, key("sun_azimuth_deg"), "degrees");
    CheckAzimuthDeg(sun.azimuth_deg, key("sun_azimuth_deg"), r.At(azimuth));
    k.sun = sun;
  }
  return k;
}

// The first keyframe decides whether the path moves the sun; every other one must agree.
void CheckSunKeysInAllOrNone(const TomlReader& r, const std::vector<CameraKeyframe>& keyframes, size_t i) {
  if (keyframes[i].sun.has_value() == keyframes[0].sun.has_value()) return;
  const std::string field = TomlReader::Join(TomlReader::Index("keyframe", i), "sun_zenith_deg");
  throw Error(field, keyframes[i].sun ? FormatNumber(keyframes[i].sun->zenith_deg) : "missing",
              keyframes[0].sun ? "a number (degrees): keyframe[0] moves the sun, so every keyframe must"
                               : "absent: keyframe[0] leaves the sun alone, so every keyframe must",
              r.WhereOf(TomlReader::Index("keyframe", i)));
}

// The camera's position s of the way from a to b (s in [0, 1]): Apply's interpolation.
glm::dvec3 PositionBetween(const CameraKeyframe& a, const CameraKeyframe& b, double s) {
  return a.position_m + s * (b.position_m - a.position_m);
}

// What the path interpolates between keyframes a and b (keyframe[index - 1] and keyframe[index])
// must be as valid as each keyframe: the camera meets every value of the segment. Linear
// interpolation keeps an angle between two valid ones in its range, so only the position needs a
// check: a straight line between two valid positions can pass through the planet. Its lowest
// point is the point of the segment nearest the planet's center.
void CheckSegment(const TomlReader& r, const CameraKeyframe& a, const CameraKeyframe& b, size_t index,
                  double planet_radius_m) {
  const glm::dvec3 center(0.0, 0.0, -planet_radius_m), step = b.position_m - a.position_m;
  double length2 = glm::dot(step, step);
  double s = length2 > 0.0 ? std::clamp(glm::dot(center - a.position_m, step) / length2, 0.0, 1.0) : 0.0;
  const std::string from = TomlReader::Index("keyframe", index - 1), to = TomlReader::Index("keyframe", index);
  const std::string field = from + " to " + to;
  try {
    CheckCameraPosition(PositionBetween(a, b, s), planet_radius_m, field,
                        r.WhereOf(TomlReader::Join(to, "position_m")));
  } catch (const Error& e) {
    throw Error(e.field(), e.value(),
                e.allowed() + " all along the segment, which reaches this point at t = " +
                    FormatNumber(a.time_s + s * (b.time_s - a.time_s)) +
                    " s (the camera moves in a straight line: a keyframe between them can lead it around)",
                e.where());
  }
}

}  // namespace

CameraPath CameraPath::Parse(std::string_view text, const std::string& where, double planet_radius_m) {
  TomlReader r(where, FormatNumber);
  toml::table root = r.Parse(text);
  r.RejectUnknownKeys(root, "", {"keyframe"});
  const toml::node* list = root.get("keyframe");
  const toml::array* keyframes = list ? list->as_array() : nullptr;
  if (!keyframes || keyframes->size() < 2) {
    throw Error("keyframe", list ? r.NodeText(*list) : "missing",
                "two or more keyframes ([[keyframe]] tables)", list ? r.At(*list) : where);
  }
  CameraPath path;
  for (size_t i = 0; i < keyframes->size(); ++i) {
    std::string field = TomlReader::Index("keyframe", i);
    path.keyframes_.push_back(ReadKeyframe(r, *keyframes->get(i), field, planet_radius_m));
    if (i > 0 && !(path.keyframes_[i].time_s > path.keyframes_[i - 1].time_s)) {
      std::string time_field = TomlReader::Join(field, "time_s");
      throw Error(time_field, FormatNumber(path.keyframes_[i].time_s),
                  "> " + FormatNumber(path.keyframes_[i - 1].time_s) +
                      " s (times must increase from keyframe to keyframe)",
                  r.WhereOf(time_field));
    }
    CheckSunKeysInAllOrNone(r, path.keyframes_, i);
    if (i > 0) CheckSegment(r, path.keyframes_[i - 1], path.keyframes_[i], i, planet_radius_m);
  }
  return path;
}

CameraPath CameraPath::Load(const std::filesystem::path& path, double planet_radius_m) {
  return Parse(ReadTomlFile(path, "--camera-path"), path.string(), planet_radius_m);
}

namespace {

// The keyframes around path time t and how far (s in [0, 1]) t is from the first to the second.
struct Segment {
  const CameraKeyframe& a;
  const CameraKeyframe& b;
  double s;
};

Segment SegmentAt(const std::vector<CameraKeyframe>& keyframes, double t_s) {
  // The first keyframe later than t; the segment is the one ending there.
  auto next = std::upper_bound(keyframes.begin(), keyframes.end(), t_s,
                               [](double t, const CameraKeyframe& k) { return t < k.time_s; });
  const CameraKeyframe& a = next == keyframes.begin() ? keyframes.front()
                            : next == keyframes.end() ? keyframes.back()
                                                      : *(next - 1);
  const CameraKeyframe& b = next == keyframes.end() ? keyframes.back() : *next;
  double s = b.time_s > a.time_s ? std::clamp((t_s - a.time_s) / (b.time_s - a.time_s), 0.0, 1.0) : 0.0;
  return {a, b, s};
}

double Lerp(double a, double b, double s) { return a + s * (b - a); }

}  // namespace

void CameraPath::Apply(double t_s, Camera& camera) const {
  auto [a, b, s] = SegmentAt(keyframes_, t_s);
  camera.position = PositionBetween(a, b, s);
  camera.yaw_deg = Lerp(a.yaw_deg, b.yaw_deg, s);
  camera.pitch_deg = Lerp(a.pitch_deg, b.pitch_deg, s);
}

void CameraPath::ApplySun(double t_s, Sun& sun) const {
  if (!moves_sun()) return;
  auto [a, b, s] = SegmentAt(keyframes_, t_s);
  sun.zenith_deg = Lerp(a.sun->zenith_deg, b.sun->zenith_deg, s);
  sun.azimuth_deg = Lerp(a.sun->azimuth_deg, b.sun->azimuth_deg, s);
}

}  // namespace aerial::viewer
