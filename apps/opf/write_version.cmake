# Writes OUT, a header with the toolkit's VERSION and the source tree's git commit, at build time
# (so `opf --version` names the commit actually built), rewriting it only when it changes.
# Run as: cmake -DSOURCE_DIR=... -DVERSION=... -DOUT=... -P write_version.cmake
execute_process(
  COMMAND git -C "${SOURCE_DIR}" describe --always --dirty --abbrev=12
  OUTPUT_VARIABLE commit
  OUTPUT_STRIP_TRAILING_WHITESPACE
  ERROR_QUIET
  RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR commit STREQUAL "")
  set(commit "unknown") # not a git checkout (a release tarball)
endif()
string(CONCAT content "#pragma once\n// Generated at build time by apps/opf/write_version.cmake.\n"
            "#define OPF_VERSION \"${VERSION}\"\n#define OPF_COMMIT \"${commit}\"\n")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL content)
  file(WRITE "${OUT}" "${content}")
endif()
