include(CMakePackageConfigHelpers)
install(EXPORT wheelwearTargets NAMESPACE wheelwear:: DESTINATION lib/cmake/wheelwear)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/wheelwearConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/wheelwearConfig.cmake INSTALL_DESTINATION lib/cmake/wheelwear)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/wheelwearConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/wheelwearConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/wheelwearConfigVersion.cmake DESTINATION lib/cmake/wheelwear)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION share/wheelwear)
