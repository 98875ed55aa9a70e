package com.cyberbotics.webots.controller;

/**
 * Webots' {@code CameraRecognitionObject}: an object a camera's Recognition saw in its last
 * sample. Positions and sizes in m in the camera frame (x forward, y left, z up), orientation
 * axis-angle {@code [x, y, z, angle]} (rad), image values in px from the top-left corner,
 * colours RGB in [0, 1]. The getters return copies.
 */
public class CameraRecognitionObject {
  private final int id;
  private final double[] position;
  private final double[] orientation;
  private final double[] size;
  private final int[] positionOnImage;
  private final int[] sizeOnImage;
  private final double[] colors;
  private final String model;

  // Built by the JNI library (java/src/recognition.rs) from the C API's object.
  CameraRecognitionObject(int id, double[] position, double[] orientation, double[] size,
      int[] positionOnImage, int[] sizeOnImage, double[] colors, String model) {
    this.id = id;
    this.position = position;
    this.orientation = orientation;
    this.size = size;
    this.positionOnImage = positionOnImage;
    this.sizeOnImage = sizeOnImage;
    this.colors = colors;
    this.model = model;
  }

  /** The object's id. */
  public int getId() {
    return id;
  }

  /** Its centre (m, camera frame). */
  public double[] getPosition() {
    return position.clone();
  }

  /** Its orientation relative to the camera, {@code [x, y, z, angle]} (rad). */
  public double[] getOrientation() {
    return orientation.clone();
  }

  /** Its extent along the camera's y and z axes (m). */
  public double[] getSize() {
    return size.clone();
  }

  /** The centre of its rectangle on the image (px). */
  public int[] getPositionOnImage() {
    return positionOnImage.clone();
  }

  /** The width and height of its rectangle on the image (px). */
  public int[] getSizeOnImage() {
    return sizeOnImage.clone();
  }

  /** How many recognition colours it has. */
  public int getNumberOfColors() {
    return colors.length / 3;
  }

  /** Its recognition colours, RGB after RGB ({@code 3 * getNumberOfColors()} values in [0, 1]). */
  public double[] getColors() {
    return colors.clone();
  }

  /** Its {@code model}. */
  public String getModel() {
    return model;
  }
}
