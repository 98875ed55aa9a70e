// webots/Compass.hpp: header-only C++ wrapper of webots/compass.h.
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class and method names as Webots' webots::Compass. Periods in ms. Requires C++11.

#ifndef WB_COMPASS_HPP
#define WB_COMPASS_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/Compass.hpp requires C++11 or later"
#endif

#include <webots/Device.hpp>
#include <webots/compass.h>

namespace webots {
  class Compass : public Device {
  public:
    explicit Compass(const std::string &name) : Device(name) {}
    explicit Compass(WbDeviceTag tag) : Device(tag) {}

    virtual void enable(int samplingPeriod) { wb_compass_enable(getTag(), samplingPeriod); }
    virtual void disable() { wb_compass_disable(getTag()); }
    int getSamplingPeriod() const { return wb_compass_get_sampling_period(getTag()); }
    const double *getValues() const { return wb_compass_get_values(getTag()); }
    int getLookupTableSize() const { return wb_compass_get_lookup_table_size(getTag()); }
    const double *getLookupTable() const { return wb_compass_get_lookup_table(getTag()); }
  };
}  // namespace webots

#endif  // WB_COMPASS_HPP
