package com.cyberbotics.webots.controller;

/** Webots' {@code Lidar}: range images and point clouds ({@link LidarPoint}), in m. */
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

  /** Computes the point cloud while the lidar is enabled. */
  public void enablePointCloud() {
    WebotsNative.lidarEnablePointCloud(getTag());
  }

  /** Stops computing the point cloud. */
  public void disablePointCloud() {
    WebotsNative.lidarDisablePointCloud(getTag());
  }

  /** True if the point cloud is enabled. */
  public boolean isPointCloudEnabled() {
    return WebotsNative.lidarIsPointCloudEnabled(getTag());
  }

  /** The points of the cloud: resolution × layers, 0 when it or the lidar is disabled. */
  public int getNumberOfPoints() {
    return WebotsNative.lidarGetNumberOfPoints(getTag());
  }

  /** The point cloud, layer after layer; {@code null} when it or the lidar is disabled. */
  public LidarPoint[] getPointCloud() {
    return WebotsNative.lidarGetPointCloud(getTag());
  }

  /** The points of {@code layer}; {@code null} when disabled or for a layer out of range. */
  public LidarPoint[] getLayerPointCloud(int layer) {
    return WebotsNative.lidarGetLayerPointCloud(getTag(), layer);
  }

  /** Points per layer. */
  public int getHorizontalResolution() {
    return WebotsNative.lidarGetHorizontalResolution(getTag());
  }

  /** Layers. */
  public int getNumberOfLayers() {
    return WebotsNative.lidarGetNumberOfLayers(getTag());
  }

  /** The rotation frequency (Hz). */
  public double getFrequency() {
    return WebotsNative.lidarGetFrequency(getTag());
  }

  /** Sets the rotation frequency (Hz), within [getMinFrequency(), getMaxFrequency()]. */
  public void setFrequency(double frequency) {
    WebotsNative.lidarSetFrequency(getTag(), frequency);
  }

  /** The minimum rotation frequency (Hz). */
  public double getMinFrequency() {
    return WebotsNative.lidarGetMinFrequency(getTag());
  }

  /** The maximum rotation frequency (Hz). */
  public double getMaxFrequency() {
    return WebotsNative.lidarGetMaxFrequency(getTag());
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
