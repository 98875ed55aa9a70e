package com.cyberbotics.webots.controller;

/**
 * Webots' {@code LidarPoint}: a point of a lidar's point cloud, in the lidar's axes (m, x
 * forward, y left, z up; infinite where the ray had no return).
 */
public class LidarPoint {
  private final float x;
  private final float y;
  private final float z;
  private final int layerId;
  private final float time;

  // Built by the JNI library (java/src/point_cloud.rs) from the C API's point.
  LidarPoint(float x, float y, float z, int layerId, float time) {
    this.x = x;
    this.y = y;
    this.z = z;
    this.layerId = layerId;
    this.time = time;
  }

  /** Along the lidar's x axis (m). */
  public float getX() {
    return x;
  }

  /** Along its y axis (m). */
  public float getY() {
    return y;
  }

  /** Along its z axis (m). */
  public float getZ() {
    return z;
  }

  /** The layer (0 the highest). */
  public int getLayerId() {
    return layerId;
  }

  /** When the ray was cast (s of simulated time). */
  public float getTime() {
    return time;
  }
}
