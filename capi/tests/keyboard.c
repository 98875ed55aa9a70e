/*
 * keyboard: the keys of worlds/keyboard.toml's programme through webots/keyboard.h, and
 * Webots' messages for misuse.
 *
 * The programme presses 'A' and CONTROL+UP at 50 ms and 'B' (66) at 200 ms. Enabled at 0 with
 * a 20 ms period, the keyboard samples at 20, 40, 60 ... ms: the two keys of 50 ms are read
 * after the step ending at 60 ms, in order, then -1; 'B' after the step ending at 200 ms.
 */

#include <webots/keyboard.h>
#include <webots/robot.h>

#include "check.h"

static void call(const char *what, const char *expected_stderr) {
  printf("keyboard: call: %s -> stderr: %s\n", what, expected_stderr);
  fflush(stdout);
}

int main(void) {
  int t, key, got_a = -1, got_up = -1, got_b = -1, extra = 0;
  wb_robot_init();
  check_begin("keyboard");
  call("wb_keyboard_get_key while disabled",
       "Error: wb_keyboard_get_key() called for a disabled device! Please use: wb_keyboard_enable().");
  check_int("key while disabled", wb_keyboard_get_key(), -1);
  call("wb_keyboard_enable(-5)", "Error: wb_keyboard_enable() called with negative sampling period.");
  wb_keyboard_enable(-5);
  check_int("period after a negative one", wb_keyboard_get_sampling_period(), 0);
  wb_keyboard_enable(20);
  check_int("period", wb_keyboard_get_sampling_period(), 20);
  for (t = 10; t <= 250; t += 10) {
    wb_robot_step(10);
    while ((key = wb_keyboard_get_key()) != -1) {
      if (key == 'A' && got_a < 0)
        got_a = t;
      else if (key == (WB_KEYBOARD_CONTROL | WB_KEYBOARD_UP) && got_up < 0)
        got_up = t;
      else if (key == 'B' && got_b < 0)
        got_b = t;
      else
        extra++;
    }
  }
  check_int("'A' read at (ms)", got_a, 60);
  check_int("CONTROL+UP read at (ms)", got_up, 60);
  check_int("'B' read at (ms)", got_b, 200);
  check_int("keys read more than once", extra, 0);
  check_int("WB_KEYBOARD_KEY of CONTROL+UP", (WB_KEYBOARD_CONTROL | WB_KEYBOARD_UP) & WB_KEYBOARD_KEY, 315);
  wb_keyboard_disable();
  check_int("period after disable", wb_keyboard_get_sampling_period(), 0);
  wb_robot_cleanup();
  return check_finish();
}
