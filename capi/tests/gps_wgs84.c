/*
 * gps_wgs84: a GPS in a world whose gpsCoordinateSystem is "WGS84" (worlds/gps_wgs84.toml)
 * through webots/gps.h: the coordinate system is WGS84 and the values are the reference's
 * latitude and longitude (degrees), the altitude the reference's plus the car's height (m).
 */

#include <webots/gps.h>
#include <webots/robot.h>

#include "check.h"

int main(void) {
  WbDeviceTag gps;
  const double *v;
  wb_robot_init();
  check_begin("gps_wgs84");
  gps = wb_robot_get_device("gps");
  check_true(gps != 0, "the GPS is found");
  check_int("coordinate system", wb_gps_get_coordinate_system(gps), WB_GPS_WGS84_COORDINATE);
  wb_gps_enable(gps, 10);
  wb_robot_step(10);
  v = wb_gps_get_values(gps);
  /* The car is parked within millimetres of the origin: 1e-6 degrees is 0.1 m. */
  check_close("latitude (deg)", v[0], 45.0, 1e-6);
  check_close("longitude (deg)", v[1], 3.0, 1e-6);
  /* The car's origin (rear axle, wheel-centre height) is under a metre above the ground. */
  check_true(v[2] > 100.0 && v[2] < 101.0, "altitude %f within [100, 101] m", v[2]);
  wb_robot_cleanup();
  return check_finish();
}
