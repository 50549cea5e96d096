# Compiles and runs the consumer with nothing but `pkg-config --cflags --libs halfwing`.
file(MAKE_DIRECTORY "${WORK}")
set(ENV{PKG_CONFIG_PATH} "${PREFIX}/${LIBDIR}/pkgconfig")
execute_process(COMMAND "${PKG_CONFIG}" --cflags --libs halfwing
                OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "pkg-config does not find halfwing in ${PREFIX}")
endif()
message(STATUS "pkg-config --cflags --libs halfwing: ${flags}")
separate_arguments(flags UNIX_COMMAND "${flags}")
execute_process(COMMAND "${CC}" -std=c11 -Wall -Wextra -Werror "${SOURCE}" ${flags}
                        "-Wl,-rpath,${PREFIX}/${LIBDIR}" -o "${WORK}/consumer"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "compiling the consumer with pkg-config flags failed")
endif()
execute_process(COMMAND "${WORK}/consumer" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the pkg-config consumer failed")
endif()
