# matc_target_warnings(<target>): the project's warning set; errors when MATC_WERROR is ON.
function(matc_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion
                                           $<$<COMPILE_LANGUAGE:CXX>:-Wnon-virtual-dtor>
                                           $<$<COMPILE_LANGUAGE:CXX>:-Wold-style-cast>
                                           $<$<COMPILE_LANGUAGE:CXX>:-Woverloaded-virtual>)
  if(MATC_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
