// The environment every test runs in, whoever starts the binary (ctest, a debugger, a shell):
// the Vulkan validation layers on, so that any message fails the test; the runtime directory
// that lavapipe and the window tests need; and the tables precomputed for the tests cached in the
// build tree, away from the user's ~/.cache/aerial. A variable already set is kept. (Set here and
// not through ctest's ENVIRONMENT: gtest_discover_tests splits a list given in PROPERTIES, so
// only its first variable ever reached the tests.)
#include <cstdlib>

namespace {

const bool kTestEnvironmentSet = [] {
  ::setenv("AERIAL_VALIDATION", "1", /*overwrite=*/0);
  ::setenv("XDG_RUNTIME_DIR", "/tmp", 0);
  ::setenv("AERIAL_CACHE_DIR", AERIAL_TEST_CACHE_DIR, 0);
  return true;
}();

}  // namespace
