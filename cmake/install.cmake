# `cmake --install`: the core as a CMake package (find_package(tumble) ->
# tumble::core, which links tumble::base). Headers keep their tree:
# include/tumble/core/*.hpp, include/tumble/core/methods/*.hpp, include/tumble/base/*.hpp.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(TUMBLE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/tumble)
file(GLOB TUMBLE_CORE_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/core/*.hpp)
install(FILES ${TUMBLE_CORE_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tumble/core)
file(GLOB TUMBLE_CORE_METHOD_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/core/methods/*.hpp)
install(FILES ${TUMBLE_CORE_METHOD_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tumble/core/methods)
file(GLOB TUMBLE_BASE_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/base/*.hpp)
install(FILES ${TUMBLE_BASE_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tumble/base)
install(TARGETS tumble_base tumble_core EXPORT tumbleTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT tumbleTargets NAMESPACE tumble:: DESTINATION ${TUMBLE_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/tumbleConfig.cmake.in
  ${PROJECT_BINARY_DIR}/tumbleConfig.cmake INSTALL_DESTINATION ${TUMBLE_CMAKE_DIR})
# 0.x: a minor version may break the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tumbleConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/tumbleConfig.cmake ${PROJECT_BINARY_DIR}/tumbleConfigVersion.cmake
  DESTINATION ${TUMBLE_CMAKE_DIR})
