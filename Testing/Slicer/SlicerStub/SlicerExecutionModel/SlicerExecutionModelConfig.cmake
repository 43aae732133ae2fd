# Stub of SlicerExecutionModel's package config (see ../SlicerConfig.cmake). Like SEM's
# SlicerExecutionModelConfig.cmake it sets TCLAP_DIR to SEM's own TCLAP and finds it, so that
# TCLAP_INCLUDE_DIRS is SEM's copy; it puts those headers in SlicerExecutionModel_INCLUDE_DIRS and
# gives SEMMacroBuildCLI its defaults (launcher source, output and install folders).
set(SlicerExecutionModel_FOUND TRUE)
set(SlicerExecutionModel_USE_FILE ${CMAKE_CURRENT_LIST_DIR}/UseSlicerExecutionModel.cmake)
set(SlicerExecutionModel_CMAKE_DIR ${CMAKE_CURRENT_LIST_DIR})

set(TCLAP_DIR ${CMAKE_CURRENT_LIST_DIR}/tclap)
find_package(TCLAP REQUIRED)
# SEM gives its ModuleDescriptionParser folder too: the generated CLP headers include
# ModuleProcessInformation.h from it (the stub carries a stand-in of that header).
set(SlicerExecutionModel_INCLUDE_DIRS ${TCLAP_INCLUDE_DIRS} ${CMAKE_CURRENT_LIST_DIR}/ModuleDescriptionParser)
if(NOT DEFINED SlicerExecutionModel_DEFAULT_CLI_TARGETS_FOLDER_PREFIX)
  set(SlicerExecutionModel_DEFAULT_CLI_TARGETS_FOLDER_PREFIX "Module-") # as Slicer sets it
endif()

if(NOT DEFINED SlicerExecutionModel_DEFAULT_CLI_LIBRARY_WRAPPER_CXX)
  set(SlicerExecutionModel_DEFAULT_CLI_LIBRARY_WRAPPER_CXX ${CMAKE_CURRENT_LIST_DIR}/SEMCommandLineLibraryWrapper.cxx)
endif()
foreach(type RUNTIME LIBRARY ARCHIVE)
  if(NOT DEFINED SlicerExecutionModel_DEFAULT_CLI_${type}_OUTPUT_DIRECTORY)
    set(SlicerExecutionModel_DEFAULT_CLI_${type}_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/${Slicer_CLIMODULES_BIN_DIR})
  endif()
  if(NOT DEFINED SlicerExecutionModel_DEFAULT_CLI_INSTALL_${type}_DESTINATION)
    set(SlicerExecutionModel_DEFAULT_CLI_INSTALL_${type}_DESTINATION ${Slicer_INSTALL_CLIMODULES_BIN_DIR})
  endif()
endforeach()

# GenerateCLP: SEM runs its compiled GenerateCLP; the stub runs GenerateCLP.py with Slicer's Python.
if(NOT Python3_EXECUTABLE)
  message(FATAL_ERROR "Slicer stub: SlicerExecutionModel needs the Python3_EXECUTABLE that SlicerConfig.cmake sets.")
endif()
set(SGP_STUB_GENERATECLP ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/GenerateCLP.py)
set(SGP_STUB_GENERATECLP_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/GenerateCLP.py
    ${CMAKE_CURRENT_LIST_DIR}/../../../../CMake/GenerateCLP.py)
