# `cmake --install`: the libraries, the matc program, the public headers, and the CMake package
# (find_package(matc CONFIG) + matc_add_materials) that examples/engine builds against.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set_target_properties(matc_compiler PROPERTIES EXPORT_NAME matc)
set_target_properties(matc_runtime PROPERTIES EXPORT_NAME runtime)
set_target_properties(matc_vulkan PROPERTIES EXPORT_NAME vulkan)
set_target_properties(matc_validate PROPERTIES EXPORT_NAME validate)
set_target_properties(matc PROPERTIES EXPORT_NAME cli)
target_include_directories(matc_compiler PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)

install(TARGETS matc_compiler matc_runtime matc_vulkan matc_validate matc
        EXPORT matcTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/compiler/include/matc ${PROJECT_SOURCE_DIR}/runtime/include/matc
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} PATTERN "*.in" EXCLUDE)
install(FILES ${PROJECT_BINARY_DIR}/compiler/include/matc/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/matc)

set(_matc_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/matc)
install(EXPORT matcTargets NAMESPACE matc:: DESTINATION ${_matc_package_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/matcConfig.cmake.in
  ${PROJECT_BINARY_DIR}/matcConfig.cmake INSTALL_DESTINATION ${_matc_package_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/matcConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/matcConfig.cmake ${PROJECT_BINARY_DIR}/matcConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/MatcAddMaterials.cmake
              ${PROJECT_SOURCE_DIR}/cmake/MatcOutputLayout.cmake
              ${PROJECT_SOURCE_DIR}/cmake/MatcAddBakedTextures.cmake
        DESTINATION ${_matc_package_dir})
