#!/usr/bin/env bash
# Install the Debian 12 packages geardyn needs, only those that are missing.
# Then build Debian's own source of SUNDIALS in Release mode into .deps/sundials-release/ when it is
# not there yet (scripts/sundials-release.sh; GD_SUNDIALS=system skips it); without it meson links
# the system package. Run by scripts/quickstart.sh and scripts/test.sh; safe to run again.
set -euo pipefail
# python3-numpy and python3-pytest: the Python module (python/, docs/python.md) and its tests, for
# Debian's /usr/bin/python3 (meson finds that interpreter when the first python3 on PATH lacks numpy)
GD_PACKAGES=(gcc pkg-config meson ninja-build cmake dpkg-dev xz-utils python3 python3-numpy python3-pytest
             libsundials-dev libgsl-dev libnlopt-dev libinih-dev libjansson-dev gnuplot-nox openmpi-bin libopenmpi-dev
             clang libclang-rt-14-dev)
missing=()
for p in "${GD_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
    echo "geardyn: installing ${missing[*]}" >&2
    SUDO=""
    [ "$(id -u)" -ne 0 ] && SUDO="sudo"
    export DEBIAN_FRONTEND=noninteractive
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if [ "${GD_SUNDIALS:-release}" != system ] && [ ! -f "$here/../.deps/sundials-release/geardyn-build.txt" ]; then
    bash "$here/sundials-release.sh" ||
        echo "geardyn: note: no release build of SUNDIALS from Debian's source (see above); meson links the system package" >&2
fi
