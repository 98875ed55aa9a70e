package com.cyberbotics.webots.controller;

/** Webots' {@code Accelerometer}: the acceleration {x, y, z} (m/s^2). */
public class Accelerometer extends Device {
  Accelerometer(int tag) {
    super(tag);
  }

  /** Samples every {@code samplingPeriod} ms. */
  public void enable(int samplingPeriod) {
    WebotsNative.accelerometerEnable(getTag(), samplingPeriod);
  }

  /** Stops sampling. */
  public void disable() {
    WebotsNative.accelerometerDisable(getTag());
  }

  /** The sampling period (ms), 0 when disabled. */
  public int getSamplingPeriod() {
    return WebotsNative.accelerometerGetSamplingPeriod(getTag());
  }

  /** The acceleration {x, y, z} (m/s^2). */
  public double[] getValues() {
    return WebotsNative.accelerometerGetValues(getTag());
  }
}
