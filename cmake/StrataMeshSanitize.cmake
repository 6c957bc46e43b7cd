# STRATAMESH_SANITIZE: every target of ours (engine, CLI, GUI, tests; not the TetGen helper, see
# app/tetgen_runner) built with AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer, so that the whole test
# suite doubles as a memory-error and undefined-behaviour check (scripts/sanitize.sh runs it).
# Undefined behaviour aborts the test instead of printing a line nobody reads. Libraries from
# Debian (Qt, VTK, CGAL's GMP, TBB) are not instrumented; their leaks are suppressed, one by one,
# in scripts/lsan-suppressions.txt.
if(STRATAMESH_SANITIZE)
  if(STRATAMESH_FUZZ)
    message(FATAL_ERROR "STRATAMESH_SANITIZE and STRATAMESH_FUZZ are separate builds: use one build folder each")
  endif()
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
