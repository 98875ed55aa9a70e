/*
 * webots/camera.h: the Webots Camera device and its Recognition.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Sampling periods are in milliseconds (ms), the field of view in rad (horizontal), the near
 * plane in m. The image is BGRA, 4 bytes a pixel, row-major from the top-left corner; it is
 * rendered from the world's geometry through a planar pinhole (see the crate README for what
 * is drawn). The pointers returned point into library storage valid until the next step (the
 * objects: until the next call); do not free them.
 */

#ifndef WB_CAMERA_H
#define WB_CAMERA_H

#include <webots/camera_recognition_object.h>
#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

void wb_camera_enable(WbDeviceTag tag, int sampling_period);
void wb_camera_disable(WbDeviceTag tag);
int wb_camera_get_sampling_period(WbDeviceTag tag);
/* The last image; NULL for a wrong tag and, with an error, while disabled. */
const unsigned char *wb_camera_get_image(WbDeviceTag tag);
/* -1 for a wrong tag. */
int wb_camera_get_width(WbDeviceTag tag);
int wb_camera_get_height(WbDeviceTag tag);
/* rad; NaN for a wrong tag. Without Zoom the min and max are the field of view. */
double wb_camera_get_fov(WbDeviceTag tag);
double wb_camera_get_min_fov(WbDeviceTag tag);
double wb_camera_get_max_fov(WbDeviceTag tag);
/* m; NaN for a wrong tag. */
double wb_camera_get_near(WbDeviceTag tag);

bool wb_camera_has_recognition(WbDeviceTag tag);
void wb_camera_recognition_enable(WbDeviceTag tag, int sampling_period);
void wb_camera_recognition_disable(WbDeviceTag tag);
int wb_camera_recognition_get_sampling_period(WbDeviceTag tag);
int wb_camera_recognition_get_number_of_objects(WbDeviceTag tag);
/* NULL with an error without Recognition or while it is disabled. */
const WbCameraRecognitionObject *wb_camera_recognition_get_objects(WbDeviceTag tag);
/* 0, or -1 with an error; PNG only (quality is for JPEG, not written here). */
int wb_camera_save_image(WbDeviceTag tag, const char *filename, int quality);
/* Always false: no segmentation image is rendered. */
bool wb_camera_recognition_has_segmentation(WbDeviceTag tag);

/* The channels of pixel (x, y) of a BGRA image `width` pixels wide, as Webots' macros. */
#define wb_camera_image_get_red(image, width, x, y) ((image)[4 * ((y) * (width) + (x)) + 2])
#define wb_camera_image_get_green(image, width, x, y) ((image)[4 * ((y) * (width) + (x)) + 1])
#define wb_camera_image_get_blue(image, width, x, y) ((image)[4 * ((y) * (width) + (x))])
#define wb_camera_image_get_gray(image, width, x, y) ((wb_camera_image_get_red(image, width, x, y) + wb_camera_image_get_green(image, width, x, y) + wb_camera_image_get_blue(image, width, x, y)) / 3)
#define wb_camera_image_get_grey(image, width, x, y) wb_camera_image_get_gray(image, width, x, y)

#ifdef __cplusplus
}
#endif

#endif /* WB_CAMERA_H */
