# SPDX-License-Identifier: Apache-2.0
# Installs bin/texsyn, libtexsyn, its headers, and a CMake package so that a downstream
# project can find_package(texsyn) and link texsyn::texsyn.
include(CMakePackageConfigHelpers)

install(TARGETS texsyn EXPORT texsynTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY core/include/texsyn DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

set(_cfgdir ${CMAKE_INSTALL_LIBDIR}/cmake/texsyn)
install(EXPORT texsynTargets NAMESPACE texsyn:: DESTINATION ${_cfgdir})
configure_package_config_file(cmake/texsynConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/texsynConfig.cmake INSTALL_DESTINATION ${_cfgdir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/texsynConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/texsynConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/texsynConfigVersion.cmake
        DESTINATION ${_cfgdir})
install(FILES LICENSE README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
