# Stub of Slicer's UseSlicer.cmake: the scripted-module macro and the Python test macro.
include(${CMAKE_CURRENT_LIST_DIR}/SlicerStubSupport.cmake)

# The extension template sets its metadata before find_package(Slicer) and include(${Slicer_USE_FILE}).
foreach(name HOMEPAGE CONTRIBUTORS DESCRIPTION ICONURL SCREENSHOTURLS DEPENDS)
  if("${EXTENSION_${name}}" STREQUAL "")
    message(FATAL_ERROR "Slicer stub: EXTENSION_${name} must be set before include(\${Slicer_USE_FILE}).")
  endif()
endforeach()
sgp_stub_record("include(Slicer_USE_FILE) project=${PROJECT_NAME}")

# As Slicer's UseSlicer.cmake: Slicer registers the ITK IO factories itself (its
# ITKFactoryRegistration library, called by its CLI launcher), so UseITK must not generate the
# register managers. Slicer picks the variable names by ITK version (>= 5.3: one per factory
# kind); ITK is not found yet here, so the stub sets both spellings.
set(ITK_NO_IO_FACTORY_REGISTER_MANAGER 1)
foreach(factory_uc IN ITEMS "IMAGEIO" "MESHIO" "TRANSFORMIO")
  set(ITK_NO_${factory_uc}_FACTORY_REGISTER_MANAGER 1)
endforeach()

# As Slicer's UseSlicer.cmake: SEMMacroBuildCLI puts the CLIs in Slicer's CLI folder of the build tree.
set(SlicerExecutionModel_DEFAULT_CLI_RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${Slicer_CLIMODULES_BIN_DIR}")
set(SlicerExecutionModel_DEFAULT_CLI_LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${Slicer_CLIMODULES_LIB_DIR}")
set(SlicerExecutionModel_DEFAULT_CLI_ARCHIVE_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${Slicer_CLIMODULES_LIB_DIR}")

# slicerMacroBuildScriptedModule(NAME <name> SCRIPTS <py...> RESOURCES <files...>
#                                [WITH_GENERIC_TESTS] [WITH_SUBDIR] [VERBOSE])
function(slicerMacroBuildScriptedModule)
  cmake_parse_arguments(MY "WITH_GENERIC_TESTS;WITH_SUBDIR;VERBOSE" "NAME" "SCRIPTS;RESOURCES" ${ARGN})
  sgp_stub_require_arguments(slicerMacroBuildScriptedModule MY NAME SCRIPTS)
  sgp_stub_require_files("slicerMacroBuildScriptedModule(${MY_NAME})" ${MY_SCRIPTS} ${MY_RESOURCES})
  if(NOT "${MY_NAME}.py" IN_LIST MY_SCRIPTS)
    message(FATAL_ERROR "Slicer stub: slicerMacroBuildScriptedModule(${MY_NAME}) does not list ${MY_NAME}.py.")
  endif()
  foreach(script IN LISTS MY_SCRIPTS)
    if(NOT script MATCHES "\\.py$")
      message(FATAL_ERROR "Slicer stub: script ${script} of ${MY_NAME} is not a .py file.")
    endif()
  endforeach()
  sgp_stub_record("slicerMacroBuildScriptedModule ${MY_NAME} SCRIPTS ${MY_SCRIPTS} RESOURCES ${MY_RESOURCES}")
endfunction()

# slicer_add_python_unittest(SCRIPT <file> [SLICER_ARGS ...] [TESTNAME_PREFIX ...])
function(slicer_add_python_unittest)
  cmake_parse_arguments(MY "" "SCRIPT;TESTNAME_PREFIX" "SLICER_ARGS" ${ARGN})
  sgp_stub_require_arguments(slicer_add_python_unittest MY SCRIPT)
  sgp_stub_require_files(slicer_add_python_unittest ${MY_SCRIPT})
  sgp_stub_record("slicer_add_python_unittest ${MY_SCRIPT}")
endfunction()
