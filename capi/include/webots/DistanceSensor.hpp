// webots/DistanceSensor.hpp: header-only C++ wrapper of webots/distance_sensor.h.
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class and method names as Webots' webots::DistanceSensor. Periods in ms, the aperture in
// rad. Requires C++11.

#ifndef WB_DISTANCE_SENSOR_HPP
#define WB_DISTANCE_SENSOR_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/DistanceSensor.hpp requires C++11 or later"
#endif

#include <webots/Device.hpp>
#include <webots/distance_sensor.h>

namespace webots {
  class DistanceSensor : public Device {
  public:
    typedef enum { GENERIC = 0, INFRA_RED, SONAR, LASER } Type;

    explicit DistanceSensor(const std::string &name) : Device(name) {}
    explicit DistanceSensor(WbDeviceTag tag) : Device(tag) {}

    virtual void enable(int samplingPeriod) { wb_distance_sensor_enable(getTag(), samplingPeriod); }
    virtual void disable() { wb_distance_sensor_disable(getTag()); }
    int getSamplingPeriod() const { return wb_distance_sensor_get_sampling_period(getTag()); }
    double getValue() const { return wb_distance_sensor_get_value(getTag()); }
    double getMaxValue() const { return wb_distance_sensor_get_max_value(getTag()); }
    double getMinValue() const { return wb_distance_sensor_get_min_value(getTag()); }
    double getAperture() const { return wb_distance_sensor_get_aperture(getTag()); }
    int getLookupTableSize() const { return wb_distance_sensor_get_lookup_table_size(getTag()); }
    const double *getLookupTable() const { return wb_distance_sensor_get_lookup_table(getTag()); }
    Type getType() const { return static_cast<Type>(wb_distance_sensor_get_type(getTag())); }
  };
}  // namespace webots

#endif  // WB_DISTANCE_SENSOR_HPP
