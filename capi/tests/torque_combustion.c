/*
 * torque_combustion: TORQUE mode with gears on the BmwX5 (combustion engine, front-wheel drive).
 *
 * World: the default one (VEHICLE_WORLD unset, or VEHICLE_WORLD=BmwX5).
 *
 * BmwX5 (spec section 5.1): gearRatio [-12.5 12.5 8 5.35 4.3 4], engineMinRPM 1000,
 * engineMaxRPM 6500, engineFunctionCoefficients 34.11 0.136 -0.00001461, tyres 0.374 m,
 * 2000 kg body + 4 x 30 kg wheels = 2120 kg.
 * Below 1000 rpm the engine torque is taken at 1000 rpm:
 *   f(1000) = 34.11 + 0.136 * 1000 - 0.00001461 * 1000^2 = 155.5 N*m.
 * First gear, throttle 0.25: wheel torque 155.5 * 0.25 * 12.5 = 485.9 N*m, force
 *   485.9 / 0.374 = 1299 N, acceleration 1299 / 2120 = 0.61 m/s^2 = 2.2 km/h per s before
 *   rolling losses: the check asks for more than 0.5 km/h per s.
 * Throttle 0.8: 3.2 times the force (the rpm stays near 1000, where f is nearly flat): the check
 *   asks for more than twice the low-throttle gain.
 * Second gear: rpm scaled by 8 / 12.5 = 0.64 at the same speed.
 * Reverse, throttle 0.5: -972 N*m, about -1.2 m/s^2: more than 2 km/h backwards after 3 s
 *   (about 13 km/h expected).
 */

#include "torque_common.h"

int main(void) {
  struct torque_case c;
  c.model = drive_bmw_x5();
  c.ratio_first = 12.5;
  c.ratio_second = 8.0;
  c.ratio_reverse = 12.5;
  c.max_rpm = 6500.0;
  c.throttle_low = 0.25;
  c.throttle_high = 0.8;
  c.min_gain_low = 0.5;
  c.throttle_reverse = 0.5;
  torque_run("torque_combustion", &c);
  return check_finish();
}
