#!/usr/bin/env bash
# Build Debian's own source package of SUNDIALS (the version of libsundials-dev, 6.4.1 on Debian 12)
# with cmake in Release mode into .deps/sundials-release/ (ignored by git): ARKODE, the serial
# vector and the dense matrix and linear solver, which geardyn links (meson.build finds the prefix
# and sets an rpath). Debian's binary package is compiled without optimisation; the source and its
# Debian patches are the same, so the results are the same bits (tests/compare_sundials.sh checks it).
#
# Called by scripts/deps.sh; does nothing when the prefix is there. The source comes through apt
# with a private sources list (a deb-src entry for bookworm, verified with Debian's archive key), so
# the machine's apt configuration is left alone and root is not needed. Exits non-zero when the
# source cannot be had or does not build; deps.sh then notes it and meson uses the system package.
# GD_DEBIAN_MIRROR overrides the mirror (default http://deb.debian.org/debian).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
prefix="$root/.deps/sundials-release"
stamp="$prefix/geardyn-build.txt"
[ -f "$stamp" ] && exit 0

pkgver=$(dpkg-query -W -f='${Version}' libsundials-dev 2>/dev/null) || { echo "libsundials-dev is not installed" >&2; exit 1; }
mkdir -p "$root/.deps"
work=$(mktemp -d "$root/.deps/sundials-work.XXXXXX")
trap 'rm -rf "$work"' EXIT

# apt with a private state: a deb-src entry for bookworm and its own lists and cache
apt_dir="$work/apt"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial"
mirror="${GD_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
printf 'Types: deb-src\nURIs: %s\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "$mirror" >"$apt_dir/deb-src.sources"
apt_opts=(-o "Dir::Etc::SourceList=$apt_dir/deb-src.sources" -o "Dir::Etc::SourceParts=/nonexistent"
          -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache" -o "APT::Sandbox::User=$(id -un)"
          -o "Debug::NoLocking=1" -o "Acquire::Retries=2")
echo "geardyn: fetching Debian's source of sundials $pkgver" >&2
apt-get "${apt_opts[@]}" -qq update >&2
(cd "$work" && apt-get "${apt_opts[@]}" -qq source "sundials=$pkgver" >/dev/null)
src=$(find "$work" -mindepth 1 -maxdepth 1 -type d -name 'sundials-*' | head -1)
[ -n "$src" ] || { echo "apt-get source sundials=$pkgver gave no source tree" >&2; exit 1; }

# Release (-O3 -DNDEBUG), no contraction into FMA (as geardyn itself), 64-bit indices as Debian's
# package, no MPI, threads, Fortran, examples or static libraries; ARKODE is the only integrator.
flags="-ffp-contract=off"
echo "geardyn: building SUNDIALS $pkgver (cmake Release) into .deps/sundials-release" >&2
cmake -S "$src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_FLAGS="$flags" \
    -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_INSTALL_LIBDIR=lib -DSUNDIALS_INDEX_SIZE=64 \
    -DBUILD_ARKODE=ON -DBUILD_CVODE=OFF -DBUILD_CVODES=OFF -DBUILD_IDA=OFF -DBUILD_IDAS=OFF \
    -DBUILD_KINSOL=OFF -DBUILD_NVECTOR_MANYVECTOR=OFF -DBUILD_STATIC_LIBS=OFF -DBUILD_SHARED_LIBS=ON \
    -DBUILD_FORTRAN_MODULE_INTERFACE=OFF -DENABLE_MPI=OFF -DENABLE_OPENMP=OFF -DENABLE_PTHREAD=OFF \
    -DEXAMPLES_ENABLE_C=OFF -DEXAMPLES_ENABLE_CXX=OFF -DEXAMPLES_INSTALL=OFF >/dev/null
targets=(sundials_arkode_shared sundials_nvecserial_shared sundials_sunmatrixdense_shared
         sundials_sunlinsoldense_shared)
cmake --build "$work/build" --parallel "$(nproc 2>/dev/null || echo 2)" --target "${targets[@]}" >/dev/null

# install only what geardyn links (the four libraries and the headers), then move into place
out="$work/prefix"
mkdir -p "$out/lib" "$out/include"
cp -a "$src/include/." "$work/build/include/." "$out/include/"
find "$work/build/src" \( -name 'libsundials_arkode.so*' -o -name 'libsundials_nvecserial.so*' \
     -o -name 'libsundials_sunmatrixdense.so*' -o -name 'libsundials_sunlinsoldense.so*' \) \
     -exec cp -a {} "$out/lib/" \;
[ -e "$out/lib/libsundials_arkode.so" ] || { echo "the SUNDIALS build left no libsundials_arkode.so" >&2; exit 1; }
printf 'release build (cmake Release: -O3 -DNDEBUG %s) of Debian source package sundials %s\n' "$flags" "$pkgver" \
    >"$out/geardyn-build.txt"
rm -rf "$prefix"
mv "$out" "$prefix"
echo "geardyn: SUNDIALS release build in $prefix" >&2
