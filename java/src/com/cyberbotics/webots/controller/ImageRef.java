package com.cyberbotics.webots.controller;

/**
 * Webots' {@code ImageRef}: an image held by a display ({@code Display.imageNew},
 * {@code imageCopy}, {@code imageLoad}), freed by {@code Display.imageDelete}.
 */
public class ImageRef {
  // The C API's WbImageRef value: a key into the robot's table of images, not memory.
  final long handle;

  ImageRef(long handle) {
    this.handle = handle;
  }
}
