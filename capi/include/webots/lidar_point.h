/*
 * webots/lidar_point.h: a point of the Webots Lidar device's point cloud.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 */

#ifndef WB_LIDAR_POINT_H
#define WB_LIDAR_POINT_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  float x; /* m, lidar axes (x forward, y left, z up); inf where there is no return */
  float y;
  float z;
  int layer_id; /* 0 is the highest layer */
  float time;   /* s of simulated time */
} WbLidarPoint;

#ifdef __cplusplus
}
#endif

#endif /* WB_LIDAR_POINT_H */
