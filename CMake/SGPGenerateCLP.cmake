# sgp_generate_clp(<out_var> <xml>): generate <Name>CLP.h from <xml> with CMake/GenerateCLP.py,
# the project's stand-in for SlicerExecutionModel's GenerateCLP in the standalone build.
function(sgp_generate_clp out_var xml)
  get_filename_component(name ${xml} NAME_WE)
  set(header ${CMAKE_CURRENT_BINARY_DIR}/${name}CLP.h)
  add_custom_command(
    OUTPUT ${header}
    COMMAND ${SGP_PYTHON} ${PROJECT_SOURCE_DIR}/CMake/GenerateCLP.py --InputXML ${xml} --OutputCxx ${header}
    DEPENDS ${xml} ${PROJECT_SOURCE_DIR}/CMake/GenerateCLP.py
    COMMENT "Generating ${name}CLP.h from ${name}.xml"
    VERBATIM)
  set(${out_var} ${header} PARENT_SCOPE)
endfunction()
