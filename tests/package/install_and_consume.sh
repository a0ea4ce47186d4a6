#!/usr/bin/env bash
# Installs the build into a scratch prefix and uses it as another project would:
#   1. examples/track_frames finds the package (find_package(opf)), builds, runs and tracks
#      through the gap (a `dynamics` frame), linking neither OpenCV nor OpenGL;
#   2. the same source builds with pkg-config (opf.pc) alone;
#   3. find_package(opf COMPONENTS vision sim mrpt_bridge) resolves the optional layers;
#   4. the Python module imports from <prefix>/lib/python3/dist-packages;
#   5. CPack's .deb holds the same files under /usr;
#   6. the installed `opf` runs from the prefix with its bundled data, also a command it hands to
#      libexec/opf/opf-experiments.
#   bash tests/package/install_and_consume.sh BUILD_DIR SCRATCH_DIR
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$1"
scratch="$2"
rm -rf "$scratch"
mkdir -p "$scratch"
prefix="$scratch/prefix"

cmake --install "$build" --prefix "$prefix" >"$scratch/install.log"
for f in include/opf/opf.h include/opf/core/tracker.h lib/cmake/opf/opfConfig.cmake \
  lib/cmake/opf/opfConfigVersion.cmake lib/pkgconfig/opf.pc bin/opf \
  libexec/opf/opf-experiments share/opf/experiments/general_op.yaml share/opf/experiments/data/example_log.csv \
  share/bash-completion/completions/opf share/man/man1/opf.1; do
  [ -e "$prefix/$f" ] || { echo "install: $prefix/$f missing" >&2; exit 1; }
done

# The kernels' headers are private: not installed, and no installed header needs them.
for f in include/opf/particles/motion_kernels.h include/opf/particles/kernel_support.h; do
  [ ! -e "$prefix/$f" ] || { echo "install: private header $prefix/$f installed" >&2; exit 1; }
done

example="$scratch/example"
cmake -S "$repo/examples/track_frames" -B "$example" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
  >"$scratch/example_configure.log"
cmake --build "$example" >"$scratch/example_build.log"
"$example/track_frames" >"$scratch/example.out"
grep -q " measured " "$scratch/example.out" || { echo "example: no measured frame" >&2; exit 1; }
grep -q " dynamics " "$scratch/example.out" || { echo "example: no dynamics frame" >&2; exit 1; }
[ "$(wc -l <"$scratch/example.out")" -eq 45 ] || { echo "example: not 45 frames" >&2; exit 1; }
if ldd "$example/track_frames" | grep -E "libopencv_|libGL[.UX]|libEGL|libOpenGL|libmrpt-opengl"; then
  echo "example: a tracking program must link neither OpenCV nor OpenGL" >&2
  exit 1
fi
echo "find_package: example tracked $(grep -c " dynamics " "$scratch/example.out") hidden frames"

export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
# shellcheck disable=SC2046
g++ -O1 -o "$scratch/track_frames_pc" "$repo/examples/track_frames/track_frames.cpp" \
  $(pkg-config --cflags --libs opf)
"$scratch/track_frames_pc" | cmp - "$scratch/example.out"
echo "pkg-config: the same program, the same output"

components="$scratch/components"
mkdir -p "$components"
cat >"$components/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(components LANGUAGES CXX)
find_package(opf 0.1 REQUIRED COMPONENTS vision sim mrpt_bridge)
foreach(target opf::opf opf::filter opf::estimators opf::io opf::vision opf::sim opf::mrpt_bridge)
  if(NOT TARGET ${target})
    message(FATAL_ERROR "${target} missing")
  endif()
endforeach()
CMAKE
cmake -S "$components" -B "$components/build" -DCMAKE_PREFIX_PATH="$prefix" >"$scratch/components.log"
echo "components: vision, sim and mrpt_bridge found"


# The Python module from the prefix's Python path, with the system interpreter.
if grep -q "^OPF_BUILD_PYTHON:BOOL=ON" "$build/CMakeCache.txt"; then
  PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c '
import opf
e = opf.Tracker("cvkf", seed=1).step(0.0, {"cup": [0.1, 0.2, 0.3, 0, 0, 0, 1]})["cup"]
assert abs(e.position[0] - 0.1) < 1e-9 and e.mode == "measured", e
print("python: opf imported from", opf.__file__.rsplit("/opf/", 1)[0])'
fi

# CPack's .deb holds the same install under /usr.
(cd "$build" && cpack -G DEB -B "$scratch/deb" >"$scratch/cpack.log")
deb="$(ls "$scratch"/deb/opf-toolkit_*.deb)"
contents="$(dpkg-deb -c "$deb")"
for f in ./usr/bin/opf ./usr/libexec/opf/opf-experiments ./usr/include/opf/opf.h ./usr/lib/cmake/opf/opfConfig.cmake \
  ./usr/lib/pkgconfig/opf.pc ./usr/share/opf/experiments/general_op.yaml \
  ./usr/share/bash-completion/completions/opf ./usr/share/man/man1/opf.1; do
  grep -q " $f\$" <<<"$contents" || { echo "deb: $f missing from $deb" >&2; exit 1; }
done
echo "deb: $(basename "$deb") holds the program, headers, package config, data, completion and man page"

OPF_DATA_DIR="" "$prefix/bin/opf" evaluate --seeds 1 --estimators cvkf >"$scratch/evaluate.out"
grep -q "cvkf" "$scratch/evaluate.out"
echo "installed opf: evaluate ran on the bundled example log"
# A command of the experiments program, run from the prefix: `opf` finds it in libexec/opf, and
# it finds the bundled experiments in share/opf.
OPF_DATA_DIR="" "$prefix/bin/opf" render "$prefix/share/opf/experiments/general_op.yaml" \
  --out "$scratch/render.png" >"$scratch/render.out"
[ -s "$scratch/render.png" ] || { echo "installed opf render wrote no image" >&2; exit 1; }
echo "installed opf: render ran through libexec/opf/opf-experiments"
