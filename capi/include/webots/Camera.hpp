// webots/Camera.hpp: header-only C++ wrapper of webots/camera.h.
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class and method names as Webots' webots::Camera (the methods of the functions this
// simulator has). Periods in ms, angles in rad, distances in m, images BGRA. Requires C++11.

#ifndef WB_CAMERA_HPP
#define WB_CAMERA_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/Camera.hpp requires C++11 or later"
#endif

#include <webots/Device.hpp>
#include <webots/camera.h>

namespace webots {
  typedef WbCameraRecognitionObject CameraRecognitionObject;

  class Camera : public Device {
  public:
    explicit Camera(const std::string &name) : Device(name) {}
    explicit Camera(WbDeviceTag tag) : Device(tag) {}

    virtual void enable(int samplingPeriod) { wb_camera_enable(getTag(), samplingPeriod); }
    virtual void disable() { wb_camera_disable(getTag()); }
    int getSamplingPeriod() const { return wb_camera_get_sampling_period(getTag()); }
    const unsigned char *getImage() const { return wb_camera_get_image(getTag()); }
    int getWidth() const { return wb_camera_get_width(getTag()); }
    int getHeight() const { return wb_camera_get_height(getTag()); }
    double getFov() const { return wb_camera_get_fov(getTag()); }
    double getMinFov() const { return wb_camera_get_min_fov(getTag()); }
    double getMaxFov() const { return wb_camera_get_max_fov(getTag()); }
    double getNear() const { return wb_camera_get_near(getTag()); }
    int saveImage(const std::string &filename, int quality) const {
      return wb_camera_save_image(getTag(), filename.c_str(), quality);
    }

    bool hasRecognition() const { return wb_camera_has_recognition(getTag()); }
    void recognitionEnable(int samplingPeriod) { wb_camera_recognition_enable(getTag(), samplingPeriod); }
    void recognitionDisable() { wb_camera_recognition_disable(getTag()); }
    int getRecognitionSamplingPeriod() const { return wb_camera_recognition_get_sampling_period(getTag()); }
    int getRecognitionNumberOfObjects() const { return wb_camera_recognition_get_number_of_objects(getTag()); }
    const CameraRecognitionObject *getRecognitionObjects() const {
      return wb_camera_recognition_get_objects(getTag());
    }
    bool hasRecognitionSegmentation() const { return wb_camera_recognition_has_segmentation(getTag()); }

    static unsigned char imageGetRed(const unsigned char *image, int width, int x, int y) {
      return wb_camera_image_get_red(image, width, x, y);
    }
    static unsigned char imageGetGreen(const unsigned char *image, int width, int x, int y) {
      return wb_camera_image_get_green(image, width, x, y);
    }
    static unsigned char imageGetBlue(const unsigned char *image, int width, int x, int y) {
      return wb_camera_image_get_blue(image, width, x, y);
    }
    static unsigned char imageGetGray(const unsigned char *image, int width, int x, int y) {
      return static_cast<unsigned char>(wb_camera_image_get_gray(image, width, x, y));
    }
    static unsigned char imageGetGrey(const unsigned char *image, int width, int x, int y) {
      return imageGetGray(image, width, x, y);
    }
  };
}  // namespace webots

#endif  // WB_CAMERA_HPP
