# SPDX-License-Identifier: Apache-2.0
# Installs bin/texsyn, libtexsyn, its headers, a CMake package so that a downstream
# project can find_package(texsyn) and link texsyn::texsyn, and a pkg-config file
# (pkg-config --cflags --libs texsyn) for other build systems.
include(CMakePackageConfigHelpers)

install(TARGETS texsyn EXPORT texsynTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY core/include/texsyn DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        PATTERN "*.in" EXCLUDE)
install(FILES ${CMAKE_BINARY_DIR}/core/include/texsyn/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/texsyn)

set(_cfgdir ${CMAKE_INSTALL_LIBDIR}/cmake/texsyn)
install(EXPORT texsynTargets NAMESPACE texsyn:: DESTINATION ${_cfgdir})
configure_package_config_file(cmake/texsynConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/texsynConfig.cmake INSTALL_DESTINATION ${_cfgdir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/texsynConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/texsynConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/texsynConfigVersion.cmake
        DESTINATION ${_cfgdir})
file(RELATIVE_PATH TEXSYN_PC_TO_PREFIX "/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/")
string(REGEX REPLACE "/$" "" TEXSYN_PC_TO_PREFIX "${TEXSYN_PC_TO_PREFIX}")
configure_file(cmake/texsyn.pc.in ${CMAKE_CURRENT_BINARY_DIR}/texsyn.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/texsyn.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
install(FILES LICENSE README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
