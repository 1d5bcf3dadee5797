#!/usr/bin/env bash
# Installs the Debian packages illum builds against. Idempotent; uses sudo only when not root.
set -euo pipefail
# clang, libclang-rt-dev (the ASan/UBSan/libFuzzer runtimes: only a Recommends of clang, which
# --no-install-recommends skips) and llvm (llvm-symbolizer, for sanitizer stack traces with file:line) are for
# `make test-sanitize` and `make fuzz`. pybind11-dev, python3-dev, python3-numpy and python3-pytest are for the
# Python module (python/) and its tests.
packages=(build-essential cmake pkg-config libembree-dev libtbb-dev libopenexr-dev libstb-dev libcli11-dev
          nlohmann-json3-dev libfmt-dev libgtest-dev libgmock-dev libbenchmark-dev zlib1g-dev clang
          libclang-rt-dev llvm libnanovdb-dev libopenmpi-dev openmpi-bin libcpp-httplib-dev chromium pybind11-dev
          python3-dev python3-numpy python3-pytest)
# --peers: also Debian's Blender, whose Cycles scripts/compare_peers.sh --blender times against illum (not
# needed to build, test or render).
case "${1:-}" in
    "") ;;
    --peers) packages+=(blender) ;;
    *) echo "usage: scripts/setup.sh [--peers]" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all packages present"
    exit 0
fi
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
