# hullpack_warnings(target): the warning set every project target is built with.
function(hullpack_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local -Wno-unused-parameter)
endfunction()
