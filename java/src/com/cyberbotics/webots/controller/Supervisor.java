package com.cyberbotics.webots.controller;

/**
 * Webots' {@code Supervisor}, the parent of {@code vehicle.Driver}: here only its place in the
 * hierarchy (Robot, Supervisor, Driver, Car). The scene-tree functions (nodes and fields) are
 * not part of this binding (COMPATIBILITY.md).
 */
public class Supervisor extends Robot {
  /** Loads the world, as {@link Robot#Robot()}. */
  public Supervisor() {
    super();
  }
}
