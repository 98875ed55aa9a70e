#!/usr/bin/env bash
# capi/stage.sh [--debug] PREFIX
#
# Builds the capi crate (release by default; --debug uses the dev profile, as the tests do) and
# stages a Webots-style controller tree under PREFIX:
#   PREFIX/include/webots/...                       C headers and the C++ wrapper
#   PREFIX/lib/controller/libcar.so   libcar.a      the car library, and all the state
#   PREFIX/lib/controller/libdriver.so libdriver.a  the driver library (a shim over libcar)
#   PREFIX/lib/pkgconfig/webots-vehicle.pc          cflags and libs for pkg-config
#   PREFIX/lib/java/vehicle.jar                     the Java classes (when javac and jar exist)
#   PREFIX/lib/libvehicle_java.so                   their JNI library (java/, vehicle-java)
# after which a controller builds with
#   cc my_controller.c $(pkg-config --cflags --libs webots-vehicle)   # PKG_CONFIG_PATH=PREFIX/lib/pkgconfig
# or, without pkg-config,
#   cc my_controller.c -I PREFIX/include -L PREFIX/lib/controller -ldriver -lcar -Wl,-rpath,PREFIX/lib/controller
# and a Java controller with
#   javac -cp PREFIX/lib/java/vehicle.jar MyController.java
#   java -cp PREFIX/lib/java/vehicle.jar:. -Djava.library.path=PREFIX/lib MyController
# Without javac or jar on the PATH the Java part is skipped with a message (the rest is staged).
#
# Environment: CARGO (default cargo), CC (default cc), AR (default ar), CARGO_TARGET_DIR.
# Linux (ELF) only: libdriver.so records libcar.so as DT_NEEDED with RUNPATH $ORIGIN.
set -euo pipefail

usage() {
  echo "usage: $0 [--debug] PREFIX" >&2
  exit 2
}

profile=release
prefix=""
for arg in "$@"; do
  case "$arg" in
    --debug) profile=dev ;;
    --release) profile=release ;;
    -h | --help) usage ;;
    -*) echo "$0: unknown option $arg" >&2; usage ;;
    *) [ -z "$prefix" ] || usage; prefix=$arg ;;
  esac
done
[ -n "$prefix" ] || usage

capi=$(cd "$(dirname "$0")" && pwd)
workspace=$(dirname "$capi")
CARGO=${CARGO:-cargo}
CC=${CC:-cc}
AR=${AR:-ar}

echo "stage.sh: building libcar ($profile profile)" >&2
"$CARGO" build --manifest-path "$workspace/Cargo.toml" -p capi --lib --profile "$profile"

# Where cargo put the libraries (honours CARGO_TARGET_DIR and .cargo/config).
target=$("$CARGO" metadata --manifest-path "$workspace/Cargo.toml" --no-deps --format-version 1 |
  grep -o '"target_directory":"[^"]*"' | sed 's/^"target_directory":"//; s/"$//')
if [ "$profile" = dev ]; then build="$target/debug"; else build="$target/release"; fi
for f in libcar.so libcar.a; do
  [ -f "$build/$f" ] || { echo "$0: $build/$f was not built" >&2; exit 1; }
done

mkdir -p "$prefix/include" "$prefix/lib/controller" "$prefix/lib/pkgconfig"
prefix=$(cd "$prefix" && pwd)
libdir="$prefix/lib/controller"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Replace files by renaming, so that a controller running from this tree keeps its mapping.
put() {
  cp "$1" "$2.staging.$$"
  mv -f "$2.staging.$$" "$2"
}

cp -R "$capi/include/webots" "$prefix/include/"
put "$build/libcar.so" "$libdir/libcar.so"
put "$build/libcar.a" "$libdir/libcar.a"

echo "stage.sh: building libdriver" >&2
"$CC" -std=c99 -pedantic -Wall -Wextra -Werror -O2 -fPIC -I "$prefix/include" \
  -c "$capi/driver/driver.c" -o "$work/driver.o"
"$CC" -shared -o "$work/libdriver.so" "$work/driver.o" -L "$libdir" -lcar \
  -Wl,-soname,libdriver.so -Wl,-rpath,'$ORIGIN' -Wl,--no-undefined
rm -f "$work/libdriver.a"
"$AR" rcs "$work/libdriver.a" "$work/driver.o"
put "$work/libdriver.so" "$libdir/libdriver.so"
put "$work/libdriver.a" "$libdir/libdriver.a"

# The system libraries a Rust static library needs, as rustc reports them for this toolchain.
printf '#[unsafe(no_mangle)]\npub extern "C" fn f() -> usize { std::env::args().count() }\n' >"$work/probe.rs"
native=$(cd "$work" && rustc --edition 2024 --crate-type staticlib --print native-static-libs probe.rs 2>&1 |
  sed -n 's/.*native-static-libs: //p' | head -n 1)
[ -n "$native" ] || native="-lgcc_s -lutil -lrt -lpthread -lm -ldl -lc"

version=$(sed -n 's/^version = "\(.*\)"/\1/p' "$workspace/Cargo.toml" | head -n 1)
cat >"$prefix/lib/pkgconfig/webots-vehicle.pc" <<PC
prefix=$prefix
includedir=\${prefix}/include
libdir=\${prefix}/lib/controller

Name: webots-vehicle
Description: Webots-compatible driver and car libraries (libdriver, libcar) of the vehicle simulator
Version: ${version:-0.0.0}
Cflags: -I\${includedir}
Libs: -L\${libdir} -ldriver -lcar -Wl,-rpath,\${libdir}
Libs.private: $native
PC

# The Java binding: the JDK's javac and jar only (no Maven or Gradle), classes for Java 8 as
# Webots compiles its own; the JNI library holds the C API itself (capi as an rlib).
if command -v javac >/dev/null 2>&1 && command -v jar >/dev/null 2>&1; then
  echo "stage.sh: building the Java binding (vehicle.jar, libvehicle_java.so)" >&2
  "$CARGO" build --manifest-path "$workspace/Cargo.toml" -p vehicle-java --lib --profile "$profile"
  [ -f "$build/libvehicle_java.so" ] || { echo "$0: $build/libvehicle_java.so was not built" >&2; exit 1; }
  mkdir -p "$prefix/lib/java" "$work/classes"
  javac -Xlint:-options -Xlint -Werror --release 8 -d "$work/classes" \
    $(find "$workspace/java/src" -name '*.java' | sort)
  jar cf "$work/vehicle.jar" -C "$work/classes" .
  put "$work/vehicle.jar" "$prefix/lib/java/vehicle.jar"
  put "$build/libvehicle_java.so" "$prefix/lib/libvehicle_java.so"
else
  echo "stage.sh: javac or jar not found: the Java binding (lib/java/vehicle.jar) is not staged" >&2
fi

echo "stage.sh: staged in $prefix" >&2
