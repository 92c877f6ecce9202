# hullpack_warnings(target): the warning set every project target is built with.
# -Wshadow=local is GCC's (clang, which builds the sanitized tree, has no "local" level of it).
function(hullpack_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-unused-parameter
                         $<$<CXX_COMPILER_ID:GNU>:-Wshadow=local>)
endfunction()
