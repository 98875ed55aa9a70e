/*
 * webots/radar.h: the Webots Radar device.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Sampling periods are in milliseconds (ms). The targets are the other cars and boxes whose
 * radarCrossSection is above 0, seen from the radar's origin within its field of view and
 * range. The pointers returned point into library storage valid until the next call; do not
 * free them.
 */

#ifndef WB_RADAR_H
#define WB_RADAR_H

#include <webots/radar_target.h>
#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

void wb_radar_enable(WbDeviceTag tag, int sampling_period);
void wb_radar_disable(WbDeviceTag tag);
int wb_radar_get_sampling_period(WbDeviceTag tag);
/* The number of targets of the last sample; 0 before the first sample. */
int wb_radar_get_number_of_targets(WbDeviceTag tag);
/* The targets of the last sample; NULL before the first sample, when there are none, and for a
   wrong tag. */
const WbRadarTarget *wb_radar_get_targets(WbDeviceTag tag);
/* The fields (m, rad); 0 for a wrong tag. */
double wb_radar_get_min_range(WbDeviceTag tag);
double wb_radar_get_max_range(WbDeviceTag tag);
double wb_radar_get_horizontal_fov(WbDeviceTag tag);
double wb_radar_get_vertical_fov(WbDeviceTag tag);

#ifdef __cplusplus
}
#endif

#endif /* WB_RADAR_H */
