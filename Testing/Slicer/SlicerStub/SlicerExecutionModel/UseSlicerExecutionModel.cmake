# Stub of SlicerExecutionModel's use file: a recording SEMMacroBuildCLI.
include(${CMAKE_CURRENT_LIST_DIR}/../SlicerStubSupport.cmake)

# SEMMacroBuildCLI with SEM's keywords. Like the real macro it creates the targets <NAME>Lib and
# <NAME> (excluded from all: this build tree is only configured), so the rest of the project can
# refer to them; it fails when a source, the XML or an include directory is missing, or when a
# TARGET_LIBRARIES entry is neither a target nor an existing file.
function(SEMMacroBuildCLI)
  cmake_parse_arguments(MY "EXECUTABLE_ONLY;NO_INSTALL;VERBOSE;DISABLE_DEFAULT_CXX_FILE"
    "NAME;LOGO_HEADER;FOLDER;CLI_XML_FILE;CLI_LIBRARY_WRAPPER_CXX;RUNTIME_OUTPUT_DIRECTORY;LIBRARY_OUTPUT_DIRECTORY;ARCHIVE_OUTPUT_DIRECTORY;INSTALL_RUNTIME_DESTINATION;INSTALL_LIBRARY_DESTINATION;INSTALL_ARCHIVE_DESTINATION"
    "ADDITIONAL_SRCS;TARGET_LIBRARIES;LINK_DIRECTORIES;INCLUDE_DIRECTORIES" ${ARGN})
  sgp_stub_require_arguments(SEMMacroBuildCLI MY NAME)
  set(sources ${MY_ADDITIONAL_SRCS})
  if(NOT MY_DISABLE_DEFAULT_CXX_FILE)
    list(PREPEND sources ${MY_NAME}.cxx)
  endif()
  set(xml ${MY_NAME}.xml)
  if(MY_CLI_XML_FILE)
    set(xml ${MY_CLI_XML_FILE})
  endif()
  sgp_stub_require_files("SEMMacroBuildCLI(${MY_NAME})" ${sources} ${xml} ${MY_LOGO_HEADER})
  foreach(dir IN LISTS MY_INCLUDE_DIRECTORIES)
    if(NOT IS_DIRECTORY "${dir}")
      message(FATAL_ERROR "Slicer stub: SEMMacroBuildCLI(${MY_NAME}) includes ${dir}, which is not a directory.")
    endif()
  endforeach()
  foreach(library IN LISTS MY_TARGET_LIBRARIES)
    if(NOT TARGET ${library} AND NOT EXISTS "${library}" AND NOT library MATCHES "^(debug|optimized|general)$")
      message(FATAL_ERROR "Slicer stub: SEMMacroBuildCLI(${MY_NAME}) links ${library}, which is neither a target nor a file.")
    endif()
  endforeach()
  add_library(${MY_NAME}Lib STATIC EXCLUDE_FROM_ALL ${sources})
  target_link_libraries(${MY_NAME}Lib PUBLIC ${MY_TARGET_LIBRARIES})
  target_include_directories(${MY_NAME}Lib PUBLIC ${MY_INCLUDE_DIRECTORIES})
  add_executable(${MY_NAME} EXCLUDE_FROM_ALL ${sources})
  target_link_libraries(${MY_NAME} PRIVATE ${MY_TARGET_LIBRARIES})
  sgp_stub_record("SEMMacroBuildCLI ${MY_NAME} XML ${xml} LIBRARIES ${MY_TARGET_LIBRARIES}")
endfunction()
