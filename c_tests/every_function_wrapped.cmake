# Fails when a function declared in halfwing.h (or defined inline in halfwing_nav.h) has no C++
# counterpart in halfwing.hpp and is not listed below as an exception with its reason, or when a
# constant of a C enumeration is not the value of a scoped enumeration there.
#
# A counterpart is recognised by the C function's name appearing in halfwing.hpp's code, comments
# left out, as a whole identifier: the wrapper calls the function (hw_mesh_split_face(...)) or
# hands it over (hw_mesh_free as an owner's release function, hw_nav_circ_next_vertex as a
# range's step). The wrapper's naming rule (the C name minus its prefix, same argument order and
# defaults) is stated at the top of halfwing.hpp. HEADERS lists the C headers, HPP the wrapper.
set(exceptions
  # The checked circulator steps and their callback walk: C++ walks with the ranges
  # (hw::mesh::outgoing(), vertices_of(), ...), whose start checks the id with hw_circ_around_*
  # and whose steps are the inline hw_nav_circ_next_* of halfwing_nav.h, in the same order.
  hw_circ_next_halfedge "the ranges step with hw_nav_circ_next_halfedge"
  hw_circ_next_vertex "the ranges step with hw_nav_circ_next_vertex"
  hw_circ_next_edge "the ranges step with hw_nav_circ_next_edge"
  hw_circ_next_face "the ranges step with hw_nav_circ_next_face"
  hw_circ_visit "C's callback form of a circulation; C++ iterates a range with a for loop"
)

set(header "")
foreach(path IN LISTS HEADERS)
  file(READ "${path}" text)
  string(APPEND header "${text}")
endforeach()
# Declarations only: the comments name functions too.
string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" "" header "${header}")
string(REGEX REPLACE "//[^\n]*" "" header "${header}")
# Every function the code of the headers names: the declarations, and in halfwing_nav.h the
# inline definitions (which call each other).
string(REGEX MATCHALL "hw_[a-z_0-9]+\\(" declarations "${header}")
list(REMOVE_DUPLICATES declarations)

file(READ "${HPP}" wrapper)
string(REGEX REPLACE "//[^\n]*" "" wrapper "${wrapper}")
string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" "" wrapper "${wrapper}")

set(excepted "")
list(LENGTH exceptions n_entries)
math(EXPR last "${n_entries} - 1")
foreach(i RANGE 0 ${last} 2)
  list(GET exceptions ${i} name)
  list(APPEND excepted "${name}")
endforeach()

set(missing "")
set(stale "")
set(count 0)
foreach(declaration IN LISTS declarations)
  string(REGEX REPLACE "\\($" "" name "${declaration}")
  math(EXPR count "${count} + 1")
  # A whole identifier: not followed by another identifier character.
  string(REGEX MATCH "${name}([^a-z_0-9]|$)" used "${wrapper}")
  list(FIND excepted "${name}" at)
  if(NOT used AND at EQUAL -1)
    list(APPEND missing "${name}")
  elseif(used AND NOT at EQUAL -1)
    list(APPEND stale "${name}")
  endif()
endforeach()
if(stale)
  message(FATAL_ERROR "listed as exceptions but wrapped: ${stale}; remove them from the list")
endif()
if(missing)
  list(LENGTH missing n_missing)
  message(FATAL_ERROR "${n_missing} C functions have no C++ counterpart in halfwing.hpp: ${missing}")
endif()

# Every constant of a C enumeration is a value of a scoped enumeration of halfwing.hpp. Left out:
# the limits and version numbers (plain numbers, used as they are), and each family's _FIRST and
# _COUNT (bounds of C loops; C++ loops over the scoped values).
set(plain_constants HW_MAX_MESSAGE_SIZE HW_FREED_ADDRESSES_KEPT HW_MAX_THREAD_COUNT
  HW_VERSION_MAJOR HW_VERSION_MINOR HW_VERSION_PATCH HW_VERSION_NUMBER)
string(REGEX MATCHALL "#define HW_[A-Z0-9_]+" defines "${header}")
set(unscoped "")
foreach(define IN LISTS defines)
  string(REGEX REPLACE "^#define " "" name "${define}")
  list(FIND plain_constants "${name}" at)
  if(NOT at EQUAL -1 OR name MATCHES "_(FIRST|COUNT)$")
    continue()
  endif()
  string(REGEX MATCH "${name}([^A-Z_0-9]|$)" used "${wrapper}")
  if(NOT used)
    list(APPEND unscoped "${name}")
  endif()
endforeach()
if(unscoped)
  message(FATAL_ERROR "C constants with no scoped enumeration value in halfwing.hpp: ${unscoped}")
endif()
message(STATUS "all ${count} functions of the headers have a C++ counterpart or a listed reason")
