/*
 * webots/accelerometer.h: the Webots Accelerometer device.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Sampling periods are in milliseconds (ms). The values are the specific force
 * [ax, ay, az] (m/s^2, device axes: +9.81 on z upright at rest) through the lookup table, NaN
 * on a disabled axis and before the first sample. The pointers returned point into library storage valid until the
 * next step; do not free them.
 */

#ifndef WB_ACCELEROMETER_H
#define WB_ACCELEROMETER_H

#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

void wb_accelerometer_enable(WbDeviceTag tag, int sampling_period);
void wb_accelerometer_disable(WbDeviceTag tag);
int wb_accelerometer_get_sampling_period(WbDeviceTag tag);
/* The three values; NULL for a wrong tag. */
const double *wb_accelerometer_get_values(WbDeviceTag tag);
/* The rows of the lookupTable field (0 when empty). */
int wb_accelerometer_get_lookup_table_size(WbDeviceTag tag);
/* The lookupTable as rows [input, output, noise], row after row; NULL when empty. */
const double *wb_accelerometer_get_lookup_table(WbDeviceTag tag);

#ifdef __cplusplus
}
#endif

#endif /* WB_ACCELEROMETER_H */
