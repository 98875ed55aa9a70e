/*
 * webots/camera_recognition_object.h: an object recognised by a camera's Recognition.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Webots' layout (LP64: 120 bytes). Positions and sizes in m in the camera frame (x forward,
 * y left, z up), orientation as axis-angle [x, y, z, angle] (rad), image values in pixels from
 * the top-left corner, colours in [0, 1].
 */

#ifndef WB_CAMERA_RECOGNITION_OBJECT_H
#define WB_CAMERA_RECOGNITION_OBJECT_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  int id;
  double position[3];
  double orientation[4];
  double size[2];
  int position_on_image[2];
  int size_on_image[2];
  int number_of_colors;
  double *colors;
  char *model;
} WbCameraRecognitionObject;

#ifdef __cplusplus
}
#endif

#endif /* WB_CAMERA_RECOGNITION_OBJECT_H */
