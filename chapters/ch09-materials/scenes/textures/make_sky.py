# Writes sky.hdr, the environment map of envmap.xml (run with a Python that has mitsuba).
import mitsuba as mi, numpy as np
mi.set_variant('scalar_rgb')
# 64 x 32 in latitude-longitude: a blue sky paling to the horizon over brown ground, and a
# small sun (a Gaussian about one pixel wide, peak 200) at u = 0.3, 35 degrees above the horizon.
w, h = 64, 32
img = np.zeros((h, w, 3), dtype=np.float32)
zenith, horizon, ground = np.array([0.2, 0.4, 0.9]), np.array([0.95, 0.9, 0.85]), np.array([0.2, 0.15, 0.1])
sun_u, sun_theta = 0.3, np.radians(55.0)
for j in range(h):
    theta = np.pi * j / (h - 1)  # Mitsuba's rows: the first at the north pole, the last at the south
    for i in range(w):
        u = (i + 0.5) / w
        if theta < np.pi / 2:
            t = np.cos(theta) ** 0.5
            c = (1 - t) * horizon + t * zenith
        else:
            c = ground
        # Angle to the sun, on the sphere.
        d = np.array([np.sin(2 * np.pi * u) * np.sin(theta), np.cos(theta), -np.cos(2 * np.pi * u) * np.sin(theta)])
        s = np.array([np.sin(2 * np.pi * sun_u) * np.sin(sun_theta), np.cos(sun_theta), -np.cos(2 * np.pi * sun_u) * np.sin(sun_theta)])
        angle = np.arccos(np.clip(d @ s, -1, 1))
        c = c + 200.0 * np.exp(-0.5 * (angle / np.radians(5.0)) ** 2) * np.array([1.0, 0.9, 0.75])
        img[j, i] = c
mi.Bitmap(img, pixel_format=mi.Bitmap.PixelFormat.RGB).write(__file__.replace('make_sky.py', 'sky.hdr'))
