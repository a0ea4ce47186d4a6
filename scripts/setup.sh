#!/usr/bin/env bash
# Installs the Debian packages the toolkit needs (only the missing ones), then configures and
# builds it in Release with Ninja. Idempotent: a second run installs nothing and rebuilds nothing.
# Usage: bash scripts/setup.sh            (from anywhere; the build goes to <repo>/build)
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

mapfile -t packages < <(cat "$repo/scripts/packages-minimal.txt" "$repo/scripts/packages.txt" |
  grep -v '^\s*#' | grep -v '^\s*$')
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  # A fresh machine's package lists can be empty or stale: update before installing.
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# Every optional part required: the tests, the benchmarks and the Python module.
cmake --preset release -S "$repo" -DOPF_BUILD_TESTS=ON -DOPF_BUILD_BENCHMARKS=ON \
  -DOPF_BUILD_PYTHON=ON >/dev/null
cmake --build "$repo/build" -j 2
