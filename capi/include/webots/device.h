/*
 * webots/device.h: what every device of the robot has (Webots' generic device functions).
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Tags come from wb_robot_get_device() or wb_robot_get_device_by_index() (webots/robot.h).
 */

#ifndef WB_DEVICE_H
#define WB_DEVICE_H

#include <webots/nodes.h>
#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The device's name field, or NULL for a tag the robot does not have. Library storage: do not
   free it. */
const char *wb_device_get_name(WbDeviceTag tag);

/* The device's model field ("" for every device of this simulator), or NULL for a tag the
   robot does not have. */
const char *wb_device_get_model(WbDeviceTag tag);

/* The device's node type (WB_NODE_GPS, WB_NODE_ROTATIONAL_MOTOR...), WB_NODE_NO_NODE for a tag
   the robot does not have. */
WbNodeType wb_device_get_node_type(WbDeviceTag tag);

#ifdef __cplusplus
}
#endif

#endif /* WB_DEVICE_H */
