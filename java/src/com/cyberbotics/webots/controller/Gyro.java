package com.cyberbotics.webots.controller;

/** Webots' {@code Gyro}: the angular velocity {x, y, z} (rad/s). */
public class Gyro extends Device {
  Gyro(int tag) {
    super(tag);
  }

  /** Samples every {@code samplingPeriod} ms. */
  public void enable(int samplingPeriod) {
    WebotsNative.gyroEnable(getTag(), samplingPeriod);
  }

  /** Stops sampling. */
  public void disable() {
    WebotsNative.gyroDisable(getTag());
  }

  /** The sampling period (ms), 0 when disabled. */
  public int getSamplingPeriod() {
    return WebotsNative.gyroGetSamplingPeriod(getTag());
  }

  /** The angular velocity {x, y, z} (rad/s). */
  public double[] getValues() {
    return WebotsNative.gyroGetValues(getTag());
  }
}
