package com.cyberbotics.webots.controller;

/** Webots' {@code RadarTarget}: one target of a radar's last sample. */
public class RadarTarget {
  private final double distance;
  private final double receivedPower;
  private final double speed;
  private final double azimuth;

  RadarTarget(double distance, double receivedPower, double speed, double azimuth) {
    this.distance = distance;
    this.receivedPower = receivedPower;
    this.speed = speed;
    this.azimuth = azimuth;
  }

  /** Distance (m). */
  public double getDistance() {
    return distance;
  }

  /** Received power (dBm). */
  public double getReceivedPower() {
    return receivedPower;
  }

  /** Radial speed (m/s, positive when the target moves away). */
  public double getSpeed() {
    return speed;
  }

  /** Azimuth (rad, positive to the right of the radar's x axis). */
  public double getAzimuth() {
    return azimuth;
  }
}
