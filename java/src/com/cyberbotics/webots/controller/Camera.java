package com.cyberbotics.webots.controller;

/**
 * Webots' {@code Camera}: the image as one {@code int} per pixel, {@code 0xAARRGGBB}, row after
 * row, with Webots' static pixel helpers, and its Recognition ({@link CameraRecognitionObject}).
 */
public class Camera extends Device {
  Camera(int tag) {
    super(tag);
  }

  /** Samples every {@code samplingPeriod} ms. */
  public void enable(int samplingPeriod) {
    WebotsNative.cameraEnable(getTag(), samplingPeriod);
  }

  /** Stops sampling. */
  public void disable() {
    WebotsNative.cameraDisable(getTag());
  }

  /** The sampling period (ms), 0 when disabled. */
  public int getSamplingPeriod() {
    return WebotsNative.cameraGetSamplingPeriod(getTag());
  }

  /** The width (pixels). */
  public int getWidth() {
    return WebotsNative.cameraGetWidth(getTag());
  }

  /** The height (pixels). */
  public int getHeight() {
    return WebotsNative.cameraGetHeight(getTag());
  }

  /** The horizontal field of view (rad). */
  public double getFov() {
    return WebotsNative.cameraGetFov(getTag());
  }

  /** The minimum horizontal field of view (rad): the field of view (no zoom here). */
  public double getMinFov() {
    return WebotsNative.cameraGetMinFov(getTag());
  }

  /** The maximum horizontal field of view (rad): the field of view (no zoom here). */
  public double getMaxFov() {
    return WebotsNative.cameraGetMaxFov(getTag());
  }

  /**
   * Saves the last image as the PNG file {@code filename} ({@code quality} is for JPEG, which
   * is not written); 0, or -1 with the C API's error.
   */
  public int saveImage(String filename, int quality) {
    return WebotsNative.cameraSaveImage(getTag(), filename, quality);
  }

  /** The near clipping distance (m). */
  public double getNear() {
    return WebotsNative.cameraGetNear(getTag());
  }

  /** The last image, {@code getWidth() * getHeight()} pixels {@code 0xAARRGGBB}; null if none. */
  public int[] getImage() {
    return WebotsNative.cameraGetImage(getTag());
  }

  /** True if the camera has a Recognition node. */
  public boolean hasRecognition() {
    return WebotsNative.cameraHasRecognition(getTag());
  }

  /** Recognises objects every {@code samplingPeriod} ms (the camera need not be enabled). */
  public void recognitionEnable(int samplingPeriod) {
    WebotsNative.cameraRecognitionEnable(getTag(), samplingPeriod);
  }

  /** Stops recognising. */
  public void recognitionDisable() {
    WebotsNative.cameraRecognitionDisable(getTag());
  }

  /** Recognition's sampling period (ms), 0 when disabled. */
  public int getRecognitionSamplingPeriod() {
    return WebotsNative.cameraRecognitionGetSamplingPeriod(getTag());
  }

  /** How many objects the last recognition sample holds. */
  public int getRecognitionNumberOfObjects() {
    return WebotsNative.cameraRecognitionGetNumberOfObjects(getTag());
  }

  /** The objects of the last recognition sample (empty when disabled or before the first). */
  public CameraRecognitionObject[] getRecognitionObjects() {
    return WebotsNative.cameraRecognitionGetObjects(getTag());
  }

  /** False: no segmentation image is rendered (COMPATIBILITY.md). */
  public boolean hasRecognitionSegmentation() {
    return WebotsNative.cameraRecognitionHasSegmentation(getTag());
  }

  public static int imageGetRed(int[] image, int width, int x, int y) {
    return pixelGetRed(image[y * width + x]);
  }

  public static int imageGetGreen(int[] image, int width, int x, int y) {
    return pixelGetGreen(image[y * width + x]);
  }

  public static int imageGetBlue(int[] image, int width, int x, int y) {
    return pixelGetBlue(image[y * width + x]);
  }

  public static int imageGetGray(int[] image, int width, int x, int y) {
    return pixelGetGray(image[y * width + x]);
  }

  public static int pixelGetRed(int pixel) {
    return (pixel >>> 16) & 0xff;
  }

  public static int pixelGetGreen(int pixel) {
    return (pixel >>> 8) & 0xff;
  }

  public static int pixelGetBlue(int pixel) {
    return pixel & 0xff;
  }

  /** The mean of red, green and blue, as Webots computes it. */
  public static int pixelGetGray(int pixel) {
    return (pixelGetRed(pixel) + pixelGetGreen(pixel) + pixelGetBlue(pixel)) / 3;
  }
}
