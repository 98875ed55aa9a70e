package com.cyberbotics.webots.controller;

/**
 * Webots' {@code Keyboard}: the keys the world's programme presses ({@code key} entries of
 * {@code [[vehicle.programme]]}), as key codes with modifier bits.
 */
public class Keyboard {
  public final static int END = 312;
  public final static int HOME = 313;
  public final static int LEFT = 314;
  public final static int UP = 315;
  public final static int RIGHT = 316;
  public final static int DOWN = 317;
  public final static int PAGEUP = 366;
  public final static int PAGEDOWN = 367;
  public final static int NUMPAD_HOME = 375;
  public final static int NUMPAD_LEFT = 376;
  public final static int NUMPAD_UP = 377;
  public final static int NUMPAD_RIGHT = 378;
  public final static int NUMPAD_DOWN = 379;
  public final static int NUMPAD_END = 382;
  public final static int KEY = 0x0000ffff;
  public final static int SHIFT = 0x00010000;
  public final static int CONTROL = 0x00020000;
  public final static int ALT = 0x00040000;

  Keyboard() {}

  /** Samples the keyboard every {@code samplingPeriod} ms. */
  public void enable(int samplingPeriod) {
    WebotsNative.keyboardEnable(samplingPeriod);
  }

  /** Stops sampling. */
  public void disable() {
    WebotsNative.keyboardDisable();
  }

  /** The sampling period (ms), 0 when disabled. */
  public int getSamplingPeriod() {
    return WebotsNative.keyboardGetSamplingPeriod();
  }

  /** The next key pressed in the last sample, -1 when none is left. */
  public int getKey() {
    return WebotsNative.keyboardGetKey();
  }
}
