/*
 * webots/vehicle/driver.h: the Webots "driver" library, the controls a human driver has (steering,
 * cruise control or throttle and gears, brake, lights, indicators, wipers), for cars built on the
 * Car PROTO. Implemented by libdriver.so on top of libcar.so (webots/vehicle/car.h).
 *
 * Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Units: angles in rad (positive steers right), vehicle speeds in km/h (as in Webots), engine
 * speed in rpm (rev/min), time in s. Every function except wbu_driver_init(),
 * wbu_driver_cleanup() and wbu_driver_initialization_is_possible() prints
 *   Warning: 'wbu_driver_init()' should be called before to use '<function>()'.
 * and returns 0, false, OFF, UNDEFINED_CONTROL_MODE or, for the wiper mode, -1 when called
 * before wbu_driver_init() (or after wbu_driver_cleanup()); setters then do nothing.
 *
 * Functions are declared with empty parentheses exactly as Webots declares them: in C89 to C17
 * that leaves the argument list unchecked, so old controllers calling wbu_driver_step(TIME_STEP)
 * still compile (the argument is ignored).
 *
 * C++: the enumerators below (OFF, RIGHT, LEFT, SPEED, TORQUE, DOWN, SLOW, NORMAL, FAST,
 * UNDEFINED_CONTROL_MODE) are global names. From C++11 on, the enumerations have a fixed
 * underlying type (int, their C size) so that webots/vehicle/Driver.hpp can declare these
 * functions without defining the enumerators: a C++ controller including only Driver.hpp or
 * Car.hpp does not get them, exactly as with Webots' C++ headers.
 */

#ifndef WB_VEHICLE_DRIVER_H
#define WB_VEHICLE_DRIVER_H

#include <webots/types.h>

#if defined(__cplusplus) && (__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#define WBU_DRIVER_FIXED_ENUMS
#endif

#ifdef __cplusplus
extern "C" {
#endif

#ifdef WBU_DRIVER_FIXED_ENUMS
/* Defined (with their enumerators) at the end of this file, unless Driver.hpp is including it. */
enum WbuDriverIndicatorState : int;
enum WbuDriverControlMode : int;
enum WbuDriverWiperMode : int;
#else
/* State of the turn indicator lever: OFF = 0, RIGHT = 1, LEFT = 2. */
typedef enum { OFF = 0, RIGHT = 1, LEFT = 2 } WbuDriverIndicatorState;

/*
 * How the car is driven: SPEED = 0 (cruise control, wbu_driver_set_cruising_speed()),
 * TORQUE = 1 (engine model, wbu_driver_set_throttle()), UNDEFINED_CONTROL_MODE = -1 until one
 * of those two functions is first called.
 */
typedef enum { UNDEFINED_CONTROL_MODE = -1, SPEED = 0, TORQUE = 1 } WbuDriverControlMode;

/* Windscreen wiper mode: DOWN = 0 (parked), SLOW = 1 (one sweep every 4 s), NORMAL = 2, FAST = 3. */
typedef enum { DOWN = 0, SLOW = 1, NORMAL = 2, FAST = 3 } WbuDriverWiperMode;
#endif

/*
 * Returns true if the robot selected by VEHICLE_WORLD is a Car, i.e. its customData holds the
 * 20 header fields the libraries need (calls wb_robot_init() first). Webots documents it as a
 * private helper for webots_ros2: it lets a controller check before wbu_driver_init(), which
 * exits the process on a non-car robot.
 */
bool wbu_driver_initialization_is_possible();

/*
 * Same as wbu_driver_initialization_is_possible(): the name older Webots releases (up to 2022)
 * used, kept for controllers written against them.
 */
bool initialization_is_possible();

/*
 * Initialises the driver library (and the car library, and the robot). Call it once at the
 * beginning of the controller; further calls do nothing. Prints an error and exits the process
 * if the robot is not a Car. Initial state: steering 0 rad, cruising speed 0 km/h, throttle 0,
 * brake 0, gear 0 (neutral), indicator OFF, hazard flashers off, dipped beams off, wipers DOWN,
 * control mode UNDEFINED_CONTROL_MODE (driven wheels held at 0 rad/s, like a parked car).
 */
void wbu_driver_init();

/* Frees the driver and car libraries and disconnects from the simulation (wb_robot_cleanup()). */
void wbu_driver_cleanup();

/*
 * Runs one basic time step (basicTimeStep ms of the world): updates the indicators, wipers and
 * reversing lights, measures the wheel speeds, estimates the engine rpm, applies the engine
 * torque (TORQUE mode) and brakes, then advances the simulation. Takes no argument. Returns 0,
 * or -1 when the simulation has ended.
 */
int wbu_driver_step();

/*
 * Steers the front wheels to `steering_angle` (rad, positive = right, negative = left) with
 * Ackermann geometry: right wheel atan(1/(cot(a) - trackFront/(2*wheelbase))), left wheel
 * atan(1/(cot(a) + trackFront/(2*wheelbase))), limited by the steering motors to
 * [minSteeringAngle, maxSteeringAngle]. In SPEED mode the wheel speeds are recomputed for the new
 * geometry. May switch the indicator off (see wbu_car_enable_indicator_auto_disabling()).
 * A NaN prints a warning and is ignored; an infinity never reaches the wheels.
 */
void wbu_driver_set_steering_angle(double steering_angle);

/*
 * Measured steering angle (rad): the mean of the right and left steering position sensors
 * after the last step (not the commanded value, which the wheels reach after a few steps).
 */
double wbu_driver_get_steering_angle();

/*
 * Switches to SPEED mode (cruise control) and sets the target speed in km/h (negative drives
 * backwards). The driven wheels are given the differential speeds of the current steering
 * geometry and accelerate to them as set by the Car field time0To100, up to the Car field
 * maxVelocity; no engine model runs. A NaN is ignored with a warning (Webots passes it on to
 * the wheel motors).
 */
void wbu_driver_set_cruising_speed(double speed);

/* Target speed of the last wbu_driver_set_cruising_speed() call, in km/h (0 initially). */
double wbu_driver_get_target_cruising_speed();

/*
 * Current speed in km/h, estimated from the measured rotation speed of the driven wheels and
 * their tyre radius (negative when moving backwards). Valid from the third step on.
 */
double wbu_driver_get_current_speed();

/*
 * Switches to TORQUE mode and sets the throttle, from 0 (no engine torque) to 1 (full engine
 * torque); values outside [0, 1], infinities included, are clamped with a warning, and a NaN is
 * ignored with a warning (Webots stores it). The engine torque also depends on the engine rpm
 * and the gear (wbu_driver_set_gear()).
 */
void wbu_driver_set_throttle(double throttle);

/* Throttle of the last wbu_driver_set_throttle() call, in [0, 1] (0 initially). */
double wbu_driver_get_throttle();

/*
 * Sets the brake, from 0 (released) to 1 (each wheel braked with brakeCoefficient N*m);
 * values outside [0, 1], infinities included, are clamped with a warning, and a NaN is ignored
 * with a warning (Webots stores it). Any value above 0 lights the brake lights. Works in every
 * control mode (in SPEED mode the wheel motors overpower it).
 */
void wbu_driver_set_brake_intensity(double intensity);

/* Brake intensity of the last wbu_driver_set_brake_intensity() call, in [0, 1]. */
double wbu_driver_get_brake_intensity();

/*
 * Sets the indicator lever: OFF, RIGHT or LEFT (any other value is ignored with a warning;
 * Webots stores it). The indicator LEDs blink with the period of wbu_car_set_indicator_period()
 * (0.34 s on, 0.34 s off by default).
 */
void wbu_driver_set_indicator(WbuDriverIndicatorState state);

/* Switches the hazard flashers (both indicators blinking) on (true) or off (false). */
void wbu_driver_set_hazard_flashers(bool state);

/* Indicator lever state (OFF, RIGHT or LEFT); it returns to OFF when auto-cancelled. */
WbuDriverIndicatorState wbu_driver_get_indicator();

/* true if the hazard flashers are on. */
bool wbu_driver_get_hazard_flashers();

/* Switches the dipped beams (front and rear lights together) on (true) or off (false). */
void wbu_driver_set_dipped_beams(bool state);

/* Switches the anti-fog lights on (true) or off (false); does nothing if the car has none. */
void wbu_driver_set_antifog_lights(bool state);

/* Last state given to wbu_driver_set_dipped_beams() (true even if the car has no such lights). */
bool wbu_driver_get_dipped_beams();

/* State of the anti-fog lights LED (false if the car has no anti-fog lights). */
bool wbu_driver_get_antifog_lights();

/*
 * Engine speed in rpm estimated at the last step: |mean of the four wheel speeds (rad/s) *
 * 60/(2*pi) * gear ratio|, 0 in neutral, at most engineMaxRPM. In SPEED mode there is no engine
 * model: prints a warning and returns 0.
 */
double wbu_driver_get_rpm();

/*
 * Engaged gear: -1 reverse, 0 neutral, 1 and up forward. In SPEED mode there is no gearbox:
 * prints a warning and returns 0.
 */
int wbu_driver_get_gear();

/*
 * Engages a gear: -1 reverse, 0 neutral, 1 to wbu_driver_get_gear_number() - 1 forward (gear k
 * uses gearRatio[k], reverse uses gearRatio[0]). Values below -1 become -1 and values above the
 * highest forward gear become that gear; as in Webots, a warning is printed below -1 and above
 * wbu_driver_get_gear_number(), but not for wbu_driver_get_gear_number() itself (which Webots
 * accepts and then reads past its ratio table). Allowed in every mode; only TORQUE mode uses it.
 */
void wbu_driver_set_gear(int gear);

/* Number of entries of the Car field gearRatio: the forward gears plus the reverse gear. */
int wbu_driver_get_gear_number();

/* Current control mode: SPEED, TORQUE, or UNDEFINED_CONTROL_MODE before either is chosen. */
WbuDriverControlMode wbu_driver_get_control_mode();

/*
 * Sets the wiper mode (DOWN, SLOW, NORMAL or FAST; any other value is ignored with a warning,
 * Webots stores it); ignored if the car has no wipers. The wipers sweep at 2 rad/s (SLOW,
 * NORMAL) or 4 rad/s (FAST).
 */
void wbu_driver_set_wiper_mode(WbuDriverWiperMode mode);

/* Current wiper mode (DOWN initially). */
WbuDriverWiperMode wbu_driver_get_wiper_mode();

/* Deprecated (Webots 8.6): prints a warning, then wbu_driver_set_brake_intensity(brake). */
void wbu_driver_set_brake(double brake) WB_DEPRECATED;

/* Deprecated (Webots 8.6): prints a warning, then returns wbu_driver_get_brake_intensity(). */
double wbu_driver_get_brake() WB_DEPRECATED;

/* Deprecated (Webots 2014 name of the hazard flashers): wbu_driver_set_hazard_flashers(state). */
void wbu_driver_set_indicator_warning(bool state) WB_DEPRECATED;

/* Type names of Webots R2018a, kept for backward compatibility. */
typedef WbuDriverWiperMode wbu_wipers_mode;
typedef WbuDriverIndicatorState wbu_indicator_state;
typedef WbuDriverControlMode wbu_control_mode;

/* Deprecated (Webots R2018a): same as wbu_driver_set_wiper_mode(mode). */
void wbu_driver_set_wipers_mode(wbu_wipers_mode mode) WB_DEPRECATED;

/* Deprecated (Webots R2018a): same as wbu_driver_get_wiper_mode(). */
wbu_wipers_mode wbu_driver_get_wipers_mode() WB_DEPRECATED;

#ifdef __cplusplus
}
#endif

#endif /* WB_VEHICLE_DRIVER_H */

/*
 * C++11 and later: the enumerators, outside the include guard so that a later #include of this
 * header still defines them after webots/vehicle/Driver.hpp included it without them
 * (Driver.hpp defines WB_VEHICLE_DRIVER_HPP_NO_ENUMERATORS around its #include).
 */
#if defined(WBU_DRIVER_FIXED_ENUMS) && !defined(WB_VEHICLE_DRIVER_HPP_NO_ENUMERATORS) && \
  !defined(WB_VEHICLE_DRIVER_ENUMERATORS)
#define WB_VEHICLE_DRIVER_ENUMERATORS
extern "C" {
/* State of the turn indicator lever: OFF = 0, RIGHT = 1, LEFT = 2. */
enum WbuDriverIndicatorState : int { OFF = 0, RIGHT = 1, LEFT = 2 };

/*
 * How the car is driven: SPEED = 0 (cruise control, wbu_driver_set_cruising_speed()),
 * TORQUE = 1 (engine model, wbu_driver_set_throttle()), UNDEFINED_CONTROL_MODE = -1 until one
 * of those two functions is first called.
 */
enum WbuDriverControlMode : int { UNDEFINED_CONTROL_MODE = -1, SPEED = 0, TORQUE = 1 };

/* Windscreen wiper mode: DOWN = 0 (parked), SLOW = 1 (one sweep every 4 s), NORMAL = 2, FAST = 3. */
enum WbuDriverWiperMode : int { DOWN = 0, SLOW = 1, NORMAL = 2, FAST = 3 };
}
#endif
