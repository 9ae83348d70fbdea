#pragma once
// Large allocations on transparent huge pages. A command touches hundreds of megabytes of fresh
// memory (tables read from the cache and uploaded, lavapipe's images and buffers, read-back
// images), and each 4 KiB page's first touch is a page fault; on virtual machines a fault is
// expensive. glibc (2.35 on) puts its large chunks on huge pages when the tunable
// glibc.malloc.hugetlb=1 is set, which glibc reads only as a process starts: so the command
// starts itself again with it, once (docs/speed.md has what it buys).
#include <optional>
#include <string>

namespace aerial::cli {

// The GLIBC_TUNABLES value that adds glibc.malloc.hugetlb=1 to `current` (null: unset), or
// nullopt when `current` already says anything of hugetlb (the user's choice, or this process
// started itself again).
std::optional<std::string> TunablesWithHugePages(const char* current);

// Starts this program again (/proc/self/exe, the same arguments) with the tunable added, unless it
// is already set or cannot be; returns only when it does not.
void RestartWithHugePages(char** argv);

}  // namespace aerial::cli
