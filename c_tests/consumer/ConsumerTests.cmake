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
                          "-DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}"
                          "-DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}"
          --test-command "${CMAKE_CTEST_COMMAND}" --output-on-failure)
set_tests_properties(consumer_examples PROPERTIES FIXTURES_REQUIRED halfwing_installed)
