package com.cyberbotics.webots.controller;

/**
 * Webots' {@code Display}: drawing into the display's image, pixels (px) from the top-left
 * corner. The display starts opaque black; colour {@code 0xRRGGBB} (default white), alpha and
 * opacity in [0, 1] (default 1). Calls take effect at once (the C API's). Image files are PNG
 * only. Attaching a camera is not available (COMPATIBILITY.md).
 */
public class Display extends Device {
  /** Image formats of {@link #imageNew}: one {@code int} per pixel, bytes most significant first. */
  public static final int RGB = 3;
  public static final int RGBA = 4;
  public static final int ARGB = 5;
  public static final int BGRA = 6;
  public static final int ABGR = 7;

  Display(int tag) {
    super(tag);
  }

  /** The width (px). */
  public int getWidth() {
    return WebotsNative.displayGetWidth(getTag());
  }

  /** The height (px). */
  public int getHeight() {
    return WebotsNative.displayGetHeight(getTag());
  }

  /** The drawing colour, {@code 0xRRGGBB}. */
  public void setColor(int color) {
    WebotsNative.displaySetColor(getTag(), color);
  }

  /** The alpha of what is drawn, 0 (transparent) to 1. */
  public void setAlpha(double alpha) {
    WebotsNative.displaySetAlpha(getTag(), alpha);
  }

  /** The opacity of what is drawn (the weight of new pixels), 0 to 1. */
  public void setOpacity(double opacity) {
    WebotsNative.displaySetOpacity(getTag(), opacity);
  }

  /** The font: one of Webots' 13 families, the character height (px), anti-aliasing. */
  public void setFont(String font, int size, boolean antiAliasing) {
    WebotsNative.displaySetFont(getTag(), font, size, antiAliasing);
  }

  /** Draws {@code text} with its top-left corner at (x, y); '\n' starts a new line. */
  public void drawText(String text, int x, int y) {
    WebotsNative.displayDrawText(getTag(), text, x, y);
  }

  /** Draws pixel (x, y). */
  public void drawPixel(int x, int y) {
    WebotsNative.displayDrawPixel(getTag(), x, y);
  }

  /** Draws the line from (x1, y1) to (x2, y2) (Bresenham). */
  public void drawLine(int x1, int y1, int x2, int y2) {
    WebotsNative.displayDrawLine(getTag(), x1, y1, x2, y2);
  }

  /** The outline of the rectangle of top-left corner (x, y). */
  public void drawRectangle(int x, int y, int width, int height) {
    WebotsNative.displayDrawRectangle(getTag(), x, y, width, height);
  }

  /** The outline of the ellipse of centre (cx, cy) and radii a (along x), b (along y). */
  public void drawOval(int cx, int cy, int a, int b) {
    WebotsNative.displayDrawOval(getTag(), cx, cy, a, b);
  }

  /**
   * The outline of the closed polygon of the first {@code size} corners (x[i], y[i]).
   *
   * @throws ArrayIndexOutOfBoundsException if {@code x} or {@code y} has fewer than size
   */
  public void drawPolygon(int[] x, int[] y, int size) {
    checkCorners(x, y, size);
    WebotsNative.displayDrawPolygon(getTag(), x, y, size);
  }

  /** The outline of the closed polygon of the corners (x[i], y[i]). */
  public void drawPolygon(int[] x, int[] y) {
    drawPolygon(x, y, Math.min(x.length, y.length));
  }

  /** Fills the rectangle of top-left corner (x, y). */
  public void fillRectangle(int x, int y, int width, int height) {
    WebotsNative.displayFillRectangle(getTag(), x, y, width, height);
  }

  /** Fills the ellipse of centre (cx, cy) and radii a (along x), b (along y). */
  public void fillOval(int cx, int cy, int a, int b) {
    WebotsNative.displayFillOval(getTag(), cx, cy, a, b);
  }

  /**
   * Fills the polygon of the first {@code size} corners (x[i], y[i]).
   *
   * @throws ArrayIndexOutOfBoundsException if {@code x} or {@code y} has fewer than size
   */
  public void fillPolygon(int[] x, int[] y, int size) {
    checkCorners(x, y, size);
    WebotsNative.displayFillPolygon(getTag(), x, y, size);
  }

  /** Fills the polygon of the corners (x[i], y[i]). */
  public void fillPolygon(int[] x, int[] y) {
    fillPolygon(x, y, Math.min(x.length, y.length));
  }

  /**
   * A new image of {@code width × height} pixels, row after row, one {@code int} per pixel in
   * {@code format} ({@link #ARGB}: {@code 0xAARRGGBB}, as {@code Camera.getImage} gives them);
   * {@code null} (with the C API's error) for an unknown format or an empty size.
   *
   * @throws ArrayIndexOutOfBoundsException if {@code data} has fewer than width × height pixels
   */
  public ImageRef imageNew(int width, int height, int[] data, int format) {
    long pixels = (long) Math.max(width, 0) * Math.max(height, 0);
    if (data.length < pixels)
      throw new ArrayIndexOutOfBoundsException(
          "imageNew: " + data.length + " pixels for " + width + " x " + height);
    return image(WebotsNative.displayImageNew(getTag(), width, height, data, format));
  }

  /** A copy of the rectangle of top-left corner (x, y); {@code null} if it is off the display. */
  public ImageRef imageCopy(int x, int y, int width, int height) {
    return image(WebotsNative.displayImageCopy(getTag(), x, y, width, height));
  }

  /** Pastes {@code ir} with its top-left corner at (x, y), alpha-blended if {@code blend}. */
  public void imagePaste(ImageRef ir, int x, int y, boolean blend) {
    WebotsNative.displayImagePaste(getTag(), handle(ir), x, y, blend);
  }

  /** Pastes {@code ir} with its top-left corner at (x, y), not blended. */
  public void imagePaste(ImageRef ir, int x, int y) {
    imagePaste(ir, x, y, false);
  }

  /** The image of the PNG file {@code filename}; {@code null} if it cannot be read. */
  public ImageRef imageLoad(String filename) {
    return image(WebotsNative.displayImageLoad(getTag(), filename));
  }

  /** Saves {@code ir} ({@code null}: the display itself) as the PNG file {@code filename}. */
  public void imageSave(ImageRef ir, String filename) {
    WebotsNative.displayImageSave(getTag(), handle(ir), filename);
  }

  /** Frees {@code ir}. */
  public void imageDelete(ImageRef ir) {
    WebotsNative.displayImageDelete(getTag(), handle(ir));
  }

  private static ImageRef image(long handle) {
    return handle == 0 ? null : new ImageRef(handle);
  }

  private static long handle(ImageRef ir) {
    return ir == null ? 0 : ir.handle;
  }

  private static void checkCorners(int[] x, int[] y, int size) {
    if (size > x.length || size > y.length)
      throw new ArrayIndexOutOfBoundsException(
          "polygon of " + size + " corners from " + x.length + " x and " + y.length + " y");
  }
}
