/*
 * webots/types.h: definitions shared by every header of the Webots-compatible C API.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Compiles as C89, C99, C11, C17, C23 and as C++98 or later. Only C-style comments are used so
 * that `gcc -std=c89 -pedantic` accepts it.
 */

#ifndef WB_TYPES_H
#define WB_TYPES_H

/*
 * Identifier of a device of the robot (as returned by wb_robot_get_device()); 0 means "no such
 * device". A robot can have at most 65534 devices (65535 is reserved).
 */
typedef unsigned short WbDeviceTag;

/*
 * "bool" for C controllers, as Webots defines it. C++ uses its built-in bool. C23 has a bool
 * keyword, and a compiler in C2x mode may or may not have it yet: <stdbool.h> covers both cases
 * (it is freestanding and defines nothing harmful in C23). In C89 to C17 Webots makes bool a
 * macro for char unless the controller already included <stdbool.h> (then bool is _Bool); the
 * macro form lets <stdbool.h> be included before or after this header. Either way the value
 * crosses the ABI as one byte; the libraries treat any non-zero byte as true and return 0 or 1.
 */
#ifndef __cplusplus
#if defined(__STDC_VERSION__) && __STDC_VERSION__ > 201710L
#include <stdbool.h>
#else
#ifndef bool
#define bool char
#endif
#ifndef true
#define true ((bool)1)
#endif
#ifndef false
#define false ((bool)0)
#endif
#endif
#endif

/*
 * Marks a function kept only for old controllers: GCC and Clang warn at each call.
 * Usage: `void old_function() WB_DEPRECATED;`. Define WB_DEPRECATED to nothing beforehand to
 * silence these warnings.
 */
#ifndef WB_DEPRECATED
#if defined(__GNUC__) && __GNUC__ >= 3
#define WB_DEPRECATED __attribute__((deprecated))
#else
#define WB_DEPRECATED
#endif
#endif

#endif /* WB_TYPES_H */
