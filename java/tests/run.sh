#!/usr/bin/env bash
# java/tests/run.sh [PREFIX]: the Java binding's tests, as a user builds and runs a controller.
#
# Stages the C API and the Java binding into PREFIX (a temporary directory by default) with
# `capi/stage.sh --debug`, compiles DriveParity.java against PREFIX/lib/java/vehicle.jar with
# the JDK's javac and drive_parity.c against the staged C libraries, runs both on
# worlds/drive.toml, and requires:
#   * DriveParity's own assertions (java -ea): device lookup, bad input without exceptions,
#     the range image as float[], the point cloud and recognised objects, the saved PNG files
#     read back, the loop ending at the world's duration;
#   * identical stdout: every driver/car getter, GPS, camera (recognition included) and lidar
#     (point cloud included) value after every step, as raw bits, equal to the C ABI's for the
#     same calls, and the bytes of the PNG files each saves of its display and camera;
#   * identical, non-empty stderr: the bad input's warnings are the C API's own;
#   * VehicleDriver.java, Webots' reference controller, compiles and runs to the world's end
#     with nothing on stderr.
# Needs cargo, cc, javac, jar and java.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$(dirname "$here")")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=${1:-$work/prefix}

"$root/capi/stage.sh" --debug "$prefix"
jar=$prefix/lib/java/vehicle.jar
[ -f "$jar" ] || { echo "$0: $jar was not staged (is javac on the PATH?)" >&2; exit 1; }

cc -std=c99 -Wall -Wextra -Werror -Wno-deprecated-declarations -I "$prefix/include" "$here/drive_parity.c" -o "$work/drive_parity" \
  -L "$prefix/lib/controller" -ldriver -lcar -Wl,-rpath,"$prefix/lib/controller" -lm
javac -Xlint:-options --release 8 -cp "$jar" -d "$work" "$here/DriveParity.java"

export VEHICLE_WORLD="$here/worlds/drive.toml"
unset VEHICLE_OUT
# Each runs in a directory of its own, where it saves PNG files (the display's, the camera's) and
# prints their bytes; relative file names keep the C API's messages about them equal.
mkdir "$work/c" "$work/java"
(cd "$work/c" && "$work/drive_parity") >"$work/c.out" 2>"$work/c.err"
(cd "$work/java" && exec java -ea -cp "$jar:$work" -Djava.library.path="$prefix/lib" DriveParity) >"$work/java.out" 2>"$work/java.err" || {
  echo "$0: DriveParity failed:" >&2
  cat "$work/java.err" >&2
  exit 1
}
diff -u "$work/c.out" "$work/java.out" || { echo "$0: Java getters differ from C's" >&2; exit 1; }
diff -u "$work/c.err" "$work/java.err" || { echo "$0: Java's stderr differs from C's" >&2; exit 1; }
[ -s "$work/c.err" ] || { echo "$0: the bad input printed no warning" >&2; exit 1; }
# Webots' reference controller, unchanged: compiled as a user would (javac -cp vehicle.jar) and
# run to the world's end; the driver library writes nothing to stderr for it.
javac -cp "$jar" -d "$work" "$here/VehicleDriver.java"
java -cp "$jar:$work" -Djava.library.path="$prefix/lib" VehicleDriver 2>"$work/driver.err"
[ ! -s "$work/driver.err" ] || { echo "$0: VehicleDriver wrote to stderr:" >&2; cat "$work/driver.err" >&2; exit 1; }

echo "java/tests/run.sh: $(wc -l <"$work/java.out") lines of getters equal to C's; stderr equal ($(wc -l <"$work/c.err") lines):"
sed 's/^/  /' "$work/c.err"
