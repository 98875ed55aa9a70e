/*
 * differential_wheels: the legacy DifferentialWheels API (webots/differential_wheels.h).
 *
 * World: VEHICLE_WORLD=<path to capi/tests/worlds/differential_wheels.toml>: basicTimeStep
 * 32 ms, kinematics mode, maxSpeed 6.28 rad/s, speedUnit 1 rad/s, encoderResolution 159.23
 * increments/rad, no slip or encoder noise, maxAcceleration 10000 rad/s^2 (any commanded speed
 * is reached within one step).
 *
 * Golden values: a wheel at w rad/s advances its encoder by 159.23 * w * 0.032 per step:
 *   w = 1:     5.09536 per step; 32 steps (1.024 s) = 163.05152 (1 s would be 159.23)
 *   w = 2:     10.19072 per step
 *   w = 3:     15.28608 per step
 *   w = 6.28:  31.9988608 per step (maxSpeed: what a command above it is limited to)
 * Per-step increments are compared to 1e-3 once the speed is reached (the difference of two
 * counts near 300 in single precision is good to about 1e-4); the 32-step total allows one step
 * of latency between the command and the first increment (157.95616 to 163.05152).
 *
 * Speed limit: Webots prints
 *   Error: wb_differential_wheels_set_speed(L,R) overflows maxSpeed/speedUnit: 6.28/1=6.28.
 * when a command exceeds maxSpeed (positive side only) but still applies it (its clamp is a
 * no-op, spec section 7.3); this simulator applies the message and limits each wheel to
 * [-maxSpeed, maxSpeed] (a documented difference). The speed getters return the commanded
 * values, as Webots documents ("the last speed commands given as an argument").
 */

#include <webots/differential_wheels.h>
#include <webots/robot.h>

#include "check.h"

#define RESOLUTION 159.23 /* increments per rad */
#define STEP_S 0.032      /* s */

static int steps_run = 0;

static void step(int count) {
  int i;
  for (i = 0; i < count; ++i) {
    if (wb_robot_step(32) == -1)
      check_fatal("wb_robot_step(32) returned -1 (simulation ended) at t = %g s", wb_robot_get_time());
    steps_run++;
  }
}

/* Announces a misuse on stdout with the stderr text Webots prints for it ("" if none). */
static void call(const char *what, const char *expected_stderr) {
  if (expected_stderr[0] != '\0')
    printf("differential_wheels: call: %s -> stderr: %s\n", what, expected_stderr);
  else
    printf("differential_wheels: call: %s\n", what);
  fflush(stdout);
}

/* Runs 2 steps to reach the commanded speeds, then checks the encoder increments of 1 more step. */
static void check_increments(const char *what, double left_speed, double right_speed) {
  double left, right;
  char text[128];
  step(2);
  left = wb_differential_wheels_get_left_encoder();
  right = wb_differential_wheels_get_right_encoder();
  step(1);
  sprintf(text, "%s: left encoder increment per step", what);
  check_close(text, wb_differential_wheels_get_left_encoder() - left, RESOLUTION * left_speed * STEP_S, 1e-3);
  sprintf(text, "%s: right encoder increment per step", what);
  check_close(text, wb_differential_wheels_get_right_encoder() - right, RESOLUTION * right_speed * STEP_S, 1e-3);
}

int main(void) {
  double left, right, total_left, total_right;

  check_begin("differential_wheels");
  wb_robot_init();
  if (!(wb_differential_wheels_get_max_speed() > 0.0))
    check_fatal("this program needs VEHICLE_WORLD=<path to capi/tests/worlds/differential_wheels.toml> "
                "(wb_differential_wheels_get_max_speed() = %g)",
                wb_differential_wheels_get_max_speed());

  check_close("wb_robot_get_basic_time_step() (ms)", wb_robot_get_basic_time_step(), 32.0, 0.0);
  check_close("wb_differential_wheels_get_max_speed() (rad/s)", wb_differential_wheels_get_max_speed(), 6.28, 1e-12);
  check_close("wb_differential_wheels_get_speed_unit() (rad/s)", wb_differential_wheels_get_speed_unit(), 1.0, 1e-12);
  call("wb_robot_get_device(\"no such device\")", "Warning: \"no such device\" device not found.");
  check_int("wb_robot_get_device(\"no such device\")", wb_robot_get_device("no such device"), 0);
  check_int("initial wb_differential_wheels_get_encoders_sampling_period() (ms)",
            wb_differential_wheels_get_encoders_sampling_period(), 0);

  /* Encoders on, robot still: both read 0 after the first sampling period. */
  wb_differential_wheels_enable_encoders(32);
  check_int("wb_differential_wheels_get_encoders_sampling_period() after enable(32) (ms)",
            wb_differential_wheels_get_encoders_sampling_period(), 32);
  step(1);
  check_close("left encoder before moving", wb_differential_wheels_get_left_encoder(), 0.0, 1e-12);
  check_close("right encoder before moving", wb_differential_wheels_get_right_encoder(), 0.0, 1e-12);

  /* Both wheels at 1 rad/s for 32 steps = 1.024 s. */
  wb_differential_wheels_set_speed(1.0, 1.0);
  check_close("wb_differential_wheels_get_left_speed()", wb_differential_wheels_get_left_speed(), 1.0, 0.0);
  check_close("wb_differential_wheels_get_right_speed()", wb_differential_wheels_get_right_speed(), 1.0, 0.0);
  step(31);
  left = wb_differential_wheels_get_left_encoder();
  right = wb_differential_wheels_get_right_encoder();
  step(1);
  total_left = wb_differential_wheels_get_left_encoder();
  total_right = wb_differential_wheels_get_right_encoder();
  check_close("1 rad/s: left encoder increment per step", total_left - left, RESOLUTION * STEP_S, 1e-3);
  check_close("1 rad/s: right encoder increment per step", total_right - right, RESOLUTION * STEP_S, 1e-3);
  check_close("1 rad/s for 1.024 s: left encoder", total_left, RESOLUTION * 1.024, RESOLUTION * STEP_S + 1e-3);
  check_close("1 rad/s for 1.024 s: right encoder", total_right, RESOLUTION * 1.024, RESOLUTION * STEP_S + 1e-3);

  /* Turning on the spot: opposite encoder directions. */
  wb_differential_wheels_set_speed(-2.0, 2.0);
  check_increments("spin at -2/+2 rad/s", -2.0, 2.0);

  /* A command above maxSpeed: Webots' error message, then limited to maxSpeed. */
  call("wb_differential_wheels_set_speed(10, 3)",
       "Error: wb_differential_wheels_set_speed(10,3) overflows maxSpeed/speedUnit: 6.28/1=6.28.");
  wb_differential_wheels_set_speed(10.0, 3.0);
  check_close("wb_differential_wheels_get_left_speed() returns the command", wb_differential_wheels_get_left_speed(), 10.0,
              0.0);
  check_close("wb_differential_wheels_get_right_speed() returns the command", wb_differential_wheels_get_right_speed(), 3.0,
              0.0);
  check_increments("command 10/3 rad/s, left limited to 6.28", 6.28, 3.0);
  call("wb_differential_wheels_set_speed(-10, 0) (Webots checks only the positive side: no message)", "");
  wb_differential_wheels_set_speed(-10.0, 0.0);
  check_increments("command -10/0 rad/s, left limited to -6.28", -6.28, 0.0);
  /* Infinite speeds are refused like NaN (as the driver library's setters refuse them; Webots
     would pass them on): an error naming the argument, the last command stays. */
  call("wb_differential_wheels_set_speed(inf, 0)",
       "Error: wb_differential_wheels_set_speed() called with an invalid 'left' argument (inf)");
  wb_differential_wheels_set_speed(INFINITY, 0.0);
  check_increments("command +inf/0 refused: still -10/0 rad/s, left limited to -6.28", -6.28, 0.0);
  call("wb_differential_wheels_set_speed(0, -inf)",
       "Error: wb_differential_wheels_set_speed() called with an invalid 'right' argument (-inf)");
  wb_differential_wheels_set_speed(0.0, -INFINITY);
  check_close("refused command: wb_differential_wheels_get_left_speed() still -10",
              wb_differential_wheels_get_left_speed(), -10.0, 0.0);

  /* Stopped: set_encoders overwrites the counts and nothing moves them. */
  wb_differential_wheels_set_speed(0.0, 0.0);
  step(2);
  wb_differential_wheels_set_encoders(100.0, -50.0);
  step(2);
  check_close("left encoder after set_encoders(100, -50)", wb_differential_wheels_get_left_encoder(), 100.0, 1e-9);
  check_close("right encoder after set_encoders(100, -50)", wb_differential_wheels_get_right_encoder(), -50.0, 1e-9);

  /* NaN arguments: error, call ignored. */
  call("wb_differential_wheels_set_speed(NaN, 1)",
       "Error: wb_differential_wheels_set_speed(): invalid NaN value passed as argument.");
  wb_differential_wheels_set_speed(NAN, 1.0);
  check_close("wb_differential_wheels_get_left_speed() after NaN", wb_differential_wheels_get_left_speed(), 0.0, 0.0);
  check_close("wb_differential_wheels_get_right_speed() after NaN", wb_differential_wheels_get_right_speed(), 0.0, 0.0);
  call("wb_differential_wheels_set_encoders(NaN, 0)",
       "Error: wb_differential_wheels_set_encoders(): invalid NaN value passed as argument.");
  wb_differential_wheels_set_encoders(NAN, 0.0);
  step(2);
  check_close("left encoder after NaN commands: unchanged", wb_differential_wheels_get_left_encoder(), 100.0, 1e-9);
  check_close("right encoder after NaN commands: unchanged", wb_differential_wheels_get_right_encoder(), -50.0, 1e-9);

  /* Sampling period: negative rejected, disable keeps the last value. */
  call("wb_differential_wheels_enable_encoders(-5)",
       "Error: wb_differential_wheels_enable_encoders() called with negative sampling period.");
  wb_differential_wheels_enable_encoders(-5);
  check_int("sampling period after enable(-5): unchanged (ms)", wb_differential_wheels_get_encoders_sampling_period(), 32);
  wb_differential_wheels_disable_encoders();
  check_int("sampling period after disable (ms)", wb_differential_wheels_get_encoders_sampling_period(), 0);
  wb_differential_wheels_set_speed(1.0, 1.0);
  step(3);
  call("wb_differential_wheels_get_left_encoder() while disabled",
       "Error: wb_differential_wheels_get_left_encoder() called for a disabled device! Please use: "
       "wb_differential_wheels_enable_encoders().");
  check_close("left encoder while disabled: the last sampled value", wb_differential_wheels_get_left_encoder(), 100.0, 1e-9);
  call("wb_differential_wheels_get_right_encoder() while disabled",
       "Error: wb_differential_wheels_get_right_encoder() called for a disabled device! Please use: "
       "wb_differential_wheels_enable_encoders().");
  check_close("right encoder while disabled: the last sampled value", wb_differential_wheels_get_right_encoder(), -50.0,
              1e-9);

  check_close("wb_robot_get_time() (s)", wb_robot_get_time(), steps_run * STEP_S, 1e-6);
  wb_robot_cleanup();
  return check_finish();
}
