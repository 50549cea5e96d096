# Builds the Rust crate with cargo and exposes it as the imported targets Halfwing::shared and
# Halfwing::static (and Halfwing::halfwing, following BUILD_SHARED_LIBS), the same names the
# installed HalfwingConfig.cmake gives consumers. The same cargo step builds the `halfwing`
# command-line tool (HALFWING_CLI), a binary of the crate.
#
# Cargo does its own dependency tracking, so the cargo step always runs and is a no-op when
# nothing changed. No network beyond the crates.io registry is used.

find_program(CARGO_EXECUTABLE cargo HINTS "$ENV{HOME}/.cargo/bin" REQUIRED)

if(CMAKE_BUILD_TYPE STREQUAL "Debug")
  set(HALFWING_CARGO_PROFILE_FLAG "")
  set(HALFWING_CARGO_PROFILE_DIR debug)
else()
  set(HALFWING_CARGO_PROFILE_FLAG --release)
  set(HALFWING_CARGO_PROFILE_DIR release)
endif()

set(HALFWING_CARGO_TARGET_DIR "${CMAKE_BINARY_DIR}/cargo")
set(HALFWING_LIB_DIR "${HALFWING_CARGO_TARGET_DIR}/${HALFWING_CARGO_PROFILE_DIR}")
set(HALFWING_SHARED_LIB "${HALFWING_LIB_DIR}/libhalfwing.so")
set(HALFWING_STATIC_LIB "${HALFWING_LIB_DIR}/libhalfwing.a")
set(HALFWING_CLI "${HALFWING_LIB_DIR}/halfwing")
# Same rule as build.rs: one ABI per major version, per minor version while at 0.x.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(HALFWING_SOVERSION "0.${PROJECT_VERSION_MINOR}")
else()
  set(HALFWING_SOVERSION "${PROJECT_VERSION_MAJOR}")
endif()
set(HALFWING_SONAME "libhalfwing.so.${HALFWING_SOVERSION}")

# What the Rust standard library needs when linked statically (`cargo rustc -- --print
# native-static-libs` on Linux/glibc).
set(HALFWING_STATIC_DEPS pthread dl m rt util gcc_s)

add_custom_target(halfwing_cargo ALL
  COMMAND "${CMAKE_COMMAND}" -E env CARGO_TARGET_DIR=${HALFWING_CARGO_TARGET_DIR}
          "${CARGO_EXECUTABLE}" build --lib --bin halfwing ${HALFWING_CARGO_PROFILE_FLAG}
          --manifest-path "${PROJECT_SOURCE_DIR}/Cargo.toml"
  # The loader looks the library up by its soname.
  COMMAND "${CMAKE_COMMAND}" -E create_symlink libhalfwing.so "${HALFWING_LIB_DIR}/${HALFWING_SONAME}"
  BYPRODUCTS "${HALFWING_SHARED_LIB}" "${HALFWING_STATIC_LIB}" "${HALFWING_CLI}"
  WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
  COMMENT "cargo build halfwing (${HALFWING_CARGO_PROFILE_DIR})"
  USES_TERMINAL
  VERBATIM)

add_library(Halfwing::shared SHARED IMPORTED GLOBAL)
set_target_properties(Halfwing::shared PROPERTIES
  IMPORTED_LOCATION "${HALFWING_SHARED_LIB}"
  IMPORTED_SONAME "${HALFWING_SONAME}"
  INTERFACE_INCLUDE_DIRECTORIES "${PROJECT_SOURCE_DIR}/include")
add_dependencies(Halfwing::shared halfwing_cargo)

add_library(Halfwing::static STATIC IMPORTED GLOBAL)
set_target_properties(Halfwing::static PROPERTIES
  IMPORTED_LOCATION "${HALFWING_STATIC_LIB}"
  INTERFACE_INCLUDE_DIRECTORIES "${PROJECT_SOURCE_DIR}/include"
  INTERFACE_LINK_LIBRARIES "${HALFWING_STATIC_DEPS}")
add_dependencies(Halfwing::static halfwing_cargo)

add_library(Halfwing::halfwing INTERFACE IMPORTED GLOBAL)
if(BUILD_SHARED_LIBS)
  set_target_properties(Halfwing::halfwing PROPERTIES INTERFACE_LINK_LIBRARIES Halfwing::shared)
else()
  set_target_properties(Halfwing::halfwing PROPERTIES INTERFACE_LINK_LIBRARIES Halfwing::static)
endif()
