/*
 * webots/display.h: the Webots Display device, for headless runs.
 *
 * Part of the `capi` crate (libcar.so / libdriver.so). SPDX-License-Identifier: MIT OR Apache-2.0
 *
 * Pixels (0, 0) top-left; the display starts opaque black; colour 0xRRGGBB (default white),
 * alpha and opacity in [0, 1] (default 1). Every drawing blends its pixels as Webots does:
 * c = ((255 - O) c_old + O c_draw) / 255 with O = (unsigned char)(opacity * 255). Calls take
 * effect at once. Image files are PNG only. Text draws with a bitmap font whatever the family
 * (see the capi README). Not available here: attaching a camera.
 */

#ifndef WB_DISPLAY_H
#define WB_DISPLAY_H

#include <webots/types.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct WbImageStructPrivate *WbImageRef;

enum { WB_IMAGE_RGB = 3, WB_IMAGE_RGBA, WB_IMAGE_ARGB, WB_IMAGE_BGRA, WB_IMAGE_ABGR };

/* -1 for a wrong tag. */
int wb_display_get_width(WbDeviceTag tag);
int wb_display_get_height(WbDeviceTag tag);
void wb_display_set_color(WbDeviceTag tag, int color);
void wb_display_set_alpha(WbDeviceTag tag, double alpha);
void wb_display_set_opacity(WbDeviceTag tag, double opacity);
void wb_display_draw_pixel(WbDeviceTag tag, int x, int y);
void wb_display_draw_line(WbDeviceTag tag, int x1, int y1, int x2, int y2);
void wb_display_draw_rectangle(WbDeviceTag tag, int x, int y, int width, int height);
void wb_display_fill_rectangle(WbDeviceTag tag, int x, int y, int width, int height);
void wb_display_draw_oval(WbDeviceTag tag, int cx, int cy, int a, int b);
void wb_display_fill_oval(WbDeviceTag tag, int cx, int cy, int a, int b);
void wb_display_draw_polygon(WbDeviceTag tag, const int *x, const int *y, int size);
void wb_display_fill_polygon(WbDeviceTag tag, const int *x, const int *y, int size);
/* font: one of Webots' 13 families; size: character height (px, > 0). */
void wb_display_set_font(WbDeviceTag tag, const char *font, int size, bool anti_aliasing);
/* (x, y): the text's top-left corner; '\n' starts a new line. */
void wb_display_draw_text(WbDeviceTag tag, const char *text, int x, int y);
/* data: width * height pixels of format (WB_IMAGE_*); NULL for a bad format or data. */
WbImageRef wb_display_image_new(WbDeviceTag tag, int width, int height, const void *data, int format);
/* NULL if the rectangle is off the display. */
WbImageRef wb_display_image_copy(WbDeviceTag tag, int x, int y, int width, int height);
void wb_display_image_paste(WbDeviceTag tag, WbImageRef ir, int x, int y, bool blend);
void wb_display_image_delete(WbDeviceTag tag, WbImageRef ir);
/* PNG files only; ir NULL saves the display itself. */
void wb_display_image_save(WbDeviceTag tag, WbImageRef ir, const char *filename);
WbImageRef wb_display_image_load(WbDeviceTag tag, const char *filename);

#ifdef __cplusplus
}
#endif

#endif /* WB_DISPLAY_H */
