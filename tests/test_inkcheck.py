"""tests/inkcheck.py reads cairo's pixels straight off the surface: the same grey, bit for bit, as
writing the PNG and reading it back through PIL (laid on white, converted to "L") — over every
premultiplied value a pixel can hold and a sample of mixed colours."""
from __future__ import annotations

import io

import numpy as np

from inkcheck import _grey


def _through_png(bgra: np.ndarray) -> np.ndarray:
    """The grey levels as the PNG round trip gives them (cairo's write_to_png, PIL's decoder,
    alpha_composite over white, convert("L"))."""
    import cairocffi
    from PIL import Image
    h, w, _ = bgra.shape
    data = bytearray(np.ascontiguousarray(bgra).tobytes())
    surface = cairocffi.ImageSurface.create_for_data(data, cairocffi.FORMAT_ARGB32, w, h, w * 4)
    png = io.BytesIO()
    surface.write_to_png(png)
    im = Image.open(io.BytesIO(png.getvalue())).convert("RGBA")
    white = Image.new("RGBA", im.size, (255, 255, 255, 255))
    white.alpha_composite(im)
    return np.asarray(white.convert("L"))


def test_the_grey_read_off_the_surface_is_the_pngs():
    a, c = np.meshgrid(np.arange(256), np.arange(256), indexing="ij")
    a, c = a[c <= a], c[c <= a]                     # every premultiplied (alpha, channel) pair
    grey = np.stack([c, c, c, a], axis=-1)
    rng = np.random.default_rng(7)
    alpha = rng.integers(0, 256, 20000)
    mixed = np.concatenate([(rng.random((20000, 3)) * (alpha[:, None] + 1)).astype(int).clip(0, alpha[:, None]),
                            alpha[:, None]], axis=1)
    pixels = np.concatenate([grey, mixed]).astype(np.uint8)
    pixels = np.concatenate([pixels, np.zeros((-len(pixels) % 256, 4), np.uint8)]).reshape(-1, 256, 4)
    assert (_grey(pixels) == _through_png(pixels)).all()
