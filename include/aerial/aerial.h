#pragma once
// aerial: a physically based sky and aerial perspective (Bruneton & Neyret 2008) on the caller's
// Vulkan device. docs/api.md walks through a frame; examples/embed/ is a complete program.
//
//   aerial::Device device(aerial::DeviceHandoff{instance, physical_device, vk_device, family});
//   aerial::Tables tables = aerial::Tables::LoadOrPrecompute(device, aerial::AtmosphereParameters::Earth(),
//                                                            aerial::PrecomputeOptions::Default());
//   aerial::Froxels froxels(device);                      // 32x32x32 up to 128 km
//   froxels.Record(command_buffer, tables, camera);       // per frame, before the caller's passes
//   // The caller's shaders: #include "aerial_perspective.glsl" (share/aerial/glsl), bind
//   // tables.atmosphere_block(), froxels.frame_block() and the images, ApplyAerialPerspective(...).
#include "aerial/atmosphere.h"
#include "aerial/device.h"
#include "aerial/error.h"
#include "aerial/froxels.h"
#include "aerial/image.h"
#include "aerial/probe.h"
#include "aerial/renderer.h"
#include "aerial/scene.h"
#include "aerial/tables.h"
#include "aerial/vdb_export.h"
#include "aerial/version.h"
