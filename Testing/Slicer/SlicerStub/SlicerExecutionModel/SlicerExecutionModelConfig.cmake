# Stub of SlicerExecutionModel's package config (see ../SlicerConfig.cmake).
set(SlicerExecutionModel_FOUND TRUE)
set(SlicerExecutionModel_USE_FILE ${CMAKE_CURRENT_LIST_DIR}/UseSlicerExecutionModel.cmake)
set(SlicerExecutionModel_INCLUDE_DIRS "")
