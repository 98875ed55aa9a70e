package com.cyberbotics.webots.controller;

/** Webots' {@code Radar}: the targets of its last sample. */
public class Radar extends Device {
  Radar(int tag) {
    super(tag);
  }

  /** Samples every {@code samplingPeriod} ms. */
  public void enable(int samplingPeriod) {
    WebotsNative.radarEnable(getTag(), samplingPeriod);
  }

  /** Stops sampling. */
  public void disable() {
    WebotsNative.radarDisable(getTag());
  }

  /** The sampling period (ms), 0 when disabled. */
  public int getSamplingPeriod() {
    return WebotsNative.radarGetSamplingPeriod(getTag());
  }

  /** The number of targets of the last sample. */
  public int getNumberOfTargets() {
    return WebotsNative.radarGetNumberOfTargets(getTag());
  }

  /** The targets of the last sample (empty before the first one). */
  public RadarTarget[] getTargets() {
    double[] flat = WebotsNative.radarGetTargets(getTag());
    if (flat == null) return new RadarTarget[0];
    RadarTarget[] targets = new RadarTarget[flat.length / 4];
    for (int k = 0; k < targets.length; ++k)
      targets[k] = new RadarTarget(flat[4 * k], flat[4 * k + 1], flat[4 * k + 2], flat[4 * k + 3]);
    return targets;
  }

  /** The minimum range (m). */
  public double getMinRange() {
    return WebotsNative.radarGetMinRange(getTag());
  }

  /** The maximum range (m). */
  public double getMaxRange() {
    return WebotsNative.radarGetMaxRange(getTag());
  }

  /** The horizontal field of view (rad). */
  public double getHorizontalFov() {
    return WebotsNative.radarGetHorizontalFov(getTag());
  }

  /** The vertical field of view (rad). */
  public double getVerticalFov() {
    return WebotsNative.radarGetVerticalFov(getTag());
  }
}
