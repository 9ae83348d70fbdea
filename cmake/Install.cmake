# `cmake --install build --prefix P`: the library aerial::aerial, its public headers (include/aerial
# and the generated version.h), its GLSL includes and the CMake package, so that another project
# writes
#   find_package(aerial 1.0 REQUIRED)
#   target_link_libraries(app PRIVATE aerial::aerial)
# The command, the viewer and the benchmark are not part of the package, nor are the headers of
# src/: the public headers use Vulkan's C API and nothing of aerial's implementation.
include(CMakePackageConfigHelpers)

install(TARGETS aerial_lib EXPORT aerialTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/aerial DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/generated/aerial/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/aerial)
# The shaders' shared GLSL (the lookups, the froxel read, the phase functions), for a caller's own
# shaders to #include: aerial_perspective.glsl is the entry point.
install(DIRECTORY shaders/include/ DESTINATION ${CMAKE_INSTALL_DATADIR}/aerial/glsl)

set(aerial_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/aerial)
install(EXPORT aerialTargets NAMESPACE aerial:: DESTINATION ${aerial_cmake_dir})
configure_package_config_file(cmake/aerialConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/aerialConfig.cmake INSTALL_DESTINATION ${aerial_cmake_dir}
  PATH_VARS CMAKE_INSTALL_DATADIR)
# Semantic versioning: find_package(aerial 1.0) accepts any 1.x at or above 1.0.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/aerialConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/aerialConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/aerialConfigVersion.cmake
        DESTINATION ${aerial_cmake_dir})
