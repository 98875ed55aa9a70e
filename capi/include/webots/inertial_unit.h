/*
 * webots/inertial_unit.h: the Webots InertialUnit device.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Sampling periods are in milliseconds (ms); angles in radians (rad). The world is ENU (x east,
 * y north, z up): yaw is 0 with the device's x axis east and pi/2 north; pitch is positive
 * with the x axis below the horizon. The pointers returned point into library storage valid
 * until the next step; do not free them. NaN before the first sample.
 */

#ifndef WB_INERTIAL_UNIT_H
#define WB_INERTIAL_UNIT_H

#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

void wb_inertial_unit_enable(WbDeviceTag tag, int sampling_period);
void wb_inertial_unit_disable(WbDeviceTag tag);
int wb_inertial_unit_get_sampling_period(WbDeviceTag tag);
/* The noise field; 0 for a wrong tag. */
double wb_inertial_unit_get_noise(WbDeviceTag tag);
/* [roll, pitch, yaw] (rad), in one array shared by all inertial units (as in Webots, also
   returned for a wrong tag, unchanged). */
const double *wb_inertial_unit_get_roll_pitch_yaw(WbDeviceTag tag);
/* The orientation quaternion [x, y, z, w]; NULL for a wrong tag. */
const double *wb_inertial_unit_get_quaternion(WbDeviceTag tag);

#ifdef __cplusplus
}
#endif

#endif /* WB_INERTIAL_UNIT_H */
