# Installs the libraries, headers, CMake package (HalfwingConfig.cmake, HalfwingConfigVersion.cmake)
# and pkg-config file (halfwing.pc).

include(CMakePackageConfigHelpers)

set(HALFWING_SHARED_FILE "libhalfwing.so.${PROJECT_VERSION}")
set(HALFWING_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/Halfwing")

# libhalfwing.so -> libhalfwing.so.<soversion> -> libhalfwing.so.<version>, as distributions lay
# out shared libraries. The links are made in the build tree and installed as links.
set(_links "${CMAKE_CURRENT_BINARY_DIR}/install-links")
file(MAKE_DIRECTORY "${_links}")
file(CREATE_LINK "${HALFWING_SHARED_FILE}" "${_links}/${HALFWING_SONAME}" SYMBOLIC)
file(CREATE_LINK "${HALFWING_SONAME}" "${_links}/libhalfwing.so" SYMBOLIC)

install(FILES "${HALFWING_SHARED_LIB}" RENAME "${HALFWING_SHARED_FILE}"
        PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE
        DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(FILES "${_links}/${HALFWING_SONAME}" "${_links}/libhalfwing.so"
        DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(FILES "${HALFWING_STATIC_LIB}" DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(FILES include/halfwing.h include/halfwing_nav.h include/halfwing.hpp DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")

string(REPLACE ";" " -l" HALFWING_PC_LIBS_PRIVATE "-l${HALFWING_STATIC_DEPS}")
configure_package_config_file(cmake/HalfwingConfig.cmake.in
  "${CMAKE_CURRENT_BINARY_DIR}/HalfwingConfig.cmake"
  INSTALL_DESTINATION "${HALFWING_CMAKE_DIR}"
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_LIBDIR)
# The C ABI changes with the minor version while at 0.x.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(_compat SameMinorVersion)
else()
  set(_compat SameMajorVersion)
endif()
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/HalfwingConfigVersion.cmake"
  COMPATIBILITY ${_compat})
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/HalfwingConfig.cmake"
              "${CMAKE_CURRENT_BINARY_DIR}/HalfwingConfigVersion.cmake"
        DESTINATION "${HALFWING_CMAKE_DIR}")

# The .pc file finds its prefix relative to itself, so the installed tree can be moved (and
# `cmake --install --prefix` works).
file(RELATIVE_PATH HALFWING_PC_PREFIX_FROM_PCFILEDIR
     "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
configure_file(cmake/halfwing.pc.in "${CMAKE_CURRENT_BINARY_DIR}/halfwing.pc" @ONLY)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/halfwing.pc"
        DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
