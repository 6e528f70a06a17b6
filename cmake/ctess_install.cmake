# Install rules and the CMake package (find_package(ctess CONFIG)). Headers keep their include paths:
# <ctess/...> for the constexpr layer, <ctess/runtime/...> and <ctess/runtime.hpp> for the runtime.
include(CMakePackageConfigHelpers)

set(CTESS_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/ctess)
set(CTESS_INSTALL_SHADERDIR ${CMAKE_INSTALL_DATADIR}/ctess/shaders)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/constexpr/ctess ${PROJECT_SOURCE_DIR}/runtime/include/ctess
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
install(TARGETS ctess_constexpr ctess_runtime_core ctess_uniform_core ctess_runtime_64 ctess_runtime_256 ctess_uniform_runtime_11
                ctess_uniform_runtime_16 ctess_uniform_runtime ctess_runtime
        EXPORT ctessTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(CTESS_HAVE_MODELS)
  install(TARGETS ctess_models EXPORT ctessTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
if(CTESS_HAVE_VULKAN)
  install(TARGETS ctess_vulkan EXPORT ctessTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
install(EXPORT ctessTargets NAMESPACE ctess:: DESTINATION ${CTESS_INSTALL_CMAKEDIR})

# The `ctess` CLI (docs/cli.md) and the viewer it serves; `ctess serve` looks for the viewer and the shaders
# beside its own prefix (../share/ctess) before the build tree's.
if(TARGET ctess)
  install(TARGETS ctess RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/viewer/ DESTINATION ${CMAKE_INSTALL_DATADIR}/ctess/viewer)
endif()

if(CTESS_BUILD_SHADERS)
  install(FILES ${CTESS_GENERATED_SHADERS} DESTINATION ${CTESS_INSTALL_SHADERDIR})
endif()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ctessConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/ctessConfig.cmake
                              INSTALL_DESTINATION ${CTESS_INSTALL_CMAKEDIR}
                              PATH_VARS CTESS_INSTALL_SHADERDIR)
# 0.x: a minor version may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ctessConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ctessConfig.cmake ${PROJECT_BINARY_DIR}/ctessConfigVersion.cmake
        DESTINATION ${CTESS_INSTALL_CMAKEDIR})
