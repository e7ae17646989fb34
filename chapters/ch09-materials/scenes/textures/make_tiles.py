# Writes tiles.png, the bitmap texture of textured.xml (run with a Python that has mitsuba).
import mitsuba as mi, numpy as np
mi.set_variant('scalar_rgb')
# 8 x 8: a warm-to-cool gradient left to right, darker towards the bottom, with a light cross.
w = h = 8
img = np.zeros((h, w, 3), dtype=np.uint8)
for j in range(h):
    for i in range(w):
        t = i / (w - 1); s = 1 - 0.6 * j / (h - 1)
        r, g, b = (0.9 - 0.7 * t) * s, 0.45 * s, (0.15 + 0.75 * t) * s
        if i == 2 or j == 5:
            r, g, b = 0.95, 0.9, 0.8
        img[j, i] = [int(round(255 * c)) for c in (r, g, b)]
mi.Bitmap(img, pixel_format=mi.Bitmap.PixelFormat.RGB).write(__file__.replace('make_tiles.py', 'tiles.png'))
