#!/usr/bin/env python3
"""Writes the unit spheres of 24 x 12 quads (split into triangles) the chapter's scenes use.
Run from this folder.

- coarse-sphere.obj: a normal at every vertex, so that a renderer that shades with the
  interpolated normals shows it round and one that uses the facets' own normals shows it cut.
- brushed-sphere.obj: texture coordinates as well, u running along the meridians (from pole
  to pole) and v around them. An anisotropic material on it is brushed along u, so a renderer
  that takes the tangent from the texture coordinates, as Mitsuba does, brushes it from pole
  to pole; one that takes it from the triangles' first edges (which run along the parallels)
  or from the normal alone brushes it otherwise."""
import math

SEGMENTS, RINGS = 24, 12


def sphere(header, with_uv):
    lines = [header]
    index = {}
    for ring in range(RINGS + 1):
        theta = math.pi * ring / RINGS
        for segment in range(SEGMENTS + 1):
            phi = 2 * math.pi * segment / SEGMENTS
            x, y, z = math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)
            index[ring, segment] = len(index) + 1
            lines.append("v %.6f %.6f %.6f" % (x, y, z))
            lines.append("vn %.6f %.6f %.6f" % (x, y, z))
            if with_uv:
                lines.append("vt %.6f %.6f" % (ring / RINGS, segment / SEGMENTS))
    corner = "%d/%d/%d" if with_uv else "%d//%d"
    face = "f " + " ".join([corner] * 3)
    for ring in range(RINGS):
        for segment in range(SEGMENTS):
            a, b = index[ring, segment], index[ring, segment + 1]
            c, d = index[ring + 1, segment + 1], index[ring + 1, segment]
            # Counter-clockwise seen from outside.
            for triangle, wanted in (((a, b, c), ring > 0), ((a, c, d), ring < RINGS - 1)):
                if wanted:
                    numbers = [i for v in triangle for i in ([v] * (3 if with_uv else 2))]
                    lines.append(face % tuple(numbers))
    return "\n".join(lines) + "\n"


with open("coarse-sphere.obj", "w") as f:
    f.write(sphere("# A unit sphere of %d x %d quads with vertex normals (make_sphere.py)"
                   % (SEGMENTS, RINGS), False))
with open("brushed-sphere.obj", "w") as f:
    f.write(sphere("# A unit sphere of %d x %d quads, u along the meridians (make_sphere.py)"
                   % (SEGMENTS, RINGS), True))
