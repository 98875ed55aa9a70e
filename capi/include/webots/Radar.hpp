// webots/Radar.hpp: header-only C++ wrapper of webots/radar.h.
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class and method names as Webots' webots::Radar (and webots::RadarTarget). Periods in
// ms, ranges in m, angles in rad. Requires C++11.

#ifndef WB_RADAR_HPP
#define WB_RADAR_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/Radar.hpp requires C++11 or later"
#endif

#include <webots/Device.hpp>
#include <webots/radar.h>

namespace webots {
  typedef WbRadarTarget RadarTarget;

  class Radar : public Device {
  public:
    explicit Radar(const std::string &name) : Device(name) {}
    explicit Radar(WbDeviceTag tag) : Device(tag) {}

    virtual void enable(int samplingPeriod) { wb_radar_enable(getTag(), samplingPeriod); }
    virtual void disable() { wb_radar_disable(getTag()); }
    int getSamplingPeriod() const { return wb_radar_get_sampling_period(getTag()); }
    int getNumberOfTargets() const { return wb_radar_get_number_of_targets(getTag()); }
    const RadarTarget *getTargets() const { return wb_radar_get_targets(getTag()); }
    double getMinRange() const { return wb_radar_get_min_range(getTag()); }
    double getMaxRange() const { return wb_radar_get_max_range(getTag()); }
    double getHorizontalFov() const { return wb_radar_get_horizontal_fov(getTag()); }
    double getVerticalFov() const { return wb_radar_get_vertical_fov(getTag()); }
  };
}  // namespace webots

#endif  // WB_RADAR_HPP
