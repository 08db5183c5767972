# highlift_raw_string_literal(<text> <delimiter> <out_var> [<what>])
#
# Sets <out_var> to C++ source for <text> as adjacent raw string literals R"<delimiter>(...)"
# of 8000 characters each (below the compilers' per-literal limits), or "" for an empty text.
# Stops with an error naming <what> when the text contains the literal's end ")<delimiter>"".
# Used by the -P scripts that embed files into libraries (the Modelica library, the database
# seed, the report's web assets).
function(highlift_raw_string_literal text delimiter out_var)
  set(what "${ARGV3}")
  string(FIND "${text}" ")${delimiter}\"" found)
  if(NOT found EQUAL -1)
    message(FATAL_ERROR "${what} contains the raw-string delimiter )${delimiter}\"")
  endif()
  string(LENGTH "${text}" length)
  set(pieces "")
  set(offset 0)
  while(offset LESS length)
    string(SUBSTRING "${text}" ${offset} 8000 piece)
    string(APPEND pieces "R\"${delimiter}(${piece})${delimiter}\"\n")
    math(EXPR offset "${offset} + 8000")
  endwhile()
  if(pieces STREQUAL "")
    set(pieces "\"\"")
  endif()
  set(${out_var} "${pieces}" PARENT_SCOPE)
endfunction()
