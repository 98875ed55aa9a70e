/*
 * webots/keyboard.h: the Webots keyboard, fed by the world's programme.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * There is no window to type in: the keys are those the car's programme presses
 * ([[vehicle.programme]] at = 2.0, key = "A"). A press at time t is held by the keyboard's
 * first sample at or after t; wb_keyboard_get_key() returns the keys of the last sample in
 * turn, then -1. Sampling periods are in milliseconds (ms).
 */

#ifndef WB_KEYBOARD_H
#define WB_KEYBOARD_H

#ifdef __cplusplus
extern "C" {
#endif

enum {
  WB_KEYBOARD_END = 312,
  WB_KEYBOARD_HOME,
  WB_KEYBOARD_LEFT,
  WB_KEYBOARD_UP,
  WB_KEYBOARD_RIGHT,
  WB_KEYBOARD_DOWN,
  WB_KEYBOARD_PAGEUP = 366,
  WB_KEYBOARD_PAGEDOWN,
  WB_KEYBOARD_NUMPAD_HOME = 375,
  WB_KEYBOARD_NUMPAD_LEFT,
  WB_KEYBOARD_NUMPAD_UP,
  WB_KEYBOARD_NUMPAD_RIGHT,
  WB_KEYBOARD_NUMPAD_DOWN,
  WB_KEYBOARD_NUMPAD_END = 382,
  WB_KEYBOARD_KEY = 0x0000ffff,
  WB_KEYBOARD_SHIFT = 0x00010000,
  WB_KEYBOARD_CONTROL = 0x00020000,
  WB_KEYBOARD_ALT = 0x00040000
};

void wb_keyboard_enable(int sampling_period);
void wb_keyboard_disable(void);
int wb_keyboard_get_sampling_period(void);
/* The next key, -1 when none is left (and, with an error, while disabled). */
int wb_keyboard_get_key(void);

#ifdef __cplusplus
}
#endif

#endif /* WB_KEYBOARD_H */
