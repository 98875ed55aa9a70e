/*
 * drive_parity: the C twin of DriveParity.java. Both drive java/tests/worlds/drive.toml with the
 * same calls in the same order (bad input included) and print every driver and car getter, the
 * GPS, the distance sensor and the lidar range image after each step as raw bits; run.sh requires their stdout and
 * stderr to be identical, so every Java getter returns the C ABI's value for the same state
 * and every warning reaches stderr exactly as from C.
 * It calls the deprecated functions too (Java has them), hence -Wno-deprecated-declarations.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <webots/camera.h>
#include <webots/distance_sensor.h>
#include <webots/gps.h>
#include <webots/keyboard.h>
#include <webots/lidar.h>
#include <webots/radar.h>
#include <webots/robot.h>
#include <webots/vehicle/car.h>
#include <webots/vehicle/driver.h>
#include <webots/vehicle/road_sensor.h>

static void d(const char *name, double x) {
  uint64_t bits;
  memcpy(&bits, &x, sizeof bits);
  printf(" %s=%016llx", name, (unsigned long long)bits);
}

static void i(const char *name, int x) {
  printf(" %s=%d", name, x);
}

static void print_state(WbDeviceTag gps, WbDeviceTag lidar, WbDeviceTag front, WbDeviceTag radar, WbDeviceTag lanes, WbDeviceTag camera) {
  int w, k;
  d("t", wb_robot_get_time());
  d("steer", wbu_driver_get_steering_angle());
  d("target", wbu_driver_get_target_cruising_speed());
  d("speed", wbu_driver_get_current_speed());
  d("throttle", wbu_driver_get_throttle());
  d("brake", wbu_driver_get_brake_intensity());
  i("indicator", wbu_driver_get_indicator());
  i("hazard", wbu_driver_get_hazard_flashers());
  i("dipped", wbu_driver_get_dipped_beams());
  i("antifog", wbu_driver_get_antifog_lights());
  d("rpm", wbu_driver_get_rpm());
  i("gear", wbu_driver_get_gear());
  i("gears", wbu_driver_get_gear_number());
  i("mode", wbu_driver_get_control_mode());
  i("wiper", wbu_driver_get_wiper_mode());
  i("wipers", wbu_driver_get_wipers_mode());
  i("type", wbu_car_get_type());
  i("engine", wbu_car_get_engine_type());
  d("period", wbu_car_get_indicator_period());
  i("backwards", wbu_car_get_backwards_lights());
  i("brakelights", wbu_car_get_brake_lights());
  d("trackf", wbu_car_get_track_front());
  d("trackr", wbu_car_get_track_rear());
  d("wheelbase", wbu_car_get_wheelbase());
  d("rf", wbu_car_get_front_wheel_radius());
  d("rr", wbu_car_get_rear_wheel_radius());
  for (w = 0; w < WBU_CAR_WHEEL_NB; ++w) {
    d("enc", wbu_car_get_wheel_encoder((WbuCarWheelIndex)w));
    d("ws", wbu_car_get_wheel_speed((WbuCarWheelIndex)w));
  }
  d("left", wbu_car_get_left_steering_angle());
  d("right", wbu_car_get_right_steering_angle());
  {
    const double *p = wb_gps_get_values(gps);
    const double *v = wb_gps_get_speed_vector(gps);
    for (k = 0; k < 3; ++k) d("gps", p[k]);
    for (k = 0; k < 3; ++k) d("gpsv", v[k]);
    d("gpss", wb_gps_get_speed(gps));
  }
  d("front", wb_distance_sensor_get_value(front));
  {
    /* Java's pixels: 0xAARRGGBB from the BGRA bytes. */
    const unsigned char *image = wb_camera_get_image(camera);
    const int n = wb_camera_get_width(camera) * wb_camera_get_height(camera);
    for (k = 0; image != NULL && k < n; ++k) {
      const unsigned char *p = image + 4 * k;
      printf(" px=%08x", ((unsigned)p[3] << 24) | ((unsigned)p[2] << 16) | ((unsigned)p[1] << 8) | p[0]);
    }
  }
  i("road", vehicle_road_sensor_get_road(lanes));
  i("lane", vehicle_road_sensor_get_lane(lanes));
  d("lookahead", vehicle_road_sensor_get_lookahead(lanes));
  d("station", vehicle_road_sensor_get_station(lanes));
  d("lateral_offset", vehicle_road_sensor_get_lateral_offset(lanes));
  d("heading_error", vehicle_road_sensor_get_heading_error(lanes));
  d("curvature", vehicle_road_sensor_get_curvature(lanes));
  d("curvature_ahead", vehicle_road_sensor_get_curvature_ahead(lanes));
  d("left_line_distance", vehicle_road_sensor_get_left_line_distance(lanes));
  d("right_line_distance", vehicle_road_sensor_get_right_line_distance(lanes));
  d("left_edge_distance", vehicle_road_sensor_get_left_edge_distance(lanes));
  d("right_edge_distance", vehicle_road_sensor_get_right_edge_distance(lanes));
  d("lane_width", vehicle_road_sensor_get_lane_width(lanes));
  {
    const WbRadarTarget *targets = wb_radar_get_targets(radar);
    const int n = wb_radar_get_number_of_targets(radar);
    for (k = 0; k < n; ++k) {
      d("rd", targets[k].distance);
      d("rp", targets[k].received_power);
      d("rs", targets[k].speed);
      d("ra", targets[k].azimuth);
    }
  }
  {
    int key;
    while ((key = wb_keyboard_get_key()) != -1) i("key", key);
  }
  d("battery", wb_robot_battery_sensor_get_value());
  {
    const float *image = wb_lidar_get_range_image(lidar);
    const int n = wb_lidar_get_horizontal_resolution(lidar) * wb_lidar_get_number_of_layers(lidar);
    for (k = 0; k < n; ++k) {
      uint32_t bits;
      memcpy(&bits, &image[k], sizeof bits);
      printf(" r=%08x", (unsigned)bits);
    }
  }
  printf("\n");
  fflush(stdout);
}

int main(void) {
  WbDeviceTag gps, lidar, front, radar, lanes, camera;
  int steps = 0;
  wbu_driver_init();
  gps = wb_robot_get_device("gps");
  lidar = wb_robot_get_device("lidar");
  wb_gps_enable(gps, 10);
  wb_lidar_enable(lidar, 10);
  front = wb_robot_get_device("front");
  wb_distance_sensor_enable(front, 10);
  wb_keyboard_enable(10);
  wb_robot_battery_sensor_enable(10);
  radar = wb_robot_get_device("radar");
  wb_radar_enable(radar, 10);
  lanes = wb_robot_get_device("lanes");
  vehicle_road_sensor_enable(lanes, 10);
  camera = wb_robot_get_device("camera");
  wb_camera_enable(camera, 100);

  wbu_driver_set_cruising_speed(30.0);
  wbu_driver_set_steering_angle(0.1);
  wbu_driver_set_indicator(LEFT);
  wbu_driver_set_dipped_beams(true);
  wbu_driver_set_wiper_mode(SLOW);
  wbu_car_set_indicator_period(0.5);
  /* Bad input: each is refused or clamped by the C API, with its warning on stderr. */
  wbu_driver_set_steering_angle(NAN);
  wbu_driver_set_gear(99);
  wbu_driver_set_indicator((WbuDriverIndicatorState)7);
  wbu_driver_set_wiper_mode((WbuDriverWiperMode)9);
  wbu_driver_set_brake_intensity(-1.0);
  d("badwheel", wbu_car_get_wheel_speed((WbuCarWheelIndex)4));
  printf("\n");

  while (wbu_driver_step() != -1) {
    ++steps;
    if (steps == 100) {
      wbu_driver_set_throttle(0.5);
      wbu_driver_set_gear(1);
      wbu_driver_set_throttle(2.0);
      wbu_driver_set_hazard_flashers(true);
    }
    if (steps == 150) {
      wbu_driver_set_brake_intensity(0.3);
      wbu_driver_set_antifog_lights(true);
      wbu_car_enable_limited_slip_differential(false);
      wbu_car_enable_indicator_auto_disabling(false);
      wbu_car_set_left_steering_angle(0.05);
      wbu_car_set_right_steering_angle(0.04);
      wbu_driver_set_wipers_mode(FAST);
      wbu_driver_set_brake(0.4);
    }
    print_state(gps, lidar, front, radar, lanes, camera);
  }
  printf("end steps=%d", steps);
  d("t", wb_robot_get_time());
  printf("\n");
  wbu_driver_cleanup();
  return 0;
}
