/*
 * webots/robot.h: the subset of the Webots Robot C API provided by this simulator.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * The world is chosen by the VEHICLE_WORLD environment variable (a shipped model name such as
 * "BmwX5" or "TeslaModel3", or the path of a world file); unset means the default world, a BmwX5
 * on flat ground with basicTimeStep 10 ms. Functions are declared with empty parentheses exactly
 * as Webots declares them.
 */

#ifndef WB_ROBOT_H
#define WB_ROBOT_H

#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Connects the controller to the simulation and loads the world. Must be called before any
 * other wb_robot_* function (wbu_car_init() and wbu_driver_init() call it themselves); further
 * calls do nothing. Returns 1 on success (Webots returns an int too; old controllers ignore it).
 */
int wb_robot_init();

/*
 * Advances the simulation by `duration` milliseconds (rounded to whole basic time steps) and
 * exchanges sensor and actuator values. Returns 0 while the simulation goes on and -1 when it
 * has ended and the controller should clean up and exit.
 */
int wb_robot_step(int duration);

/* Simulation time in seconds (s) elapsed since the world was loaded. */
double wb_robot_get_time();

/* The world's basicTimeStep field, in milliseconds (ms). */
double wb_robot_get_basic_time_step();

/* Disconnects the controller from the simulation; call once just before exiting. */
void wb_robot_cleanup();

/*
 * Looks a device up by its exact name (for example "right_steer" or "engine_speaker").
 * Returns its tag, or 0 if the robot has no device of that name.
 */
WbDeviceTag wb_robot_get_device(const char *name);

/*
 * The number of devices of the robot: a car's fixed table of car-library devices (27 tags, the
 * ones its model lacks included, whose name is NULL) and then its world-file sensors.
 */
int wb_robot_get_number_of_devices();

/*
 * The tag of device `index` (0 <= index < wb_robot_get_number_of_devices()): index + 1. Out of
 * range: an error and 0.
 */
WbDeviceTag wb_robot_get_device_by_index(int index);

/*
 * The battery sensor: the energy left in the robot's battery, in joules (J). A car's battery is
 * its traction battery when its world file accounts its energy (Webots' Robot field
 * `battery = [energy, maxEnergy, chargingRate]`, `[vehicle.battery]` or `energy = true`).
 * Sampled as every device: the first value one full period after enabling, then every period;
 * NaN before the first sample and without a battery. A negative period is refused with an
 * error; reading while disabled prints an error and returns the last value. When the energy of
 * Webots' `battery` field reaches 0 the controller is stopped: wb_robot_step() and
 * wbu_driver_step() return -1 from then on.
 */
void wb_robot_battery_sensor_enable(int sampling_period);
void wb_robot_battery_sensor_disable();
int wb_robot_battery_sensor_get_sampling_period();
double wb_robot_battery_sensor_get_value();

#ifdef __cplusplus
}
#endif

#endif /* WB_ROBOT_H */
