# Compiles and runs the consumer with the README's command line:
#   cc app.c $(pkg-config --cflags --libs halfwing) -Wl,-rpath,$(pkg-config --variable=libdir halfwing)
# (the rpath lets the program find the shared library outside the loader's default folders).
file(MAKE_DIRECTORY "${WORK}")
set(ENV{PKG_CONFIG_PATH} "${PREFIX}/${LIBDIR}/pkgconfig")
execute_process(COMMAND "${PKG_CONFIG}" --cflags --libs halfwing
                OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "pkg-config does not find halfwing in ${PREFIX}")
endif()
execute_process(COMMAND "${PKG_CONFIG}" --variable=libdir halfwing
                OUTPUT_VARIABLE libdir OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE result)
if(NOT result EQUAL 0 OR libdir STREQUAL "")
  message(FATAL_ERROR "pkg-config gives no libdir for halfwing")
endif()
message(STATUS "pkg-config --cflags --libs halfwing: ${flags}; libdir: ${libdir}")
separate_arguments(flags UNIX_COMMAND "${flags}")
execute_process(COMMAND "${CC}" -std=c11 -Wall -Wextra -Werror "${SOURCE}" ${flags}
                        "-Wl,-rpath,${libdir}" -o "${WORK}/consumer"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "compiling the consumer with pkg-config flags failed")
endif()
execute_process(COMMAND "${WORK}/consumer" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the pkg-config consumer failed")
endif()
