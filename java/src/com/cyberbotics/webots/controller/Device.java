package com.cyberbotics.webots.controller;

/** A device of the robot (Webots' {@code Device}): its tag, name, model and node type. */
public class Device {
  private final int tag;

  Device(int tag) {
    this.tag = tag;
  }

  /** The C API's device tag. */
  public int getTag() {
    return tag;
  }

  /** The device's name, as in the world file. */
  public String getName() {
    return WebotsNative.deviceGetName(tag);
  }

  /** The device's model string. */
  public String getModel() {
    return WebotsNative.deviceGetModel(tag);
  }

  /** The node type ({@code WB_NODE_*} of webots/nodes.h). */
  public int getNodeType() {
    return WebotsNative.deviceGetNodeType(tag);
  }
}
