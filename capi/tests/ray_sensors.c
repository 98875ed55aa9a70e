/*
 * ray_sensors: the Radar, Lidar and DistanceSensor of a world file's car (webots/radar.h,
 * webots/lidar.h, webots/distance_sensor.h) and Webots' messages for their misuse.
 *
 * World: worlds/rays.toml. The ego BmwX5 at the origin heading +x carries at its origin (the
 * rear-axle centre, h m above the ground, h read from its GPS) a default radar, a lidar of 9
 * rays over 0.8 rad tilted down by 0.2 rad, a distance sensor facing +y (lookup 0 m -> 0,
 * 10 m -> 1000) and a lidar of 0.5 m range; a parked BmwX5 (radarCrossSection 10 m^2) 30 m
 * ahead; a box whose face is at y = 5 m.
 *
 * Expected values (parked bodies pitch and roll by a few mrad: the tolerances):
 *   radar: one target at 30 m (+-0.05), radial speed 0 (+-0.01 m/s), azimuth 0 (+-0.005 rad),
 *          power = the radar equation for 20 dBm, 20 dBi, 24 GHz, 10 m^2 at that distance (1e-9)
 *   lidar: every ray meets the ground at h / sin(0.2) (+-0.05 m); the point cloud is the range
 *          image converted, r (cos t cos p, sin t cos p, sin p) with t = 0.4 - (j + 1/2) 0.8/9
 *          and p = -0.2 (1e-4 m)
 *   short lidar: nothing within 0.5 m, every value +inf
 *   distance sensor: 100 (5 - gps y) (+-1, i.e. 1 cm)
 * Tags: the car's 27 car-library tags, then GPS 28, radar 29, lidar 30, distance sensor 31,
 * short lidar 32.
 */

#include <math.h>
#include <webots/device.h>
#include <webots/distance_sensor.h>
#include <webots/gps.h>
#include <webots/lidar.h>
#include <webots/nodes.h>
#include <webots/radar.h>
#include <webots/robot.h>

#include "check.h"

static void call(const char *what, const char *expected_stderr) {
  if (expected_stderr[0] != '\0')
    printf("ray_sensors: call: %s -> stderr: %s\n", what, expected_stderr);
  else
    printf("ray_sensors: call: %s\n", what);
  fflush(stdout);
}

static void step(int count) {
  int i;
  for (i = 0; i < count; ++i)
    if (wb_robot_step(10) == -1)
      check_fatal("wb_robot_step(10) returned -1 at t = %g s", wb_robot_get_time());
}

int main(void) {
  WbDeviceTag gps, radar, lidar, left, shortest;
  const WbRadarTarget *targets;
  const WbLidarPoint *cloud;
  const float *image;
  const double *p;
  const double *table;
  double h, y, pt, g, lambda, pr, theta, phi = -0.2;
  int j;
  wb_robot_init();
  check_begin("ray_sensors");

  check_int("wb_robot_get_number_of_devices()", wb_robot_get_number_of_devices(), 32);
  gps = wb_robot_get_device("gps");
  radar = wb_robot_get_device("radar");
  lidar = wb_robot_get_device("lidar");
  left = wb_robot_get_device("left");
  shortest = wb_robot_get_device("short");
  check_int("radar tag", radar, 29);
  check_int("node type of radar", wb_device_get_node_type(radar), WB_NODE_RADAR);
  check_int("node type of lidar", wb_device_get_node_type(lidar), WB_NODE_LIDAR);
  check_int("node type of distance sensor", wb_device_get_node_type(left), WB_NODE_DISTANCE_SENSOR);

  /* Fields. */
  check_close("radar min range", wb_radar_get_min_range(radar), 1.0, 0.0);
  check_close("radar max range", wb_radar_get_max_range(radar), 50.0, 0.0);
  check_close("radar horizontal fov", wb_radar_get_horizontal_fov(radar), 0.78, 0.0);
  check_close("radar vertical fov", wb_radar_get_vertical_fov(radar), 0.1, 0.0);
  check_int("lidar horizontal resolution", wb_lidar_get_horizontal_resolution(lidar), 9);
  check_int("lidar layers", wb_lidar_get_number_of_layers(lidar), 1);
  check_close("lidar fov", wb_lidar_get_fov(lidar), 0.8, 0.0);
  check_close("lidar max range", wb_lidar_get_max_range(lidar), 30.0, 0.0);
  check_close("lidar frequency", wb_lidar_get_frequency(lidar), 10.0, 0.0);
  wb_lidar_set_frequency(lidar, 20.0);
  check_close("lidar frequency set", wb_lidar_get_frequency(lidar), 20.0, 0.0);
  call("wb_lidar_set_frequency(lidar, 100)",
       "Error: wb_lidar_set_frequency() out of frequency range [1.000000, 25.000000].");
  wb_lidar_set_frequency(lidar, 100.0);
  check_close("lidar frequency kept", wb_lidar_get_frequency(lidar), 20.0, 0.0);
  check_int("distance sensor type", wb_distance_sensor_get_type(left), WB_DISTANCE_SENSOR_GENERIC);
  check_close("distance sensor max value", wb_distance_sensor_get_max_value(left), 1000.0, 0.0);
  check_close("distance sensor min value", wb_distance_sensor_get_min_value(left), 0.0, 0.0);
  check_close("distance sensor aperture", wb_distance_sensor_get_aperture(left), 1.5708, 0.0);
  check_int("distance sensor lookup table size", wb_distance_sensor_get_lookup_table_size(left), 2);
  table = wb_distance_sensor_get_lookup_table(left);
  check_true(table != NULL && table[3] == 10.0 && table[4] == 1000.0, "distance sensor lookup table rows");

  /* Before the first sample. */
  call("wb_radar_get_number_of_targets(radar) while disabled",
       "Error: wb_radar_get_number_of_targets() called for a disabled device! Please use: wb_radar_enable().");
  check_int("targets before enabling", wb_radar_get_number_of_targets(radar), 0);
  call("wb_radar_enable(radar, -1)", "Error: wb_radar_enable() called with negative sampling period.");
  wb_radar_enable(radar, -1);
  wb_gps_enable(gps, 10);
  wb_radar_enable(radar, 10);
  wb_lidar_enable(lidar, 10);
  wb_lidar_enable(shortest, 10);
  wb_distance_sensor_enable(left, 10);
  check_true(isnan(wb_distance_sensor_get_value(left)), "distance sensor NaN before its first sample");
  check_true(wb_radar_get_targets(radar) == NULL, "no targets before the first sample");
  step(200); /* 2 s: the parked cars have settled on their springs. */

  p = wb_gps_get_values(gps);
  h = p[2];
  y = p[1];
  check_close("car origin height (m)", h, 0.37, 0.1);

  check_int("one radar target", wb_radar_get_number_of_targets(radar), 1);
  targets = wb_radar_get_targets(radar);
  check_close("target distance (m)", targets[0].distance, 30.0, 0.05);
  check_close("target radial speed (m/s)", targets[0].speed, 0.0, 0.01);
  check_close("target azimuth (rad)", targets[0].azimuth, 0.0, 0.005);
  pt = pow(10.0, 20.0 / 10.0) / 1000.0;
  g = pow(10.0, 20.0 / 10.0);
  lambda = 0.299792458 / 24.0;
  pr = pt * g * g * lambda * lambda * 10.0 / (pow(4.0 * 3.14159265358979323846, 3.0) * pow(targets[0].distance, 4.0));
  check_close("target power (dBm)", targets[0].received_power, 10.0 * log10(pr / 0.001), 1e-9);

  image = wb_lidar_get_range_image(lidar);
  call("wb_lidar_get_point_cloud(lidar) with the cloud disabled",
       "Error: wb_lidar_get_point_cloud() called for a lidar with point cloud disabled. Please use: "
       "wb_lidar_enable_point_cloud().");
  check_true(wb_lidar_get_point_cloud(lidar) == NULL, "no point cloud while disabled");
  wb_lidar_enable_point_cloud(lidar);
  check_true(wb_lidar_is_point_cloud_enabled(lidar), "point cloud enabled");
  check_int("number of points", wb_lidar_get_number_of_points(lidar), 9);
  cloud = wb_lidar_get_point_cloud(lidar);
  for (j = 0; j < 9; ++j) {
    theta = 0.4 - (j + 0.5) * 0.8 / 9.0;
    check_close("lidar range to the ground (m)", image[j], h / sin(0.2), 0.05);
    check_close("point x (m)", cloud[j].x, image[j] * cos(theta) * cos(phi), 1e-4);
    check_close("point y (m)", cloud[j].y, image[j] * sin(theta) * cos(phi), 1e-4);
    check_close("point z (m)", cloud[j].z, image[j] * sin(phi), 1e-4);
    check_int("point layer", cloud[j].layer_id, 0);
  }
  check_true(wb_lidar_get_layer_range_image(lidar, 0) != NULL, "layer 0 of the range image");
  call("wb_lidar_get_layer_range_image(lidar, 1)",
       "Error: wb_lidar_get_layer_range_image() called with a 'layer' argument (1) bigger or equal to the number of "
       "layers of this lidar (1).");
  check_true(wb_lidar_get_layer_range_image(lidar, 1) == NULL, "no layer 1");
  call("wb_lidar_get_layer_point_cloud(lidar, -1)",
       "Error: wb_lidar_get_layer_point_cloud() called with a negative 'layer' argument.");
  check_true(wb_lidar_get_layer_point_cloud(lidar, -1) == NULL, "no layer -1");
  image = wb_lidar_get_range_image(shortest);
  for (j = 0; j < wb_lidar_get_horizontal_resolution(shortest) * 4; ++j)
    if (!(isinf(image[j]) && image[j] > 0))
      check_true(0, "short lidar value %d is %g, not +inf", j, image[j]);

  check_close("distance sensor value", wb_distance_sensor_get_value(left), 100.0 * (5.0 - y), 1.0);

  /* Wrong tags. */
  call("wb_distance_sensor_get_value(radar)", "Error: wb_distance_sensor_get_value(): invalid device tag.");
  check_true(isnan(wb_distance_sensor_get_value(radar)), "wb_distance_sensor_get_value(radar) is NaN");
  call("wb_radar_get_targets(lidar)", "Error: wb_radar_get_targets(): invalid device tag.");
  check_true(wb_radar_get_targets(lidar) == NULL, "wb_radar_get_targets(lidar) is NULL");
  call("wb_lidar_get_range_image(left)", "Error: wb_lidar_get_range_image(): invalid device tag.");
  check_true(wb_lidar_get_range_image(left) == NULL, "wb_lidar_get_range_image(left) is NULL");

  /* Disabled: the layer getters refuse. */
  wb_lidar_disable(lidar);
  call("wb_lidar_get_layer_range_image(lidar, 0) after disable",
       "Error: wb_lidar_get_layer_range_image() called for a disabled device! Please use: wb_lidar_enable().");
  check_true(wb_lidar_get_layer_range_image(lidar, 0) == NULL, "no layer of a disabled lidar");

  wb_robot_cleanup();
  return check_finish();
}
