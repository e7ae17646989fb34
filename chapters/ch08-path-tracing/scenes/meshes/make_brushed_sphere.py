#!/usr/bin/env python3
"""Writes brushed-sphere.obj: a unit sphere of 24 x 12 quads (split into triangles) with a
normal and texture coordinates at every vertex, its u running along the meridians (from pole
to pole) and v around them. An anisotropic material on it is brushed along u, so a renderer
that takes the tangent from the texture coordinates, as Mitsuba does, brushes it from pole to
pole; one that takes it from the triangles' first edges (which run along the parallels) or
from the normal alone brushes it otherwise. Run from this folder."""
import math

SEGMENTS, RINGS = 24, 12
lines = ["# A unit sphere of %d x %d quads, u along the meridians (make_brushed_sphere.py)"
         % (SEGMENTS, RINGS)]
index = {}
for ring in range(RINGS + 1):
    theta = math.pi * ring / RINGS
    for segment in range(SEGMENTS + 1):
        phi = 2 * math.pi * segment / SEGMENTS
        x, y, z = math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)
        index[ring, segment] = len(index) + 1
        lines.append("v %.6f %.6f %.6f" % (x, y, z))
        lines.append("vn %.6f %.6f %.6f" % (x, y, z))
        lines.append("vt %.6f %.6f" % (ring / RINGS, segment / SEGMENTS))
for ring in range(RINGS):
    for segment in range(SEGMENTS):
        a, b = index[ring, segment], index[ring, segment + 1]
        c, d = index[ring + 1, segment + 1], index[ring + 1, segment]
        # Counter-clockwise seen from outside.
        if ring > 0:
            lines.append("f %d/%d/%d %d/%d/%d %d/%d/%d" % (a, a, a, b, b, b, c, c, c))
        if ring < RINGS - 1:
            lines.append("f %d/%d/%d %d/%d/%d %d/%d/%d" % (a, a, a, c, c, c, d, d, d))
with open("brushed-sphere.obj", "w") as f:
    f.write("\n".join(lines) + "\n")
