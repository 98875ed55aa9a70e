"""The car's sensors as standard ROS messages, with Webots' generic device services.

For each sensor device ``<dev>`` (its name with ``-``, ``.``, space, ``(`` and ``)`` turned
into ``_``, as Webots' ROS controller does), relative to the node's namespace:

* services ``<dev>/enable`` (``webots_ros/set_int``: a sampling period in ms, a multiple of
  the basic time step; 0 disables), ``<dev>/get_sampling_period`` (``get_int``),
  ``<dev>/get_model``, ``<dev>/get_name`` (``get_string``), ``<dev>/get_node_type``
  (``get_int``); a lidar also ``<dev>/enable_point_cloud`` (``set_bool``);
* topics, published at each sample while someone subscribes: GPS ``<dev>/values``
  (``sensor_msgs/NavSatFix`` when the world's ``gpsCoordinateSystem`` is WGS84, else
  ``geometry_msgs/PointStamped`` in m, as Webots) and ``<dev>/speed``
  (``webots_ros/Float64Stamped``, m/s); InertialUnit ``<dev>/quaternion``, Gyro and
  Accelerometer ``<dev>/values`` (``sensor_msgs/Imu``: orientation, rad/s, m/s²); Compass
  ``<dev>/values`` (``sensor_msgs/MagneticField``, the unit vector the C API gives);
  DistanceSensor ``<dev>/value`` (``sensor_msgs/Range``); Lidar ``<dev>/laser_scan/layer<i>``
  (``sensor_msgs/LaserScan``, one per layer) and ``<dev>/point_cloud``
  (``sensor_msgs/PointCloud2``, while the point cloud is enabled); Camera ``<dev>/image``
  (``sensor_msgs/Image``, ``bgra8``).

Every value is the ``controller`` module's reading (the engine's measurement). The other
devices (radar, road sensor, display, the car's own motors and lights) have the name services
only.
"""

import re
from typing import Any, Callable, Dict, List, Optional

import rospy
from geometry_msgs.msg import PointStamped
from sensor_msgs.msg import (
    Image,
    Imu,
    LaserScan,
    MagneticField,
    NavSatFix,
    PointCloud2,
    PointField,
    Range,
)
from webots_ros.msg import Float64Stamped
from webots_ros.srv import (
    get_int,
    get_intResponse,
    get_string,
    get_stringResponse,
    set_bool,
    set_boolResponse,
    set_int,
    set_intResponse,
)

from controller import GPS, Node
from vehicle_ros.calls import CarCalls

__all__ = ["HIDDEN_DEVICES", "SensorInterface", "ros_name"]

#: The car's own devices, without a generic interface in Webots' ROS controller either.
HIDDEN_DEVICES = frozenset(
    """left_steer right_steer left_front_wheel right_front_wheel left_rear_wheel
    right_rear_wheel left_front_sensor right_front_sensor left_rear_sensor right_rear_sensor
    antifog_lights backwards_lights brake_lights front_lights left_front_brake
    left_indicators left_rear_brake rear_lights right_front_brake right_indicators
    right_rear_brake""".split()
)

_SAMPLED = {
    Node.GPS,
    Node.INERTIAL_UNIT,
    Node.GYRO,
    Node.ACCELEROMETER,
    Node.COMPASS,
    Node.DISTANCE_SENSOR,
    Node.LIDAR,
    Node.CAMERA,
    Node.RADAR,
}


def ros_name(name: str) -> str:
    """A Webots name made a ROS name as Webots' ROS controller does."""
    return re.sub(r"[-. ()]", "_", name)


def _header(message: Any, stamp: rospy.Time, frame_id: str) -> Any:
    message.header.stamp = stamp
    message.header.frame_id = frame_id
    return message


def _no_orientation(message: Imu) -> Imu:
    # ROS's convention for an Imu message without a quantity: covariance[0] = -1.
    message.orientation_covariance[0] = -1.0
    message.angular_velocity_covariance[0] = -1.0
    message.linear_acceleration_covariance[0] = -1.0
    return message


class _Device:
    """One device: its services, and the topics of a sensor while enabled."""

    def __init__(
        self, device: Any, calls: CarCalls, namespace: str, basic_step: int
    ) -> None:
        self.device = device
        self.name = ros_name(device.getName())
        self._prefix = f"{namespace}{self.name}/"
        self.kind = device.getNodeType()
        self._calls = calls
        self._basic_step = basic_step
        self._publishers: Dict[str, rospy.Publisher] = {}
        self._services: List[rospy.Service] = []
        # Even the name and model are read on the main thread: every library call is.
        self._serve(
            "get_model", get_string, lambda _r: get_stringResponse(calls.call(device.getModel))
        )
        self._serve(
            "get_name", get_string, lambda _r: get_stringResponse(calls.call(device.getName))
        )
        self._serve("get_node_type", get_int, lambda _r: get_intResponse(self.kind))
        if self.kind in _SAMPLED:
            self._serve("enable", set_int, self._enable)
            self._serve(
                "get_sampling_period",
                get_int,
                lambda _r: get_intResponse(calls.call(device.getSamplingPeriod)),
            )
        if self.kind == Node.LIDAR:
            self._serve("enable_point_cloud", set_bool, self._enable_point_cloud)

    def _serve(self, name: str, kind: Any, handler: Callable[[Any], Any]) -> None:
        self._services.append(rospy.Service(f"{self._prefix}{name}", kind, handler))

    def _enable(self, request: Any) -> set_intResponse:
        period = request.value
        # Webots' RosSensor: a period that is no multiple of the basic step is refused.
        if period < 0 or period % self._basic_step != 0:
            rospy.logerr(
                "Wrong sampling period: %d for device: %s (not a multiple of the basic time step %d ms).",
                period,
                self.name,
                self._basic_step,
            )
            return set_intResponse(False)
        self._calls.call(lambda: self.enable(period))
        return set_intResponse(True)

    def _enable_point_cloud(self, request: Any) -> set_boolResponse:
        device = self.device
        self._calls.call(device.enablePointCloud if request.value else device.disablePointCloud)
        return set_boolResponse(True)

    def enable(self, period: int) -> None:
        """Enables the sensor every ``period`` ms and advertises its topics (0: disables it
        and withdraws them). Main thread."""
        if period == 0:
            self.device.disable()
            for publisher in self._publishers.values():
                publisher.unregister()
            self._publishers.clear()
            return
        self.device.enable(period)
        if not self._publishers:
            self._publishers = self._advertise()

    def _advertise(self) -> Dict[str, rospy.Publisher]:
        topics: Dict[str, Any] = {}
        if self.kind == Node.GPS:
            wgs84 = self.device.getCoordinateSystem() == GPS.WGS84
            topics = {"values": NavSatFix if wgs84 else PointStamped, "speed": Float64Stamped}
        elif self.kind == Node.INERTIAL_UNIT:
            topics = {"quaternion": Imu}
        elif self.kind in (Node.GYRO, Node.ACCELEROMETER):
            topics = {"values": Imu}
        elif self.kind == Node.COMPASS:
            topics = {"values": MagneticField}
        elif self.kind == Node.DISTANCE_SENSOR:
            topics = {"value": Range}
        elif self.kind == Node.LIDAR:
            for layer in range(self.device.getNumberOfLayers()):
                topics[f"laser_scan/layer{layer}"] = LaserScan
            topics["point_cloud"] = PointCloud2
        elif self.kind == Node.CAMERA:
            topics = {"image": Image}
        return {
            topic: rospy.Publisher(f"{self._prefix}{topic}", kind, queue_size=1)
            for topic, kind in topics.items()
        }

    def publish(self, step: int, stamp: rospy.Time) -> None:
        """Publishes the readings if the sensor sampled at this step and someone listens."""
        if not self._publishers:
            return
        period = self.device.getSamplingPeriod()
        if period <= 0 or (step * self._basic_step) % period != 0:
            return
        frame = self.name
        for topic, publisher in self._publishers.items():
            if publisher.get_num_connections() == 0:
                continue
            message = self._message(topic, stamp, frame)
            if message is not None:
                publisher.publish(message)

    def _message(self, topic: str, stamp: rospy.Time, frame: str) -> Optional[Any]:
        d = self.device
        if self.kind == Node.GPS:
            if topic == "speed":
                return _header(Float64Stamped(data=d.getSpeed()), stamp, frame)
            x, y, z = d.getValues()
            if d.getCoordinateSystem() == GPS.WGS84:
                fix = NavSatFix(latitude=x, longitude=y, altitude=z)
                fix.position_covariance_type = NavSatFix.COVARIANCE_TYPE_UNKNOWN
                return _header(fix, stamp, frame)
            message = PointStamped()
            message.point.x, message.point.y, message.point.z = x, y, z
            return _header(message, stamp, frame)
        if self.kind == Node.INERTIAL_UNIT:
            message = _no_orientation(Imu())
            qx, qy, qz, qw = d.getQuaternion()
            message.orientation.x, message.orientation.y = qx, qy
            message.orientation.z, message.orientation.w = qz, qw
            message.orientation_covariance[0] = 0.0
            return _header(message, stamp, frame)
        if self.kind == Node.GYRO:
            message = _no_orientation(Imu())
            v = message.angular_velocity
            v.x, v.y, v.z = d.getValues()
            message.angular_velocity_covariance[0] = 0.0
            return _header(message, stamp, frame)
        if self.kind == Node.ACCELEROMETER:
            message = _no_orientation(Imu())
            a = message.linear_acceleration
            a.x, a.y, a.z = d.getValues()
            message.linear_acceleration_covariance[0] = 0.0
            return _header(message, stamp, frame)
        if self.kind == Node.COMPASS:
            message = MagneticField()
            f = message.magnetic_field
            f.x, f.y, f.z = d.getValues()
            return _header(message, stamp, frame)
        if self.kind == Node.DISTANCE_SENSOR:
            message = Range(
                range=d.getValue(), min_range=d.getMinValue(), max_range=d.getMaxValue()
            )
            message.field_of_view = d.getAperture()
            message.radiation_type = (
                Range.INFRARED if d.getType() == d.INFRA_RED else Range.ULTRASOUND
            )
            return _header(message, stamp, frame)
        if self.kind == Node.LIDAR:
            if topic == "point_cloud":
                return self._point_cloud(stamp, frame)
            return self._laser_scan(int(topic.rsplit("layer", 1)[1]), stamp, frame)
        if self.kind == Node.CAMERA:
            data = d.getImage()
            if data is None:
                return None
            width, height = d.getWidth(), d.getHeight()
            image = Image(height=height, width=width, encoding="bgra8", is_bigendian=0)
            image.step, image.data = 4 * width, data
            return _header(image, stamp, frame)
        return None

    def _laser_scan(self, layer: int, stamp: rospy.Time, frame: str) -> Optional[LaserScan]:
        d = self.device
        ranges = d.getLayerRangeImage(layer)
        if not ranges:
            return None
        columns = d.getHorizontalResolution()
        fov = d.getFov()
        increment = fov / columns
        # Webots' column 0 is the leftmost ray (at +fov/2 less half a column); a LaserScan goes
        # counter-clockwise from angle_min, so the rightmost column comes first.
        scan = LaserScan(
            angle_min=-fov / 2 + increment / 2,
            angle_max=fov / 2 - increment / 2,
            angle_increment=increment,
            range_min=d.getMinRange(),
            range_max=d.getMaxRange(),
        )
        scan.scan_time = d.getSamplingPeriod() / 1000.0
        scan.ranges = list(reversed(ranges))
        return _header(scan, stamp, frame)

    def _point_cloud(self, stamp: rospy.Time, frame: str) -> Optional[PointCloud2]:
        d = self.device
        if not d.isPointCloudEnabled():
            return None
        data = d.getPointCloud(data_type="buffer")
        count = d.getNumberOfPoints()
        # WbLidarPoint: float x, y, z (m), int layer_id, float time (s): 20 bytes, kept as is.
        fields = [
            PointField(name="x", offset=0, datatype=PointField.FLOAT32, count=1),
            PointField(name="y", offset=4, datatype=PointField.FLOAT32, count=1),
            PointField(name="z", offset=8, datatype=PointField.FLOAT32, count=1),
            PointField(name="layer", offset=12, datatype=PointField.INT32, count=1),
            PointField(name="time", offset=16, datatype=PointField.FLOAT32, count=1),
        ]
        cloud = PointCloud2(height=1, width=count, fields=fields, is_bigendian=False)
        cloud.point_step, cloud.row_step = 20, 20 * count
        # Rays that hit nothing give infinite points (Webots), so the cloud is not dense.
        cloud.data, cloud.is_dense = bytes(data), False
        return _header(cloud, stamp, frame)

    def shutdown(self) -> None:
        """Withdraws the services and topics."""
        for service in self._services:
            service.shutdown()
        for publisher in self._publishers.values():
            publisher.unregister()


class SensorInterface:
    """The generic interface of every device of the robot except the car's own."""

    def __init__(
        self, robot: Any, calls: CarCalls, namespace: str, auto_publish: bool
    ) -> None:
        basic_step = int(robot.getBasicTimeStep())
        self.devices: List[_Device] = []
        for index in range(robot.getNumberOfDevices()):
            device = robot.getDeviceByIndex(index)
            if device is None or device.getName() in HIDDEN_DEVICES:
                continue
            entry = _Device(device, calls, namespace, basic_step)
            self.devices.append(entry)
            if auto_publish and entry.kind in _SAMPLED:
                entry.enable(basic_step)

    def publish(self, step: int, stamp: rospy.Time) -> None:
        """Publishes every enabled sensor that sampled at ``step`` (main thread)."""
        for device in self.devices:
            device.publish(step, stamp)

    def shutdown(self) -> None:
        for device in self.devices:
            device.shutdown()
