// webots/Display.hpp: header-only C++ wrapper of webots/display.h.
//
// Part of the `capi` crate. SPDX-License-Identifier: MIT OR Apache-2.0
//
// Same class, constants and method names as Webots' webots::Display, for the functions this
// simulator has (no camera attachment; PNG files only; text in a bitmap font). Requires C++11.

#ifndef WB_DISPLAY_HPP
#define WB_DISPLAY_HPP

#if !(__cplusplus >= 201103L || (defined(_MSVC_LANG) && _MSVC_LANG >= 201103L))
#error "webots/Display.hpp requires C++11 or later"
#endif

#include <webots/Device.hpp>
#include <webots/display.h>

namespace webots {
  class ImageRef {
  public:
    explicit ImageRef(WbImageRef ref) : ref_(ref) {}
    WbImageRef getImageRef() const { return ref_; }

  private:
    WbImageRef ref_;
  };

  class Display : public Device {
  public:
    enum { RGB = WB_IMAGE_RGB, RGBA = WB_IMAGE_RGBA, ARGB = WB_IMAGE_ARGB, BGRA = WB_IMAGE_BGRA, ABGR = WB_IMAGE_ABGR };

    explicit Display(const std::string &name) : Device(name) {}
    explicit Display(WbDeviceTag tag) : Device(tag) {}

    int getWidth() const { return wb_display_get_width(getTag()); }
    int getHeight() const { return wb_display_get_height(getTag()); }
    void setColor(int color) { wb_display_set_color(getTag(), color); }
    void setAlpha(double alpha) { wb_display_set_alpha(getTag(), alpha); }
    void setOpacity(double opacity) { wb_display_set_opacity(getTag(), opacity); }
    void drawPixel(int x, int y) { wb_display_draw_pixel(getTag(), x, y); }
    void drawLine(int x1, int y1, int x2, int y2) { wb_display_draw_line(getTag(), x1, y1, x2, y2); }
    void drawRectangle(int x, int y, int width, int height) { wb_display_draw_rectangle(getTag(), x, y, width, height); }
    void fillRectangle(int x, int y, int width, int height) { wb_display_fill_rectangle(getTag(), x, y, width, height); }
    void drawOval(int cx, int cy, int a, int b) { wb_display_draw_oval(getTag(), cx, cy, a, b); }
    void fillOval(int cx, int cy, int a, int b) { wb_display_fill_oval(getTag(), cx, cy, a, b); }
    void drawPolygon(const int *x, const int *y, int size) { wb_display_draw_polygon(getTag(), x, y, size); }
    void fillPolygon(const int *x, const int *y, int size) { wb_display_fill_polygon(getTag(), x, y, size); }
    void setFont(const std::string &font, int size, bool antiAliasing) { wb_display_set_font(getTag(), font.c_str(), size, antiAliasing); }
    void drawText(const std::string &text, int x, int y) { wb_display_draw_text(getTag(), text.c_str(), x, y); }
    // The caller deletes the returned reference (imageDelete), as in Webots.
    ImageRef *imageNew(int width, int height, const void *data, int format) const {
      WbImageRef r = wb_display_image_new(getTag(), width, height, data, format);
      return r ? new ImageRef(r) : nullptr;
    }
    ImageRef *imageCopy(int x, int y, int width, int height) const {
      WbImageRef r = wb_display_image_copy(getTag(), x, y, width, height);
      return r ? new ImageRef(r) : nullptr;
    }
    void imagePaste(ImageRef *ir, int x, int y, bool blend = false) {
      if (ir)
        wb_display_image_paste(getTag(), ir->getImageRef(), x, y, blend);
    }
    ImageRef *imageLoad(const std::string &filename) const {
      WbImageRef r = wb_display_image_load(getTag(), filename.c_str());
      return r ? new ImageRef(r) : nullptr;
    }
    void imageSave(ImageRef *ir, const std::string &filename) const {
      wb_display_image_save(getTag(), ir ? ir->getImageRef() : nullptr, filename.c_str());
    }
    void imageDelete(ImageRef *ir) {
      if (ir) {
        wb_display_image_delete(getTag(), ir->getImageRef());
        delete ir;
      }
    }
  };
}  // namespace webots

#endif  // WB_DISPLAY_HPP
