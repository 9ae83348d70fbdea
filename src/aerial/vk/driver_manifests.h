#pragma once
// The Vulkan driver manifests (ICD JSON files) a user names in VK_DRIVER_FILES or
// VK_ICD_FILENAMES, checked before and explained after vkCreateInstance: the loader opens each
// listed path with a blocking read (a FIFO there hangs it), and answers a malformed manifest with
// ErrorOutOfHostMemory, which would otherwise read as this machine's memory running out.
#include <string>

namespace aerial::vk {

// Throws Error("<variable>", path, "the path of a Vulkan driver's JSON manifest, not a FIFO ...")
// for a listed path that exists but is neither a regular file nor a directory.
void CheckDriverManifests();

// When one of the variables is set, throws Error(variable, its value, "Vulkan driver manifests
// the loader accepts (it answered: <loader_error>)"); returns otherwise.
void BlameDriverManifests(const std::string& loader_error);

}  // namespace aerial::vk
