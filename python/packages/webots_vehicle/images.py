"""numpy views of a controller's camera images."""

from typing import Any, Optional

import numpy as np


def camera_image(camera: Any) -> Optional[np.ndarray]:
    """The last image of ``camera`` (a :class:`controller.Camera`) as a read-only numpy array
    of shape ``(height, width, 4)``, dtype ``uint8``, channels B, G, R, A as Webots stores
    them (``image[..., 2::-1]`` gives RGB); None while the camera is disabled (with Webots'
    error on stderr). The array views a copy of the image taken by this call."""
    data = camera.getImage()
    if data is None:
        return None
    return np.frombuffer(data, dtype=np.uint8).reshape(camera.getHeight(), camera.getWidth(), 4)
