"""Webots' ``Display`` and the display library's ``ImageRef``."""

from typing import List, Optional

from webots_vehicle import _native

from ._c import _c_double, _c_int
from .device import Device


class ImageRef:
    """An image held by the display library (Webots: ``ImageRef``)."""

    def __init__(self, handle: int) -> None:
        self._handle = handle


class Display(Device):
    """Webots' ``Display``: an image to draw into (pixels (0, 0) top-left, opaque black at
    first; colour ``0xRRGGBB``, alpha and opacity in [0, 1], blended as Webots does). Text
    draws with a bitmap font whatever the family; no camera attachment; image files are
    PNG."""

    RGB = 3
    RGBA = 4
    ARGB = 5
    BGRA = 6
    ABGR = 7

    def getWidth(self) -> int:
        """Width (px)."""
        return _native.wb_display_get_size(self._tag)[0]

    def getHeight(self) -> int:
        """Height (px)."""
        return _native.wb_display_get_size(self._tag)[1]

    def setColor(self, color: int) -> None:
        """The drawing colour, ``0xRRGGBB``."""
        _native.wb_display_set_color(self._tag, _c_int(color))

    def setAlpha(self, alpha: float) -> None:
        """The alpha of what is drawn (0: transparent)."""
        _native.wb_display_set_alpha(self._tag, _c_double(alpha))

    def setOpacity(self, opacity: float) -> None:
        """The weight of what is drawn against what was there."""
        _native.wb_display_set_opacity(self._tag, _c_double(opacity))

    def drawPixel(self, x: int, y: int) -> None:
        """Draws pixel (x, y)."""
        _native.wb_display_draw(self._tag, "pixel", [_c_int(x), _c_int(y)])

    def drawLine(self, x1: int, y1: int, x2: int, y2: int) -> None:
        """Draws a line (Bresenham)."""
        _native.wb_display_draw(self._tag, "line", [_c_int(v) for v in (x1, y1, x2, y2)])

    def drawRectangle(self, x: int, y: int, width: int, height: int) -> None:
        """Draws a rectangle's outline, top-left (x, y)."""
        _native.wb_display_draw(self._tag, "rectangle", [_c_int(v) for v in (x, y, width, height)])

    def fillRectangle(self, x: int, y: int, width: int, height: int) -> None:
        """Fills a rectangle, top-left (x, y)."""
        _native.wb_display_draw(
            self._tag, "fill_rectangle", [_c_int(v) for v in (x, y, width, height)]
        )

    def drawOval(self, cx: int, cy: int, a: int, b: int) -> None:
        """Draws an ellipse's outline of centre (cx, cy) and radii a, b."""
        _native.wb_display_draw(self._tag, "oval", [_c_int(v) for v in (cx, cy, a, b)])

    def fillOval(self, cx: int, cy: int, a: int, b: int) -> None:
        """Fills an ellipse of centre (cx, cy) and radii a, b."""
        _native.wb_display_draw(self._tag, "fill_oval", [_c_int(v) for v in (cx, cy, a, b)])

    def drawPolygon(self, x: List[int], y: List[int]) -> None:
        """Draws the closed polygon of corners (x[i], y[i])."""
        _native.wb_display_polygon(self._tag, [_c_int(v) for v in x], [_c_int(v) for v in y], False)

    def fillPolygon(self, x: List[int], y: List[int]) -> None:
        """Fills the polygon of corners (x[i], y[i])."""
        _native.wb_display_polygon(self._tag, [_c_int(v) for v in x], [_c_int(v) for v in y], True)

    def setFont(self, font: str, size: int, antiAliasing: bool) -> None:
        """The font of ``drawText``: one of Webots' 13 families (all drawn with the same
        bitmap font), ``size`` the character height (px, > 0); ``antiAliasing`` changes
        nothing on a bitmap font."""
        _native.wb_display_set_font(self._tag, str(font), _c_int(size), bool(antiAliasing))

    def drawText(self, text: str, x: int, y: int) -> None:
        """Draws ``text`` with its top-left corner at (x, y); ``\\n`` starts a new line."""
        _native.wb_display_draw_text(self._tag, str(text), _c_int(x), _c_int(y))

    def imageNew(
        self, data: bytes, format: int, width: Optional[int] = None, height: Optional[int] = None
    ) -> Optional[ImageRef]:
        """An image from ``data`` (``width * height`` pixels of ``format``; without sizes:
        the display's)."""
        w = self.getWidth() if width is None else _c_int(width)
        h = self.getHeight() if height is None else _c_int(height)
        handle = _native.wb_display_image_new(self._tag, w, h, bytes(data), _c_int(format))
        return ImageRef(handle) if handle else None

    def imageCopy(self, x: int, y: int, width: int, height: int) -> Optional[ImageRef]:
        """A copy of a rectangle of the display; None off the display."""
        handle = _native.wb_display_image_copy(
            self._tag, _c_int(x), _c_int(y), _c_int(width), _c_int(height)
        )
        return ImageRef(handle) if handle else None

    def imagePaste(self, ir: ImageRef, x: int, y: int, blend: bool = False) -> None:
        """Pastes ``ir`` with its top-left pixel at (x, y), over what is there by its alpha
        if ``blend``."""
        _native.wb_display_image_paste(self._tag, ir._handle, _c_int(x), _c_int(y), bool(blend))

    def imageSave(self, ir: Optional[ImageRef], filename: str) -> None:
        """Saves ``ir`` (None: the display itself) as a PNG file."""
        _native.wb_display_image_save(self._tag, ir._handle if ir else 0, str(filename))

    def imageLoad(self, filename: str) -> Optional[ImageRef]:
        """The image of a PNG file; None (with Webots' error) if it cannot be read."""
        handle = _native.wb_display_image_load(self._tag, str(filename))
        return ImageRef(handle) if handle else None

    def imageDelete(self, ir: ImageRef) -> None:
        """Frees ``ir``."""
        _native.wb_display_image_delete(self._tag, ir._handle)
