# `cmake --install build --prefix P`: the library aerial::aerial, its public headers (include/aerial
# and the generated version.h), its GLSL includes and the CMake package, so that another project
# writes
#   find_package(aerial 2.0 REQUIRED)
#   target_link_libraries(app PRIVATE aerial::aerial)
# The command, the viewer and the benchmark are not part of the package, nor are the headers of
# src/: the public headers use Vulkan's C API and nothing of aerial's implementation.
include(CMakePackageConfigHelpers)

install(TARGETS aerial_lib EXPORT aerialTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/aerial DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/generated/aerial/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/aerial)
# The shaders' shared GLSL that a caller's own shaders #include (the lookups, the froxel read, the
# phase functions): the entry points aerial_perspective.glsl and blocks_not_inlined.glsl and what
# they include, found by following their #include lines so that the set follows the files.
set(aerial_glsl_pending aerial_perspective.glsl blocks_not_inlined.glsl)
set(aerial_glsl_installed)
while(aerial_glsl_pending)
  list(POP_FRONT aerial_glsl_pending glsl)
  if(glsl IN_LIST aerial_glsl_installed)
    continue()
  endif()
  set(path ${CMAKE_CURRENT_SOURCE_DIR}/shaders/include/${glsl})
  list(APPEND aerial_glsl_installed ${glsl})
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${path})
  file(STRINGS ${path} includes REGEX "^#include \"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
    list(APPEND aerial_glsl_pending ${included})
  endforeach()
endwhile()
list(TRANSFORM aerial_glsl_installed PREPEND shaders/include/)
install(FILES ${aerial_glsl_installed} DESTINATION ${CMAKE_INSTALL_DATADIR}/aerial/glsl)

set(aerial_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/aerial)
install(EXPORT aerialTargets NAMESPACE aerial:: DESTINATION ${aerial_cmake_dir})
configure_package_config_file(cmake/aerialConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/aerialConfig.cmake INSTALL_DESTINATION ${aerial_cmake_dir}
  PATH_VARS CMAKE_INSTALL_DATADIR)
# Semantic versioning: find_package(aerial 2.0) accepts any 2.x at or above 2.0, and no 1.x (2.0
# changed the API: docs/api.md).
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/aerialConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/aerialConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/aerialConfigVersion.cmake
              ${CMAKE_CURRENT_SOURCE_DIR}/cmake/OpenVDBModule.cmake
        DESTINATION ${aerial_cmake_dir})
