# cmake --install: the public headers, both libraries, the CLI, the CMake package
# (find_package(ncoffset): ncoffset::ncoffset static, ncoffset::ncoffset_shared) and ncoffset.pc.
include(CMakePackageConfigHelpers)

set(NCOFFSET_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ncoffset)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/ncoffset
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_BINARY_DIR}/include/ncoffset/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ncoffset)

set(NCOFFSET_INSTALL_TARGETS ncoffset)
if(TARGET ncoffset_shared)
  list(APPEND NCOFFSET_INSTALL_TARGETS ncoffset_shared)
endif()
install(TARGETS ${NCOFFSET_INSTALL_TARGETS} EXPORT ncoffsetTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET ncoffset_cli)
  install(TARGETS ncoffset_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(EXPORT ncoffsetTargets NAMESPACE ncoffset:: DESTINATION ${NCOFFSET_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ncoffsetConfig.cmake.in
  ${PROJECT_BINARY_DIR}/ncoffsetConfig.cmake INSTALL_DESTINATION ${NCOFFSET_CMAKE_DIR})
# Before 1.0 only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ncoffsetConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ncoffsetConfig.cmake
              ${PROJECT_BINARY_DIR}/ncoffsetConfigVersion.cmake
        DESTINATION ${NCOFFSET_CMAKE_DIR})

# pkg-config: the prefix relative to the .pc file, so that the package can be installed
# anywhere (cmake --install --prefix DIR).
set(NCOFFSET_PC_DIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
file(RELATIVE_PATH NCOFFSET_PC_TO_PREFIX /prefix/${NCOFFSET_PC_DIR} /prefix)
string(REGEX REPLACE "/$" "" NCOFFSET_PC_TO_PREFIX "${NCOFFSET_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/ncoffset.pc.in ${PROJECT_BINARY_DIR}/ncoffset.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/ncoffset.pc DESTINATION ${NCOFFSET_PC_DIR})
