package com.cyberbotics.webots.controller;

/** Webots' {@code Compass}: the north direction {x, y, z} in the device frame (unit vector). */
public class Compass extends Device {
  Compass(int tag) {
    super(tag);
  }

  /** Samples every {@code samplingPeriod} ms. */
  public void enable(int samplingPeriod) {
    WebotsNative.compassEnable(getTag(), samplingPeriod);
  }

  /** Stops sampling. */
  public void disable() {
    WebotsNative.compassDisable(getTag());
  }

  /** The sampling period (ms), 0 when disabled. */
  public int getSamplingPeriod() {
    return WebotsNative.compassGetSamplingPeriod(getTag());
  }

  /** The north direction {x, y, z} in the device frame (unit vector). */
  public double[] getValues() {
    return WebotsNative.compassGetValues(getTag());
  }
}
