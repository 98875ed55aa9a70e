// webots/Device.hpp: header-only C++ wrapper of webots/device.h, the base of the sensor classes.
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class and method names as Webots' webots::Device. Requires C++11.

#ifndef WB_DEVICE_HPP
#define WB_DEVICE_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/Device.hpp requires C++11 or later"
#endif

#include <webots/device.h>
#include <webots/robot.h>

#include <string>

namespace webots {
  // A device of the robot, known by its tag (0: the robot has no such device).
  class Device {
  public:
    // The device named `name` (Webots: looked up with wb_robot_get_device).
    explicit Device(const std::string &name) : tag_(wb_robot_get_device(name.c_str())) {}
    // The device with `tag`.
    explicit Device(WbDeviceTag tag) : tag_(tag) {}
    virtual ~Device() {}

    // The device's name ("" for a tag the robot does not have).
    std::string getName() const { return text(wb_device_get_name(tag_)); }
    // The device's model field ("" here).
    std::string getModel() const { return text(wb_device_get_model(tag_)); }
    // Its node type (WB_NODE_GPS...).
    int getNodeType() const { return wb_device_get_node_type(tag_); }
    // Its tag.
    WbDeviceTag getTag() const { return tag_; }

  private:
    static std::string text(const char *s) { return s ? std::string(s) : std::string(); }
    WbDeviceTag tag_;
  };
}  // namespace webots

#endif  // WB_DEVICE_HPP
