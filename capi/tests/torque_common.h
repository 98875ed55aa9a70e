/*
 * torque_common.h: the TORQUE-mode scenario shared by torque_combustion.c and torque_electric.c.
 *
 * Checks, in order: neutral gives no torque (a parked car with full throttle in neutral does
 * not move and reports 0 rpm); in first gear the speed rises, faster with more throttle; the
 * reported rpm is exactly the library's estimate from the wheel speeds and the engaged gear
 * (spec section 2.3: |mean of the 4 wheel speeds * 60/(2*pi) * ratio|, capped at engineMaxRPM),
 * also in a turn where the front and rear wheels turn at different speeds; a higher gear lowers
 * the rpm at the same speed; shifting to neutral while moving stops the
 * acceleration; the brake stops the car; reverse gear drives it backwards with the reversing
 * lights on.
 */

#ifndef CAPI_TEST_TORQUE_COMMON_H
#define CAPI_TEST_TORQUE_COMMON_H

#include "drive.h"

struct torque_case {
  struct drive_model model;
  double ratio_first;      /* gearRatio[1] */
  double ratio_second;     /* gearRatio[2]; 0 if the car has a single forward gear */
  double ratio_reverse;    /* -gearRatio[0] (positive): the ratio the rpm estimate uses in reverse */
  double max_rpm;          /* engineMaxRPM */
  double throttle_low;     /* first-gear throttle, then ... */
  double throttle_high;    /* ... this one, at least twice as much */
  double min_gain_low;     /* km/h gained per second at throttle_low, a floor well under the estimate */
  double throttle_reverse; /* reverse-gear throttle */
};

/* Checks wbu_driver_get_rpm() against the estimate from this step's wheel speeds. */
static inline void torque_check_rpm(const char *phase, double ratio, double max_rpm) {
  char what[96];
  const double expected = drive_expected_rpm(ratio, max_rpm);
  sprintf(what, "%s: wbu_driver_get_rpm() (rpm)", phase);
  /* Same formula on the same wheel speeds: only rounding may differ (1e-5 covers a
   * single-precision computation inside the library). */
  check_close(what, wbu_driver_get_rpm(), expected, 1e-5 * expected + 1e-6);
}

static inline void torque_run(const char *program, const struct torque_case *c) {
  double v1, v2, v3, gain_low, gain_high, rpm_before;

  check_begin(program);
  wbu_driver_init();
  drive_require_model(c->model);
  check_int("initial wbu_driver_get_control_mode()", wbu_driver_get_control_mode(), UNDEFINED_CONTROL_MODE);
  check_int("initial wbu_driver_get_gear()", wbu_driver_get_gear(), 0);
  check_close("initial wbu_driver_get_throttle()", wbu_driver_get_throttle(), 0.0, 0.0);
  drive_for(0.1);
  check_close("parked (no control mode yet): wbu_driver_get_rpm() (rpm)", wbu_driver_get_rpm(), 0.0, 0.0);

  /* Neutral: full throttle, no torque reaches the wheels. */
  wbu_driver_set_gear(0);
  wbu_driver_set_throttle(1.0);
  check_int("wbu_driver_get_control_mode() after set_throttle", wbu_driver_get_control_mode(), TORQUE);
  check_close("wbu_driver_get_throttle()", wbu_driver_get_throttle(), 1.0, 0.0);
  drive_for(2.0);
  check_int("neutral: wbu_driver_get_gear()", wbu_driver_get_gear(), 0);
  check_close("neutral from rest, throttle 1: wbu_driver_get_current_speed() (km/h)", wbu_driver_get_current_speed(), 0.0,
              0.5);
  check_close("neutral: wbu_driver_get_rpm() (rpm)", wbu_driver_get_rpm(), 0.0, 0.0);

  /* First gear: the speed rises, faster with more throttle. */
  wbu_driver_set_gear(1);
  wbu_driver_set_throttle(c->throttle_low);
  check_int("first gear: wbu_driver_get_gear()", wbu_driver_get_gear(), 1);
  check_close("first gear: wbu_driver_get_throttle()", wbu_driver_get_throttle(), c->throttle_low, 0.0);
  drive_for(1.0);
  v1 = wbu_driver_get_current_speed();
  check_true(v1 > 0.0, "first gear, throttle %g: moving forward after 1 s (%g km/h)", c->throttle_low, v1);
  torque_check_rpm("first gear after 1 s", c->ratio_first, c->max_rpm);
  drive_for(1.0);
  v2 = wbu_driver_get_current_speed();
  gain_low = v2 - v1;
  check_true(gain_low > c->min_gain_low, "first gear, throttle %g: speed gain in 1 s = %g km/h, expected > %g km/h",
             c->throttle_low, gain_low, c->min_gain_low);
  torque_check_rpm("first gear after 2 s", c->ratio_first, c->max_rpm);
  check_true(wbu_driver_get_rpm() > 0.0, "first gear: the engine turns (%g rpm)", wbu_driver_get_rpm());

  wbu_driver_set_throttle(c->throttle_high);
  drive_for(1.0);
  v3 = wbu_driver_get_current_speed();
  gain_high = v3 - v2;
  check_true(gain_high > 2.0 * gain_low,
             "first gear, throttle %g: speed gain in 1 s = %g km/h, expected > 2 x %g km/h (throttle %g)", c->throttle_high,
             gain_high, gain_low, c->throttle_low);
  torque_check_rpm("first gear, high throttle", c->ratio_first, c->max_rpm);

  /* A higher gear: same speed, lower engine speed in the ratio of the gear ratios. */
  if (c->ratio_second > 0.0) {
    rpm_before = wbu_driver_get_rpm();
    wbu_driver_set_gear(2);
    check_int("second gear: wbu_driver_get_gear()", wbu_driver_get_gear(), 2);
    drive_for(0.5);
    torque_check_rpm("second gear", c->ratio_second, c->max_rpm);
    check_true(wbu_driver_get_rpm() < rpm_before, "second gear: rpm %g is below the first-gear %g", wbu_driver_get_rpm(),
               rpm_before);
  } else
    printf("%s: (single forward gear: no second-gear check)\n", program);

  /* In a turn the front wheels roll faster than the rear ones (at 0.25 rad, on radii about 3 %
   * larger): the estimate must average all four. Low throttle keeps the lateral acceleration
   * moderate (under 4 m/s^2 at the speeds reached here). */
  wbu_driver_set_throttle(c->throttle_low);
  wbu_driver_set_steering_angle(0.25);
  drive_for(1.0);
  {
    const double front = (wbu_car_get_wheel_speed(WBU_CAR_WHEEL_FRONT_RIGHT) + wbu_car_get_wheel_speed(WBU_CAR_WHEEL_FRONT_LEFT)) / 2;
    const double rear = (wbu_car_get_wheel_speed(WBU_CAR_WHEEL_REAR_RIGHT) + wbu_car_get_wheel_speed(WBU_CAR_WHEEL_REAR_LEFT)) / 2;
    check_true(check_abs(front - rear) > 0.01 * check_abs(front),
               "turning at 0.25 rad: front wheels %g rad/s, rear wheels %g rad/s (front faster)", front, rear);
    torque_check_rpm("turning at 0.25 rad", c->ratio_second > 0.0 ? c->ratio_second : c->ratio_first, c->max_rpm);
  }
  wbu_driver_set_steering_angle(0.0);
  drive_for(1.0);

  /* Neutral while moving: no torque, the car coasts and does not speed up. */
  v1 = wbu_driver_get_current_speed();
  wbu_driver_set_gear(0);
  drive_for(2.0);
  v2 = wbu_driver_get_current_speed();
  check_true(v2 <= v1 + 0.2, "neutral while moving, throttle %g: speed %g km/h after 2 s, was %g km/h",
             wbu_driver_get_throttle(), v2, v1);
  check_true(v2 > 0.0, "neutral while moving: still rolling forward (%g km/h)", v2);
  check_close("neutral while moving: wbu_driver_get_rpm() (rpm)", wbu_driver_get_rpm(), 0.0, 0.0);

  /* Full brake to a stop. */
  wbu_driver_set_throttle(0.0);
  wbu_driver_set_brake_intensity(1.0);
  drive_for(4.0);
  check_close("after 4 s of full brake: wbu_driver_get_current_speed() (km/h)", wbu_driver_get_current_speed(), 0.0, 1.0);
  check_true(wbu_car_get_brake_lights(), "brake lights on while braking");
  wbu_driver_set_brake_intensity(0.0);

  /* Reverse gear: positive throttle drives backwards. */
  wbu_driver_set_gear(-1);
  wbu_driver_set_throttle(c->throttle_reverse);
  check_int("reverse: wbu_driver_get_gear()", wbu_driver_get_gear(), -1);
  drive_for(3.0);
  check_true(wbu_driver_get_current_speed() < -2.0, "reverse, throttle %g: moving backwards after 3 s (%g km/h)",
             c->throttle_reverse, wbu_driver_get_current_speed());
  check_true(drive_mean_wheel_speed() < 0.0, "reverse: wheels turn backwards (mean %g rad/s)", drive_mean_wheel_speed());
  torque_check_rpm("reverse", c->ratio_reverse, c->max_rpm);
  check_true(wbu_driver_get_rpm() > 0.0, "reverse: rpm is positive (%g rpm)", wbu_driver_get_rpm());
  check_true(wbu_car_get_backwards_lights(), "reversing lights on in reverse gear");
  check_true(!wbu_car_get_brake_lights(), "brake lights off once the brake is released");

  wbu_driver_cleanup();
}

#endif /* CAPI_TEST_TORQUE_COMMON_H */
