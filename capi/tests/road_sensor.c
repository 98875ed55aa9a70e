/*
 * road_sensor: the RoadSensor extension (webots/vehicle/road_sensor.h) of a world file's car,
 * and the Webots-style messages for its misuse.
 *
 * World: worlds/road.toml, a straight road along x (one 3.5 m lane each way, no borders) and
 * a BmwX5 whose origin is at (20, -1.2) heading 0.05 rad, the sensor at its origin.
 *
 * Expected values, the closed forms of the road (the parked body settles by millimetres):
 *   road 0, lane -1, station 20 m                                       +- 0.01 m
 *   lateral offset -1.2 - (-1.75) = 0.55 m                              +- 0.01 m
 *   heading error 0.05 rad                                              +- 0.001 rad
 *   left line (the centre line, y = 0) 1.2 m, right line 2.3 m          +- 0.01 m
 *   left edge (y = 3.5) 4.7 m, right edge (y = -3.5) 2.3 m              +- 0.01 m
 *   lane width 3.5 m, curvature and curvature ahead 0                   exact
 * Tag: the car's 27 car-library tags, then the sensor (28).
 */

#include <webots/device.h>
#include <webots/robot.h>
#include <webots/vehicle/road_sensor.h>

#include "check.h"

/* Announces a misuse on stdout with the stderr text expected for it. */
static void call(const char *what, const char *expected_stderr) {
  printf("road_sensor: call: %s -> stderr: %s\n", what, expected_stderr);
  fflush(stdout);
}

int main(void) {
  WbDeviceTag lanes;
  wb_robot_init();
  check_begin("road_sensor");

  lanes = wb_robot_get_device("lanes");
  check_int("road sensor tag", lanes, 28);
  check_int("node type", wb_device_get_node_type(lanes), VEHICLE_NODE_ROAD_SENSOR);
  check_close("lookahead (m)", vehicle_road_sensor_get_lookahead(lanes), 15.0, 0.0);

  call("vehicle_road_sensor_get_lateral_offset(lanes) while disabled",
       "Error: vehicle_road_sensor_get_lateral_offset() called for a disabled device! Please use: "
       "vehicle_road_sensor_enable().");
  check_true(isnan(vehicle_road_sensor_get_lateral_offset(lanes)), "offset NaN before enabling");
  call("vehicle_road_sensor_enable(lanes, -5)",
       "Error: vehicle_road_sensor_enable() called with negative sampling period.");
  vehicle_road_sensor_enable(lanes, -5);
  check_int("sampling period after a negative one", vehicle_road_sensor_get_sampling_period(lanes), 0);

  vehicle_road_sensor_enable(lanes, 20);
  check_int("sampling period", vehicle_road_sensor_get_sampling_period(lanes), 20);
  wb_robot_step(10);
  check_int("lane before the first sample", vehicle_road_sensor_get_lane(lanes), 0);
  check_int("road before the first sample", vehicle_road_sensor_get_road(lanes), -1);
  wb_robot_step(10);

  check_int("road", vehicle_road_sensor_get_road(lanes), 0);
  check_int("lane", vehicle_road_sensor_get_lane(lanes), -1);
  check_close("station (m)", vehicle_road_sensor_get_station(lanes), 20.0, 0.01);
  check_close("lateral offset (m)", vehicle_road_sensor_get_lateral_offset(lanes), 0.55, 0.01);
  check_close("heading error (rad)", vehicle_road_sensor_get_heading_error(lanes), 0.05, 0.001);
  check_close("left line (m)", vehicle_road_sensor_get_left_line_distance(lanes), 1.2, 0.01);
  check_close("right line (m)", vehicle_road_sensor_get_right_line_distance(lanes), 2.3, 0.01);
  check_close("left edge (m)", vehicle_road_sensor_get_left_edge_distance(lanes), 4.7, 0.01);
  check_close("right edge (m)", vehicle_road_sensor_get_right_edge_distance(lanes), 2.3, 0.01);
  check_close("lane width (m)", vehicle_road_sensor_get_lane_width(lanes), 3.5, 0.0);
  check_close("curvature (1/m)", vehicle_road_sensor_get_curvature(lanes), 0.0, 0.0);
  check_close("curvature ahead (1/m)", vehicle_road_sensor_get_curvature_ahead(lanes), 0.0, 0.0);

  call("vehicle_road_sensor_get_lane(1)", "Error: vehicle_road_sensor_get_lane(): invalid device tag.");
  check_int("lane of a motor's tag", vehicle_road_sensor_get_lane(1), 0);

  wb_robot_cleanup();
  return check_finish();
}
