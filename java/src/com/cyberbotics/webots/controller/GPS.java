package com.cyberbotics.webots.controller;

/** Webots' {@code GPS}: position (m), speed (m/s). */
public class GPS extends Device {
  /** {@link #getCoordinateSystem()}: x, y, z in the world frame (m). */
  public static final int LOCAL = 0;
  /** {@link #getCoordinateSystem()}: latitude, longitude (degrees) and altitude (m). */
  public static final int WGS84 = 1;

  GPS(int tag) {
    super(tag);
  }

  /** Samples every {@code samplingPeriod} ms. */
  public void enable(int samplingPeriod) {
    WebotsNative.gpsEnable(getTag(), samplingPeriod);
  }

  /** Stops sampling. */
  public void disable() {
    WebotsNative.gpsDisable(getTag());
  }

  /** The sampling period (ms), 0 when disabled. */
  public int getSamplingPeriod() {
    return WebotsNative.gpsGetSamplingPeriod(getTag());
  }

  /** The position {x, y, z} (m, or degrees and m in WGS84). */
  public double[] getValues() {
    return WebotsNative.gpsGetValues(getTag());
  }

  /** The speed (m/s). */
  public double getSpeed() {
    return WebotsNative.gpsGetSpeed(getTag());
  }

  /** The velocity {x, y, z} (m/s). */
  public double[] getSpeedVector() {
    return WebotsNative.gpsGetSpeedVector(getTag());
  }

  /** {@link #LOCAL} or {@link #WGS84}. */
  public int getCoordinateSystem() {
    return WebotsNative.gpsGetCoordinateSystem(getTag());
  }
}
