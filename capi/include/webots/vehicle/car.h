/*
 * webots/vehicle/car.h: the Webots "car" library: the characteristics of a car built on the Car
 * PROTO (geometry, engine and drive type), wheel measurements, a few low-level settings.
 * Implemented by libcar.so; the driver library (webots/vehicle/driver.h) uses it.
 *
 * Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Units: lengths in m, angles in rad (positive steers right), wheel speeds in rad/s, time in s.
 * Wheel order: 0 front right, 1 front left, 2 rear right, 3 rear left. Every function except
 * wbu_car_init() and wbu_car_cleanup() prints
 *   Warning: 'wbu_car_init()' should be called before to use '<function>()'.
 * and returns 0 or false when called before wbu_car_init() (or wbu_driver_init(), which calls
 * it); setters then do nothing. Functions are declared with empty parentheses exactly as
 * Webots declares them.
 */

#ifndef WB_VEHICLE_CAR_H
#define WB_VEHICLE_CAR_H

#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Driven axle(s), deduced from the wheel motors the car has: WBU_CAR_TRACTION = 0 (front-wheel
 * drive), WBU_CAR_PROPULSION = 1 (rear-wheel drive), WBU_CAR_FOUR_BY_FOUR = 2 (all four wheels).
 */
typedef enum { WBU_CAR_TRACTION = 0, WBU_CAR_PROPULSION = 1, WBU_CAR_FOUR_BY_FOUR = 2 } WbuCarType;

/* Engine model, from the Car field engineType. */
typedef enum {
  WBU_CAR_COMBUSTION_ENGINE = 0,
  WBU_CAR_ELECTRIC_ENGINE = 1,
  WBU_CAR_PARALLEL_HYBRID_ENGINE = 2,
  WBU_CAR_POWER_SPLIT_HYBRID_ENGINE = 3
} WbuCarEngineType;

/* Wheel index; WBU_CAR_WHEEL_NB (4) is the number of wheels, not a wheel. */
typedef enum {
  WBU_CAR_WHEEL_FRONT_RIGHT = 0,
  WBU_CAR_WHEEL_FRONT_LEFT = 1,
  WBU_CAR_WHEEL_REAR_RIGHT = 2,
  WBU_CAR_WHEEL_REAR_LEFT = 3,
  WBU_CAR_WHEEL_NB = 4
} WbuCarWheelIndex;

/*
 * Initialises the car library (and the robot, wb_robot_init()); further calls do nothing.
 * Prints an error and exits the process if the robot is not a Car or lacks a required device.
 * Defaults: indicator period 0.34 s, limited-slip differential and indicator auto-disabling on.
 */
void wbu_car_init();

/* Frees the car library and disconnects from the simulation (wb_robot_cleanup()). */
void wbu_car_cleanup();

/* Driven axle(s): WBU_CAR_TRACTION, WBU_CAR_PROPULSION or WBU_CAR_FOUR_BY_FOUR. */
WbuCarType wbu_car_get_type();

/* Engine model (Car field engineType). */
WbuCarEngineType wbu_car_get_engine_type();

/*
 * Sets the indicator blink period in seconds (s): each on phase and each off phase lasts
 * `period` (a full cycle is 2 * period). Must be finite and > 0; other values are ignored with
 * a warning (Webots does not check them).
 */
void wbu_car_set_indicator_period(double period);

/* Indicator blink period in seconds (s), 0.34 by default. */
double wbu_car_get_indicator_period();

/*
 * State of the reversing lights LED (false if the car has none). The driver library lights it
 * at each step in TORQUE mode with gear -1 and in SPEED mode with a negative cruising speed.
 */
bool wbu_car_get_backwards_lights();

/*
 * State of the brake lights LED (false if the car has none). The driver library lights it when
 * the brake intensity is set above 0 and switches it off when it is set to 0.
 */
bool wbu_car_get_brake_lights();

/* Car field trackFront: distance between the front wheels, in m. */
double wbu_car_get_track_front();

/* Car field trackRear: distance between the rear wheels, in m. */
double wbu_car_get_track_rear();

/* Car field wheelbase: distance between the front and rear axles, in m. */
double wbu_car_get_wheelbase();

/* Front tyre radius in m (-1 if the Car PROTO could not find it). */
double wbu_car_get_front_wheel_radius();

/* Rear tyre radius in m (-1 if the Car PROTO could not find it). */
double wbu_car_get_rear_wheel_radius();

/*
 * Rotation of a wheel in rad (its position sensor, enabled at the basic time step on first use;
 * NaN until the first sample). An index outside 0..3 prints
 * "Warning: maximum wheel index is 4." and returns 0.
 */
double wbu_car_get_wheel_encoder(WbuCarWheelIndex wheel_index);

/*
 * Rotation speed of a wheel in rad/s (positive forward), measured by the last
 * wbu_driver_step() (0 if only the car library is used). An index outside 0..3 prints
 * "Warning: maximum wheel index is 4." and returns 0.
 */
double wbu_car_get_wheel_speed(WbuCarWheelIndex wheel_index);

/*
 * Steers the front left wheel directly to `angle` (rad, positive = right), without Ackermann
 * geometry and without changing the driver's steering angle. A NaN prints a warning and is
 * ignored.
 */
void wbu_car_set_left_steering_angle(double angle);

/*
 * Steers the front right wheel directly to `angle` (rad, positive = right), without Ackermann
 * geometry and without changing the driver's steering angle. A NaN prints a warning and is
 * ignored.
 */
void wbu_car_set_right_steering_angle(double angle);

/* Measured steering angle of the front right wheel, in rad (position sensor, last step). */
double wbu_car_get_right_steering_angle();

/* Measured steering angle of the front left wheel, in rad (position sensor, last step). */
double wbu_car_get_left_steering_angle();

/*
 * Enables (true, the default) or disables the limited-slip differential, which shifts torque
 * away from the faster wheel of a driven axle in TORQUE mode.
 */
void wbu_car_enable_limited_slip_differential(bool enable);

/*
 * Enables (true, the default) or disables indicator auto-cancelling: RIGHT (LEFT) switches off
 * once the steering angle comes back 0.1 rad from its right-most (left-most) value since the
 * indicator was set. Hazard flashers are never cancelled.
 */
void wbu_car_enable_indicator_auto_disabling(bool enable);

/* Type names of Webots R2018a, kept for backward compatibility. */
typedef WbuCarType wbu_car_type;
typedef WbuCarEngineType wbu_car_engine_type;
typedef WbuCarWheelIndex wbu_car_wheel_index;

#ifdef __cplusplus
}
#endif

#endif /* WB_VEHICLE_CAR_H */
