/*
 * bad_input: misuse of the driver and car libraries never crashes and never corrupts state.
 *
 * World: the default one (VEHICLE_WORLD unset, or VEHICLE_WORLD=BmwX5).
 *
 * Covered: calls before initialisation, double initialisation, NaN and infinite arguments,
 * out-of-range gears (gear_number, above it, -2, INT_MIN, INT_MAX), wheel indices 4, -1 and
 * WBU_CAR_WHEEL_NB, out-of-range enumeration values, non-0/1 bool bytes, getters in the wrong
 * control mode, calls after cleanup. Each case checks the return values and that the state
 * stays valid (finite, in range, unchanged where the call must be ignored).
 *
 * stderr: this program writes nothing to stderr itself; everything there comes from the
 * libraries. Before each misuse it prints "bad_input: call: ..." on stdout (flushed), naming
 * the warning expected on stderr when Webots defines one, so that a runner can match the two
 * streams. README.md lists the expected stderr lines.
 *
 * Golden values (BmwX5, L = 2.995 m, Tf = 1.628 m): steering 0.1 rad gives
 *   cot 0.1 = 9.966644, Tf / (2 L) = 0.271786,
 *   right wheel atan(1 / (9.966644 - 0.271786)) = 0.102784 rad,
 *   left wheel  atan(1 / (9.966644 + 0.271786)) = 0.097362 rad.
 * Wheel motor speed limit: maxVelocity 50 m/s / 0.374 m = 133.69 rad/s.
 */

#include <limits.h>

#include "drive.h"

/* Announces a misuse on stdout, with the stderr text Webots prints for it ("" if none). */
static void call(const char *what, const char *expected_stderr) {
  if (expected_stderr[0] != '\0')
    printf("bad_input: call: %s -> stderr: %s\n", what, expected_stderr);
  else
    printf("bad_input: call: %s\n", what);
  fflush(stdout);
}

static int is_finite_value(double x) {
  return isfinite(x) ? 1 : 0;
}

/* Both front steering sensors finite and within the BmwX5 steering limits (+-1 rad). */
static void check_steering_valid(const char *after) {
  const double right = wbu_car_get_right_steering_angle();
  const double left = wbu_car_get_left_steering_angle();
  check_true(is_finite_value(right) && check_abs(right) <= 1.01, "after %s: right steering sensor %g rad is finite, |.| <= 1", after,
             right);
  check_true(is_finite_value(left) && check_abs(left) <= 1.01, "after %s: left steering sensor %g rad is finite, |.| <= 1", after,
             left);
  check_true(is_finite_value(wbu_driver_get_steering_angle()), "after %s: wbu_driver_get_steering_angle() is finite", after);
}

/* Every wheel speed finite and within the wheel motors' 133.69 rad/s, current speed finite. */
static void check_motion_valid(const char *after) {
  int wheel;
  for (wheel = 0; wheel < 4; ++wheel) {
    const double w = wbu_car_get_wheel_speed((WbuCarWheelIndex)wheel);
    check_true(is_finite_value(w) && check_abs(w) <= 133.69 * 1.02, "after %s: wheel %d speed %g rad/s is finite, |.| <= 133.69",
               after, wheel, w);
  }
  check_true(is_finite_value(wbu_driver_get_current_speed()), "after %s: wbu_driver_get_current_speed() = %g km/h is finite", after,
             wbu_driver_get_current_speed());
}

int main(void) {
  int gears;

  check_begin("bad_input");

  /* ---- Before any initialisation: warnings, neutral values, setters ignored. ---- */
  call("wbu_driver_get_steering_angle() before init",
       "Warning: 'wbu_driver_init()' should be called before to use 'wbu_driver_get_steering_angle()'.");
  check_close("wbu_driver_get_steering_angle() before init", wbu_driver_get_steering_angle(), 0.0, 0.0);
  call("wbu_driver_set_cruising_speed(30) before init",
       "Warning: 'wbu_driver_init()' should be called before to use 'wbu_driver_set_cruising_speed()'.");
  wbu_driver_set_cruising_speed(30.0);
  call("wbu_driver_get_control_mode() before init",
       "Warning: 'wbu_driver_init()' should be called before to use 'wbu_driver_get_control_mode()'.");
  check_int("wbu_driver_get_control_mode() before init", wbu_driver_get_control_mode(), UNDEFINED_CONTROL_MODE);
  call("wbu_driver_get_indicator() before init",
       "Warning: 'wbu_driver_init()' should be called before to use 'wbu_driver_get_indicator()'.");
  check_int("wbu_driver_get_indicator() before init", wbu_driver_get_indicator(), OFF);
  call("wbu_driver_get_wiper_mode() before init",
       "Warning: 'wbu_driver_init()' should be called before to use 'wbu_driver_get_wiper_mode()'.");
  /* (int): GCC gives an enumeration without negative values an unsigned type in C. */
  check_int("wbu_driver_get_wiper_mode() before init", (int)wbu_driver_get_wiper_mode(), -1);
  call("wbu_driver_get_hazard_flashers() before init",
       "Warning: 'wbu_driver_init()' should be called before to use 'wbu_driver_get_hazard_flashers'.");
  check_true(!wbu_driver_get_hazard_flashers(), "wbu_driver_get_hazard_flashers() before init is false");
  call("wbu_driver_get_gear() before init",
       "Warning: 'wbu_driver_init()' should be called before to use 'wbu_driver_get_gear()'.");
  check_int("wbu_driver_get_gear() before init", wbu_driver_get_gear(), 0);
  call("wbu_driver_step() before init", "Warning: 'wbu_driver_init()' should be called before to use 'wbu_driver_step()'.");
  check_int("wbu_driver_step() before init", wbu_driver_step(), 0);
  call("wbu_car_get_wheelbase() before init",
       "Warning: 'wbu_car_init()' should be called before to use 'wbu_car_get_wheelbase()'.");
  check_close("wbu_car_get_wheelbase() before init", wbu_car_get_wheelbase(), 0.0, 0.0);
  call("wbu_car_get_type() before init", "Warning: 'wbu_car_init()' should be called before to use 'wbu_car_get_type()'.");
  check_int("wbu_car_get_type() before init", wbu_car_get_type(), 0);
  call("wbu_car_get_wheel_speed(0) before init",
       "Warning: 'wbu_car_init()' should be called before to use 'wbu_car_get_wheel_speed()'.");
  check_close("wbu_car_get_wheel_speed(0) before init", wbu_car_get_wheel_speed(WBU_CAR_WHEEL_FRONT_RIGHT), 0.0, 0.0);
  call("wbu_car_set_indicator_period(1) before init",
       "Warning: 'wbu_car_init()' should be called before to use 'wbu_car_set_indicator_period()'.");
  wbu_car_set_indicator_period(1.0);

  /* ---- The car library alone, then the driver library initialised twice. ---- */
  wbu_car_init();
  check_close("wbu_car_get_wheelbase() after wbu_car_init() (m)", wbu_car_get_wheelbase(), 2.995, 1e-9);
  check_close("wbu_car_get_wheel_speed(0) with no driver step (rad/s)", wbu_car_get_wheel_speed(WBU_CAR_WHEEL_FRONT_RIGHT),
              0.0, 0.0);
  check_close("wbu_car_get_indicator_period(): the call before init was ignored (s)", wbu_car_get_indicator_period(), 0.34,
              1e-12);
  wbu_driver_init();
  wbu_driver_set_gear(2);
  call("wbu_driver_init() a second time (no-op, no message)", "");
  wbu_driver_init();
  call("wbu_car_init() after wbu_driver_init() (no-op, no message)", "");
  wbu_car_init();
  check_int("wbu_driver_get_gear() survives the second init", wbu_driver_get_gear(), 2);
  check_close("wbu_driver_get_target_cruising_speed(): the call before init was ignored (km/h)",
              wbu_driver_get_target_cruising_speed(), 0.0, 0.0);
  check_int("wbu_driver_get_control_mode(): the call before init was ignored", wbu_driver_get_control_mode(),
            UNDEFINED_CONTROL_MODE);
  drive_require_model(drive_bmw_x5());
  gears = wbu_driver_get_gear_number();

  /* ---- Gears out of range: clamped to -1 .. gear_number - 1 (the highest real forward gear). ---- */
  call("wbu_driver_set_gear(gear_number) (Webots accepts it and reads past gearRatio; clamped here)", "");
  wbu_driver_set_gear(gears);
  check_int("wbu_driver_get_gear() after set_gear(gear_number)", wbu_driver_get_gear(), gears - 1);
  call("wbu_driver_set_gear(100)", "Warning: this car has only 6 gears.");
  wbu_driver_set_gear(100);
  check_int("wbu_driver_get_gear() after set_gear(100)", wbu_driver_get_gear(), gears - 1);
  call("wbu_driver_set_gear(INT_MAX)", "Warning: this car has only 6 gears.");
  wbu_driver_set_gear(INT_MAX);
  check_int("wbu_driver_get_gear() after set_gear(INT_MAX)", wbu_driver_get_gear(), gears - 1);
  call("wbu_driver_set_gear(-2)", "Warning: Minimum gear value is -1");
  wbu_driver_set_gear(-2);
  check_int("wbu_driver_get_gear() after set_gear(-2)", wbu_driver_get_gear(), -1);
  call("wbu_driver_set_gear(INT_MIN)", "Warning: Minimum gear value is -1");
  wbu_driver_set_gear(INT_MIN);
  check_int("wbu_driver_get_gear() after set_gear(INT_MIN)", wbu_driver_get_gear(), -1);
  wbu_driver_set_gear(gears);
  wbu_driver_set_throttle(0.0);
  drive_for(0.2);
  check_true(is_finite_value(wbu_driver_get_rpm()) && wbu_driver_get_rpm() >= 0.0,
             "wbu_driver_get_rpm() in the clamped top gear is finite and >= 0 (%g rpm)", wbu_driver_get_rpm());
  check_motion_valid("driving in the clamped top gear");

  /* ---- Throttle and brake: NaN ignored, infinities and out-of-range values clamped to [0, 1]. ---- */
  wbu_driver_set_throttle(0.5);
  call("wbu_driver_set_throttle(NaN) (ignored; Webots stores the NaN)", "");
  wbu_driver_set_throttle(NAN);
  check_close("wbu_driver_get_throttle() after NaN", wbu_driver_get_throttle(), 0.5, 0.0);
  call("wbu_driver_set_throttle(+inf)", "Warning: 'throttle' should be smaller or equal to 1, used 1 instead.");
  wbu_driver_set_throttle(INFINITY);
  check_close("wbu_driver_get_throttle() after +inf", wbu_driver_get_throttle(), 1.0, 0.0);
  call("wbu_driver_set_throttle(-inf)", "Warning: 'throttle' should be bigger or equal to 0, used 0 instead.");
  wbu_driver_set_throttle(-INFINITY);
  check_close("wbu_driver_get_throttle() after -inf", wbu_driver_get_throttle(), 0.0, 0.0);
  call("wbu_driver_set_throttle(1.5)", "Warning: 'throttle' should be smaller or equal to 1, used 1 instead.");
  wbu_driver_set_throttle(1.5);
  check_close("wbu_driver_get_throttle() after 1.5", wbu_driver_get_throttle(), 1.0, 0.0);
  call("wbu_driver_set_throttle(-0.5)", "Warning: 'throttle' should be bigger or equal to 0, used 0 instead.");
  wbu_driver_set_throttle(-0.5);
  check_close("wbu_driver_get_throttle() after -0.5", wbu_driver_get_throttle(), 0.0, 0.0);

  wbu_driver_set_brake_intensity(0.3);
  call("wbu_driver_set_brake_intensity(NaN) (ignored; Webots stores the NaN)", "");
  wbu_driver_set_brake_intensity(NAN);
  check_close("wbu_driver_get_brake_intensity() after NaN", wbu_driver_get_brake_intensity(), 0.3, 0.0);
  call("wbu_driver_set_brake_intensity(+inf)", "Warning: 'intensity' should be smaller or equal to 1, used 1 instead.");
  wbu_driver_set_brake_intensity(INFINITY);
  check_close("wbu_driver_get_brake_intensity() after +inf", wbu_driver_get_brake_intensity(), 1.0, 0.0);
  drive_for(0.2);
  check_motion_valid("braking at intensity 1 while parked");
  call("wbu_driver_set_brake_intensity(-inf)", "Warning: 'intensity' should be bigger or equal to 0, used 0 instead.");
  wbu_driver_set_brake_intensity(-INFINITY);
  check_close("wbu_driver_get_brake_intensity() after -inf", wbu_driver_get_brake_intensity(), 0.0, 0.0);
  drive_for(0.1);
  check_true(!wbu_car_get_brake_lights(), "brake lights off after the clamped 0 intensity");

  /* ---- Steering: NaN ignored (Webots), infinities never reach the wheels. ---- */
  wbu_driver_set_steering_angle(0.1);
  drive_for(1.0);
  check_close("right steering sensor at steering 0.1 (rad)", wbu_car_get_right_steering_angle(), 0.102784, 0.01);
  check_close("left steering sensor at steering 0.1 (rad)", wbu_car_get_left_steering_angle(), 0.097362, 0.01);
  call("wbu_driver_set_steering_angle(NaN)",
       "Warning: wbu_driver_set_steering_angle() called with an invalid 'steering_angle' argument (NaN)");
  wbu_driver_set_steering_angle(NAN);
  drive_for(0.5);
  check_close("right steering sensor after NaN: unchanged (rad)", wbu_car_get_right_steering_angle(), 0.102784, 0.01);
  check_close("left steering sensor after NaN: unchanged (rad)", wbu_car_get_left_steering_angle(), 0.097362, 0.01);
  call("wbu_driver_set_steering_angle(+inf)", "");
  wbu_driver_set_steering_angle(INFINITY);
  drive_for(0.5);
  check_steering_valid("set_steering_angle(+inf)");
  call("wbu_driver_set_steering_angle(-inf)", "");
  wbu_driver_set_steering_angle(-INFINITY);
  drive_for(0.5);
  check_steering_valid("set_steering_angle(-inf)");
  wbu_driver_set_steering_angle(0.0);
  drive_for(1.0);
  check_close("right steering sensor back at steering 0 (rad)", wbu_car_get_right_steering_angle(), 0.0, 0.01);
  check_close("left steering sensor back at steering 0 (rad)", wbu_car_get_left_steering_angle(), 0.0, 0.01);

  /* ---- Car-library steering: NaN ignored (Webots), infinities never reach the wheels. ---- */
  call("wbu_car_set_right_steering_angle(NaN)",
       "Warning: wbu_car_set_right_steering_angle() called with an invalid 'angle' argument (NaN)");
  wbu_car_set_right_steering_angle(NAN);
  call("wbu_car_set_left_steering_angle(NaN)",
       "Warning: wbu_car_set_left_steering_angle() called with an invalid 'angle' argument (NaN)");
  wbu_car_set_left_steering_angle(NAN);
  drive_for(0.5);
  check_close("right steering sensor after car-library NaN: unchanged (rad)", wbu_car_get_right_steering_angle(), 0.0, 0.01);
  check_close("left steering sensor after car-library NaN: unchanged (rad)", wbu_car_get_left_steering_angle(), 0.0, 0.01);
  call("wbu_car_set_right_steering_angle(+inf)", "");
  wbu_car_set_right_steering_angle(INFINITY);
  call("wbu_car_set_left_steering_angle(-inf)", "");
  wbu_car_set_left_steering_angle(-INFINITY);
  drive_for(0.5);
  check_steering_valid("wbu_car_set_right/left_steering_angle(+inf/-inf)");
  wbu_driver_set_steering_angle(0.0);
  drive_for(1.0);

  /* ---- Cruising speed: NaN ignored, infinities never reach the wheels. ---- */
  wbu_driver_set_cruising_speed(10.0);
  call("wbu_driver_set_cruising_speed(NaN) (ignored; Webots passes the NaN to the motors)", "");
  wbu_driver_set_cruising_speed(NAN);
  check_close("wbu_driver_get_target_cruising_speed() after NaN (km/h)", wbu_driver_get_target_cruising_speed(), 10.0, 0.0);
  drive_for(2.0);
  check_motion_valid("set_cruising_speed(NaN)");
  check_rel("cruising after NaN: wbu_driver_get_current_speed() still reaches 10 km/h", wbu_driver_get_current_speed(), 10.0,
            0.05);

  /* ---- Wheel indices out of range, while the wheels turn (a 0 is then not a real speed). ---- */
  check_true(wbu_car_get_wheel_speed(WBU_CAR_WHEEL_FRONT_RIGHT) > 1.0, "front right wheel turns at %g rad/s",
             wbu_car_get_wheel_speed(WBU_CAR_WHEEL_FRONT_RIGHT));
  call("wbu_car_get_wheel_speed(4)", "Warning: maximum wheel index is 4.");
  check_close("wbu_car_get_wheel_speed(4)", wbu_car_get_wheel_speed((WbuCarWheelIndex)4), 0.0, 0.0);
  call("wbu_car_get_wheel_speed(WBU_CAR_WHEEL_NB)", "Warning: maximum wheel index is 4.");
  check_close("wbu_car_get_wheel_speed(WBU_CAR_WHEEL_NB)", wbu_car_get_wheel_speed(WBU_CAR_WHEEL_NB), 0.0, 0.0);
  call("wbu_car_get_wheel_speed(-1)", "Warning: maximum wheel index is 4.");
  check_close("wbu_car_get_wheel_speed(-1)", wbu_car_get_wheel_speed((WbuCarWheelIndex)-1), 0.0, 0.0);
  call("wbu_car_get_wheel_encoder(4)", "Warning: maximum wheel index is 4.");
  check_close("wbu_car_get_wheel_encoder(4)", wbu_car_get_wheel_encoder((WbuCarWheelIndex)4), 0.0, 0.0);
  call("wbu_car_get_wheel_encoder(-1)", "Warning: maximum wheel index is 4.");
  check_close("wbu_car_get_wheel_encoder(-1)", wbu_car_get_wheel_encoder((WbuCarWheelIndex)-1), 0.0, 0.0);
  check_true(is_finite_value(wbu_car_get_wheel_encoder(WBU_CAR_WHEEL_REAR_LEFT)), "wbu_car_get_wheel_encoder(3) is finite");

  /* ---- Getters in the wrong control mode (SPEED has no engine or gearbox model). ---- */
  wbu_driver_set_gear(3); /* allowed in any mode */
  call("wbu_driver_get_rpm() in SPEED mode",
       "Warning: no engine model when cruise control is enable, call to 'wbu_driver_get_rpm()' is therefore not allowed.");
  check_close("wbu_driver_get_rpm() in SPEED mode", wbu_driver_get_rpm(), 0.0, 0.0);
  call("wbu_driver_get_gear() in SPEED mode",
       "Warning: no gear model when cruise control is enable, call to 'wbu_driver_get_gear()' is therefore not allowed.");
  check_int("wbu_driver_get_gear() in SPEED mode", wbu_driver_get_gear(), 0);

  call("wbu_driver_set_cruising_speed(+inf)", "");
  wbu_driver_set_cruising_speed(INFINITY);
  check_true(is_finite_value(wbu_driver_get_target_cruising_speed()), "wbu_driver_get_target_cruising_speed() after +inf is finite (%g)",
             wbu_driver_get_target_cruising_speed());
  drive_for(0.5);
  check_motion_valid("set_cruising_speed(+inf)");
  call("wbu_driver_set_cruising_speed(-inf)", "");
  wbu_driver_set_cruising_speed(-INFINITY);
  check_true(is_finite_value(wbu_driver_get_target_cruising_speed()), "wbu_driver_get_target_cruising_speed() after -inf is finite (%g)",
             wbu_driver_get_target_cruising_speed());
  drive_for(0.5);
  check_motion_valid("set_cruising_speed(-inf)");
  wbu_driver_set_cruising_speed(0.0);
  drive_for(2.0);

  wbu_driver_set_throttle(0.0);
  check_int("wbu_driver_get_control_mode() after set_throttle", wbu_driver_get_control_mode(), TORQUE);
  check_int("wbu_driver_get_gear() in TORQUE mode: the gear set in SPEED mode", wbu_driver_get_gear(), 3);

  /* ---- Indicator period: must be finite and > 0; anything else is ignored. ---- */
  call("wbu_car_set_indicator_period(NaN) (ignored; Webots stores it)", "");
  wbu_car_set_indicator_period(NAN);
  check_close("wbu_car_get_indicator_period() after NaN (s)", wbu_car_get_indicator_period(), 0.34, 1e-12);
  call("wbu_car_set_indicator_period(+inf) (ignored; Webots stores it)", "");
  wbu_car_set_indicator_period(INFINITY);
  check_close("wbu_car_get_indicator_period() after +inf (s)", wbu_car_get_indicator_period(), 0.34, 1e-12);
  call("wbu_car_set_indicator_period(0) (ignored; Webots divides by it)", "");
  wbu_car_set_indicator_period(0.0);
  check_close("wbu_car_get_indicator_period() after 0 (s)", wbu_car_get_indicator_period(), 0.34, 1e-12);
  call("wbu_car_set_indicator_period(-1) (ignored; Webots stores it)", "");
  wbu_car_set_indicator_period(-1.0);
  check_close("wbu_car_get_indicator_period() after -1 (s)", wbu_car_get_indicator_period(), 0.34, 1e-12);
  wbu_driver_set_hazard_flashers(true);
  drive_for(1.0); /* the blink clock divides by the period */
  wbu_driver_set_hazard_flashers(false);

  /* ---- Enumeration values out of range: ignored, the state stays a valid enumerator. ---- */
  wbu_driver_set_indicator(RIGHT);
  call("wbu_driver_set_indicator(7) (ignored; Webots stores it)", "");
  wbu_driver_set_indicator((WbuDriverIndicatorState)7);
  check_int("wbu_driver_get_indicator() after set_indicator(7)", wbu_driver_get_indicator(), RIGHT);
  call("wbu_driver_set_indicator(-1) (ignored; Webots stores it)", "");
  wbu_driver_set_indicator((WbuDriverIndicatorState)-1);
  check_int("wbu_driver_get_indicator() after set_indicator(-1)", wbu_driver_get_indicator(), RIGHT);
  wbu_driver_set_indicator(OFF);
  wbu_driver_set_wiper_mode(NORMAL);
  call("wbu_driver_set_wiper_mode(9) (ignored; Webots stores it)", "");
  wbu_driver_set_wiper_mode((WbuDriverWiperMode)9);
  check_int("wbu_driver_get_wiper_mode() after set_wiper_mode(9)", wbu_driver_get_wiper_mode(), NORMAL);
  call("wbu_driver_set_wiper_mode(-1) (ignored; Webots stores it)", "");
  wbu_driver_set_wiper_mode((WbuDriverWiperMode)-1);
  check_int("wbu_driver_get_wiper_mode() after set_wiper_mode(-1)", wbu_driver_get_wiper_mode(), NORMAL);
  drive_for(0.5);
  wbu_driver_set_wiper_mode(DOWN);

  /* ---- bool arguments: any non-zero byte means true (C controllers pass a char). ---- */
  wbu_driver_set_hazard_flashers((bool)2);
  check_true(wbu_driver_get_hazard_flashers() != 0, "hazard flashers on after set_hazard_flashers(2)");
  wbu_driver_set_hazard_flashers(false);
  check_true(!wbu_driver_get_hazard_flashers(), "hazard flashers off after set_hazard_flashers(false)");
  wbu_driver_set_dipped_beams((bool)2);
  check_true(wbu_driver_get_dipped_beams() != 0, "dipped beams on after set_dipped_beams(2)");
  wbu_driver_set_dipped_beams(false);
  check_true(!wbu_driver_get_dipped_beams(), "dipped beams off after set_dipped_beams(false)");
  drive_for(0.1);
  check_motion_valid("the whole sequence");

  /* ---- After cleanup: the libraries warn again and return neutral values. ---- */
  wbu_driver_cleanup();
  call("wbu_driver_get_throttle() after cleanup",
       "Warning: 'wbu_driver_init()' should be called before to use 'wbu_driver_get_throttle()'.");
  check_close("wbu_driver_get_throttle() after cleanup", wbu_driver_get_throttle(), 0.0, 0.0);
  call("wbu_car_get_wheelbase() after cleanup",
       "Warning: 'wbu_car_init()' should be called before to use 'wbu_car_get_wheelbase()'.");
  check_close("wbu_car_get_wheelbase() after cleanup", wbu_car_get_wheelbase(), 0.0, 0.0);
  call("wbu_driver_cleanup() a second time (no-op, no message)", "");
  wbu_driver_cleanup();

  return check_finish();
}
