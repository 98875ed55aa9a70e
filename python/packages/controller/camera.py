"""Webots' ``Camera`` and its Recognition's ``CameraRecognitionObject``."""

from typing import List, Optional

from webots_vehicle import _native

from ._c import _c_int
from .device import Device


class CameraRecognitionObject:
    """An object a camera's Recognition reports (Webots: ``CameraRecognitionObject``):
    positions and sizes in m in the camera frame (x forward, y left, z up), the orientation as
    axis-angle ``[x, y, z, angle]`` (rad), image values in pixels from the top-left corner."""

    def __init__(self, fields: tuple) -> None:  # type: ignore[type-arg]
        (
            self._id,
            self._position,
            self._orientation,
            self._size,
            self._position_on_image,
            self._size_on_image,
            self._colors,
            self._model,
        ) = fields

    def getId(self) -> int:
        """The object's id."""
        return self._id

    def getPosition(self) -> List[float]:
        """Its centre (m, camera frame)."""
        return list(self._position)

    def getOrientation(self) -> List[float]:
        """Its orientation relative to the camera, ``[x, y, z, angle]``."""
        return list(self._orientation)

    def getSize(self) -> List[float]:
        """Its extent along the camera's y and z (m)."""
        return list(self._size)

    def getPositionOnImage(self) -> List[int]:
        """The centre of its rectangle on the image (px)."""
        return list(self._position_on_image)

    def getSizeOnImage(self) -> List[int]:
        """The width and height of its rectangle on the image (px)."""
        return list(self._size_on_image)

    def getNumberOfColors(self) -> int:
        """How many recognition colours it has."""
        return len(self._colors)

    def getColors(self) -> List[float]:
        """Its recognition colours, flat: ``[r, g, b]`` after ``[r, g, b]``."""
        return [c for rgb in self._colors for c in rgb]

    def getModel(self) -> str:
        """Its ``model``."""
        return self._model

    def __repr__(self) -> str:
        return f"CameraRecognitionObject(id={self._id}, position={self._position})"


class Camera(Device):
    """Webots' ``Camera``: a BGRA image of the world through a planar pinhole, rendered by
    the engine (the world's boxes, ramps, cars, robots and ground), and its Recognition."""

    def enable(self, samplingPeriod: int) -> None:
        """Renders every ``samplingPeriod`` ms; the first image comes one period later."""
        _native.wb_camera_enable(self._tag, _c_int(samplingPeriod))

    def disable(self) -> None:
        """Stops rendering."""
        _native.wb_camera_enable(self._tag, 0)

    def getSamplingPeriod(self) -> int:
        """The sampling period (ms), 0 when disabled."""
        return _native.wb_camera_get_sampling_period(self._tag)

    def getImage(self) -> Optional[bytes]:
        """The last image: BGRA bytes, row-major from the top-left (``None``, with Webots'
        error, while disabled)."""
        return _native.wb_camera_get_image(self._tag)

    def getImageArray(self) -> Optional[List[List[List[int]]]]:
        """The last image as ``[x][y][r, g, b]`` (Webots' layout: column first)."""
        image = self.getImage()
        if image is None:
            return None
        w, h = self.getWidth(), self.getHeight()
        return [
            [
                [image[4 * (y * w + x) + 2], image[4 * (y * w + x) + 1], image[4 * (y * w + x)]]
                for y in range(h)
            ]
            for x in range(w)
        ]

    def getWidth(self) -> int:
        """The image width (px)."""
        return _native.wb_camera_get_size(self._tag)[0]

    def getHeight(self) -> int:
        """The image height (px)."""
        return _native.wb_camera_get_size(self._tag)[1]

    def getFov(self) -> float:
        """The horizontal field of view (rad)."""
        return _native.wb_camera_get_optics(self._tag)[0]

    def getMinFov(self) -> float:
        """The smallest field of view (rad): the field of view, there being no Zoom."""
        return _native.wb_camera_get_optics(self._tag)[1]

    def getMaxFov(self) -> float:
        """The largest field of view (rad): the field of view, there being no Zoom."""
        return _native.wb_camera_get_optics(self._tag)[2]

    def getNear(self) -> float:
        """The near plane (m)."""
        return _native.wb_camera_get_optics(self._tag)[3]

    def saveImage(self, filename: str, quality: int) -> int:
        """Saves the last image as a PNG file (``quality`` is for JPEG, not written here):
        0, or -1 with Webots' error."""
        return _native.wb_camera_save_image(self._tag, str(filename), _c_int(quality))

    def hasRecognition(self) -> bool:
        """True if the camera has a Recognition node."""
        return _native.wb_camera_has_recognition(self._tag)

    def recognitionEnable(self, samplingPeriod: int) -> None:
        """Recognises objects every ``samplingPeriod`` ms."""
        _native.wb_camera_recognition_enable(self._tag, _c_int(samplingPeriod))

    def recognitionDisable(self) -> None:
        """Stops recognising."""
        _native.wb_camera_recognition_enable(self._tag, 0)

    def getRecognitionSamplingPeriod(self) -> int:
        """Recognition's sampling period (ms), 0 when disabled."""
        return _native.wb_camera_recognition_get_sampling_period(self._tag)

    def getRecognitionNumberOfObjects(self) -> int:
        """How many objects the last Recognition sample found."""
        return _native.wb_camera_recognition_get_number_of_objects(self._tag)

    def getRecognitionObjects(self) -> List[CameraRecognitionObject]:
        """The objects of the last Recognition sample."""
        return [
            CameraRecognitionObject(o)
            for o in _native.wb_camera_recognition_get_objects(self._tag)
        ]

    def hasRecognitionSegmentation(self) -> bool:
        """False: no segmentation image is rendered."""
        return _native.wb_camera_recognition_has_segmentation(self._tag)

    @staticmethod
    def imageGetRed(image: bytes, width: int, x: int, y: int) -> int:
        """The red channel of pixel (x, y) of a BGRA image ``width`` pixels wide."""
        return image[4 * (y * width + x) + 2]

    @staticmethod
    def imageGetGreen(image: bytes, width: int, x: int, y: int) -> int:
        """The green channel of pixel (x, y)."""
        return image[4 * (y * width + x) + 1]

    @staticmethod
    def imageGetBlue(image: bytes, width: int, x: int, y: int) -> int:
        """The blue channel of pixel (x, y)."""
        return image[4 * (y * width + x)]

    @staticmethod
    def imageGetGray(image: bytes, width: int, x: int, y: int) -> int:
        """The mean of the three channels of pixel (x, y), truncated."""
        k = 4 * (y * width + x)
        return (image[k] + image[k + 1] + image[k + 2]) // 3

    imageGetGrey = imageGetGray
