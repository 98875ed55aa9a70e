// webots/InertialUnit.hpp: header-only C++ wrapper of webots/inertial_unit.h.
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class and method names as Webots' webots::InertialUnit. Periods in ms, angles in rad.
// Requires C++11.

#ifndef WB_INERTIAL_UNIT_HPP
#define WB_INERTIAL_UNIT_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/InertialUnit.hpp requires C++11 or later"
#endif

#include <webots/Device.hpp>
#include <webots/inertial_unit.h>

namespace webots {
  class InertialUnit : public Device {
  public:
    explicit InertialUnit(const std::string &name) : Device(name) {}
    explicit InertialUnit(WbDeviceTag tag) : Device(tag) {}

    virtual void enable(int samplingPeriod) { wb_inertial_unit_enable(getTag(), samplingPeriod); }
    virtual void disable() { wb_inertial_unit_disable(getTag()); }
    int getSamplingPeriod() const { return wb_inertial_unit_get_sampling_period(getTag()); }
    double getNoise() const { return wb_inertial_unit_get_noise(getTag()); }
    const double *getRollPitchYaw() const { return wb_inertial_unit_get_roll_pitch_yaw(getTag()); }
    const double *getQuaternion() const { return wb_inertial_unit_get_quaternion(getTag()); }
  };
}  // namespace webots

#endif  // WB_INERTIAL_UNIT_HPP
