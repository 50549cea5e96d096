# Installs the libraries (stripped unless HALFWING_INSTALL_DEBUG_INFO is ON), headers, CMake
# package (HalfwingConfig.cmake, HalfwingConfigVersion.cmake), pkg-config file (halfwing.pc),
# licenses, changelog and the `halfwing` command-line tool. The viewer is installed by
# examples/CMakeLists.txt.

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
install(FILES include/halfwing.h include/halfwing_nav.h include/halfwing.hpp
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
install(PROGRAMS "${HALFWING_CLI}" DESTINATION "${CMAKE_INSTALL_BINDIR}")
install(FILES LICENSE-MIT LICENSE-APACHE CHANGELOG.md DESTINATION "${CMAKE_INSTALL_DOCDIR}")

# The release profile keeps line tables for the tests' backtraces (a ~20 MB shared library);
# users get the libraries without them unless they ask. Stripped where they were installed,
# so `cmake --install --prefix` and DESTDIR are honoured.
option(HALFWING_INSTALL_DEBUG_INFO "Install the libraries with their debug info (not stripped)" OFF)
if(NOT HALFWING_INSTALL_DEBUG_INFO)
  if(NOT CMAKE_STRIP)
    message(FATAL_ERROR "no strip program found: install one (binutils) or set "
                        "HALFWING_INSTALL_DEBUG_INFO=ON")
  endif()
  if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
    set(_installed_libdir "\$ENV{DESTDIR}${CMAKE_INSTALL_LIBDIR}")
  else()
    set(_installed_libdir "\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}")
  endif()
  # The shared library keeps the symbols it exports; the archive keeps every symbol a link needs.
  if(IS_ABSOLUTE "${CMAKE_INSTALL_BINDIR}")
    set(_installed_bindir "\$ENV{DESTDIR}${CMAKE_INSTALL_BINDIR}")
  else()
    set(_installed_bindir "\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}")
  endif()
  # The tool is linked statically against the crate: it needs no symbol table at all.
  foreach(_strip IN ITEMS "--strip-unneeded;${_installed_libdir}/${HALFWING_SHARED_FILE}"
                          "--strip-debug;${_installed_libdir}/libhalfwing.a"
                          "--strip-all;${_installed_bindir}/halfwing")
    list(GET _strip 0 _how)
    list(GET _strip 1 _file)
    install(CODE "
      execute_process(COMMAND \"${CMAKE_STRIP}\" ${_how} \"${_file}\"
                      RESULT_VARIABLE _halfwing_strip_status)
      if(NOT _halfwing_strip_status EQUAL 0)
        message(FATAL_ERROR \"${CMAKE_STRIP} ${_how} ${_file} failed\")
      endif()")
  endforeach()
endif()

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
