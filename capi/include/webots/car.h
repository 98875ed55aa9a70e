/*
 * webots/car.h: the header path of the car library before Webots moved it to
 * <webots/vehicle/car.h>; kept so that old controllers compile unchanged.
 *
 * Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
 */

#include <webots/vehicle/car.h>
