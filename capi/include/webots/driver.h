/*
 * webots/driver.h: the header path of the driver library before Webots moved it to
 * <webots/vehicle/driver.h>; kept so that old controllers compile unchanged.
 *
 * Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
 */

#include <webots/vehicle/driver.h>
