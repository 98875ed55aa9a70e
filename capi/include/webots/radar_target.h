/*
 * webots/radar_target.h: a target of the Webots Radar device.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 */

#ifndef WB_RADAR_TARGET_H
#define WB_RADAR_TARGET_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  double distance;       /* m */
  double received_power; /* dBm */
  double speed;          /* m/s, radial, positive when the target moves away */
  double azimuth;        /* rad, positive to the right of the radar's x axis */
} WbRadarTarget;

#ifdef __cplusplus
}
#endif

#endif /* WB_RADAR_TARGET_H */
