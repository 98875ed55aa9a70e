// webots/GPS.hpp: header-only C++ wrapper of webots/gps.h.
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class and method names as Webots' webots::GPS. Periods in ms, positions in m (x east,
// y north, z up), speeds in m/s. Requires C++11.

#ifndef WB_GPS_HPP
#define WB_GPS_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/GPS.hpp requires C++11 or later"
#endif

#include <webots/Device.hpp>
#include <webots/gps.h>

#include <cstdlib>

namespace webots {
  class GPS : public Device {
  public:
    typedef enum { LOCAL = 0, WGS84 } CoordinateSystem;

    explicit GPS(const std::string &name) : Device(name) {}
    explicit GPS(WbDeviceTag tag) : Device(tag) {}

    virtual void enable(int samplingPeriod) { wb_gps_enable(getTag(), samplingPeriod); }
    virtual void disable() { wb_gps_disable(getTag()); }
    int getSamplingPeriod() const { return wb_gps_get_sampling_period(getTag()); }
    const double *getValues() const { return wb_gps_get_values(getTag()); }
    double getSpeed() const { return wb_gps_get_speed(getTag()); }
    const double *getSpeedVector() const { return wb_gps_get_speed_vector(getTag()); }
    CoordinateSystem getCoordinateSystem() const {
      return static_cast<CoordinateSystem>(wb_gps_get_coordinate_system(getTag()));
    }
    static std::string convertToDegreesMinutesSeconds(double decimalDegrees) {
      char *text = const_cast<char *>(wb_gps_convert_to_degrees_minutes_seconds(decimalDegrees));
      std::string result = text ? std::string(text) : std::string();
      std::free(text);
      return result;
    }
  };
}  // namespace webots

#endif  // WB_GPS_HPP
