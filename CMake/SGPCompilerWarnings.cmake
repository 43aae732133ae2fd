# sgp_target_warnings(<target>): -Wall -Wextra on our own code; -Werror when SGP_WERROR is ON (CI).
function(sgp_target_warnings target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra)
    if(SGP_WERROR)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
  endif()
endfunction()
