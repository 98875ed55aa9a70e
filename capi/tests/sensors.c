/*
 * sensors: the GPS, InertialUnit, Gyro, Accelerometer and Compass of a world file's car, the
 * device enumeration of webots/robot.h and webots/device.h, and Webots' messages for misuse.
 *
 * World: worlds/sensors.toml, a BmwX5 parked at the origin heading north-east (yaw pi/4 from
 * east, the world being ENU), with a GPS on the top sensor slot (1 m ahead of the rear axle,
 * 1.45 m up), an inertial unit, a gyro, an accelerometer whose lookup table multiplies by 100
 * (rows [-20, -2000, 0] and [20, 2000, 0]) and a compass at the car's origin.
 *
 * Expected values, with the parked body on its springs pitched by a few mrad (tolerances):
 *   compass = (sin pi/4, cos pi/4, 0) = (0.707107, 0.707107, 0)            +- 0.005
 *   inertial unit yaw = pi/4 = 0.785398 rad, roll and pitch 0              +- 0.005 rad
 *   quaternion [0, 0, sin pi/8, cos pi/8] = [0, 0, 0.382683, 0.923880]    +- 0.005
 *   accelerometer = 100 * (0, 0, 9.81) = (0, 0, 981)                       +- 5
 *   gyro = (0, 0, 0) rad/s                                                 +- 0.001
 *   GPS x, y = R(pi/4) (1, 0) = (0.707107, 0.707107) m                     +- 0.02 m
 *   GPS speed 0 m/s                                                        +- 0.01 m/s
 * Tags: the car's 27 car-library tags, then the sensors in file order (28 to 32).
 */

#include <stdlib.h>
#include <string.h>
#include <webots/accelerometer.h>
#include <webots/compass.h>
#include <webots/device.h>
#include <webots/gps.h>
#include <webots/gyro.h>
#include <webots/inertial_unit.h>
#include <webots/nodes.h>
#include <webots/robot.h>

#include "check.h"

/* Announces a misuse on stdout with the stderr text Webots prints for it ("" if none). */
static void call(const char *what, const char *expected_stderr) {
  if (expected_stderr[0] != '\0')
    printf("sensors: call: %s -> stderr: %s\n", what, expected_stderr);
  else
    printf("sensors: call: %s\n", what);
  fflush(stdout);
}

static void step(int count) {
  int i;
  for (i = 0; i < count; ++i)
    if (wb_robot_step(10) == -1)
      check_fatal("wb_robot_step(10) returned -1 at t = %g s", wb_robot_get_time());
}

int main(void) {
  WbDeviceTag gps, unit, gyro, accelerometer, compass;
  const double *v;
  const double *table;
  double kept[3];
  char *text;
  wb_robot_init();
  check_begin("sensors");

  /* Enumeration. */
  check_int("wb_robot_get_number_of_devices()", wb_robot_get_number_of_devices(), 32);
  gps = wb_robot_get_device("gps");
  unit = wb_robot_get_device("inertial unit");
  gyro = wb_robot_get_device("gyro");
  accelerometer = wb_robot_get_device("accelerometer");
  compass = wb_robot_get_device("compass");
  check_int("gps tag", gps, 28);
  check_int("compass tag", compass, 32);
  check_int("wb_robot_get_device_by_index(27)", wb_robot_get_device_by_index(27), 28);
  check_true(strcmp(wb_device_get_name(unit), "inertial unit") == 0, "wb_device_get_name(29)");
  check_true(strcmp(wb_device_get_model(unit), "") == 0, "wb_device_get_model(29)");
  check_int("node type of gps", wb_device_get_node_type(gps), WB_NODE_GPS);
  check_int("node type of inertial unit", wb_device_get_node_type(unit), WB_NODE_INERTIAL_UNIT);
  check_int("node type of gyro", wb_device_get_node_type(gyro), WB_NODE_GYRO);
  check_int("node type of accelerometer", wb_device_get_node_type(accelerometer), WB_NODE_ACCELEROMETER);
  check_int("node type of compass", wb_device_get_node_type(compass), WB_NODE_COMPASS);
  check_int("node type of right_steer", wb_device_get_node_type(1), WB_NODE_ROTATIONAL_MOTOR);
  check_int("node type of brake_lights", wb_device_get_node_type(23), WB_NODE_LED);
  /* The BmwX5 drives its front wheels: tag 7 (right_rear_wheel) is a hole. */
  check_true(wb_device_get_name(7) == NULL, "wb_device_get_name(7) is NULL (no rear motor)");
  check_int("node type of tag 7", wb_device_get_node_type(7), WB_NODE_NO_NODE);
  check_true(wb_device_get_name(99) == NULL, "wb_device_get_name(99) is NULL");
  call("wb_robot_get_device_by_index(32)",
       "Error: The index of wb_robot_get_device_by_index() is out of the bounds.");
  check_int("wb_robot_get_device_by_index(32)", wb_robot_get_device_by_index(32), 0);

  /* Before enabling: NaN, with Webots' error for a disabled device. */
  call("wb_gps_get_values(gps) while disabled",
       "Error: wb_gps_get_values() called for a disabled device! Please use: wb_gps_enable().");
  v = wb_gps_get_values(gps);
  check_true(v != NULL && isnan(v[0]) && isnan(v[1]) && isnan(v[2]), "GPS values NaN before enabling");
  call("wb_gps_enable(gps, -10)", "Error: wb_gps_enable() called with negative sampling period.");
  wb_gps_enable(gps, -10);
  check_int("wb_gps_get_sampling_period after a negative period", wb_gps_get_sampling_period(gps), 0);

  /* Enabled at 20 ms: NaN until one full period, then sampled. */
  wb_gps_enable(gps, 20);
  wb_inertial_unit_enable(unit, 10);
  wb_gyro_enable(gyro, 10);
  wb_accelerometer_enable(accelerometer, 10);
  wb_compass_enable(compass, 10);
  check_int("wb_gps_get_sampling_period", wb_gps_get_sampling_period(gps), 20);
  step(1);
  check_true(isnan(wb_gps_get_values(gps)[0]), "GPS NaN after 10 of its 20 ms");
  check_true(isnan(wb_gps_get_speed(gps)), "GPS speed NaN after 10 of its 20 ms");
  step(299); /* 3 s: the car has settled on its springs (at 1 s it still bounces by 0.15 m/s^2). */

  v = wb_compass_get_values(compass);
  check_close("compass x", v[0], 0.707107, 0.005);
  check_close("compass y", v[1], 0.707107, 0.005);
  check_close("compass z", v[2], 0.0, 0.005);
  v = wb_inertial_unit_get_roll_pitch_yaw(unit);
  check_close("roll (rad)", v[0], 0.0, 0.005);
  check_close("pitch (rad)", v[1], 0.0, 0.005);
  check_close("yaw (rad)", v[2], 0.785398, 0.005);
  v = wb_inertial_unit_get_quaternion(unit);
  check_close("quaternion z", v[2], 0.382683, 0.005);
  check_close("quaternion w", v[3], 0.923880, 0.005);
  check_close("wb_inertial_unit_get_noise", wb_inertial_unit_get_noise(unit), 0.0, 0.0);
  v = wb_gyro_get_values(gyro);
  check_close("gyro x (rad/s)", v[0], 0.0, 0.001);
  check_close("gyro z (rad/s)", v[2], 0.0, 0.001);
  v = wb_accelerometer_get_values(accelerometer);
  check_close("accelerometer x (x100)", v[0], 0.0, 5.0);
  check_close("accelerometer z (x100)", v[2], 981.0, 5.0);
  check_int("wb_accelerometer_get_lookup_table_size", wb_accelerometer_get_lookup_table_size(accelerometer), 2);
  table = wb_accelerometer_get_lookup_table(accelerometer);
  check_true(table != NULL && table[0] == -20.0 && table[1] == -2000.0 && table[3] == 20.0 && table[4] == 2000.0,
             "accelerometer lookup table rows");
  check_int("wb_gyro_get_lookup_table_size (empty)", wb_gyro_get_lookup_table_size(gyro), 0);
  check_true(wb_gyro_get_lookup_table(gyro) == NULL, "wb_gyro_get_lookup_table (empty) is NULL");
  v = wb_gps_get_values(gps);
  check_close("GPS x (m)", v[0], 0.707107, 0.02);
  check_close("GPS y (m)", v[1], 0.707107, 0.02);
  check_close("GPS speed (m/s)", wb_gps_get_speed(gps), 0.0, 0.01);
  v = wb_gps_get_speed_vector(gps);
  check_close("GPS speed vector x (m/s)", v[0], 0.0, 0.01);
  check_int("wb_gps_get_coordinate_system", wb_gps_get_coordinate_system(gps), WB_GPS_LOCAL_COORDINATE);
  /* 12.625 degrees = 12 degrees 37.5 minutes = 12 degrees 37 minutes 30 seconds (exact in binary). */
  text = (char *)wb_gps_convert_to_degrees_minutes_seconds(12.625);
  check_true(strcmp(text, "12\xc2\xb0 37\xe2\x80\xb2 30\xe2\x80\xb3") == 0, "12.625 degrees = %s", text);
  free(text);

  /* Wrong tags. */
  call("wb_gps_get_values(compass)", "Error: wb_gps_get_values(): invalid device tag.");
  check_true(wb_gps_get_values(compass) == NULL, "wb_gps_get_values(compass) is NULL");
  call("wb_gyro_get_values(200)",
       "Error: device with tag=200 not found.\\nError: wb_gyro_get_values(): invalid device tag.");
  check_true(wb_gyro_get_values(200) == NULL, "wb_gyro_get_values(200) is NULL");
  call("wb_accelerometer_get_values(gps)", "");
  check_true(wb_accelerometer_get_values(gps) == NULL, "wb_accelerometer_get_values(gps) is NULL");
  call("wb_inertial_unit_get_quaternion(gyro)", "Error: wb_inertial_unit_get_quaternion(): invalid device tag.");
  check_true(wb_inertial_unit_get_quaternion(gyro) == NULL, "wb_inertial_unit_get_quaternion(gyro) is NULL");
  call("wb_compass_enable(gyro, 10)", "Error: wb_compass_enable(): invalid device tag.");
  wb_compass_enable(gyro, 10);
  call("wb_gps_get_sampling_period(unit)", "Error: wb_gps_get_sampling_period(): invalid device tag.");
  check_int("wb_gps_get_sampling_period(unit)", wb_gps_get_sampling_period(unit), 0);

  /* Disabled: the last sample stays readable, with the error. */
  v = wb_gps_get_values(gps);
  kept[0] = v[0];
  kept[1] = v[1];
  kept[2] = v[2];
  wb_gps_disable(gps);
  check_int("wb_gps_get_sampling_period after disable", wb_gps_get_sampling_period(gps), 0);
  step(5);
  call("wb_gps_get_values(gps) after disable",
       "Error: wb_gps_get_values() called for a disabled device! Please use: wb_gps_enable().");
  v = wb_gps_get_values(gps);
  check_true(v[0] == kept[0] && v[1] == kept[1] && v[2] == kept[2], "the last GPS sample is kept");

  wb_robot_cleanup();
  return check_finish();
}
