#!/usr/bin/env bash
# check_headers.sh INCLUDE_DIR
#
# Compile checks of the Webots-compatible headers in INCLUDE_DIR (the directory holding
# webots/...), and syntax checks of the test programs next to this script:
#   * every C header alone as C89, C99, C11 and C17 (and C2x and GNU C89 when the compiler has
#     them) with -pedantic -Wall -Wextra -Werror, and as C++98, C++11 and C++17;
#   * every C++ header alone as C++11 and C++17 (and C++20 when available);
#   * enumeration values, type sizes and the R2018a typedef aliases (compile-time assertions);
#   * old controllers: wbu_driver_step(TIME_STEP) compiles in C, <webots/driver.h> and
#     <webots/car.h> still work, deprecated functions do warn;
#   * <stdbool.h> before or after the headers;
#   * C++: the C enumerators (OFF, LEFT, SPEED...) do not leak out of Driver.hpp/Car.hpp, and
#     driver.h may be included before or after Driver.hpp;
#   * the test programs (C99 and C11; the C++ one as C++11 and C++17) with -fsyntax-only.
# Environment: CC (default gcc) and CXX (default g++). Exits non-zero if any check fails.
set -uo pipefail

if [ $# -ne 1 ] || [ ! -d "$1/webots" ]; then
  echo "usage: $0 INCLUDE_DIR   (the directory that contains webots/vehicle/driver.h)" >&2
  exit 2
fi
INC=$(cd "$1" && pwd)
TESTS=$(cd "$(dirname "$0")" && pwd)
CC=${CC:-gcc}
CXX=${CXX:-g++}
WARN=(-pedantic -Wall -Wextra -Werror)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

passed=0
failed=0

# run_compiler EXPECT NAME LANG STD FILE [EXTRA_ARGS...] : compile FILE (syntax only) as LANG (c
# or c++) with -std=STD and the warning flags; EXPECT is "ok" (must compile) or "error" (must not).
run_compiler() {
  local expect=$1 name=$2 lang=$3 std=$4 file=$5
  shift 5
  local compiler=$CC
  if [ "$lang" = c++ ]; then compiler=$CXX; fi
  if "$compiler" -x "$lang" -std="$std" "${WARN[@]}" "$@" -I "$INC" -fsyntax-only "$file" >"$WORK/log" 2>&1; then
    if [ "$expect" = ok ]; then
      passed=$((passed + 1))
    else
      failed=$((failed + 1))
      echo "FAIL (compiled but must not): $name"
    fi
  else
    if [ "$expect" = ok ]; then
      failed=$((failed + 1))
      echo "FAIL: $name"
      sed 's/^/    /' "$WORK/log"
    else
      passed=$((passed + 1))
    fi
  fi
}

# check NAME LANG STD SOURCE : SOURCE (text) must compile.
check() {
  printf '%s\n' "$4" >"$WORK/snippet"
  run_compiler ok "$1" "$2" "$3" "$WORK/snippet"
}

# check_rejected NAME LANG STD SOURCE : SOURCE (text) must not compile.
check_rejected() {
  printf '%s\n' "$4" >"$WORK/snippet"
  run_compiler error "$1" "$2" "$3" "$WORK/snippet"
}

# check_file NAME LANG STD FILE : FILE must compile.
check_file() {
  run_compiler ok "$1" "$2" "$3" "$4"
}

# supports COMPILER LANG STD : whether the compiler knows -std=STD.
supports() {
  echo "" | "$1" -x "$2" -std="$3" -fsyntax-only - >/dev/null 2>&1
}

C_HEADERS=(webots/types.h webots/robot.h webots/differential_wheels.h webots/vehicle/driver.h webots/vehicle/car.h
  webots/driver.h webots/car.h webots/nodes.h webots/device.h webots/gps.h webots/inertial_unit.h webots/gyro.h
  webots/accelerometer.h webots/compass.h webots/distance_sensor.h webots/radar_target.h webots/radar.h
  webots/lidar_point.h webots/lidar.h webots/vehicle/road_sensor.h)
CPP_HEADERS=(webots/vehicle/Driver.hpp webots/vehicle/Car.hpp webots/Device.hpp webots/GPS.hpp webots/InertialUnit.hpp
  webots/Gyro.hpp webots/Accelerometer.hpp webots/Compass.hpp webots/DistanceSensor.hpp webots/Radar.hpp
  webots/Lidar.hpp webots/vehicle/RoadSensor.hpp)

C_STDS=(c89 c99 c11 c17)
for std in c2x gnu89; do
  if supports "$CC" c "$std"; then C_STDS+=("$std"); fi
done
CXX_STDS_FOR_C=(c++98 c++11 c++17)
CXX_STDS=(c++11 c++17)
if supports "$CXX" c++ c++20; then CXX_STDS+=(c++20); fi

# ---- Each header alone. ----
for header in "${C_HEADERS[@]}"; do
  for std in "${C_STDS[@]}"; do
    check "$header alone as $std" c "$std" "#include <$header>"
  done
  for std in "${CXX_STDS_FOR_C[@]}"; do
    check "$header alone as $std" c++ "$std" "#include <$header>"
  done
done
for header in "${CPP_HEADERS[@]}"; do
  for std in "${CXX_STDS[@]}"; do
    check "$header alone as $std" c++ "$std" "#include <$header>"
  done
  check_rejected "$header refuses C++98 with a clear #error" c++ c++98 "#include <$header>"
done

# ---- Values, sizes and aliases, in C and C++. ----
VALUES='#include <webots/differential_wheels.h>
#include <webots/robot.h>
#include <webots/vehicle/car.h>
#include <webots/vehicle/driver.h>
#define ASSERT(name, condition) typedef char name[(condition) ? 1 : -1]
ASSERT(indicator_values, OFF == 0 && RIGHT == 1 && LEFT == 2);
ASSERT(control_values, UNDEFINED_CONTROL_MODE == -1 && SPEED == 0 && TORQUE == 1);
ASSERT(wiper_values, DOWN == 0 && SLOW == 1 && NORMAL == 2 && FAST == 3);
ASSERT(type_values, WBU_CAR_TRACTION == 0 && WBU_CAR_PROPULSION == 1 && WBU_CAR_FOUR_BY_FOUR == 2);
ASSERT(engine_values, WBU_CAR_COMBUSTION_ENGINE == 0 && WBU_CAR_ELECTRIC_ENGINE == 1 &&
                        WBU_CAR_PARALLEL_HYBRID_ENGINE == 2 && WBU_CAR_POWER_SPLIT_HYBRID_ENGINE == 3);
ASSERT(wheel_values, WBU_CAR_WHEEL_FRONT_RIGHT == 0 && WBU_CAR_WHEEL_FRONT_LEFT == 1 && WBU_CAR_WHEEL_REAR_RIGHT == 2 &&
                       WBU_CAR_WHEEL_REAR_LEFT == 3 && WBU_CAR_WHEEL_NB == 4);
ASSERT(enum_sizes, sizeof(WbuDriverIndicatorState) == sizeof(int) && sizeof(WbuDriverControlMode) == sizeof(int) &&
                     sizeof(WbuDriverWiperMode) == sizeof(int) && sizeof(WbuCarType) == sizeof(int) &&
                     sizeof(WbuCarEngineType) == sizeof(int) && sizeof(WbuCarWheelIndex) == sizeof(int));
ASSERT(tag_size, sizeof(WbDeviceTag) == sizeof(unsigned short));
ASSERT(bool_size, sizeof(bool) == 1);
ASSERT(bool_values, true == 1 && false == 0);
ASSERT(aliases, sizeof(wbu_wipers_mode) == sizeof(WbuDriverWiperMode) &&
                  sizeof(wbu_indicator_state) == sizeof(WbuDriverIndicatorState) &&
                  sizeof(wbu_control_mode) == sizeof(WbuDriverControlMode) && sizeof(wbu_car_type) == sizeof(WbuCarType) &&
                  sizeof(wbu_car_engine_type) == sizeof(WbuCarEngineType) &&
                  sizeof(wbu_car_wheel_index) == sizeof(WbuCarWheelIndex));'
for std in "${C_STDS[@]}"; do
  check "enumeration values, sizes, R2018a aliases as $std" c "$std" "$VALUES"
done
for std in "${CXX_STDS_FOR_C[@]}"; do
  check "enumeration values, sizes, R2018a aliases as $std" c++ "$std" "$VALUES"
done

# ---- Every function, with its exact type: C++ reads () as (void), so the pointer types match
# exactly there (and in C every pointer assignment is at least compatible). ----
SIGNATURES='#include <webots/differential_wheels.h>
#include <webots/robot.h>
#include <webots/vehicle/car.h>
#include <webots/vehicle/driver.h>
void signatures(void);
void signatures(void) {
  bool (*fb)(void);
  void (*fv)(void);
  int (*fi)(void);
  int (*fii)(int);
  double (*fd)(void);
  void (*fvd)(double);
  void (*fvb)(bool);
  void (*fvi)(int);
  void (*fvdd)(double, double);
  WbDeviceTag (*ftag)(const char *);
  WbuDriverIndicatorState (*find)(void);
  WbuDriverControlMode (*fmode)(void);
  WbuDriverWiperMode (*fwiper)(void);
  void (*fsetind)(WbuDriverIndicatorState);
  void (*fsetwiper)(WbuDriverWiperMode);
  WbuCarType (*ftype)(void);
  WbuCarEngineType (*fengine)(void);
  double (*fwheel)(WbuCarWheelIndex);
  fi = wb_robot_init; fii = wb_robot_step; fv = wb_robot_cleanup; fd = wb_robot_get_time;
  fd = wb_robot_get_basic_time_step; ftag = wb_robot_get_device;
  fb = wbu_driver_initialization_is_possible; fb = initialization_is_possible;
  fv = wbu_driver_init; fv = wbu_driver_cleanup; fi = wbu_driver_step;
  fvd = wbu_driver_set_steering_angle; fd = wbu_driver_get_steering_angle;
  fvd = wbu_driver_set_cruising_speed; fd = wbu_driver_get_target_cruising_speed; fd = wbu_driver_get_current_speed;
  fvd = wbu_driver_set_throttle; fd = wbu_driver_get_throttle;
  fvd = wbu_driver_set_brake_intensity; fd = wbu_driver_get_brake_intensity;
  fsetind = wbu_driver_set_indicator; find = wbu_driver_get_indicator;
  fvb = wbu_driver_set_hazard_flashers; fb = wbu_driver_get_hazard_flashers;
  fvb = wbu_driver_set_dipped_beams; fvb = wbu_driver_set_antifog_lights;
  fb = wbu_driver_get_dipped_beams; fb = wbu_driver_get_antifog_lights;
  fd = wbu_driver_get_rpm; fi = wbu_driver_get_gear; fvi = wbu_driver_set_gear; fi = wbu_driver_get_gear_number;
  fmode = wbu_driver_get_control_mode;
  fsetwiper = wbu_driver_set_wiper_mode; fwiper = wbu_driver_get_wiper_mode;
  fv = wbu_car_init; fv = wbu_car_cleanup; ftype = wbu_car_get_type; fengine = wbu_car_get_engine_type;
  fvd = wbu_car_set_indicator_period; fd = wbu_car_get_indicator_period;
  fb = wbu_car_get_backwards_lights; fb = wbu_car_get_brake_lights;
  fd = wbu_car_get_track_front; fd = wbu_car_get_track_rear; fd = wbu_car_get_wheelbase;
  fd = wbu_car_get_front_wheel_radius; fd = wbu_car_get_rear_wheel_radius;
  fwheel = wbu_car_get_wheel_encoder; fwheel = wbu_car_get_wheel_speed;
  fvd = wbu_car_set_left_steering_angle; fvd = wbu_car_set_right_steering_angle;
  fd = wbu_car_get_right_steering_angle; fd = wbu_car_get_left_steering_angle;
  fvb = wbu_car_enable_limited_slip_differential; fvb = wbu_car_enable_indicator_auto_disabling;
  fvdd = wb_differential_wheels_set_speed; fd = wb_differential_wheels_get_left_speed;
  fd = wb_differential_wheels_get_right_speed; fd = wb_differential_wheels_get_max_speed;
  fd = wb_differential_wheels_get_speed_unit; fvi = wb_differential_wheels_enable_encoders;
  fv = wb_differential_wheels_disable_encoders; fi = wb_differential_wheels_get_encoders_sampling_period;
  fd = wb_differential_wheels_get_left_encoder; fd = wb_differential_wheels_get_right_encoder;
  fvdd = wb_differential_wheels_set_encoders;
  (void)fb; (void)fv; (void)fi; (void)fii; (void)fd; (void)fvd; (void)fvb; (void)fvi; (void)fvdd; (void)ftag;
  (void)find; (void)fmode; (void)fwiper; (void)fsetind; (void)fsetwiper; (void)ftype; (void)fengine; (void)fwheel;
}'
for std in "${CXX_STDS_FOR_C[@]}"; do
  check "every function declared with its type, as $std" c++ "$std" "$SIGNATURES"
done
check "every function declared with a compatible type, as c99" c c99 "$SIGNATURES"

# ---- Old controllers. ----
OLD_CONTROLLER='#include <webots/car.h>
#include <webots/driver.h>
#define TIME_STEP 50
int old_controller(void);
int old_controller(void) {
  wbu_indicator_state state = RIGHT;
  wbu_car_wheel_index wheel = WBU_CAR_WHEEL_REAR_LEFT;
  wbu_driver_init();
  wbu_driver_set_indicator(state);
  while (wbu_driver_step(TIME_STEP) != -1) { /* an argument Webots controllers pass and the library ignores */
    if (wbu_car_get_wheel_speed(wheel) > 1.0 && initialization_is_possible())
      break;
  }
  wbu_driver_cleanup();
  return 0;
}'
for std in c89 c99 c11 c17; do
  check "old controller: <webots/driver.h>, wbu_driver_step(TIME_STEP), R2018a names, as $std" c "$std" "$OLD_CONTROLLER"
done
for call in "wbu_driver_set_brake(0.5)" "(void)wbu_driver_get_brake()" "wbu_driver_set_indicator_warning(true)" \
  "wbu_driver_set_wipers_mode(FAST)" "(void)wbu_driver_get_wipers_mode()"; do
  check_rejected "deprecated $call warns (an error under -Werror)" c c99 \
    "#include <webots/vehicle/driver.h>
void f(void);
void f(void) { $call; }"
  check "deprecated $call compiles with WB_DEPRECATED defined empty" c c99 \
    "#define WB_DEPRECATED
#include <webots/vehicle/driver.h>
void f(void);
void f(void) { $call; }"
done

# ---- <stdbool.h> before or after; everything together. ----
ALL_C='#include <webots/types.h>
#include <webots/robot.h>
#include <webots/differential_wheels.h>
#include <webots/vehicle/driver.h>
#include <webots/vehicle/car.h>
#include <webots/driver.h>
#include <webots/car.h>
#include <webots/nodes.h>
#include <webots/device.h>
#include <webots/gps.h>
#include <webots/inertial_unit.h>
#include <webots/gyro.h>
#include <webots/accelerometer.h>
#include <webots/compass.h>
#include <webots/distance_sensor.h>
#include <webots/radar.h>
#include <webots/lidar.h>
void use(bool b);
void use(bool b) { wbu_driver_set_hazard_flashers(b && true); }'
for std in c99 c11 c17; do
  check "<stdbool.h> before the headers, $std" c "$std" "#include <stdbool.h>
$ALL_C"
  check "<stdbool.h> after the headers, $std" c "$std" "$ALL_C
#include <stdbool.h>
bool after = true;"
done
check "all C headers together, c89" c c89 "$ALL_C"
check "all headers together, c++17" c++ c++17 "$ALL_C
#include <webots/vehicle/Car.hpp>"

# ---- WbNodeType: the R2023b+ numbering (spec section 1). ----
NODES='#include <webots/nodes.h>
#include <webots/gps.h>
typedef char first_robot_34[(WB_NODE_ROBOT == 34) ? 1 : -1];
typedef char accelerometer_35[(WB_NODE_ACCELEROMETER == 35) ? 1 : -1];
typedef char compass_39[(WB_NODE_COMPASS == 39) ? 1 : -1];
typedef char gps_44[(WB_NODE_GPS == 44) ? 1 : -1];
typedef char gyro_45[(WB_NODE_GYRO == 45) ? 1 : -1];
typedef char inertial_unit_46[(WB_NODE_INERTIAL_UNIT == 46) ? 1 : -1];
typedef char rotational_motor_57[(WB_NODE_ROTATIONAL_MOTOR == 57) ? 1 : -1];
typedef char vacuum_gripper_61[(WB_NODE_VACUUM_GRIPPER == 61) ? 1 : -1];
typedef char solid_80[(WB_NODE_SOLID == 80) ? 1 : -1];
typedef char distance_sensor_42[(WB_NODE_DISTANCE_SENSOR == 42) ? 1 : -1];
typedef char lidar_48[(WB_NODE_LIDAR == 48) ? 1 : -1];
typedef char radar_54[(WB_NODE_RADAR == 54) ? 1 : -1];
typedef char radio_87[(WB_NODE_RADIO == 87) ? 1 : -1];
typedef char wgs84_1[(WB_GPS_WGS84_COORDINATE == 1) ? 1 : -1];'
check "WbNodeType and WbGpsCoordinateSystem values, c89" c c89 "$NODES"
check "WbNodeType and WbGpsCoordinateSystem values, c++11" c++ c++11 "$NODES"

# ---- C++ wrapper: no enumerator leak, include order, singleton and step(int) rules. ----
for std in "${CXX_STDS[@]}"; do
  check "Car.hpp leaves OFF, LEFT, SPEED... to the controller, $std" c++ "$std" \
    "#include <webots/vehicle/Car.hpp>
enum Own { OFF, RIGHT, LEFT, SPEED, TORQUE, DOWN, SLOW, NORMAL, FAST, UNDEFINED_CONTROL_MODE };"
  check "driver.h after Driver.hpp still defines the enumerators, $std" c++ "$std" \
    "#include <webots/vehicle/Driver.hpp>
#include <webots/vehicle/driver.h>
static_assert(LEFT == 2 && FAST == 3 && UNDEFINED_CONTROL_MODE == -1, \"values\");
WbuDriverIndicatorState s = RIGHT;"
  check "driver.h before Car.hpp, $std" c++ "$std" \
    "#include <webots/vehicle/driver.h>
#include <webots/vehicle/Car.hpp>
static_assert(LEFT == 2 && webots::Driver::INDICATOR_LEFT == 2, \"values\");"
  check "a class derived from webots::Car calls step(), $std" c++ "$std" \
    "#include <webots/vehicle/Car.hpp>
struct MyCar : webots::Car {
  int run() { return step(); }
};"
  check_rejected "Driver::step(int) cannot be called, $std" c++ "$std" \
    "#include <webots/vehicle/Car.hpp>
int f(webots::Car &c) { return c.step(32); }"
  check_rejected "a Car cannot be copied, $std" c++ "$std" \
    "#include <webots/vehicle/Car.hpp>
void f(webots::Car &c) { webots::Car copy(c); (void)copy; }"
done

# ---- The test programs. ----
for program in "$TESTS"/*.c; do
  for std in c99 c11; do
    check_file "$(basename "$program") as $std" c "$std" "$program"
  done
done
for program in "$TESTS"/*.cpp; do
  for std in c++11 c++17; do
    check_file "$(basename "$program") as $std" c++ "$std" "$program"
  done
done

echo "check_headers: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
