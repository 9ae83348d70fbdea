# Sanitizer and fuzzing builds (tools/run-sanitizer-tests.sh, tools/fuzz.sh). Both apply to every
# target of the build, so the library, the command and the tests are instrumented alike.
#
# AERIAL_SANITIZE: a -fsanitize= list, e.g. "address,undefined". Any report stops the process
# (-fno-sanitize-recover), so a test that provokes one fails. With clang, float-cast-overflow is
# added: a float converted to an integer type it does not fit (a texel index from a NaN or a huge
# coordinate) is undefined behaviour that the "undefined" group does not include there.
# AERIAL_FUZZ: also builds the libFuzzer targets of tests/fuzz (clang only); the library gets
# coverage instrumentation (fuzzer-no-link) so that the fuzzer sees its branches.
set(AERIAL_SANITIZE "" CACHE STRING "Sanitizers for every target, e.g. address,undefined")
option(AERIAL_FUZZ "Build the libFuzzer targets in tests/fuzz (clang only)" OFF)

if(AERIAL_SANITIZE)
  set(aerial_sanitize_flags -fsanitize=${AERIAL_SANITIZE} -fno-sanitize-recover=all
      -fno-omit-frame-pointer)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    list(APPEND aerial_sanitize_flags -fsanitize=float-cast-overflow
         -fsanitize-ignorelist=${PROJECT_SOURCE_DIR}/tools/sanitizers/ubsan_ignorelist.txt)
  endif()
  add_compile_options(${aerial_sanitize_flags})
  add_link_options(${aerial_sanitize_flags})
endif()

if(AERIAL_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "AERIAL_FUZZ needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
  add_link_options(-fsanitize=fuzzer-no-link)
endif()
