# Writes spots.hdr, the radiance of the glowing panel of textured-light.xml (run with a Python
# that has mitsuba). 64 x 64: a dim warm background (0.05) with two bright patches, a warm
# square (12, 10.8, 8.4) and a cool band (7.2, 9.6, 12), which hold nearly all the panel's light
# on a tenth of its area: a panel sampled by area spends most of its samples in the dark.
import mitsuba as mi, numpy as np
mi.set_variant('scalar_rgb')
img = np.full((64, 64, 3), 0.05, dtype=np.float32)
img[10:22, 8:20] = [12.0, 10.8, 8.4]
img[40:50, 36:60] = [7.2, 9.6, 12.0]
mi.Bitmap(img, pixel_format=mi.Bitmap.PixelFormat.RGB).write(__file__.replace('make_spots.py', 'spots.hdr'))
