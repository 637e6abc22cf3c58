# `cmake --install <build> --prefix P`: the engine and model libraries, their headers, the command
# line and the CMake package gamephysicsConfig.cmake, so that a project outside this tree does
# find_package(gamephysics) and links gamephysics::gamephysics. The headers go under
# include/gamephysics/, which is their include root, so that their folders (engine/, gamephysics/)
# do not land in the prefix's include/ itself. The scene library (src/scene) comes with them: the
# engine's headers include it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GP_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/gamephysics)
set(GP_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/gamephysics)

set_target_properties(gamephysics_models PROPERTIES EXPORT_NAME models)
set_target_properties(gamephysics_scene PROPERTIES EXPORT_NAME scene)
install(TARGETS gamephysics gamephysics_scene gamephysics_models EXPORT gamephysicsTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${GP_INSTALL_INCLUDEDIR})
install(TARGETS gamephysics_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Of the engine, only the public API (tests/api/public_headers.txt lists the same headers).
file(STRINGS ${PROJECT_SOURCE_DIR}/tests/api/public_headers.txt GP_PUBLIC_ENGINE_HEADERS)
list(TRANSFORM GP_PUBLIC_ENGINE_HEADERS PREPEND ${PROJECT_SOURCE_DIR}/src/)
install(FILES ${GP_PUBLIC_ENGINE_HEADERS} DESTINATION ${GP_INSTALL_INCLUDEDIR}/engine)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/scene ${PROJECT_SOURCE_DIR}/src/gamephysics
                  ${PROJECT_SOURCE_DIR}/models/include/gamephysics
        DESTINATION ${GP_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")

install(EXPORT gamephysicsTargets NAMESPACE gamephysics:: DESTINATION ${GP_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/gamephysicsConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/gamephysicsConfig.cmake
                              INSTALL_DESTINATION ${GP_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/gamephysicsConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/gamephysicsConfig.cmake
              ${PROJECT_BINARY_DIR}/gamephysicsConfigVersion.cmake
        DESTINATION ${GP_INSTALL_CMAKEDIR})
