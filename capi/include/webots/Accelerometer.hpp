// webots/Accelerometer.hpp: header-only C++ wrapper of webots/accelerometer.h.
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class and method names as Webots' webots::Accelerometer. Periods in ms. Requires C++11.

#ifndef WB_ACCELEROMETER_HPP
#define WB_ACCELEROMETER_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/Accelerometer.hpp requires C++11 or later"
#endif

#include <webots/Device.hpp>
#include <webots/accelerometer.h>

namespace webots {
  class Accelerometer : public Device {
  public:
    explicit Accelerometer(const std::string &name) : Device(name) {}
    explicit Accelerometer(WbDeviceTag tag) : Device(tag) {}

    virtual void enable(int samplingPeriod) { wb_accelerometer_enable(getTag(), samplingPeriod); }
    virtual void disable() { wb_accelerometer_disable(getTag()); }
    int getSamplingPeriod() const { return wb_accelerometer_get_sampling_period(getTag()); }
    const double *getValues() const { return wb_accelerometer_get_values(getTag()); }
    int getLookupTableSize() const { return wb_accelerometer_get_lookup_table_size(getTag()); }
    const double *getLookupTable() const { return wb_accelerometer_get_lookup_table(getTag()); }
  };
}  // namespace webots

#endif  // WB_ACCELEROMETER_HPP
