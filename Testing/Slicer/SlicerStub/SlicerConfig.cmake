# A stand-in for Slicer's build tree, for configure-testing the extension's Slicer branch without
# Slicer (Testing/Slicer/configure_with_slicer_stub.py). It defines what the extension uses from
# Slicer - the use file, the extension generate-config and CPack includes, the directories, and
# SlicerExecutionModel (with its TCLAP) and Slicer's Python - as recording versions that stop the
# configure (FATAL_ERROR) when a call names a file that does not exist or misses a required
# argument. ITK and VTK are not set here, so the project finds the system's, as it would find
# Slicer's inside Slicer. Slicer ships no nlohmann JSON, GoogleTest or Google Benchmark, and
# neither does the stub.

set(Slicer_FOUND TRUE)
set(Slicer_VERSION_MAJOR 5)
set(Slicer_VERSION_MINOR 8)
set(Slicer_VERSION "5.8.0")
set(Slicer_USE_FILE ${CMAKE_CURRENT_LIST_DIR}/UseSlicer.cmake)
set(Slicer_EXTENSION_GENERATE_CONFIG ${CMAKE_CURRENT_LIST_DIR}/SlicerExtensionGenerateConfig.cmake)
set(Slicer_EXTENSION_CPACK ${CMAKE_CURRENT_LIST_DIR}/SlicerExtensionCPack.cmake)
set(SlicerExecutionModel_DIR ${CMAKE_CURRENT_LIST_DIR}/SlicerExecutionModel)

# The directory variables of Slicer's CMake/SlicerDirectories.cmake that extensions use.
set(Slicer_CLIMODULES_SUBDIR "cli-modules")
set(Slicer_CLIMODULES_BIN_DIR "lib/Slicer-5.8/cli-modules")
set(Slicer_CLIMODULES_LIB_DIR "lib/Slicer-5.8/cli-modules")
set(Slicer_INSTALL_CLIMODULES_BIN_DIR "lib/Slicer-5.8/cli-modules")
set(Slicer_INSTALL_CLIMODULES_LIB_DIR "lib/Slicer-5.8/cli-modules")
set(Slicer_QTSCRIPTEDMODULES_LIB_DIR "lib/Slicer-5.8/qt-scripted-modules")
set(Slicer_INSTALL_QTSCRIPTEDMODULES_LIB_DIR "lib/Slicer-5.8/qt-scripted-modules")

# Slicer's Python: SlicerConfig.cmake sets PYTHON_EXECUTABLE and Python3_EXECUTABLE to the
# superbuild's PythonSlicer (slicer_config_set_ep of the FIND_PACKAGE variables of
# SuperBuild/External_python.cmake). The stub's PythonSlicer is a link, in the build tree, to
# SGP_STUB_PYTHON (default Debian's /usr/bin/python3, which has numpy as PythonSlicer does).
if(NOT DEFINED SGP_STUB_PYTHON)
  set(SGP_STUB_PYTHON /usr/bin/python3)
endif()
set(_sgp_stub_python ${CMAKE_BINARY_DIR}/slicer-stub/python-install/bin/PythonSlicer)
if(NOT EXISTS ${_sgp_stub_python})
  file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/slicer-stub/python-install/bin)
  file(CREATE_LINK ${SGP_STUB_PYTHON} ${_sgp_stub_python} SYMBOLIC)
endif()
set(PYTHON_EXECUTABLE ${_sgp_stub_python} CACHE STRING "Path to project build directory or file" FORCE)
set(Python3_EXECUTABLE ${_sgp_stub_python} CACHE STRING "Path to project build directory or file" FORCE)

set(SGP_STUB_RECORD ${CMAKE_BINARY_DIR}/slicer-stub-record.txt)
file(WRITE ${SGP_STUB_RECORD} "find_package(Slicer) ${CMAKE_CURRENT_LIST_FILE}\n")
