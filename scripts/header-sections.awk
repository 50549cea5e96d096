# Lays out cbindgen's output (scripts/gen-header.sh runs it; never edit the header by hand) so
# the header reads by topic. cbindgen writes every constant, then every type, then every
# function; this puts each type, with an enumeration's constants, at the head of the section of
# the first function that names it. A section is a run of functions of one Doxygen group
# (`\ingroup`), introduced by a banner with the group's title. A group split over two runs is
# refused: the module order in src/ffi is wrong.
#
# Declaration order is kept where it matters: a type goes no later than the section of the first
# function or type naming it, and types of one section keep cbindgen's dependency order.

function is_blank(s) { return s ~ /^[ \t]*$/ }

# Whether the code of `text` names `name` as a whole identifier.
function names(text, name) {
  return text ~ ("(^|[^A-Za-z0-9_])" name "([^A-Za-z0-9_]|$)")
}

# The code of block `b` (its lines after the doc comment).
function code_of(first, last,    i, in_doc, text) {
  text = ""
  in_doc = 0
  for (i = first; i <= last; i++) {
    if (line[i] ~ /^\/\*\*/) in_doc = 1
    if (!in_doc) text = text line[i] "\n"
    if (in_doc && line[i] ~ /\*\/[ \t]*$/) in_doc = 0
  }
  return text
}

function print_block(first, last,    i) {
  for (i = first; i <= last; i++) print line[i]
  print ""
}

function banner(title,    rule) {
  rule = "----------------------------------------------------------------------------------------------"
  print "/* " rule
  print " * " title
  print " * " rule " */"
  print ""
}

{ line[++n] = $0 }

END {
  # The regions: the preamble ends with the last #include, the functions sit in extern "C".
  for (i = 1; i <= n; i++) {
    if (line[i] ~ /^#ifdef __cplusplus/) {
      if (!open_at) open_at = i; else close_at = i
    }
    if (!open_at && line[i] ~ /^#include </) preamble_end = i
    if (match(line[i], /@defgroup [a-z_]+ /)) {
      group = substr(line[i], RSTART + 10, RLENGTH - 11)
      title[group] = substr(line[i], RSTART + RLENGTH)
    }
  }
  if (!preamble_end || !open_at || !close_at) {
    print "header-sections: unexpected cbindgen output" > "/dev/stderr"
    exit 1
  }

  # Blocks before extern "C": constants and types.
  n_blocks = 0
  i = preamble_end + 1
  while (i < open_at) {
    if (is_blank(line[i])) { i++; continue }
    first = i
    while (i < open_at && !is_blank(line[i])) i++
    b = ++n_blocks
    block_first[b] = first
    block_last[b] = i - 1
    code = code_of(first, i - 1)
    block_code[b] = code
    if (match(code, /#define HW_[A-Z0-9_]+/)) {
      block_kind[b] = "constant"
      block_name[b] = substr(code, RSTART + 8, RLENGTH - 8)
      if (!seen_type) top_constant[b] = 1
    } else {
      seen_type = 1
      if (code ~ /^typedef struct hw_[a-z0-9_]+ hw_[a-z0-9_]+;/) block_kind[b] = "opaque"
      else block_kind[b] = "type"
      if (match(code, /hw_[a-z0-9_]+;[ \t\n]*$/)) block_name[b] = substr(code, RSTART, RLENGTH)
      else if (match(code, /\(\*hw_[a-z0-9_]+\)/)) block_name[b] = substr(code, RSTART + 2, RLENGTH - 3)
      sub(/;.*/, "", block_name[b])
      if (code ~ /^typedef u?int[0-9]+_t hw_[a-z0-9_]+;/) is_enum[b] = 1
    }
  }

  # Functions, and their sections.
  n_functions = 0
  n_sections = 0
  i = open_at + 3
  while (i < close_at) {
    if (is_blank(line[i])) { i++; continue }
    first = i
    while (i < close_at && !is_blank(line[i])) i++
    f = ++n_functions
    function_first[f] = first
    function_last[f] = i - 1
    function_code[f] = code_of(first, i - 1)
    group = ""
    for (j = first; j < i; j++)
      if (match(line[j], /\\ingroup [a-z_]+/)) group = substr(line[j], RSTART + 9, RLENGTH - 9)
    if (n_sections == 0 || group != section_group[n_sections]) {
      if (group in section_of_group) {
        printf "header-sections: group `%s` is split (before %s); declare its modules together\n",
          group, function_code[f] > "/dev/stderr"
        exit 1
      }
      section_group[++n_sections] = group
      section_of_group[group] = n_sections
    }
    function_section[f] = n_sections
  }

  # A type's section: that of the first function naming it, or earlier when a type of an
  # earlier section names it. Later types are placed first so their sections are known.
  for (b = n_blocks; b >= 1; b--) {
    if (block_kind[b] != "type") continue
    s = n_sections + 1
    for (f = 1; f <= n_functions; f++)
      if (names(function_code[f], block_name[b])) { s = function_section[f]; break }
    for (u = b + 1; u <= n_blocks; u++)
      if (block_kind[u] == "type" && type_section[u] < s && names(block_code[u], block_name[b]))
        s = type_section[u]
    if (s > n_sections) s = 1
    type_section[b] = s
  }

  # An enumeration's constants carry its name (hw_normal_weighting: HW_NORMAL_WEIGHTING_*; the
  # status codes: HW_OK, HW_ERR_*); the longest matching name wins.
  for (c = 1; c <= n_blocks; c++) {
    if (block_kind[c] != "constant" || top_constant[c]) continue
    best = 0
    for (b = 1; b <= n_blocks; b++) {
      if (!is_enum[b]) continue
      prefix = toupper(block_name[b]) "_"
      fits = index(block_name[c], prefix) == 1
      if (block_name[b] == "hw_status")
        fits = block_name[c] == "HW_OK" || index(block_name[c], "HW_ERR_") == 1
      if (fits && (!best || length(block_name[b]) > length(block_name[best]))) best = b
    }
    if (!best) {
      printf "header-sections: constant %s belongs to no enumeration\n", block_name[c] > "/dev/stderr"
      exit 1
    }
    constant_of[c] = best
  }

  for (i = 1; i <= preamble_end; i++) print line[i]
  print ""
  for (b = 1; b <= n_blocks; b++) if (top_constant[b]) print_block(block_first[b], block_last[b])
  for (b = 1; b <= n_blocks; b++) if (block_kind[b] == "opaque") print_block(block_first[b], block_last[b])
  for (i = open_at; i < open_at + 3; i++) print line[i]
  print ""
  for (s = 1; s <= n_sections; s++) {
    group = section_group[s]
    banner(group in title ? title[group] : group)
    for (b = 1; b <= n_blocks; b++) {
      if (block_kind[b] != "type" || type_section[b] != s) continue
      print_block(block_first[b], block_last[b])
      for (c = 1; c <= n_blocks; c++) if (constant_of[c] == b) print_block(block_first[c], block_last[c])
    }
    for (f = 1; f <= n_functions; f++)
      if (function_section[f] == s) print_block(function_first[f], function_last[f])
  }
  for (i = close_at; i <= n; i++) print line[i]
}
