# A stand-in for Slicer's build tree, for configure-testing the extension's Slicer branch without
# Slicer (Testing/Slicer/configure_with_slicer_stub.py). It defines what the extension uses from
# Slicer - the use file, the extension generate-config and CPack includes, the directories, and
# SlicerExecutionModel - as recording versions that stop the configure (FATAL_ERROR) when a call
# names a file that does not exist or misses a required argument. ITK and VTK are not set here,
# so the project finds the system's, as it would find Slicer's inside Slicer.

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

set(SGP_STUB_RECORD ${CMAKE_BINARY_DIR}/slicer-stub-record.txt)
file(WRITE ${SGP_STUB_RECORD} "find_package(Slicer) ${CMAKE_CURRENT_LIST_FILE}\n")
