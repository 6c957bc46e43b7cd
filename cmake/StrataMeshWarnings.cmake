# Warnings on for our own targets only; third-party headers are included as SYSTEM.
function(stratamesh_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
endfunction()
