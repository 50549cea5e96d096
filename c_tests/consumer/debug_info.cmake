# Fails unless each of LIBRARIES ('|'-separated) has debug sections exactly when
# EXPECT_DEBUG_INFO is true (readelf -S lists the sections of a library, or of every member of
# an archive).
string(REPLACE "|" ";" LIBRARIES "${LIBRARIES}")
foreach(library IN LISTS LIBRARIES)
  execute_process(COMMAND "${READELF}" -S --wide "${library}"
                  OUTPUT_VARIABLE sections RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "readelf cannot read ${library}")
  endif()
  string(FIND "${sections}" " .debug_" debug_at)
  if(EXPECT_DEBUG_INFO AND debug_at EQUAL -1)
    message(FATAL_ERROR "${library} has no debug info, though HALFWING_INSTALL_DEBUG_INFO is ON")
  elseif(NOT EXPECT_DEBUG_INFO AND NOT debug_at EQUAL -1)
    message(FATAL_ERROR "${library} was installed with its debug info")
  endif()
  file(SIZE "${library}" size)
  message(STATUS "${library}: ${size} bytes")
endforeach()
