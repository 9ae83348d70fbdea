#include "aerial/cli/huge_pages.h"

#include <cstdlib>
#include <string_view>

#include <unistd.h>

namespace aerial::cli {

std::optional<std::string> TunablesWithHugePages(const char* current) {
  constexpr std::string_view kTunable = "glibc.malloc.hugetlb";
  if (current == nullptr || *current == '\0') return std::string(kTunable) + "=1";
  if (std::string_view(current).find(kTunable) != std::string_view::npos) return std::nullopt;
  return std::string(current) + ":" + std::string(kTunable) + "=1";  // tunables are separated by colons
}

void RestartWithHugePages(char** argv) {
#if defined(__GLIBC__) && defined(__linux__)
  const std::optional<std::string> tunables = TunablesWithHugePages(std::getenv("GLIBC_TUNABLES"));
  if (!tunables || setenv("GLIBC_TUNABLES", tunables->c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Not started again (no /proc, say): this process goes on as it is.
#else
  (void)argv;
#endif
}

}  // namespace aerial::cli
