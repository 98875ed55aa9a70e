// webots/Gyro.hpp: header-only C++ wrapper of webots/gyro.h.
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class and method names as Webots' webots::Gyro. Periods in ms. Requires C++11.

#ifndef WB_GYRO_HPP
#define WB_GYRO_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/Gyro.hpp requires C++11 or later"
#endif

#include <webots/Device.hpp>
#include <webots/gyro.h>

namespace webots {
  class Gyro : public Device {
  public:
    explicit Gyro(const std::string &name) : Device(name) {}
    explicit Gyro(WbDeviceTag tag) : Device(tag) {}

    virtual void enable(int samplingPeriod) { wb_gyro_enable(getTag(), samplingPeriod); }
    virtual void disable() { wb_gyro_disable(getTag()); }
    int getSamplingPeriod() const { return wb_gyro_get_sampling_period(getTag()); }
    const double *getValues() const { return wb_gyro_get_values(getTag()); }
    int getLookupTableSize() const { return wb_gyro_get_lookup_table_size(getTag()); }
    const double *getLookupTable() const { return wb_gyro_get_lookup_table(getTag()); }
  };
}  // namespace webots

#endif  // WB_GYRO_HPP
