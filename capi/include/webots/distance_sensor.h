/*
 * webots/distance_sensor.h: the Webots DistanceSensor device.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Sampling periods are in milliseconds (ms). The value is the lookupTable's output for the
 * distance (m) the rays measure: NaN before the first sample. Types generic, infra-red (the red
 * channel of the surfaces' colours), sonar and laser. The pointers returned point
 * into library storage; do not free them.
 */

#ifndef WB_DISTANCE_SENSOR_H
#define WB_DISTANCE_SENSOR_H

#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
  WB_DISTANCE_SENSOR_GENERIC = 0,
  WB_DISTANCE_SENSOR_INFRA_RED,
  WB_DISTANCE_SENSOR_SONAR,
  WB_DISTANCE_SENSOR_LASER
} WbDistanceSensorType;

void wb_distance_sensor_enable(WbDeviceTag tag, int sampling_period);
void wb_distance_sensor_disable(WbDeviceTag tag);
int wb_distance_sensor_get_sampling_period(WbDeviceTag tag);
/* The value; NaN before the first sample and for a wrong tag. */
double wb_distance_sensor_get_value(WbDeviceTag tag);
/* The largest / smallest output of the lookupTable (0 when empty); NaN for a wrong tag. */
double wb_distance_sensor_get_max_value(WbDeviceTag tag);
double wb_distance_sensor_get_min_value(WbDeviceTag tag);
/* The aperture field (rad). */
double wb_distance_sensor_get_aperture(WbDeviceTag tag);
/* The rows of the lookupTable field (0 when empty). */
int wb_distance_sensor_get_lookup_table_size(WbDeviceTag tag);
/* The lookupTable as rows [distance, value, noise], row after row; NULL when empty. */
const double *wb_distance_sensor_get_lookup_table(WbDeviceTag tag);
/* The type field; WB_DISTANCE_SENSOR_GENERIC for a wrong tag. */
WbDistanceSensorType wb_distance_sensor_get_type(WbDeviceTag tag);

#ifdef __cplusplus
}
#endif

#endif /* WB_DISTANCE_SENSOR_H */
