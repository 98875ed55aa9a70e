/*
 * battery: the battery sensor of worlds/battery.toml's car (Webots' Robot field
 * battery = [20000, 3.6e6, 0]: 20 kJ of 1 kWh) through webots/robot.h, Webots' messages for
 * misuse, and the controller stopped when the energy reaches 0.
 *
 * Enabled at 0 with a 30 ms period, the sensor samples at 30, 60, 90 ... ms: NaN before. The
 * car stands without throttle for the first sample, which reads the field's 20 kJ (the engine's
 * pack holds it at the starting charge to 1e-3 J, the bisection's resolution being far finer).
 * At full throttle the readings fall at each sample and hold between samples, until the battery
 * is empty: wbu_driver_step() and wb_robot_step() return -1 from then on, time stops, and the
 * last reading (taken before the battery emptied, no sensor refreshing once it is) is > 0.
 */

#include <math.h>
#include <webots/robot.h>
#include <webots/vehicle/driver.h>

#include "check.h"

static void call(const char *what, const char *expected_stderr) {
  printf("battery: call: %s -> stderr: %s\n", what, expected_stderr);
  fflush(stdout);
}

int main(void) {
  int t = 0, steps = 0, rising = 0, changed_between = 0;
  double value, last, stop_time;
  wbu_driver_init();
  check_begin("battery");
  call("wb_robot_battery_sensor_get_value while disabled",
       "Error: wb_robot_battery_sensor_get_value() called for a disabled device! Please use: "
       "wb_robot_battery_sensor_enable().");
  check_true(isnan(wb_robot_battery_sensor_get_value()), "value while disabled is NaN");
  call("wb_robot_battery_sensor_enable(-1)",
       "Error: wb_robot_battery_sensor_enable() called with negative sampling period.");
  wb_robot_battery_sensor_enable(-1);
  check_int("period after a negative one", wb_robot_battery_sensor_get_sampling_period(), 0);
  wb_robot_battery_sensor_enable(30);
  check_int("period", wb_robot_battery_sensor_get_sampling_period(), 30);
  wbu_driver_step();
  wbu_driver_step();
  check_true(isnan(wb_robot_battery_sensor_get_value()), "NaN before the first sample (20 ms)");
  wbu_driver_step();
  last = wb_robot_battery_sensor_get_value();
  check_close("first sample, standing (J)", last, 20000.0, 1e-3);
  wbu_driver_set_gear(1);
  wbu_driver_set_throttle(1.0);
  t = 30;
  while (wbu_driver_step() != -1) {
    t += 10;
    steps++;
    value = wb_robot_battery_sensor_get_value();
    if (t % 30 == 0) {
      if (value >= last && t > 120)
        rising++;
      last = value;
    } else if (value != last) {
      changed_between++;
    }
    if (steps > 3000)
      break;
  }
  stop_time = wb_robot_get_time();
  check_true(steps < 3000, "the battery emptied (%d steps)", steps);
  check_int("samples that did not fall at full throttle", rising, 0);
  check_int("readings changed between samples", changed_between, 0);
  check_true(last > 0.0 && last < 20000.0, "last reading %g J in (0, 20000)", last);
  check_close("last reading holds", wb_robot_battery_sensor_get_value(), last, 0.0);
  check_int("wb_robot_step once stopped", wb_robot_step(10), -1);
  check_int("wbu_driver_step once stopped", wbu_driver_step(), -1);
  check_close("time once stopped (s)", wb_robot_get_time(), stop_time, 0.0);
  wb_robot_battery_sensor_disable();
  check_int("period after disable", wb_robot_battery_sensor_get_sampling_period(), 0);
  wbu_driver_cleanup();
  return check_finish();
}
