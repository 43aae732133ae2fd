# Stub of SEM's UseTCLAP.cmake.
include_directories(BEFORE ${TCLAP_INCLUDE_DIRS})
