# CTest labels of aerial_tests' tests: `gpu` for those that use Vulkan (a device of their own, the
# shared test context, or the `aerial` command), `cpu` for the others, `slow` besides for the
# end-to-end benchmark, and `sanitizer` besides for the GPU tests that the sanitizer run also
# takes (tools/run-sanitizer-tests.sh). Scripts choose tests by label (`ctest -L gpu -LE slow`),
# so no list of suites is kept by hand.
#
# A test file is a GPU file when it includes what a GPU test needs: the test fixture
# (gpu_fixture.h), the command runner (command_run.h, hostile_command.h), a window
# (xvfb_display.h), a device (aerial/device.h) or the Vulkan layer (aerial/vk/). Every suite such
# a file defines is labelled `gpu`. A GPU file that also holds the comment line
#   // CTest label "sanitizer": ...
# (saying why its tests are the ones the sanitizer run takes) labels its suites `sanitizer` too. The
# other tests run with the Vulkan loader given a driver manifest that does not exist, so a test
# that uses the GPU without being labelled fails in every run instead of hiding among the CPU ones.

# The gtest filter (Suite.*:*/Suite.* for each suite) of the suites that the GPU files among
# `sources` define; with `marker` not empty, of those whose text also matches it.
function(aerial_gpu_test_filter out marker)
  set(suites)
  foreach(source IN LISTS ARGN)
    file(READ ${source} text)
    if(NOT text MATCHES "#include \"(gpu_fixture|command_run|hostile_command|xvfb_display|aerial/device|aerial/vk/[a-z_]+)\\.h\"")
      continue()
    endif()
    if(marker AND NOT text MATCHES "${marker}")
      continue()
    endif()
    string(REGEX MATCHALL "(TEST|TEST_F|TEST_P)\\([ \t\r\n]*[A-Za-z0-9_]+," definitions "${text}")
    foreach(definition IN LISTS definitions)
      string(REGEX REPLACE "^.*\\([ \t\r\n]*([A-Za-z0-9_]+),$" "\\1" suite "${definition}")
      list(APPEND suites ${suite})
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES suites)
  list(SORT suites)
  set(patterns)
  foreach(suite IN LISTS suites)
    list(APPEND patterns "${suite}.*" "*/${suite}.*")  # */: a parameterized suite's instances
  endforeach()
  list(JOIN patterns ":" filter)
  set(${out} "${filter}" PARENT_SCOPE)
endfunction()

# Discovers `target`'s tests in four groups and labels them once ctest has read the groups (the
# labels are set by a script ctest includes after the discovery's own, since gtest_discover_tests
# splits a list given in PROPERTIES). `slow_filter`: the gtest filter of the slow tests. Their
# COST starts them first in a parallel run that has no timings of an earlier one (a fresh clone,
# CI): started last, the longest test would run alone at the end.
function(aerial_discover_labelled_tests target slow_filter)
  get_target_property(sources ${target} SOURCES)
  aerial_gpu_test_filter(gpu_filter "" ${sources})
  aerial_gpu_test_filter(sanitizer_filter "// CTest label \"sanitizer\":" ${sources})
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 TEST_FILTER "-${slow_filter}:${gpu_filter}"
                       TEST_LIST aerial_cpu_tests)
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 TEST_FILTER "${gpu_filter}-${slow_filter}:${sanitizer_filter}"
                       TEST_LIST aerial_gpu_tests)
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 TEST_FILTER "${sanitizer_filter}-${slow_filter}"
                       TEST_LIST aerial_sanitizer_tests)
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 TEST_FILTER "${slow_filter}"
                       TEST_LIST aerial_slow_tests)
  set(no_driver "${CMAKE_CURRENT_BINARY_DIR}/no-vulkan-driver.json")  # never created
  set(script "${CMAKE_CURRENT_BINARY_DIR}/${target}_labels.cmake")
  file(WRITE ${script}
    "set_tests_properties(\${aerial_gpu_tests} PROPERTIES LABELS gpu)\n"
    "set_tests_properties(\${aerial_sanitizer_tests} PROPERTIES LABELS \"gpu;sanitizer\")\n"
    "set_tests_properties(\${aerial_slow_tests} PROPERTIES LABELS \"gpu;slow\" COST 1000)\n"
    "set_tests_properties(\${aerial_cpu_tests} PROPERTIES LABELS cpu\n"
    "                    ENVIRONMENT \"VK_DRIVER_FILES=${no_driver}\")\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${script})
endfunction()
