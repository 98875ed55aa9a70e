/*
 * webots/gps.h: the Webots GPS device.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Sampling periods are in milliseconds (ms). A sample comes one full period after enabling;
 * before it the values are NaN. The pointers returned point into library storage that stays
 * valid until the next step; do not free them. The coordinates are those of the world file's
 * gpsCoordinateSystem: "local" (x east, y north, z up, in m, plus gpsReference) or "WGS84"
 * (latitude and longitude in degrees, altitude in m, gpsReference those of the origin).
 */

#ifndef WB_GPS_H
#define WB_GPS_H

#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { WB_GPS_LOCAL_COORDINATE = 0, WB_GPS_WGS84_COORDINATE } WbGpsCoordinateSystem;

/* Samples every `sampling_period` ms (negative: refused with an error). */
void wb_gps_enable(WbDeviceTag tag, int sampling_period);
/* Stops sampling; the last sample stays readable (with an error, as in Webots). */
void wb_gps_disable(WbDeviceTag tag);
/* The sampling period (ms), 0 when disabled. */
int wb_gps_get_sampling_period(WbDeviceTag tag);
/* The device's world position [x, y, z] (m); NULL for a wrong tag. */
const double *wb_gps_get_values(WbDeviceTag tag);
/* Its speed (m/s); NaN for a wrong tag. (Webots declares the result `const double`, a
   qualifier C ignores and -Wextra warns about; the ABI is the same.) */
double wb_gps_get_speed(WbDeviceTag tag);
/* Its velocity [vx, vy, vz] (m/s, world axes); NULL for a wrong tag. */
const double *wb_gps_get_speed_vector(WbDeviceTag tag);
/* The world's gpsCoordinateSystem (LOCAL for a wrong tag). */
WbGpsCoordinateSystem wb_gps_get_coordinate_system(WbDeviceTag tag);
/* The degrees, minutes and seconds of a decimal angle (degrees) as UTF-8 text, "D\xc2\xb0 M' S''"
   in Webots' format (degree, prime and double-prime signs), in memory the caller frees with
   free(). */
const char *wb_gps_convert_to_degrees_minutes_seconds(double decimal_degrees);

#ifdef __cplusplus
}
#endif

#endif /* WB_GPS_H */
