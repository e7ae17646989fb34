#!/usr/bin/env python3
"""Writes coarse-sphere.obj: a unit sphere of 24 x 12 quads (split into triangles) with a
normal at every vertex, so that a renderer that shades with the interpolated normals shows
it round and one that uses the facets' own normals shows it cut. Run from this folder."""
import math

SEGMENTS, RINGS = 24, 12
lines = ["# A unit sphere of %d x %d quads with vertex normals (make_sphere.py)" % (SEGMENTS, RINGS)]
index = {}
for ring in range(RINGS + 1):
    theta = math.pi * ring / RINGS
    for segment in range(SEGMENTS + 1):
        phi = 2 * math.pi * segment / SEGMENTS
        x, y, z = math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)
        index[ring, segment] = len(index) + 1
        lines.append("v %.6f %.6f %.6f" % (x, y, z))
        lines.append("vn %.6f %.6f %.6f" % (x, y, z))
for ring in range(RINGS):
    for segment in range(SEGMENTS):
        a, b = index[ring, segment], index[ring, segment + 1]
        c, d = index[ring + 1, segment + 1], index[ring + 1, segment]
        # Counter-clockwise seen from outside.
        if ring > 0:
            lines.append("f %d//%d %d//%d %d//%d" % (a, a, b, b, c, c))
        if ring < RINGS - 1:
            lines.append("f %d//%d %d//%d %d//%d" % (a, a, c, c, d, d))
with open("coarse-sphere.obj", "w") as f:
    f.write("\n".join(lines) + "\n")
