package com.cyberbotics.webots.controller;

/** Webots' {@code Lidar}: range images (m); the point cloud is not wrapped (COMPATIBILITY.md). */
public class Lidar extends Device {
  Lidar(int tag) {
    super(tag);
  }

  /** Samples every {@code samplingPeriod} ms. */
  public void enable(int samplingPeriod) {
    WebotsNative.lidarEnable(getTag(), samplingPeriod);
  }

  /** Stops sampling. */
  public void disable() {
    WebotsNative.lidarDisable(getTag());
  }

  /** The sampling period (ms), 0 when disabled. */
  public int getSamplingPeriod() {
    return WebotsNative.lidarGetSamplingPeriod(getTag());
  }

  /** The range image (m), layer after layer, each {@link #getHorizontalResolution()} long. */
  public float[] getRangeImage() {
    return WebotsNative.lidarGetRangeImage(getTag());
  }

  /** The range image of {@code layer} (m). */
  public float[] getLayerRangeImage(int layer) {
    return WebotsNative.lidarGetLayerRangeImage(getTag(), layer);
  }

  /** Points per layer. */
  public int getHorizontalResolution() {
    return WebotsNative.lidarGetHorizontalResolution(getTag());
  }

  /** Layers. */
  public int getNumberOfLayers() {
    return WebotsNative.lidarGetNumberOfLayers(getTag());
  }

  /** The horizontal field of view (rad). */
  public double getFov() {
    return WebotsNative.lidarGetFov(getTag());
  }

  /** The vertical field of view (rad). */
  public double getVerticalFov() {
    return WebotsNative.lidarGetVerticalFov(getTag());
  }

  /** The minimum range (m). */
  public double getMinRange() {
    return WebotsNative.lidarGetMinRange(getTag());
  }

  /** The maximum range (m). */
  public double getMaxRange() {
    return WebotsNative.lidarGetMaxRange(getTag());
  }
}
