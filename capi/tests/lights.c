/*
 * lights: lights, indicators, hazard flashers and wipers on the BmwX5.
 *
 * World: the default one (VEHICLE_WORLD unset, or VEHICLE_WORLD=BmwX5). The BmwX5 carries the
 * full VehicleLights set (front, rear, anti-fog, indicator, brake and reversing LEDs) and two
 * wiper motors with a wiper sensor.
 *
 * Webots has no getter for the indicator LEDs, so the indicators are observed through what the
 * API exposes: wbu_driver_get_indicator() and wbu_driver_get_hazard_flashers(). LED getters
 * exist for the brake and reversing lights (car library) and the anti-fog lights (driver
 * library); the dipped-beam getter returns the stored state (spec section 1.3).
 *
 * Indicator auto-cancelling (spec section 3.2, threshold 0.1 rad): RIGHT tracks the right-most
 * commanded steering angle since it was set and switches off once the steering comes back
 * 0.1 rad from it; LEFT mirrored. Angles below avoid the exact 0.1 boundary (0.2 - 0.3 is
 * -0.0999999... in binary floating point).
 * LEDs are updated by the driver step (reversing lights) or by the setter (brake lights):
 * each LED check runs after one step so that both are observed the same way.
 */

#include "drive.h"

/* Steers to `angle` rad, runs 0.1 s, and checks the indicator state. */
static void steer_and_check_indicator(double angle, WbuDriverIndicatorState expected, const char *why) {
  char what[128];
  wbu_driver_set_steering_angle(angle);
  drive_for(0.1);
  sprintf(what, "steering %g rad (%s): wbu_driver_get_indicator()", angle, why);
  check_int(what, wbu_driver_get_indicator(), expected);
}

int main(void) {
  check_begin("lights");
  wbu_driver_init();
  drive_require_model(drive_bmw_x5());

  /* Initial state. */
  check_int("initial wbu_driver_get_indicator()", wbu_driver_get_indicator(), OFF);
  check_true(!wbu_driver_get_hazard_flashers(), "initial hazard flashers off");
  check_true(!wbu_driver_get_dipped_beams(), "initial dipped beams off");
  check_true(!wbu_driver_get_antifog_lights(), "initial anti-fog lights off");
  check_int("initial wbu_driver_get_wiper_mode()", wbu_driver_get_wiper_mode(), DOWN);
  check_close("initial wbu_car_get_indicator_period() (s)", wbu_car_get_indicator_period(), 0.34, 1e-12);
  drive_for(0.1);
  check_true(!wbu_car_get_brake_lights(), "initial brake lights off");
  check_true(!wbu_car_get_backwards_lights(), "initial reversing lights off");

  /* Dipped beams: the getter returns the stored state. */
  wbu_driver_set_dipped_beams(true);
  check_true(wbu_driver_get_dipped_beams(), "dipped beams on after set_dipped_beams(true)");
  drive_for(0.1);
  check_true(wbu_driver_get_dipped_beams(), "dipped beams still on after a step");
  wbu_driver_set_dipped_beams(false);
  check_true(!wbu_driver_get_dipped_beams(), "dipped beams off after set_dipped_beams(false)");

  /* Anti-fog lights: the getter reads the LED, which the BmwX5 has. */
  wbu_driver_set_antifog_lights(true);
  drive_for(0.1);
  check_true(wbu_driver_get_antifog_lights(), "anti-fog LED on after set_antifog_lights(true)");
  wbu_driver_set_antifog_lights(false);
  drive_for(0.1);
  check_true(!wbu_driver_get_antifog_lights(), "anti-fog LED off after set_antifog_lights(false)");

  /* Brake lights follow the brake intensity: on iff > 0. */
  wbu_driver_set_brake_intensity(0.4);
  check_close("wbu_driver_get_brake_intensity()", wbu_driver_get_brake_intensity(), 0.4, 0.0);
  drive_for(0.1);
  check_true(wbu_car_get_brake_lights(), "brake lights on at brake intensity 0.4");
  wbu_driver_set_brake_intensity(0.0);
  drive_for(0.1);
  check_true(!wbu_car_get_brake_lights(), "brake lights off at brake intensity 0");
  {
    /* The Webots 8.6 names still work (and print a deprecation warning on stderr). */
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    wbu_driver_set_brake(0.7);
    check_close("deprecated wbu_driver_get_brake()", wbu_driver_get_brake(), 0.7, 0.0);
    check_close("wbu_driver_get_brake_intensity() after wbu_driver_set_brake(0.7)", wbu_driver_get_brake_intensity(), 0.7,
                0.0);
    drive_for(0.1);
    check_true(wbu_car_get_brake_lights(), "brake lights on after deprecated wbu_driver_set_brake(0.7)");
    wbu_driver_set_brake(0.0);
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
  }
  drive_for(0.1);
  check_true(!wbu_car_get_brake_lights(), "brake lights off after deprecated wbu_driver_set_brake(0)");

  /* Reversing lights: TORQUE mode with gear -1, or SPEED mode with a negative cruising speed. */
  wbu_driver_set_gear(-1);
  wbu_driver_set_throttle(0.0);
  drive_for(0.1);
  check_true(wbu_car_get_backwards_lights(), "reversing lights on: TORQUE mode, gear -1");
  wbu_driver_set_gear(0);
  drive_for(0.1);
  check_true(!wbu_car_get_backwards_lights(), "reversing lights off: TORQUE mode, gear 0");
  wbu_driver_set_gear(1);
  drive_for(0.1);
  check_true(!wbu_car_get_backwards_lights(), "reversing lights off: TORQUE mode, gear 1");
  wbu_driver_set_cruising_speed(-3.0);
  drive_for(0.1);
  check_true(wbu_car_get_backwards_lights(), "reversing lights on: SPEED mode, cruising speed -3 km/h");
  wbu_driver_set_cruising_speed(3.0);
  drive_for(0.1);
  check_true(!wbu_car_get_backwards_lights(), "reversing lights off: SPEED mode, cruising speed 3 km/h");
  wbu_driver_set_gear(-1);
  drive_for(0.1);
  check_true(!wbu_car_get_backwards_lights(), "reversing lights off: SPEED mode at 3 km/h even with gear -1 engaged");
  wbu_driver_set_gear(0);
  wbu_driver_set_cruising_speed(0.0);
  drive_for(0.1);
  check_true(!wbu_car_get_backwards_lights(), "reversing lights off: SPEED mode, cruising speed 0");

  /* Right indicator: cancelled 0.1 rad back from the right-most angle. */
  wbu_driver_set_steering_angle(0.0);
  wbu_driver_set_indicator(RIGHT);
  check_int("wbu_driver_get_indicator() after set_indicator(RIGHT)", wbu_driver_get_indicator(), RIGHT);
  steer_and_check_indicator(0.3, RIGHT, "turning right");
  steer_and_check_indicator(0.25, RIGHT, "0.05 rad back from 0.3");
  steer_and_check_indicator(0.19, OFF, "0.11 rad back from 0.3: cancelled");

  /* Left indicator, set at 0.19 rad: cancelled 0.1 rad back from the left-most angle. */
  wbu_driver_set_indicator(LEFT);
  check_int("wbu_driver_get_indicator() after set_indicator(LEFT)", wbu_driver_get_indicator(), LEFT);
  steer_and_check_indicator(-0.2, LEFT, "turning left");
  steer_and_check_indicator(-0.15, LEFT, "0.05 rad back from -0.2");
  steer_and_check_indicator(-0.05, OFF, "0.15 rad back from -0.2: cancelled");

  /* Right indicator set at -0.05 rad, then steering further left: 0.1 rad away cancels it too. */
  wbu_driver_set_indicator(RIGHT);
  steer_and_check_indicator(-0.1, RIGHT, "0.05 rad left of where RIGHT was set");
  steer_and_check_indicator(-0.2, OFF, "0.15 rad left of where RIGHT was set: cancelled");

  /* Auto-cancelling disabled: LEFT (set at -0.2 rad) survives steering to the right. */
  wbu_car_enable_indicator_auto_disabling(false);
  wbu_driver_set_indicator(LEFT);
  steer_and_check_indicator(0.3, LEFT, "auto-disabling off");
  steer_and_check_indicator(-0.1, LEFT, "auto-disabling off");
  /* Re-enabled: the reference is still the -0.2 rad where LEFT was set. */
  wbu_car_enable_indicator_auto_disabling(true);
  steer_and_check_indicator(-0.15, LEFT, "auto-disabling on again, 0.05 rad right of -0.2");
  steer_and_check_indicator(0.0, OFF, "auto-disabling on again, 0.2 rad right of -0.2: cancelled");

  /* Hazard flashers: independent of the lever, never cancelled by steering. */
  wbu_driver_set_hazard_flashers(true);
  check_true(wbu_driver_get_hazard_flashers(), "hazard flashers on");
  check_int("wbu_driver_get_indicator() with hazard flashers on", wbu_driver_get_indicator(), OFF);
  wbu_driver_set_indicator(RIGHT);
  steer_and_check_indicator(0.3, RIGHT, "hazard flashers on, turning right");
  steer_and_check_indicator(0.1, OFF, "hazard flashers on, 0.2 rad back: lever cancelled");
  check_true(wbu_driver_get_hazard_flashers(), "hazard flashers still on after the lever was cancelled");
  wbu_driver_set_hazard_flashers(false);
  check_true(!wbu_driver_get_hazard_flashers(), "hazard flashers off");
  {
    /* The 2014 name of the hazard flashers. */
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    wbu_driver_set_indicator_warning(true);
    check_true(wbu_driver_get_hazard_flashers(), "hazard flashers on after deprecated set_indicator_warning(true)");
    wbu_driver_set_indicator_warning(false);
    check_true(!wbu_driver_get_hazard_flashers(), "hazard flashers off after deprecated set_indicator_warning(false)");
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
  }

  /* Indicator period. */
  wbu_car_set_indicator_period(0.5);
  check_close("wbu_car_get_indicator_period() after set 0.5 (s)", wbu_car_get_indicator_period(), 0.5, 0.0);
  wbu_driver_set_indicator(LEFT);
  drive_for(1.2); /* blink through several on/off phases */
  check_int("wbu_driver_get_indicator() while blinking", wbu_driver_get_indicator(), LEFT);
  wbu_driver_set_indicator(OFF);
  check_int("wbu_driver_get_indicator() after set_indicator(OFF)", wbu_driver_get_indicator(), OFF);
  wbu_car_set_indicator_period(0.34);

  /* Wipers (the BmwX5 has them; a car without wiper motors would keep DOWN). */
  wbu_driver_set_wiper_mode(SLOW);
  check_int("wbu_driver_get_wiper_mode() after SLOW", wbu_driver_get_wiper_mode(), SLOW);
  drive_for(1.0);
  wbu_driver_set_wiper_mode(NORMAL);
  check_int("wbu_driver_get_wiper_mode() after NORMAL", wbu_driver_get_wiper_mode(), NORMAL);
  drive_for(1.0);
  wbu_driver_set_wiper_mode(FAST);
  check_int("wbu_driver_get_wiper_mode() after FAST", wbu_driver_get_wiper_mode(), FAST);
  drive_for(1.0);
  wbu_driver_set_wiper_mode(DOWN);
  check_int("wbu_driver_get_wiper_mode() after DOWN", wbu_driver_get_wiper_mode(), DOWN);
  {
    /* The R2018a names. */
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    wbu_driver_set_wipers_mode(FAST);
    check_int("deprecated wbu_driver_get_wipers_mode() after set_wipers_mode(FAST)", wbu_driver_get_wipers_mode(), FAST);
    check_int("wbu_driver_get_wiper_mode() after set_wipers_mode(FAST)", wbu_driver_get_wiper_mode(), FAST);
    wbu_driver_set_wipers_mode(DOWN);
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
  }
  check_int("wbu_driver_get_wiper_mode() after set_wipers_mode(DOWN)", wbu_driver_get_wiper_mode(), DOWN);

  wbu_driver_cleanup();
  return check_finish();
}
