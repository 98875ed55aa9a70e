/*
 * webots/vehicle/road_sensor.h: the RoadSensor, a project extension (no Webots device
 * measures roads; BeamNG's roads sensor is the model). A `[[vehicle.device]]` of
 * `type = "RoadSensor"` in the world file; its tag comes from wb_robot_get_device() like
 * any device's, and wb_device_get_node_type() gives VEHICLE_NODE_ROAD_SENSOR.
 *
 * Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * It measures at the device point, in the lane holding it and in that lane's travel
 * direction (right lanes -1, -2, ... along the road, left lanes 1, 2, ... against it):
 * lateral offset in m, positive left of the lane centre; heading error in rad, positive
 * pointing left of the lane; curvatures in 1/m, positive turning left; distances in m to
 * the lane's lines and the road's edges, positive inside them. Sampling as for every
 * Webots sensor: periods in ms, the first sample one full period after enabling, NaN (and
 * road -1, lane 0) before it, off the roads and for a wrong tag.
 */

#ifndef VEHICLE_ROAD_SENSOR_H
#define VEHICLE_ROAD_SENSOR_H

#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The node type of a RoadSensor (no WB_NODE_ value names one). */
#define VEHICLE_NODE_ROAD_SENSOR 1000

/* Samples every `sampling_period` ms (negative: refused with an error). */
void vehicle_road_sensor_enable(WbDeviceTag tag, int sampling_period);
/* Stops sampling; the last sample stays readable (with an error). */
void vehicle_road_sensor_disable(WbDeviceTag tag);
/* The sampling period (ms), 0 when disabled. */
int vehicle_road_sensor_get_sampling_period(WbDeviceTag tag);
/* Its `lookahead` field (m): where the curvature ahead is read. */
double vehicle_road_sensor_get_lookahead(WbDeviceTag tag);
/* The index of the road (0: the world's first [[road]]); -1 off the roads. */
int vehicle_road_sensor_get_road(WbDeviceTag tag);
/* The lane (1, 2, ... left of the reference line; -1, -2, ... right); 0 off the roads. */
int vehicle_road_sensor_get_lane(WbDeviceTag tag);
/* The station along the road (m). */
double vehicle_road_sensor_get_station(WbDeviceTag tag);
/* The offset from the lane centre (m, positive left). */
double vehicle_road_sensor_get_lateral_offset(WbDeviceTag tag);
/* The heading minus the lane's travel direction (rad, positive left). */
double vehicle_road_sensor_get_heading_error(WbDeviceTag tag);
/* The lane's curvature at the device (1/m, positive turning left). */
double vehicle_road_sensor_get_curvature(WbDeviceTag tag);
/* The lane's curvature `lookahead` m ahead (1/m, positive turning left). */
double vehicle_road_sensor_get_curvature_ahead(WbDeviceTag tag);
/* The distances to the lane's left and right lines (m, positive inside the lane). */
double vehicle_road_sensor_get_left_line_distance(WbDeviceTag tag);
double vehicle_road_sensor_get_right_line_distance(WbDeviceTag tag);
/* The distances to the road's left and right edges (m, positive on the road). */
double vehicle_road_sensor_get_left_edge_distance(WbDeviceTag tag);
double vehicle_road_sensor_get_right_edge_distance(WbDeviceTag tag);
/* The lane's width (m). */
double vehicle_road_sensor_get_lane_width(WbDeviceTag tag);

#ifdef __cplusplus
}
#endif

#endif /* VEHICLE_ROAD_SENSOR_H */
