/*
 * webots/lidar.h: the Webots Lidar device (fixed and rotating types).
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Sampling periods are in milliseconds (ms), ranges in m, angles in rad, frequencies in Hz.
 * The range image holds horizontalResolution values per layer, layer 0 (the highest) first,
 * column 0 the leftmost (a rotating lidar's column j looks along -pi - j*2pi/horizontalResolution
 * rad and is rewritten as its head sweeps it, at every step, at the world's defaultFrequency);
 * a value is INFINITY where nothing lies within [minRange, maxRange).
 * The point cloud is the range image converted to points. The pointers returned point into
 * library storage valid until the next call; do not free them.
 */

#ifndef WB_LIDAR_H
#define WB_LIDAR_H

#include <webots/lidar_point.h>
#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

void wb_lidar_enable(WbDeviceTag tag, int sampling_period);
void wb_lidar_disable(WbDeviceTag tag);
int wb_lidar_get_sampling_period(WbDeviceTag tag);
void wb_lidar_enable_point_cloud(WbDeviceTag tag);
void wb_lidar_disable_point_cloud(WbDeviceTag tag);
bool wb_lidar_is_point_cloud_enabled(WbDeviceTag tag);
/* The range image; NULL for a wrong tag. */
const float *wb_lidar_get_range_image(WbDeviceTag tag);
/* One layer of it; NULL (with an error) if the lidar is disabled or has no such layer. */
const float *wb_lidar_get_layer_range_image(WbDeviceTag tag, int layer);
/* The point cloud; NULL (with an error) if the lidar or its point cloud is disabled. */
const WbLidarPoint *wb_lidar_get_point_cloud(WbDeviceTag tag);
const WbLidarPoint *wb_lidar_get_layer_point_cloud(WbDeviceTag tag, int layer);
/* horizontalResolution * numberOfLayers; 0 if the lidar or its point cloud is disabled. */
int wb_lidar_get_number_of_points(WbDeviceTag tag);
int wb_lidar_get_horizontal_resolution(WbDeviceTag tag);
int wb_lidar_get_number_of_layers(WbDeviceTag tag);
double wb_lidar_get_min_frequency(WbDeviceTag tag);
double wb_lidar_get_max_frequency(WbDeviceTag tag);
double wb_lidar_get_frequency(WbDeviceTag tag);
/* Within [min, max] frequency, else refused with an error. */
void wb_lidar_set_frequency(WbDeviceTag tag, double frequency);
double wb_lidar_get_fov(WbDeviceTag tag);
double wb_lidar_get_vertical_fov(WbDeviceTag tag);
double wb_lidar_get_min_range(WbDeviceTag tag);
double wb_lidar_get_max_range(WbDeviceTag tag);

#ifdef __cplusplus
}
#endif

#endif /* WB_LIDAR_H */
