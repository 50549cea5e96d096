# Installs the package into a prefix inside the build tree, then builds and runs a consumer
# project outside the tree against it: with find_package (shared and static) and with pkg-config.

set(HALFWING_TEST_PREFIX "${CMAKE_BINARY_DIR}/consumer-prefix")
set(_consumer_src "${CMAKE_CURRENT_LIST_DIR}")

add_test(NAME consumer_install
  COMMAND "${CMAKE_COMMAND}" --install "${CMAKE_BINARY_DIR}" --prefix "${HALFWING_TEST_PREFIX}")
set_tests_properties(consumer_install PROPERTIES FIXTURES_SETUP halfwing_installed)

foreach(kind shared static)
  if(kind STREQUAL "static")
    set(_use_static ON)
  else()
    set(_use_static OFF)
  endif()
  add_test(NAME consumer_find_package_${kind}
    COMMAND "${CMAKE_CTEST_COMMAND}" --build-and-test "${_consumer_src}"
            "${CMAKE_BINARY_DIR}/consumer-${kind}"
            --build-generator "${CMAKE_GENERATOR}"
            --build-options "-DCMAKE_PREFIX_PATH=${HALFWING_TEST_PREFIX}"
                            "-DHALFWING_USE_STATIC=${_use_static}"
                            "-DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}"
            --test-command "${CMAKE_CTEST_COMMAND}" --output-on-failure)
  set_tests_properties(consumer_find_package_${kind} PROPERTIES
    FIXTURES_REQUIRED halfwing_installed)
endforeach()

find_program(PKG_CONFIG_EXECUTABLE pkg-config REQUIRED)
add_test(NAME consumer_pkg_config
  COMMAND "${CMAKE_COMMAND}"
          -DPKG_CONFIG=${PKG_CONFIG_EXECUTABLE} -DCC=${CMAKE_C_COMPILER}
          -DPREFIX=${HALFWING_TEST_PREFIX} -DLIBDIR=${CMAKE_INSTALL_LIBDIR}
          -DSOURCE=${_consumer_src}/main.c -DWORK=${CMAKE_BINARY_DIR}/consumer-pkg-config
          -P "${_consumer_src}/pkg_config_consumer.cmake")
set_tests_properties(consumer_pkg_config PROPERTIES FIXTURES_REQUIRED halfwing_installed)

# The examples (C, C++ and, with GLFW, the OpenGL programs) build on their own against the
# installed package too, and their tests pass there.
add_test(NAME consumer_examples
  COMMAND "${CMAKE_CTEST_COMMAND}" --build-and-test "${PROJECT_SOURCE_DIR}/examples"
          "${CMAKE_BINARY_DIR}/consumer-examples"
          --build-generator "${CMAKE_GENERATOR}"
          --build-options "-DCMAKE_PREFIX_PATH=${HALFWING_TEST_PREFIX}"
                          "-DHALFWING_DATA_DIR=${HALFWING_DATA_DIR}"
                          "-DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}"
                          "-DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}"
          --test-command "${CMAKE_CTEST_COMMAND}" --output-on-failure)
set_tests_properties(consumer_examples PROPERTIES FIXTURES_REQUIRED halfwing_installed)

# The installed libraries carry no debug info unless HALFWING_INSTALL_DEBUG_INFO asks for it.
set(_prefix_libdir "${HALFWING_TEST_PREFIX}/${CMAKE_INSTALL_LIBDIR}")
find_program(READELF_EXECUTABLE readelf REQUIRED)
add_test(NAME consumer_debug_info
  COMMAND "${CMAKE_COMMAND}" -DREADELF=${READELF_EXECUTABLE}
          -DEXPECT_DEBUG_INFO=${HALFWING_INSTALL_DEBUG_INFO}
          "-DLIBRARIES=${_prefix_libdir}/${HALFWING_SHARED_FILE}|${_prefix_libdir}/libhalfwing.a"
          -P "${_consumer_src}/debug_info.cmake")
set_tests_properties(consumer_debug_info PROPERTIES FIXTURES_REQUIRED halfwing_installed)

# The installed viewer (built when GLFW and OpenGL are found) runs from the prefix: it finds the
# library through its rpath, prints its help, and headless, opens the installed copy of the
# bundled model (the capsule's boundary loops in magenta, as in the examples' screenshot test).
if(TARGET halfwing_viewer)
  set(_installed_viewer "${HALFWING_TEST_PREFIX}/${CMAKE_INSTALL_BINDIR}/halfwing_viewer")
  add_test(NAME consumer_viewer_help COMMAND "${_installed_viewer}" --help)
  set_tests_properties(consumer_viewer_help PROPERTIES FIXTURES_REQUIRED halfwing_installed
    PASS_REGULAR_EXPRESSION "usage: [^\n]*halfwing_viewer.*--screenshot out.png  render")
  add_test(NAME consumer_viewer_model
    COMMAND "${CMAKE_COMMAND}" -E compare_files "${PROJECT_SOURCE_DIR}/examples/data/hole_capsule.off"
            "${HALFWING_TEST_PREFIX}/${CMAKE_INSTALL_DATADIR}/halfwing/hole_capsule.off")
  set_tests_properties(consumer_viewer_model PROPERTIES FIXTURES_REQUIRED halfwing_installed)
  if(TARGET png_content_check)
    set(_png "${CMAKE_BINARY_DIR}/consumer-viewer.png")
    add_test(NAME consumer_viewer_screenshot
      COMMAND ${XVFB_RUN} -a -s "-screen 0 1024x768x24" "${_installed_viewer}" --screenshot "${_png}")
    set_tests_properties(consumer_viewer_screenshot PROPERTIES
      FIXTURES_REQUIRED halfwing_installed FIXTURES_SETUP consumer_viewer_png)
    add_test(NAME consumer_viewer_png_content
      COMMAND png_content_check "${_png}" --min-content 0.10 --color 255,0,255 --min-color-pixels 500)
    set_tests_properties(consumer_viewer_png_content PROPERTIES FIXTURES_REQUIRED consumer_viewer_png)
  endif()
endif()
