# Helpers shared by the stub's recording functions.

# Fail unless every path in ARGN exists, relative to the calling directory's source dir.
function(sgp_stub_require_files caller)
  foreach(path IN LISTS ARGN)
    if(IS_ABSOLUTE "${path}")
      set(full "${path}")
    else()
      set(full "${CMAKE_CURRENT_SOURCE_DIR}/${path}")
    endif()
    if(NOT EXISTS "${full}")
      message(FATAL_ERROR "Slicer stub: ${caller} names ${path}, which does not exist (looked for ${full}).")
    endif()
  endforeach()
endfunction()

# Fail when arguments were left unparsed (a misspelt keyword) or a required one is empty.
function(sgp_stub_require_arguments caller prefix)
  if(${prefix}_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "Slicer stub: ${caller} got unknown arguments: ${${prefix}_UNPARSED_ARGUMENTS}.")
  endif()
  foreach(name IN LISTS ARGN)
    if("${${prefix}_${name}}" STREQUAL "")
      message(FATAL_ERROR "Slicer stub: ${caller} needs ${name}.")
    endif()
  endforeach()
endfunction()

function(sgp_stub_record)
  if(DEFINED SGP_STUB_RECORD)
    string(JOIN " " line ${ARGN})
    file(APPEND ${SGP_STUB_RECORD} "${line}\n")
  endif()
endfunction()
