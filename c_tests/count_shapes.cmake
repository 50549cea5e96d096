# Fails when a count in halfwing.h breaks the rule of its shape (docs/vocabulary.md):
#
# - `hw_<object>_n_<what>` is a count the object stores: `size_t hw_<object>_n_<what>(const
#   hw_<object> *<object>);`, no other argument, nothing to fail (a NULL object gives 0).
# - `hw_<object>_count_<what>` is a count that is computed or can fail (it allocates, or takes an
#   argument that can be invalid): `hw_status hw_<object>_count_<what>(const hw_<object>
#   *<object>, ..., size_t *out_count);`.
#
# HEADER is the generated C header.
file(READ "${HEADER}" header)
# Declarations only: the comments name functions too.
string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" "" header "${header}")
string(REGEX REPLACE "//[^\n]*" "" header "${header}")
# One declaration per match (return type, name, arguments; its lines joined below), without the
# closing semicolon, which would split the CMake list.
string(REGEX MATCHALL "[a-z_0-9]+ \\*?hw_[a-z_0-9]+\\([^;{]*\\)" declarations "${header}")

set(broken "")
set(n_stored 0)
set(n_computed 0)
foreach(declaration IN LISTS declarations)
  string(REGEX REPLACE "[ \n]+" " " declaration "${declaration}")
  string(REGEX MATCH "hw_[a-z_0-9]+\\(" name "${declaration}")
  string(REGEX REPLACE "\\($" "" name "${name}")
  if(name MATCHES "^hw_([a-z0-9_]+)_n_[a-z0-9_]+$")
    math(EXPR n_stored "${n_stored} + 1")
    set(object "${CMAKE_MATCH_1}")
    if(NOT declaration MATCHES "^size_t ${name}\\(const hw_${object} \\*[a-z_]+\\)$")
      list(APPEND broken "${name}: a stored count is `size_t ${name}(const hw_${object} *)`, not `${declaration}`")
    endif()
  elseif(name MATCHES "^hw_([a-z0-9_]+)_count_[a-z0-9_]+$")
    math(EXPR n_computed "${n_computed} + 1")
    set(object "${CMAKE_MATCH_1}")
    if(NOT declaration MATCHES "^hw_status ${name}\\(const hw_${object} \\*[a-z_]+,( [^,]+,)* size_t \\*out_count\\)$")
      list(APPEND broken "${name}: a computed count is `hw_status ${name}(const hw_${object} *, ..., size_t *out_count)`, not `${declaration}`")
    endif()
  elseif(declaration MATCHES "size_t \\*out_count\\)")
    list(APPEND broken "${name}: a count returned through `out_count` is named hw_<object>_count_<what>")
  endif()
endforeach()
if(n_stored EQUAL 0)
  message(FATAL_ERROR "no hw_*_n_* declarations found in ${HEADER}: the pattern no longer reads it")
endif()
if(broken)
  list(JOIN broken "\n  " report)
  message(FATAL_ERROR "counts in the wrong shape:\n  ${report}")
endif()
message(STATUS "${n_stored} stored counts and ${n_computed} computed counts in their shapes")
