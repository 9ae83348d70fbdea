#pragma once
// What the Vulkan loader reads, checked before it starts and explained after it fails. The loader
// opens every manifest (JSON) it finds with a blocking read and loads every library a manifest
// names, so a FIFO anywhere in that chain hangs the program for ever; and it answers a malformed
// driver manifest with ErrorOutOfHostMemory, which would otherwise read as this machine's memory
// running out.
#include <string>

namespace aerial::vk {

// Throws Error before the loader starts when anything it would open is neither a regular file nor
// (for a listed path) a directory: the paths listed in VK_DRIVER_FILES, VK_ICD_FILENAMES,
// VK_ADD_DRIVER_FILES, VK_LAYER_PATH, VK_ADD_LAYER_PATH, VK_IMPLICIT_LAYER_PATH and
// VK_ADD_IMPLICIT_LAYER_PATH and the loader's own search directories (.../vulkan/icd.d,
// implicit_layer.d and explicit_layer.d under XDG_CONFIG_HOME, XDG_CONFIG_DIRS, /etc,
// XDG_DATA_HOME and XDG_DATA_DIRS), each directory's *.json entries, and the library_path of
// every manifest there that names a file by a path (a bare file name is found by the dynamic
// linker, like any library the program loads). The error names the variable (or the search
// directory), the path and what it is: Error("VK_LAYER_PATH", ".../fifo.json", "... not a FIFO
// (named pipe)").
void CheckLoaderFiles();

// When one of the driver variables is set, throws Error(variable, its value, "Vulkan driver
// manifests the loader accepts (it answered: <loader_error>)"); returns otherwise.
void BlameDriverManifests(const std::string& loader_error);

}  // namespace aerial::vk
