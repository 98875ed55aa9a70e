"""Webots' ROS 1 automobile interface (``ros_automobile``) over the project's Python package:
the ``vehicle-ros`` command (:func:`vehicle_ros.node.main`). See ros/README.md."""
