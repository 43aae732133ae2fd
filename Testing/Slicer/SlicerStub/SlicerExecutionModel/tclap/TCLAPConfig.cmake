# Stub of the TCLAPConfig.cmake that SlicerExecutionModel ships (SEM's tclap/ folder; TCLAP_DIR).
# SEM carries its own copy of the TCLAP headers. The stub carries none (the house rule is not to
# vendor what Debian provides): it makes <build>/slicer-stub/tclap/include/tclap a link to
# SGP_STUB_TCLAP_HEADERS (default Debian's /usr/include/tclap) and offers that folder, so the
# extension compiles against "SEM's" TCLAP without ever looking for a system one.
if(NOT DEFINED SGP_STUB_TCLAP_HEADERS)
  set(SGP_STUB_TCLAP_HEADERS /usr/include/tclap)
endif()
if(NOT EXISTS ${SGP_STUB_TCLAP_HEADERS}/CmdLine.h)
  message(FATAL_ERROR "Slicer stub: no TCLAP headers at ${SGP_STUB_TCLAP_HEADERS} to stand in for SEM's copy.")
endif()
set(_sgp_stub_tclap ${CMAKE_BINARY_DIR}/slicer-stub/tclap/include)
if(NOT EXISTS ${_sgp_stub_tclap}/tclap/CmdLine.h)
  file(MAKE_DIRECTORY ${_sgp_stub_tclap})
  file(CREATE_LINK ${SGP_STUB_TCLAP_HEADERS} ${_sgp_stub_tclap}/tclap SYMBOLIC)
endif()
set(TCLAP_FOUND TRUE)
set(TCLAP_INCLUDE_DIRS ${_sgp_stub_tclap})
set(TCLAP_LIBRARY_DIRS "")
set(TCLAP_USE_FILE ${CMAKE_CURRENT_LIST_DIR}/UseTCLAP.cmake)
