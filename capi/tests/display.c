/*
 * display: every drawing function of webots/display.h on a car's 16 x 8 Display, image
 * handles (new, copy, paste, delete) and Webots' messages for misuse. The C API has no pixel
 * getter: the pixels each primitive gives are checked by the engine's tests
 * (sim/src/devices/display.rs) and through Python's Display.imageCopy.
 */

#include <webots/device.h>
#include <webots/display.h>
#include <webots/nodes.h>
#include <webots/robot.h>

#include "check.h"

static void call(const char *what, const char *expected_stderr) {
  printf("display: call: %s -> stderr: %s\n", what, expected_stderr);
  fflush(stdout);
}

int main(void) {
  WbDeviceTag display;
  WbImageRef copy, made, loaded;
  const unsigned char red[4] = {255, 0, 0, 255};
  int xs[3] = {0, 4, 0}, ys[3] = {0, 0, 4};
  wb_robot_init();
  check_begin("display");
  display = wb_robot_get_device("display");
  check_int("node type", wb_device_get_node_type(display), WB_NODE_DISPLAY);
  check_int("width", wb_display_get_width(display), 16);
  check_int("height", wb_display_get_height(display), 8);
  call("wb_display_get_width(1)", "Error: wb_display_get_width(): invalid device tag.");
  check_int("width of a wrong tag", wb_display_get_width(1), -1);
  call("wb_display_set_color(display, 0x1000000)",
       "Error: wb_display_set_color(): color must be in [0, 0xFFFFFF].");
  wb_display_set_color(display, 0x1000000);
  call("wb_display_set_opacity(display, 2)", "Error: wb_display_set_opacity(): opacity must be in [0, 1].");
  wb_display_set_opacity(display, 2.0);

  wb_display_set_color(display, 0xFFFFFF);
  wb_display_fill_rectangle(display, 1, 1, 4, 3);
  wb_display_draw_line(display, 0, 7, 15, 7);
  wb_display_draw_oval(display, 10, 3, 3, 2);
  wb_display_fill_oval(display, 10, 3, 1, 1);
  wb_display_draw_polygon(display, xs, ys, 3);
  wb_display_fill_polygon(display, xs, ys, 3);
  wb_display_draw_pixel(display, 100, 100); /* off the display: skipped */
  copy = wb_display_image_copy(display, 1, 1, 4, 3);
  check_true(copy != NULL, "copy of a drawn rectangle");
  check_true(wb_display_image_copy(display, 20, 20, 2, 2) == NULL, "copy off the display is NULL");
  made = wb_display_image_new(display, 1, 1, red, WB_IMAGE_RGBA);
  check_true(made != NULL && made != copy, "new image from RGBA data");
  call("wb_display_image_new(format 9)", "Error: wb_display_image_new(): unknown image format 9.");
  check_true(wb_display_image_new(display, 1, 1, red, 9) == NULL, "unknown format gives NULL");
  wb_display_image_paste(display, made, 15, 0, false);
  wb_display_image_paste(display, copy, 12, 4, true);
  wb_display_image_delete(display, copy);
  call("wb_display_image_delete twice", "Error: wb_display_image_delete(): invalid image reference.");
  wb_display_image_delete(display, copy);
  wb_display_image_save(display, made, "/tmp/capi_display_test.png");
  loaded = wb_display_image_load(display, "/tmp/capi_display_test.png");
  check_true(loaded != NULL, "a saved image loads back");
  wb_display_image_save(display, NULL, "/tmp/capi_display_whole.png");
  check_true(wb_display_image_load(display, "/tmp/capi_display_whole.png") != NULL, "the saved display loads back");
  call("wb_display_image_load (missing)",
       "Error: wb_display_image_load(): /tmp/capi_no_such_file.png: No such file or directory (os error 2).");
  check_true(wb_display_image_load(display, "/tmp/capi_no_such_file.png") == NULL, "a missing file gives NULL");
  wb_display_image_delete(display, loaded);
  wb_display_image_delete(display, made);
  /* Text: its pixels are checked by sim's tests and Python's; here the calls and messages. */
  wb_display_set_font(display, "Lucida Console", 10, true);
  wb_display_draw_text(display, "Ab\n1", 2, 1);
  wb_display_draw_text(display, NULL, 0, 0); /* nothing */
  call("wb_display_set_font(size 0)",
       "Error: wb_display_set_font(): font size 0 must be > 0 and at most 4096 px.");
  wb_display_set_font(display, "Arial", 0, false);
  call("wb_display_set_font(NULL)", "Error: wb_display_set_font(): NULL font.");
  wb_display_set_font(display, NULL, 8, false);
  wb_robot_step(10);
  wb_robot_cleanup();
  return check_finish();
}
