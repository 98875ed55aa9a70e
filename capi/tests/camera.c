/*
 * camera: the Camera of a world file's car through webots/camera.h, its Recognition, and
 * Webots' messages for misuse.
 *
 * World: worlds/camera.toml. The camera looks along +x from about (4.5, 0, 1.0) m; the red
 * box's face towards it is at x = 14.5 m, y in [-1, 1], z in [0, 2]: 10 m ahead, it covers
 * the centre of the image (f = 32 / tan 0.5 = 58.6 px, so about 12 x 12 px).
 * Expected:
 *   centre pixel = 0.5 x (0.8, 0.2, 0.1) x 255 = (102, 26, 13): a face turned away from the
 *     light shows half its colour (the default light's ambient share);
 *   one object recognised (the cyan box is behind the camera), at x = 15 - 4.5 = 10.5 m
 *     (+- 0.05 m: the car settles by millimetres), y = 0 (+- 0.01 m), size 2 x 2 m (+- 0.01),
 *     one colour (1, 0, 0), model "".
 */

#include <stddef.h>
#include <string.h>
#include <webots/camera.h>
#include <webots/device.h>
#include <webots/nodes.h>
#include <webots/robot.h>

#include "check.h"

static void call(const char *what, const char *expected_stderr) {
  printf("camera: call: %s -> stderr: %s\n", what, expected_stderr);
  fflush(stdout);
}

static void step(int count) {
  int i;
  for (i = 0; i < count; ++i)
    if (wb_robot_step(10) == -1)
      check_fatal("wb_robot_step(10) returned -1 at t = %g s", wb_robot_get_time());
}

int main(void) {
  WbDeviceTag camera;
  const unsigned char *image;
  const WbCameraRecognitionObject *objects;
  int w, h, n;
  wb_robot_init();
  check_begin("camera");

  check_int("sizeof(WbCameraRecognitionObject)", (int)sizeof(WbCameraRecognitionObject), 120);
  check_int("offsetof colors", (int)offsetof(WbCameraRecognitionObject, colors), 104);
  camera = wb_robot_get_device("camera");
  check_int("node type", wb_device_get_node_type(camera), WB_NODE_CAMERA);
  w = wb_camera_get_width(camera);
  h = wb_camera_get_height(camera);
  check_int("width", w, 64);
  check_int("height", h, 32);
  check_close("fov (rad)", wb_camera_get_fov(camera), 1.0, 0.0);
  check_close("min fov (rad)", wb_camera_get_min_fov(camera), 1.0, 0.0);
  check_close("near (m)", wb_camera_get_near(camera), 0.01, 0.0);
  check_true(wb_camera_has_recognition(camera), "has recognition");
  call("wb_camera_get_width(0)", "Error: wb_camera_get_width(): invalid device tag.");
  check_int("width of a wrong tag", wb_camera_get_width(0), -1);

  call("wb_camera_get_image while disabled",
       "Error: wb_camera_get_image() called for a disabled device! Please use: wb_camera_enable().");
  check_true(wb_camera_get_image(camera) == NULL, "image NULL while disabled");
  call("wb_camera_enable(camera, -1)", "Error: wb_camera_enable() called with negative sampling period.");
  wb_camera_enable(camera, -1);
  call("wb_camera_recognition_get_number_of_objects while disabled",
       "Error: wb_camera_recognition_get_number_of_objects() called for a disabled device! Please use: "
       "wb_camera_recognition_enable().");
  check_int("objects while disabled", wb_camera_recognition_get_number_of_objects(camera), 0);

  wb_camera_enable(camera, 20);
  wb_camera_recognition_enable(camera, 20);
  check_int("sampling period", wb_camera_get_sampling_period(camera), 20);
  check_int("recognition sampling period", wb_camera_recognition_get_sampling_period(camera), 20);
  step(2);
  image = wb_camera_get_image(camera);
  check_true(image != NULL, "image after one period");
  if (image != NULL) {
    check_int("centre red", wb_camera_image_get_red(image, w, w / 2, h / 2), 102);
    check_int("centre green", wb_camera_image_get_green(image, w, w / 2, h / 2), 26);
    check_int("centre blue", wb_camera_image_get_blue(image, w, w / 2, h / 2), 13);
    check_int("centre alpha", image[4 * ((h / 2) * w + w / 2) + 3], 255);
    check_true(wb_camera_image_get_red(image, w, 0, h / 2) != 102, "left edge is not the box");
  }
  n = wb_camera_recognition_get_number_of_objects(camera);
  check_int("number of objects", n, 1);
  objects = wb_camera_recognition_get_objects(camera);
  if (n == 1 && objects != NULL) {
    check_close("object x (m)", objects[0].position[0], 10.5, 0.05);
    check_close("object y (m)", objects[0].position[1], 0.0, 0.01);
    check_close("object size y (m)", objects[0].size[0], 2.0, 0.01);
    check_close("object size z (m)", objects[0].size[1], 2.0, 0.01);
    check_int("object colours", objects[0].number_of_colors, 1);
    check_close("object colour red", objects[0].colors[0], 1.0, 0.0);
    check_true(strcmp(objects[0].model, "") == 0, "object model empty");
    check_true(objects[0].position_on_image[0] >= w / 2 - 1 && objects[0].position_on_image[0] <= w / 2 + 1,
               "object centred on the image (u = %d)", objects[0].position_on_image[0]);
  }
  check_int("wb_camera_save_image (png)", wb_camera_save_image(camera, "/tmp/capi_camera_test.png", 100), 0);
  call("wb_camera_save_image (jpg)",
       "Error: wb_camera_save_image(): /tmp/capi_camera_test.jpg: only .png files are supported.");
  check_int("wb_camera_save_image (jpg)", wb_camera_save_image(camera, "/tmp/capi_camera_test.jpg", 100), -1);
  wb_camera_disable(camera);
  check_int("sampling period after disable", wb_camera_get_sampling_period(camera), 0);
  wb_robot_cleanup();
  return check_finish();
}
