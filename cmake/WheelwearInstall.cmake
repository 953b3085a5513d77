include(CMakePackageConfigHelpers)

# wheelwear::wheelwear: every library of the project, for consumers that want all of them.
# (The plain name wheelwear is the command-line tool's.)
get_property(wheelwear_modules GLOBAL PROPERTY WHEELWEAR_MODULES)
add_library(wheelwear_all INTERFACE)
add_library(wheelwear::wheelwear ALIAS wheelwear_all)
set_target_properties(wheelwear_all PROPERTIES EXPORT_NAME wheelwear)
target_link_libraries(wheelwear_all INTERFACE ${wheelwear_modules})
install(TARGETS wheelwear_all EXPORT wheelwearTargets)

set(wheelwear_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/wheelwear)
install(EXPORT wheelwearTargets NAMESPACE wheelwear:: DESTINATION ${wheelwear_cmake_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/wheelwearConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/wheelwearConfig.cmake INSTALL_DESTINATION ${wheelwear_cmake_dir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/wheelwearConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/wheelwearConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/wheelwearConfigVersion.cmake
        DESTINATION ${wheelwear_cmake_dir})
# Fixed share/wheelwear rather than CMAKE_INSTALL_DATADIR: the tool looks for its data at
# <prefix>/share/wheelwear relative to its own location.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION share/wheelwear)
