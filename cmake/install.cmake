# `cmake --install build --prefix P`: the libraries, their headers, the shadowlab command,
# the data folder assets/ with the built-in scenes (scenes/CMakeLists.txt) and a CMake package, so that another project
# can write
#   find_package(shadowlab CONFIG REQUIRED)
#   target_link_libraries(my_program PRIVATE shadowlab::frame)
# with -DCMAKE_PREFIX_PATH=P (examples/CMakeLists.txt does). Tests, benchmarks and the
# command's own library (shadowlab_app) are not installed.
include(CMakePackageConfigHelpers)

install(TARGETS shadowlab_raster shadowlab_scenes shadowlab_shading shadowlab_shadows shadowlab_frame
  shadowlab_differential_scene shadowlab_differential
  EXPORT shadowlabTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  FILE_SET HEADERS DESTINATION ${SHADOWLAB_INSTALL_INCLUDEDIR})
install(TARGETS shadowlab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The data folder as it is in the tree, licences included: scene files name their meshes,
# maps and textures by paths relative to themselves.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets/ DESTINATION ${SHADOWLAB_INSTALL_DATADIR})

install(EXPORT shadowlabTargets
  NAMESPACE shadowlab::
  FILE shadowlabTargets.cmake
  DESTINATION ${SHADOWLAB_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/shadowlabConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/shadowlabConfig.cmake
  INSTALL_DESTINATION ${SHADOWLAB_INSTALL_CMAKEDIR}
  PATH_VARS SHADOWLAB_INSTALL_DATADIR SHADOWLAB_INSTALL_SCENEDIR)
# 0.x: a new minor version may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/shadowlabConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)
# FindStb.cmake: Debian's stb has no CMake package, and shadowlab::shading links Stb::Stb
# (privately, but a static library's private dependencies are linked by its consumers).
install(FILES
  ${CMAKE_CURRENT_BINARY_DIR}/shadowlabConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/shadowlabConfigVersion.cmake
  ${CMAKE_CURRENT_LIST_DIR}/FindStb.cmake
  DESTINATION ${SHADOWLAB_INSTALL_CMAKEDIR})
