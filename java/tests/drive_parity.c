/*
 * drive_parity: the C twin of DriveParity.java. Both drive java/tests/worlds/drive.toml with the
 * same calls in the same order (bad input included) and print every driver and car getter, the
 * GPS, the distance sensor, the camera and its recognised objects, and the lidar range image
 * and point cloud after each step as raw bits; run.sh requires their stdout and
 * stderr to be identical, so every Java getter returns the C ABI's value for the same state
 * and every warning reaches stderr exactly as from C. Before the first step both draw on the
 * display and print the bytes of the PNG files they save of it (each runs in a directory of its
 * own), and at step 50 those of the camera's image.
 * It calls the deprecated functions too (Java has them), hence -Wno-deprecated-declarations.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <webots/camera.h>
#include <webots/camera_recognition_object.h>
#include <webots/display.h>
#include <webots/distance_sensor.h>
#include <webots/gps.h>
#include <webots/keyboard.h>
#include <webots/lidar.h>
#include <webots/lidar_point.h>
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

static void check_null(const char *name, const void *p) {
  printf(" %s=%s", name, p == NULL ? "null" : "image");
}

static void f(const char *name, float x) {
  uint32_t bits;
  memcpy(&bits, &x, sizeof bits);
  printf(" %s=%08x", name, (unsigned)bits);
}

/* The n points of a point cloud (Java's LidarPoint[]), "null" for NULL. */
static void print_cloud(const char *name, const WbLidarPoint *points, int n) {
  int k;
  printf(" %s=", name);
  if (points == NULL) {
    printf("null");
    return;
  }
  printf("%d", n);
  for (k = 0; k < n; ++k) {
    f("px", points[k].x);
    f("py", points[k].y);
    f("pz", points[k].z);
    i("pl", points[k].layer_id);
    f("pt", points[k].time);
  }
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
    const int n = wb_camera_recognition_get_number_of_objects(camera);
    const WbCameraRecognitionObject *objects = wb_camera_recognition_get_objects(camera);
    int c;
    i("objects", n);
    for (k = 0; objects != NULL && k < n; ++k) {
      const WbCameraRecognitionObject *o = &objects[k];
      i("id", o->id);
      for (c = 0; c < 3; ++c) d("opos", o->position[c]);
      for (c = 0; c < 4; ++c) d("orot", o->orientation[c]);
      for (c = 0; c < 2; ++c) d("osize", o->size[c]);
      for (c = 0; c < 2; ++c) i("oimg", o->position_on_image[c]);
      for (c = 0; c < 2; ++c) i("oimgsize", o->size_on_image[c]);
      i("ncolors", o->number_of_colors);
      for (c = 0; c < 3 * o->number_of_colors; ++c) d("ocolor", o->colors[c]);
      printf(" model=%s", o->model);
    }
  }
  print_cloud("cloud", wb_lidar_get_point_cloud(lidar), wb_lidar_get_number_of_points(lidar));
  print_cloud("layer1", wb_lidar_get_layer_point_cloud(lidar, 1), wb_lidar_get_horizontal_resolution(lidar));
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

/* Prints the bytes of the file `name` (in the working directory) in hex. */
static void print_file(const char *label, const char *name) {
  FILE *f;
  int c;
  f = fopen(name, "rb");
  printf("%s", label);
  if (f == NULL) {
    printf(" missing\n");
    return;
  }
  while ((c = fgetc(f)) != EOF) printf("%02x", c);
  fclose(f);
  printf("\n");
}

/* Draws on the display with every function of webots/display.h (bad input included), then
 * saves the display and a copy as PNG files and prints their bytes: the only way a
 * controller reads a display back. */
static void draw(WbDeviceTag screen) {
  static const int xs[] = {1, 6, 3}, ys[] = {1, 2, 6};
  static const int fx[] = {9, 14, 12, 10}, fy[] = {5, 5, 7, 7};
  /* 2 x 2 pixels: ARGB 0x80ff0000, 0xff00ff00, 0x000000ff, 0xffffffff, as Java's ints. */
  static const unsigned char argb[] = {0x80, 0xff, 0x00, 0x00, 0xff, 0x00, 0xff, 0x00,
                                       0x00, 0x00, 0x00, 0xff, 0xff, 0xff, 0xff, 0xff};
  static const unsigned char rgb[] = {0x10, 0x20, 0x30, 0x40, 0x50, 0x60};
  WbImageRef copy, made, flat, loaded;
  i("display_width", wb_display_get_width(screen));
  i("display_height", wb_display_get_height(screen));
  wb_display_set_color(screen, 0x3366cc);
  wb_display_fill_rectangle(screen, 0, 0, 16, 8);
  wb_display_set_color(screen, 0xff0000);
  wb_display_draw_pixel(screen, 15, 0);
  wb_display_draw_line(screen, 0, 7, 15, 0);
  wb_display_set_opacity(screen, 0.5);
  wb_display_draw_rectangle(screen, 2, 2, 5, 4);
  wb_display_set_opacity(screen, 1.0);
  wb_display_set_alpha(screen, 0.25);
  wb_display_draw_oval(screen, 8, 4, 3, 2);
  wb_display_set_alpha(screen, 1.0);
  wb_display_set_color(screen, 0x00ff00);
  wb_display_fill_oval(screen, 12, 3, 2, 2);
  wb_display_draw_polygon(screen, xs, ys, 3);
  wb_display_fill_polygon(screen, fx, fy, 4);
  wb_display_set_font(screen, "Arial", 8, true);
  wb_display_draw_text(screen, "Hi", 0, 0);
  /* Bad input: refused by the C API with its errors. */
  wb_display_set_color(screen, 0x1000000);
  wb_display_set_alpha(screen, 2.0);
  wb_display_set_opacity(screen, -1.0);
  wb_display_set_font(screen, "NoSuchFont", 8, false);
  wb_display_set_font(screen, "Arial", 0, false);
  check_null("bad_format", wb_display_image_new(screen, 2, 2, argb, 9));
  check_null("off_copy", wb_display_image_copy(screen, 100, 100, 2, 2));
  made = wb_display_image_new(screen, 2, 2, argb, WB_IMAGE_ARGB);
  flat = wb_display_image_new(screen, 2, 1, rgb, WB_IMAGE_RGB);
  wb_display_image_paste(screen, made, 3, 5, true);
  wb_display_image_paste(screen, flat, 13, 6, false);
  copy = wb_display_image_copy(screen, 0, 0, 8, 4);
  wb_display_image_paste(screen, copy, 8, 4, false);
  wb_display_image_save(screen, copy, "copy.png");
  loaded = wb_display_image_load(screen, "copy.png");
  wb_display_image_paste(screen, loaded, 9, 5, true);
  wb_display_image_save(screen, NULL, "screen.png");
  wb_display_image_delete(screen, made);
  wb_display_image_delete(screen, flat);
  wb_display_image_delete(screen, copy);
  wb_display_image_delete(screen, loaded);
  printf("\n");
  print_file("copy.png ", "copy.png");
  print_file("screen.png ", "screen.png");
}

int main(void) {
  WbDeviceTag gps, lidar, front, radar, lanes, camera, screen;
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
  screen = wb_robot_get_device("screen");
  draw(screen);
  /* Recognition and the point cloud before they are enabled (errors), then enabled. */
  i("has_recognition", wb_camera_has_recognition(camera));
  i("segmentation", wb_camera_recognition_has_segmentation(camera));
  i("recognition_period", wb_camera_recognition_get_sampling_period(camera));
  i("objects", wb_camera_recognition_get_number_of_objects(camera));
  check_null("objects", wb_camera_recognition_get_objects(camera));
  wb_camera_recognition_enable(camera, 50);
  i("recognition_period", wb_camera_recognition_get_sampling_period(camera));
  i("cloud_enabled", wb_lidar_is_point_cloud_enabled(lidar));
  i("points", wb_lidar_get_number_of_points(lidar));
  print_cloud("cloud", wb_lidar_get_point_cloud(lidar), 0);
  wb_lidar_enable_point_cloud(lidar);
  i("cloud_enabled", wb_lidar_is_point_cloud_enabled(lidar));
  print_cloud("layer5", wb_lidar_get_layer_point_cloud(lidar, 5), 0);
  printf("\n");

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
  d("min_fov", wb_camera_get_min_fov(camera));
  d("max_fov", wb_camera_get_max_fov(camera));
  d("frequency", wb_lidar_get_frequency(lidar));
  d("min_frequency", wb_lidar_get_min_frequency(lidar));
  d("max_frequency", wb_lidar_get_max_frequency(lidar));
  wb_lidar_set_frequency(lidar, wb_lidar_get_max_frequency(lidar) + 1.0);
  wb_lidar_set_frequency(lidar, wb_lidar_get_min_frequency(lidar));
  d("frequency", wb_lidar_get_frequency(lidar));
  printf("\n");

  while (wbu_driver_step() != -1) {
    ++steps;
    if (steps == 50) {
      /* The camera's image as a PNG file (read back as bytes), and a refused extension. */
      i("save", wb_camera_save_image(camera, "camera.png", 100));
      i("save_bmp", wb_camera_save_image(camera, "camera.bmp", 100));
      printf("\n");
      print_file("camera.png ", "camera.png");
    }
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
