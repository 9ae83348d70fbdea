#pragma once
// The accepted range of every camera and sun value, shared by scene files and command-line
// overrides so both reject the same things with the same words. Each check throws
// aerial::Error{field, value, allowed, where} with the caller's field name ("camera.fov_deg", or a
// command's option) and where ("scene.toml:12:9", "command line").
#include <glm/glm.hpp>
#include <string>

#include "aerial/core/format_number.h"  // FormatNumber, for the messages of these checks' callers

namespace aerial {

// Finite, with an altitude |p - (0, 0, -R)| - R in [-500, 100000] m: from below the lowest dry
// land (the Dead Sea shore, -430 m) to 100 km, above the atmosphere (Earth's top is at 60 km), for
// views from space.
void CheckCameraPosition(const glm::dvec3& position_m, double planet_radius_m,
                         const std::string& field, const std::string& where);
// Compass angles wrap, so any number of turns would do; a bound keeps the arithmetic on them
// finite (degrees x pi overflowed above 5.7e307, and a camera path interpolates between them)
// and exact enough: a million degrees is 2,778 turns.
inline constexpr double kMaxAzimuthDeg = 1e6;
// [-kMaxAzimuthDeg, kMaxAzimuthDeg], which refuses NaN and infinity too.
void CheckAzimuthDeg(double degrees, const std::string& field, const std::string& where);
// [-90, 90]: straight down to straight up.
void CheckPitchDeg(double degrees, const std::string& field, const std::string& where);
// (1, 170), open: narrower makes the projection ill-conditioned in float, and 180 is infinite.
void CheckFovDeg(double degrees, const std::string& field, const std::string& where);
// [0.001, 1000] m as float (the projection receives it as one; see ProjectionMatrix): scene
// positions are floats that resolve about 8 mm 100 km out (scene.h), so a nearer plane gains
// nothing; a farther one clips away the nearest landmark of the built-in scene (1 km) and
// everything the camera stands in.
void CheckNearM(double meters, const std::string& field, const std::string& where);
// [0, 180].
void CheckZenithDeg(double degrees, const std::string& field, const std::string& where);

// How far from the scene origin a mesh's vertices may be placed: float positions resolve 6 cm
// there, and a camera 100 km up sees the horizon at 1130 km.
inline constexpr double kMaxSceneDistanceM = 1e6;

// How far from its own origin a glTF model's vertex may be, after its node transforms: far beyond
// any model (a scene's scale may shrink it), far inside float's range, so the check that keeps
// it also keeps NaN and infinity out.
inline constexpr double kMaxModelCoordinateM = 1e12;

// The farthest vertex of a placed mesh, before its positions are rounded to float: within
// kMaxSceneDistanceM of the origin (which also keeps them finite as floats). value describes the
// placement ("scale 1e+300"), for the message.
void CheckPlacedDistance(double farthest_m, const std::string& field, const std::string& value,
                         const std::string& where);

}  // namespace aerial
