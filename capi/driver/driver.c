/*
 * libdriver: the Webots driver library's symbols (webots/vehicle/driver.h), each forwarding to
 * its implementation in libcar (vehicle_capi_driver_*).
 *
 * Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Why a separate shim: Webots ships the driver and car libraries as two shared objects, and its
 * Python binding opens them one after the other. All state lives in libcar (one copy per
 * process); libdriver is linked against it (DT_NEEDED libcar.so, RUNPATH $ORIGIN) and only
 * exports the wbu_driver_* names, so linking -ldriver -lcar (or the two static archives)
 * never defines a symbol twice. Including driver.h checks every signature against the header.
 * capi/stage.sh builds it; C89-compatible.
 */

#include <webots/vehicle/driver.h>

/* The implementations in libcar, with the same C signatures (bool: one byte; enums: int). */
extern bool vehicle_capi_driver_initialization_is_possible(void);
extern void vehicle_capi_driver_init(void);
extern void vehicle_capi_driver_cleanup(void);
extern int vehicle_capi_driver_step(void);
extern void vehicle_capi_driver_set_steering_angle(double steering_angle);
extern double vehicle_capi_driver_get_steering_angle(void);
extern void vehicle_capi_driver_set_cruising_speed(double speed);
extern double vehicle_capi_driver_get_target_cruising_speed(void);
extern double vehicle_capi_driver_get_current_speed(void);
extern void vehicle_capi_driver_set_throttle(double throttle);
extern double vehicle_capi_driver_get_throttle(void);
extern void vehicle_capi_driver_set_brake_intensity(double intensity);
extern double vehicle_capi_driver_get_brake_intensity(void);
extern void vehicle_capi_driver_set_indicator(WbuDriverIndicatorState state);
extern void vehicle_capi_driver_set_hazard_flashers(bool state);
extern WbuDriverIndicatorState vehicle_capi_driver_get_indicator(void);
extern bool vehicle_capi_driver_get_hazard_flashers(void);
extern void vehicle_capi_driver_set_dipped_beams(bool state);
extern void vehicle_capi_driver_set_antifog_lights(bool state);
extern bool vehicle_capi_driver_get_dipped_beams(void);
extern bool vehicle_capi_driver_get_antifog_lights(void);
extern double vehicle_capi_driver_get_rpm(void);
extern int vehicle_capi_driver_get_gear(void);
extern void vehicle_capi_driver_set_gear(int gear);
extern int vehicle_capi_driver_get_gear_number(void);
extern WbuDriverControlMode vehicle_capi_driver_get_control_mode(void);
extern void vehicle_capi_driver_set_wiper_mode(WbuDriverWiperMode mode);
extern WbuDriverWiperMode vehicle_capi_driver_get_wiper_mode(void);
extern void vehicle_capi_driver_set_brake(double brake);
extern double vehicle_capi_driver_get_brake(void);
extern void vehicle_capi_driver_set_indicator_warning(bool state);
extern void vehicle_capi_driver_set_wipers_mode(WbuDriverWiperMode mode);
extern WbuDriverWiperMode vehicle_capi_driver_get_wipers_mode(void);

bool wbu_driver_initialization_is_possible(void) {
  return vehicle_capi_driver_initialization_is_possible();
}

bool initialization_is_possible(void) {
  return vehicle_capi_driver_initialization_is_possible();
}

void wbu_driver_init(void) {
  vehicle_capi_driver_init();
}

void wbu_driver_cleanup(void) {
  vehicle_capi_driver_cleanup();
}

int wbu_driver_step(void) {
  return vehicle_capi_driver_step();
}

void wbu_driver_set_steering_angle(double steering_angle) {
  vehicle_capi_driver_set_steering_angle(steering_angle);
}

double wbu_driver_get_steering_angle(void) {
  return vehicle_capi_driver_get_steering_angle();
}

void wbu_driver_set_cruising_speed(double speed) {
  vehicle_capi_driver_set_cruising_speed(speed);
}

double wbu_driver_get_target_cruising_speed(void) {
  return vehicle_capi_driver_get_target_cruising_speed();
}

double wbu_driver_get_current_speed(void) {
  return vehicle_capi_driver_get_current_speed();
}

void wbu_driver_set_throttle(double throttle) {
  vehicle_capi_driver_set_throttle(throttle);
}

double wbu_driver_get_throttle(void) {
  return vehicle_capi_driver_get_throttle();
}

void wbu_driver_set_brake_intensity(double intensity) {
  vehicle_capi_driver_set_brake_intensity(intensity);
}

double wbu_driver_get_brake_intensity(void) {
  return vehicle_capi_driver_get_brake_intensity();
}

void wbu_driver_set_indicator(WbuDriverIndicatorState state) {
  vehicle_capi_driver_set_indicator(state);
}

void wbu_driver_set_hazard_flashers(bool state) {
  vehicle_capi_driver_set_hazard_flashers(state);
}

WbuDriverIndicatorState wbu_driver_get_indicator(void) {
  return vehicle_capi_driver_get_indicator();
}

bool wbu_driver_get_hazard_flashers(void) {
  return vehicle_capi_driver_get_hazard_flashers();
}

void wbu_driver_set_dipped_beams(bool state) {
  vehicle_capi_driver_set_dipped_beams(state);
}

void wbu_driver_set_antifog_lights(bool state) {
  vehicle_capi_driver_set_antifog_lights(state);
}

bool wbu_driver_get_dipped_beams(void) {
  return vehicle_capi_driver_get_dipped_beams();
}

bool wbu_driver_get_antifog_lights(void) {
  return vehicle_capi_driver_get_antifog_lights();
}

double wbu_driver_get_rpm(void) {
  return vehicle_capi_driver_get_rpm();
}

int wbu_driver_get_gear(void) {
  return vehicle_capi_driver_get_gear();
}

void wbu_driver_set_gear(int gear) {
  vehicle_capi_driver_set_gear(gear);
}

int wbu_driver_get_gear_number(void) {
  return vehicle_capi_driver_get_gear_number();
}

WbuDriverControlMode wbu_driver_get_control_mode(void) {
  return vehicle_capi_driver_get_control_mode();
}

void wbu_driver_set_wiper_mode(WbuDriverWiperMode mode) {
  vehicle_capi_driver_set_wiper_mode(mode);
}

WbuDriverWiperMode wbu_driver_get_wiper_mode(void) {
  return vehicle_capi_driver_get_wiper_mode();
}

void wbu_driver_set_brake(double brake) {
  vehicle_capi_driver_set_brake(brake);
}

double wbu_driver_get_brake(void) {
  return vehicle_capi_driver_get_brake();
}

void wbu_driver_set_indicator_warning(bool state) {
  vehicle_capi_driver_set_indicator_warning(state);
}

void wbu_driver_set_wipers_mode(wbu_wipers_mode mode) {
  vehicle_capi_driver_set_wipers_mode(mode);
}

wbu_wipers_mode wbu_driver_get_wipers_mode(void) {
  return vehicle_capi_driver_get_wipers_mode();
}
