"""Display values of linear images (matplotlib's imshow, notebooks)."""

import numpy as np


def tonemap(image, exposure=0.0):
    """sRGB display values of a linear image: radiance × 2^exposure, encoded
    with the sRGB transfer function (IEC 61966-2-1) and clipped to [0, 1].
    Returns float32 of the input's shape, the values `write_image` stores in
    a PNG (before its rounding to 8 bits). Non-finite values raise
    ValueError: a render never holds them, so one is a caller's bug."""
    a = np.asarray(image, dtype=np.float32)
    if not np.isfinite(a).all():
        raise ValueError("tonemap: the image holds NaN or infinite values")
    if not np.isfinite(exposure):
        raise ValueError(f"tonemap: exposure must be finite, got {exposure}")
    x = np.clip(a * np.float32(2.0 ** float(exposure)), 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x,
                    1.055 * np.power(x, 1.0 / 2.4, dtype=np.float32) - 0.055).astype(np.float32)
