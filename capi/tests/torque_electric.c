/*
 * torque_electric: TORQUE mode with gears on the TeslaModel3 (electric engine, rear-wheel drive).
 *
 * World: VEHICLE_WORLD=TeslaModel3.
 *
 * TeslaModel3 (spec section 5.1): gearRatio [-6.3 9] (one forward gear), engineMaxTorque
 * 639 N*m, engineMaxPower 147000 W, engineMaxRPM 25000, tyres 0.36 m, 1847 kg body +
 * 4 x 10.4 kg wheels = 1889 kg.
 * Electric torque min(639, 147000 * 60 / (2 * pi * rpm)) is the full 639 N*m up to
 *   147000 * 60 / (2 * pi * 639) = 2197 rpm, i.e. 2197 / 9 * 2 * pi / 60 * 0.36 * 3.6 = 33 km/h
 *   in first gear: the whole forward phase stays below it, so the acceleration is
 *   proportional to the throttle.
 * Throttle 0.15: 639 * 0.15 * 9 = 862.7 N*m, 862.7 / 0.36 = 2396 N, 2396 / 1889 = 1.27 m/s^2
 *   = 4.6 km/h per s before losses: the check asks for more than 1 km/h per s.
 * Throttle 0.45: 3 times the force: the check asks for more than twice the low-throttle gain
 *   (7190 N stays below the rear tyres' grip, about 10 500 N at friction 1).
 * Reverse, throttle 0.3: 639 * 0.3 * -6.3 / 0.36 = -3355 N, -1.8 m/s^2: more than 2 km/h
 *   backwards after 3 s (about 19 km/h expected).
 */

#include "torque_common.h"

int main(void) {
  struct torque_case c;
  c.model = drive_tesla_model_3();
  c.ratio_first = 9.0;
  c.ratio_second = 0.0;
  c.ratio_reverse = 6.3;
  c.max_rpm = 25000.0;
  c.throttle_low = 0.15;
  c.throttle_high = 0.45;
  c.min_gain_low = 1.0;
  c.throttle_reverse = 0.3;
  torque_run("torque_electric", &c);
  return check_finish();
}
