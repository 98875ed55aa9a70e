/*
 * webots/differential_wheels.h: the legacy DifferentialWheels robot API (deprecated by Webots in
 * R2018a, later removed), kept so that old controllers compile and run unchanged.
 *
 * Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * These functions act on the world's [differential_wheels] robot (see wb_robot_init()). Wheel
 * speeds are expressed in "speed units": 1 unit = speedUnit rad/s (field speedUnit, default 1).
 * Encoders count encoderResolution increments per radian of wheel rotation. Functions are
 * declared with empty parentheses exactly as Webots declares them.
 */

#ifndef WB_DIFFERENTIAL_WHEELS_H
#define WB_DIFFERENTIAL_WHEELS_H

#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Commands the left and right wheel speeds, in speed units (speedUnit rad/s each); applied at
 * the next step and reached at maxAcceleration rad/s^2 in kinematics mode. A NaN prints an
 * error and the command is ignored. A command above maxSpeed (rad/s) prints Webots'
 * "overflows maxSpeed/speedUnit" error. Unlike Webots, which applies the command anyway, each
 * wheel is limited to [-maxSpeed, maxSpeed]; the getters still return the command.
 */
void wb_differential_wheels_set_speed(double left, double right);

/* Last commanded left wheel speed, in speed units (the argument of the last set_speed). */
double wb_differential_wheels_get_left_speed();

/* Last commanded right wheel speed, in speed units (the argument of the last set_speed). */
double wb_differential_wheels_get_right_speed();

/* The robot's maxSpeed field: the highest wheel speed, in rad/s. */
double wb_differential_wheels_get_max_speed();

/* The robot's speedUnit field: rad/s per unit of wb_differential_wheels_set_speed(). */
double wb_differential_wheels_get_speed_unit();

/*
 * Enables both wheel encoders, refreshed every `sampling_period` milliseconds (ms); 0 disables
 * them, a negative period prints an error and is ignored. The first values are available after
 * one sampling period.
 */
void wb_differential_wheels_enable_encoders(int sampling_period);

/* Disables both wheel encoders (same as enabling them with a period of 0). */
void wb_differential_wheels_disable_encoders();

/* Encoder sampling period in milliseconds (ms), 0 when the encoders are disabled. */
int wb_differential_wheels_get_encoders_sampling_period();

/*
 * Left encoder value, in encoder increments (encoderResolution per radian turned, cumulative).
 * Prints an error if the encoders are disabled and returns the last sampled value.
 */
double wb_differential_wheels_get_left_encoder();

/*
 * Right encoder value, in encoder increments (encoderResolution per radian turned, cumulative).
 * Prints an error if the encoders are disabled and returns the last sampled value.
 */
double wb_differential_wheels_get_right_encoder();

/*
 * Overwrites both encoder accumulators (in encoder increments) at the next step, without moving
 * the wheels. A NaN prints an error and the call is ignored.
 */
void wb_differential_wheels_set_encoders(double left, double right);

#ifdef __cplusplus
}
#endif

#endif /* WB_DIFFERENTIAL_WHEELS_H */
