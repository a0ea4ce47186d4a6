# Writes the bash completion and the man page the program generates from its option tables:
#   cmake -DOPF=<program> -DOUT=<build>/share -P write_shell_docs.cmake
file(MAKE_DIRECTORY ${OUT}/bash-completion/completions ${OUT}/man/man1)
execute_process(COMMAND ${OPF} completion OUTPUT_FILE ${OUT}/bash-completion/completions/opf
                RESULT_VARIABLE completion_result)
execute_process(COMMAND ${OPF} manual OUTPUT_FILE ${OUT}/man/man1/opf.1 RESULT_VARIABLE man_result)
if(NOT completion_result EQUAL 0 OR NOT man_result EQUAL 0)
  message(FATAL_ERROR "opf completion / opf manual failed: ${completion_result} ${man_result}")
endif()
