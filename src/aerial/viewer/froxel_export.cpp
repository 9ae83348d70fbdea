#include "aerial/viewer/froxel_export.h"

namespace aerial::viewer {

std::string ExportFroxelsToVdb(const Renderer&) { return "VDB export: not available in this build"; }

}  // namespace aerial::viewer
