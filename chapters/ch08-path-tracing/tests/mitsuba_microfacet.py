"""Mitsuba 3's own values of a BSDF, for the test `mitsuba_microfacet`.

Reads from stdin a JSON list of cases, each {"bsdf": <a dictionary for mi.load_dict>,
"pairs": [[wo, wi], ...]} with directions in the local frame (z the normal), wo towards where
the path came from (Mitsuba's si.wi) and wi towards the light (Mitsuba's wo). Writes to stdout
a JSON list with, per case, a list of [r, g, b, pdf]: bsdf.eval (f cos) and bsdf.pdf, in
radiance mode, with the scalar_rgb variant.
"""

import json
import sys

import mitsuba as mi

mi.set_variant("scalar_rgb")


def values(case):
    bsdf = mi.load_dict(case["bsdf"])
    ctx = mi.BSDFContext()
    out = []
    for wo, wi in case["pairs"]:
        si = mi.SurfaceInteraction3f()
        si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
        si.n = mi.Normal3f(0, 0, 1)
        si.wi = mi.Vector3f(*wo)
        light = mi.Vector3f(*wi)
        f = bsdf.eval(ctx, si, light)
        p = bsdf.pdf(ctx, si, light)
        out.append([float(f[0]), float(f[1]), float(f[2]), float(p)])
    return out


def main():
    cases = json.load(sys.stdin)
    json.dump([values(c) for c in cases], sys.stdout)


if __name__ == "__main__":
    main()
