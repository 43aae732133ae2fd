# Stub of SlicerExecutionModel's use file: a SEMMacroBuildCLI that builds what SEM's builds, and
# records the call.
include(${CMAKE_CURRENT_LIST_DIR}/../SlicerStubSupport.cmake)

include_directories(BEFORE ${SlicerExecutionModel_INCLUDE_DIRS}) # as SEM's use file does

# SEMMacroBuildCLI with SEM's keywords, building the targets the way SEM's CMake/SEMMacroBuildCLI.cmake
# does (read at SEM 6e167626e417), unless EXECUTABLE_ONLY is given:
#   - <NAME>CLP.h generated from the XML into the current binary directory, which is added to the
#     include directories (GenerateCLP.py beside this file stands in for SEM's GenerateCLP);
#   - <NAME>Lib, a SHARED library of <NAME>.cxx and ADDITIONAL_SRCS compiled with -Dmain=ModuleEntryPoint,
#     linked with TARGET_LIBRARIES (plain target_link_libraries signature, as SEM uses). Its symbols
#     keep the default visibility: SEM hides them only when USE_COMPILER_HIDDEN_VISIBILITY is set,
#     which neither SEM, Slicer 5.8, ITK 5.2, VTK 9.1 nor CMake defines (kept here as SEM has it);
#     SEM's IPO block never runs either (it compares the policy setting NEW with EQUAL), so none;
#   - <NAME>, the launcher: SlicerExecutionModel_CLI_LIBRARY_WRAPPER_CXX linked with <NAME>Lib and
#     SlicerExecutionModel_EXTRA_EXECUTABLE_TARGET_LIBRARIES;
#   - both in Slicer's CLI folder of the build tree, with LABELS <NAME> and FOLDER
#     Module-<NAME> (SlicerExecutionModel_DEFAULT_CLI_TARGETS_FOLDER_PREFIX), and installed there;
#   - <NAME>.xml copied beside the launcher after each build (POST_BUILD, copy_if_different) and
#     installed beside it: Slicer reads that file, not --xml, when it finds one.
# With EXECUTABLE_ONLY: a STATIC <NAME>Lib compiled the same way, and the launcher with -DMODULE_STATIC.
# Beyond SEM it stops the configure when a source, the XML or an include directory is missing, or
# when a TARGET_LIBRARIES entry is neither a target nor an existing file.
function(SEMMacroBuildCLI)
  cmake_parse_arguments(MY "EXECUTABLE_ONLY;NO_INSTALL;VERBOSE;DISABLE_DEFAULT_CXX_FILE"
    "NAME;LOGO_HEADER;FOLDER;CLI_XML_FILE;CLI_LIBRARY_WRAPPER_CXX;RUNTIME_OUTPUT_DIRECTORY;LIBRARY_OUTPUT_DIRECTORY;ARCHIVE_OUTPUT_DIRECTORY;INSTALL_RUNTIME_DESTINATION;INSTALL_LIBRARY_DESTINATION;INSTALL_ARCHIVE_DESTINATION"
    "ADDITIONAL_SRCS;TARGET_LIBRARIES;LINK_DIRECTORIES;INCLUDE_DIRECTORIES" ${ARGN})
  sgp_stub_require_arguments(SEMMacroBuildCLI MY NAME)
  set(CLP ${MY_NAME})
  set(sources ${MY_ADDITIONAL_SRCS})
  if(NOT MY_DISABLE_DEFAULT_CXX_FILE)
    list(PREPEND sources ${CLP}.cxx)
  endif()
  set(xml ${CMAKE_CURRENT_SOURCE_DIR}/${CLP}.xml)
  if(MY_CLI_XML_FILE)
    set(xml ${MY_CLI_XML_FILE})
  endif()
  sgp_stub_require_files("SEMMacroBuildCLI(${CLP})" ${sources} ${xml} ${MY_LOGO_HEADER})
  foreach(dir IN LISTS MY_INCLUDE_DIRECTORIES)
    if(NOT IS_DIRECTORY "${dir}")
      message(FATAL_ERROR "Slicer stub: SEMMacroBuildCLI(${CLP}) includes ${dir}, which is not a directory.")
    endif()
  endforeach()
  foreach(library IN LISTS MY_TARGET_LIBRARIES)
    if(NOT TARGET ${library} AND NOT EXISTS "${library}" AND NOT library MATCHES "^(debug|optimized|general)$")
      message(FATAL_ERROR "Slicer stub: SEMMacroBuildCLI(${CLP}) links ${library}, which is neither a target nor a file.")
    endif()
  endforeach()

  # GenerateCLP: <NAME>CLP.h in the current binary directory, a dependency of the module's sources.
  set(clp_header ${CMAKE_CURRENT_BINARY_DIR}/${CLP}CLP.h)
  add_custom_command(
    OUTPUT ${clp_header}
    COMMAND ${SGP_STUB_GENERATECLP} --InputXML ${xml} --OutputCxx ${clp_header}
    DEPENDS ${xml} ${SGP_STUB_GENERATECLP_DEPENDS}
    COMMENT "Slicer stub: GenerateCLP ${CLP}CLP.h"
    VERBATIM)
  set_source_files_properties(${sources} PROPERTIES OBJECT_DEPENDS ${clp_header})
  set_source_files_properties(${clp_header} PROPERTIES HEADER_FILE_ONLY TRUE GENERATED TRUE)
  list(APPEND sources ${clp_header})
  include_directories(${CMAKE_CURRENT_BINARY_DIR}) # as SEM's GENERATECLP macro does

  if(MY_LINK_DIRECTORIES)
    link_directories(${MY_LINK_DIRECTORIES})
  endif()
  if(MY_INCLUDE_DIRECTORIES)
    include_directories(${MY_INCLUDE_DIRECTORIES})
  endif()
  if(SlicerExecutionModel_EXTRA_INCLUDE_DIRECTORIES)
    include_directories(${SlicerExecutionModel_EXTRA_INCLUDE_DIRECTORIES})
  endif()

  if(NOT MY_EXECUTABLE_ONLY)
    set(library_type SHARED)
    set(executable_flags "")
  else()
    set(library_type STATIC)
    set(executable_flags "-DMODULE_STATIC")
  endif()
  add_library(${CLP}Lib ${library_type} ${sources})
  set_target_properties(${CLP}Lib PROPERTIES COMPILE_FLAGS "-Dmain=ModuleEntryPoint")
  if(NOT WIN32 AND library_type STREQUAL "SHARED" AND ITK_BUILD_SHARED)
    include(GenerateExportHeader)
    generate_export_header(${CLP}Lib) # defines COMPILER_HAS_HIDDEN_VISIBILITY, as in SEM
    if(COMPILER_HAS_HIDDEN_VISIBILITY AND USE_COMPILER_HIDDEN_VISIBILITY)
      set_property(TARGET ${CLP}Lib APPEND_STRING PROPERTY COMPILE_FLAGS " -DMODULE_HIDDEN_VISIBILITY")
      set_target_properties(${CLP}Lib PROPERTIES CXX_VISIBILITY_PRESET hidden C_VISIBILITY_PRESET hidden
                                                 VISIBILITY_INLINES_HIDDEN 1)
    endif()
  endif()
  if(MY_TARGET_LIBRARIES)
    target_link_libraries(${CLP}Lib ${MY_TARGET_LIBRARIES})
  endif()

  set(wrapper ${SlicerExecutionModel_DEFAULT_CLI_LIBRARY_WRAPPER_CXX})
  if(DEFINED SlicerExecutionModel_CLI_LIBRARY_WRAPPER_CXX)
    set(wrapper ${SlicerExecutionModel_CLI_LIBRARY_WRAPPER_CXX})
  endif()
  add_executable(${CLP} ${wrapper})
  set_target_properties(${CLP} PROPERTIES COMPILE_FLAGS "${executable_flags}")
  target_link_libraries(${CLP} ${CLP}Lib ${SlicerExecutionModel_EXTRA_EXECUTABLE_TARGET_LIBRARIES})

  foreach(type RUNTIME LIBRARY ARCHIVE)
    if(NOT MY_${type}_OUTPUT_DIRECTORY)
      set(MY_${type}_OUTPUT_DIRECTORY ${SlicerExecutionModel_DEFAULT_CLI_${type}_OUTPUT_DIRECTORY})
    endif()
    if(NOT MY_INSTALL_${type}_DESTINATION)
      set(MY_INSTALL_${type}_DESTINATION ${SlicerExecutionModel_DEFAULT_CLI_INSTALL_${type}_DESTINATION})
    endif()
  endforeach()
  set_target_properties(${CLP} ${CLP}Lib PROPERTIES
    RUNTIME_OUTPUT_DIRECTORY "${MY_RUNTIME_OUTPUT_DIRECTORY}"
    LIBRARY_OUTPUT_DIRECTORY "${MY_LIBRARY_OUTPUT_DIRECTORY}"
    ARCHIVE_OUTPUT_DIRECTORY "${MY_ARCHIVE_OUTPUT_DIRECTORY}")
  set_target_properties(${CLP} ${CLP}Lib PROPERTIES LABELS ${CLP})
  get_filename_component(xml_name ${xml} NAME)
  add_custom_command(TARGET ${CLP} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -E copy_if_different ${xml} ${MY_RUNTIME_OUTPUT_DIRECTORY}/${xml_name}
    COMMENT "Slicer stub: copying ${xml_name} beside the launcher")
  if(NOT MY_NO_INSTALL)
    install(TARGETS ${CLP} ${CLP}Lib
      RUNTIME DESTINATION ${MY_INSTALL_RUNTIME_DESTINATION} COMPONENT RuntimeLibraries
      LIBRARY DESTINATION ${MY_INSTALL_LIBRARY_DESTINATION} COMPONENT RuntimeLibraries
      ARCHIVE DESTINATION ${MY_INSTALL_ARCHIVE_DESTINATION} COMPONENT Development)
    install(FILES ${xml} DESTINATION ${MY_INSTALL_RUNTIME_DESTINATION} COMPONENT RuntimeLibraries)
  endif()
  if(NOT MY_FOLDER)
    set(MY_FOLDER "${SlicerExecutionModel_DEFAULT_CLI_TARGETS_FOLDER_PREFIX}${CLP}")
  endif()
  set_target_properties(${CLP} ${CLP}Lib PROPERTIES FOLDER ${MY_FOLDER})
  sgp_stub_record("SEMMacroBuildCLI ${CLP} XML ${xml_name} LIB ${library_type} LIBRARIES ${MY_TARGET_LIBRARIES}")
endfunction()
