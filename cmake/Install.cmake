# `cmake --install build --prefix P`: the library aerial::aerial, its headers, its GLSL includes
# and the CMake package, so that another project writes
#   find_package(aerial 0.1 REQUIRED)
#   target_link_libraries(app PRIVATE aerial::aerial)
# The command, the viewer and the benchmark are not part of the package.
include(CMakePackageConfigHelpers)

install(TARGETS aerial_lib EXPORT aerialTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY src/aerial DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h"
        PATTERN "bench" EXCLUDE PATTERN "cli" EXCLUDE PATTERN "viewer" EXCLUDE)
install(DIRECTORY froxel DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
# The shaders' shared GLSL (the lookups, the froxel read, the phase functions), for a caller's own
# shaders to #include.
install(DIRECTORY shaders/include/ DESTINATION ${CMAKE_INSTALL_DATADIR}/aerial/glsl)

# The build types that define NDEBUG, here and in a client (aerialConfig.cmake.in).
set(AERIAL_NDEBUG_BUILD_TYPES "Release|RelWithDebInfo|MinSizeRel")
if(CMAKE_BUILD_TYPE MATCHES "^(${AERIAL_NDEBUG_BUILD_TYPES})$")
  set(AERIAL_NDEBUG TRUE)
else()
  set(AERIAL_NDEBUG FALSE)
endif()
set(aerial_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/aerial)
install(EXPORT aerialTargets NAMESPACE aerial:: DESTINATION ${aerial_cmake_dir})
configure_package_config_file(cmake/aerialConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/aerialConfig.cmake INSTALL_DESTINATION ${aerial_cmake_dir})
# 0.x releases promise nothing across minor versions; from 1.0 on, the same major version.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/aerialConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/aerialConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/aerialConfigVersion.cmake
        DESTINATION ${aerial_cmake_dir})
