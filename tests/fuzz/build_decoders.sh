#!/usr/bin/env bash
# The image decoders the lab links (libspng, libjpeg-turbo, OpenEXRCore), built
# from Debian's own source packages with the fuzz targets' instrumentation
# (-fsanitize=fuzzer-no-link,address,undefined), so that libFuzzer sees the
# edges inside the decoder it fuzzes and ASan sees its errors:
#
#     bash tests/fuzz/build_decoders.sh DIR    # DIR/lib/*.a, DIR/include
#
# The sources are the versions Debian 12 ships (libspng 0.7.3, libjpeg-turbo
# 2.1.5, OpenEXR 3.1.5), fetched with `apt-get source` through a deb-src list
# of this script's own (the system's apt sources are not touched) and
# unpacked with Debian's patches by dpkg-source (package dpkg-dev). zlib stays
# Debian's (uninstrumented): libspng and OpenEXRCore call it for inflate.
# libjpeg-turbo is built without its SIMD code (assembly, which the
# instrumentation cannot see), as OSS-Fuzz builds it. Used by run_fuzzers.sh
# when SNELL_FUZZ_DECODERS=source (campaign.sh's default); the test command's
# 6-second smoke run links Debian's libraries.
set -euo pipefail
dir=$(mkdir -p "$1" && cd "$1" && pwd)
cc=${CLANG:-$(command -v clang-14 || command -v clang || true)}
[ -n "$cc" ] || { echo "build_decoders: clang not found (apt-get install clang-14)" >&2; exit 1; }
command -v dpkg-source > /dev/null || { echo "build_decoders: dpkg-source not found (apt-get install dpkg-dev)" >&2; exit 1; }
flags="-g -O1 -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined"
[ -f "$dir/lib/libspng.a" ] && [ -f "$dir/lib/libjpeg.a" ] && [ -f "$dir/lib/libOpenEXRCore.a" ] && exit 0

# Debian's source packages, through a deb-src list in $dir/apt.
apt=$dir/apt
mkdir -p "$apt/lists/partial" "$dir/src" "$dir/lib" "$dir/include"
echo "deb-src http://deb.debian.org/debian bookworm main" > "$apt/sources.list"
opts=(-o "Dir::Etc::SourceList=$apt/sources.list" -o Dir::Etc::SourceParts=/dev/null -o "Dir::State::Lists=$apt/lists"
      -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache= -o APT::Sandbox::User="$(id -un)")
if [ ! -d "$dir/src/libspng-0.7.3" ] || [ ! -d "$dir/src/libjpeg-turbo-2.1.5" ] || [ ! -d "$dir/src/openexr-3.1.5" ]; then
  echo "build_decoders: fetching Debian's sources of libspng, libjpeg-turbo and openexr"
  apt-get "${opts[@]}" -q update > "$dir/apt.log" 2>&1 || { cat "$dir/apt.log" >&2; exit 1; }
  (cd "$dir/src" && apt-get "${opts[@]}" -q source libspng=0.7.3-3 libjpeg-turbo=1:2.1.5-2 openexr=3.1.5-5 >> "$dir/apt.log" 2>&1) ||
    { tail -n 20 "$dir/apt.log" >&2; echo "build_decoders: apt-get source failed (network, or a version Debian no longer serves)" >&2; exit 1; }
fi

echo "build_decoders: libspng (one C file)"
"$cc" $flags -DSPNG_STATIC -c "$dir/src/libspng-0.7.3/spng/spng.c" -o "$dir/src/spng.o"
ar rcs "$dir/lib/libspng.a" "$dir/src/spng.o"

echo "build_decoders: libjpeg-turbo (no SIMD)"
cmake -S "$dir/src/libjpeg-turbo-2.1.5" -B "$dir/build/jpeg" -DCMAKE_C_COMPILER="$cc" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_BUILD_TYPE=None -DENABLE_SHARED=OFF -DENABLE_STATIC=ON -DWITH_SIMD=OFF -DWITH_TURBOJPEG=OFF > "$dir/jpeg.log" 2>&1 ||
  { tail -n 20 "$dir/jpeg.log" >&2; exit 1; }
cmake --build "$dir/build/jpeg" -j "$(nproc)" --target jpeg-static >> "$dir/jpeg.log" 2>&1 || { tail -n 20 "$dir/jpeg.log" >&2; exit 1; }
cp "$dir/build/jpeg/libjpeg.a" "$dir/lib/"

echo "build_decoders: OpenEXRCore"
cmake -S "$dir/src/openexr-3.1.5" -B "$dir/build/exr" -DCMAKE_C_COMPILER="$cc" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_BUILD_TYPE=None -DBUILD_SHARED_LIBS=OFF -DBUILD_TESTING=OFF -DOPENEXR_BUILD_TOOLS=OFF \
  -DOPENEXR_INSTALL_EXAMPLES=OFF > "$dir/exr.log" 2>&1 || { tail -n 20 "$dir/exr.log" >&2; exit 1; }
cmake --build "$dir/build/exr" -j "$(nproc)" --target OpenEXRCore >> "$dir/exr.log" 2>&1 || { tail -n 20 "$dir/exr.log" >&2; exit 1; }
find "$dir/build/exr" -name 'libOpenEXRCore*.a' -exec cp {} "$dir/lib/libOpenEXRCore.a" \;
[ -f "$dir/lib/libOpenEXRCore.a" ] || { echo "build_decoders: no libOpenEXRCore*.a was built" >&2; exit 1; }
echo "build_decoders: $dir/lib: $(cd "$dir/lib" && echo *.a)"
