# Precompiled third-party headers: every source of the libraries, the program and the drivers
# parses Eigen and most of it MRPT's poses (about 2 s a file); parsed once per target instead, the
# libraries' clean build took 218 s instead of 256 s on 2 cores. Only third-party and standard
# headers go in, so an include of our own headers that runs the wrong way still fails to build
# (the layers stay enforced).
#
#   opf_precompile_common_headers(<target> [EIGEN_ONLY])
#
# EIGEN_ONLY for a target that does not link MRPT. A source compiled with its own floating-point
# options (the particle kernels) sets SKIP_PRECOMPILE_HEADERS: GCC refuses a header precompiled
# under other options.
function(opf_precompile_common_headers target)
  cmake_parse_arguments(ARG "EIGEN_ONLY" "" "" ${ARGN})
  set(headers <Eigen/Core> <Eigen/Geometry>)
  if(NOT ARG_EIGEN_ONLY)
    list(APPEND headers <mrpt/poses/CPose3D.h>)
  endif()
  target_precompile_headers(${target} PRIVATE ${headers} <algorithm> <cmath> <string> <vector>)
endfunction()
