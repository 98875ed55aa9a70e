// webots/vehicle/RoadSensor.hpp: header-only C++ wrapper of webots/vehicle/road_sensor.h, the
// project's RoadSensor extension (no Webots counterpart).
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Naming. The class is webots::RoadSensor, beside the C header it wraps (webots/vehicle/),
// because the Python module offers the same device as controller.RoadSensor with these same
// method names: a controller reads alike in both languages, and Driver::getRoadSensor() returns
// it as the other typed getters return webots:: classes. Webots has no RoadSensor class to
// clash with; the C functions keep their vehicle_ prefix (not wb_) to mark the extension.
//
// Units as in road_sensor.h: periods in ms, distances in m (lateral offset positive left of
// the lane centre; line and edge distances positive inside), angles in rad (positive left),
// curvatures in 1/m (positive turning left). Before the first sample, off the roads and for a
// wrong tag: NaN, road -1, lane 0. Requires C++11.

#ifndef VEHICLE_ROAD_SENSOR_HPP
#define VEHICLE_ROAD_SENSOR_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/vehicle/RoadSensor.hpp requires C++11 or later"
#endif

#include <webots/Device.hpp>
#include <webots/vehicle/road_sensor.h>

namespace webots {
  class RoadSensor : public Device {
  public:
    // The node type wb_device_get_node_type() gives (VEHICLE_NODE_ROAD_SENSOR).
    static const int NODE_TYPE = VEHICLE_NODE_ROAD_SENSOR;

    explicit RoadSensor(const std::string &name) : Device(name) {}
    explicit RoadSensor(WbDeviceTag tag) : Device(tag) {}

    // Samples every samplingPeriod ms (negative: refused with an error).
    virtual void enable(int samplingPeriod) { vehicle_road_sensor_enable(getTag(), samplingPeriod); }
    // Stops sampling; the last sample stays readable (with an error).
    virtual void disable() { vehicle_road_sensor_disable(getTag()); }
    // The sampling period (ms), 0 when disabled.
    int getSamplingPeriod() const { return vehicle_road_sensor_get_sampling_period(getTag()); }
    // Its lookahead field (m): where getCurvatureAhead() is read.
    double getLookahead() const { return vehicle_road_sensor_get_lookahead(getTag()); }
    // The road's index (0: the world's first [[road]]), -1 off the roads.
    int getRoad() const { return vehicle_road_sensor_get_road(getTag()); }
    // The lane (1, 2, ... left of the reference line; -1, -2, ... right), 0 off the roads.
    int getLane() const { return vehicle_road_sensor_get_lane(getTag()); }
    // The station along the road (m).
    double getStation() const { return vehicle_road_sensor_get_station(getTag()); }
    // The offset from the lane centre (m, positive left).
    double getLateralOffset() const { return vehicle_road_sensor_get_lateral_offset(getTag()); }
    // The heading minus the lane's travel direction (rad, positive left).
    double getHeadingError() const { return vehicle_road_sensor_get_heading_error(getTag()); }
    // The lane's curvature at the device (1/m, positive turning left).
    double getCurvature() const { return vehicle_road_sensor_get_curvature(getTag()); }
    // The lane's curvature getLookahead() m ahead (1/m, positive turning left).
    double getCurvatureAhead() const { return vehicle_road_sensor_get_curvature_ahead(getTag()); }
    // The distances to the lane's lines (m, positive inside the lane).
    double getLeftLineDistance() const { return vehicle_road_sensor_get_left_line_distance(getTag()); }
    double getRightLineDistance() const { return vehicle_road_sensor_get_right_line_distance(getTag()); }
    // The distances to the road's edges (m, positive on the road).
    double getLeftEdgeDistance() const { return vehicle_road_sensor_get_left_edge_distance(getTag()); }
    double getRightEdgeDistance() const { return vehicle_road_sensor_get_right_edge_distance(getTag()); }
    // The lane's width (m).
    double getLaneWidth() const { return vehicle_road_sensor_get_lane_width(getTag()); }
  };
}  // namespace webots

#endif  // VEHICLE_ROAD_SENSOR_HPP
