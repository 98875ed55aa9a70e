// webots/Lidar.hpp: header-only C++ wrapper of webots/lidar.h.
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class and method names as Webots' webots::Lidar (and webots::LidarPoint). Periods in
// ms, ranges in m, angles in rad, frequencies in Hz. Requires C++11.

#ifndef WB_LIDAR_HPP
#define WB_LIDAR_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/Lidar.hpp requires C++11 or later"
#endif

#include <webots/Device.hpp>
#include <webots/lidar.h>

namespace webots {
  typedef WbLidarPoint LidarPoint;

  class Lidar : public Device {
  public:
    explicit Lidar(const std::string &name) : Device(name) {}
    explicit Lidar(WbDeviceTag tag) : Device(tag) {}

    virtual void enable(int samplingPeriod) { wb_lidar_enable(getTag(), samplingPeriod); }
    virtual void disable() { wb_lidar_disable(getTag()); }
    int getSamplingPeriod() const { return wb_lidar_get_sampling_period(getTag()); }
    void enablePointCloud() { wb_lidar_enable_point_cloud(getTag()); }
    void disablePointCloud() { wb_lidar_disable_point_cloud(getTag()); }
    bool isPointCloudEnabled() const { return wb_lidar_is_point_cloud_enabled(getTag()) != 0; }
    const float *getRangeImage() const { return wb_lidar_get_range_image(getTag()); }
    const float *getLayerRangeImage(int layer) const { return wb_lidar_get_layer_range_image(getTag(), layer); }
    const LidarPoint *getPointCloud() const { return wb_lidar_get_point_cloud(getTag()); }
    const LidarPoint *getLayerPointCloud(int layer) const { return wb_lidar_get_layer_point_cloud(getTag(), layer); }
    int getNumberOfPoints() const { return wb_lidar_get_number_of_points(getTag()); }
    int getHorizontalResolution() const { return wb_lidar_get_horizontal_resolution(getTag()); }
    int getNumberOfLayers() const { return wb_lidar_get_number_of_layers(getTag()); }
    double getMinFrequency() const { return wb_lidar_get_min_frequency(getTag()); }
    double getMaxFrequency() const { return wb_lidar_get_max_frequency(getTag()); }
    double getFrequency() const { return wb_lidar_get_frequency(getTag()); }
    void setFrequency(double frequency) { wb_lidar_set_frequency(getTag(), frequency); }
    double getFov() const { return wb_lidar_get_fov(getTag()); }
    double getVerticalFov() const { return wb_lidar_get_vertical_fov(getTag()); }
    double getMinRange() const { return wb_lidar_get_min_range(getTag()); }
    double getMaxRange() const { return wb_lidar_get_max_range(getTag()); }
  };
}  // namespace webots

#endif  // WB_LIDAR_HPP
