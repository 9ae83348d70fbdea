#pragma once
// The accepted range of every camera and sun value, shared by scene files and command-line
// overrides so both reject the same things with the same words. Each check throws
// aerial::Error{field, value, allowed, where} with the caller's field name ("camera.fov_deg",
// "--camera-fov-deg") and where ("scene.toml:12:9", "command line").
#include <glm/glm.hpp>
#include <string>

namespace aerial {

// Finite, with an altitude |p - (0, 0, -R)| - R in [-500, 100000] m: from below the lowest dry
// land (the Dead Sea shore, -430 m) to 100 km, above the atmosphere (Earth's top is at 60 km), for
// views from space.
void CheckCameraPosition(const glm::dvec3& position_m, double planet_radius_m,
                         const std::string& field, const std::string& where);
// Any finite angle; compass angles wrap.
void CheckAzimuthDeg(double degrees, const std::string& field, const std::string& where);
// [-90, 90]: straight down to straight up.
void CheckPitchDeg(double degrees, const std::string& field, const std::string& where);
// (1, 170), open: narrower makes the projection ill-conditioned in float, and 180 is infinite.
void CheckFovDeg(double degrees, const std::string& field, const std::string& where);
// > 0 and finite (reversed Z divides by it; see ProjectionMatrix).
void CheckNearM(double meters, const std::string& field, const std::string& where);
// [0, 180].
void CheckZenithDeg(double degrees, const std::string& field, const std::string& where);

// Shortest text that reads back as the same double ("0.1", "6360000"), for messages.
std::string FormatNumber(double value);

}  // namespace aerial
