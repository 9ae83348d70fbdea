# OpenVDB ships a find module (FindOpenVDB.cmake), not a package config, in its own install tree:
# lib/cmake/OpenVDB upstream, lib/<multiarch>/cmake/OpenVDB on Debian, share/openvdb with vcpkg.
# aerial_find_openvdb_module() puts the folder that holds it on CMAKE_MODULE_PATH, looked for under
# CMAKE_PREFIX_PATH and the system prefixes, so that find_package(OpenVDB) works wherever OpenVDB
# was installed. aerial's build and its installed package (aerialConfig.cmake) both use it.
macro(aerial_find_openvdb_module)
  find_path(AERIAL_OPENVDB_MODULE_DIR FindOpenVDB.cmake
    PATHS ${CMAKE_PREFIX_PATH} ${CMAKE_SYSTEM_PREFIX_PATH}
    PATH_SUFFIXES lib/cmake/OpenVDB lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB lib64/cmake/OpenVDB
                  share/openvdb
    NO_DEFAULT_PATH)
  if(AERIAL_OPENVDB_MODULE_DIR)
    list(APPEND CMAKE_MODULE_PATH ${AERIAL_OPENVDB_MODULE_DIR})
  endif()
endmacro()
