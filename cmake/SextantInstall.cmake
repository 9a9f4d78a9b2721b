# install() + exported SextantConfig.cmake so other projects can find_package(Sextant)
# and link Sextant::core, Sextant::matchers, ...
include(CMakePackageConfigHelpers)
set(SEXTANT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Sextant)
install(EXPORT SextantTargets NAMESPACE Sextant:: DESTINATION ${SEXTANT_CMAKE_DIR})
configure_package_config_file(cmake/SextantConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/SextantConfig.cmake INSTALL_DESTINATION ${SEXTANT_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/SextantConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/SextantConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/SextantConfigVersion.cmake
        DESTINATION ${SEXTANT_CMAKE_DIR})
