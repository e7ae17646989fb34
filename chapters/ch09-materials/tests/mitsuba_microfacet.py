"""Mitsuba 3's own values of a BSDF, for the test `mitsuba_microfacet`.

Reads from stdin a JSON list of cases, each {"bsdf": <a dictionary for mi.load_dict>,
"pairs": [[wo, wi], ...]} with directions in the local frame (z the normal), wo towards where
the path came from (Mitsuba's si.wi) and wi towards the light (Mitsuba's wo). Writes to stdout
a JSON list with, per case, a list of [r, g, b, pdf]: bsdf.eval (f cos) and bsdf.pdf, in
radiance mode, with the scalar_rgb variant.

A case may also hold "albedo_from": [wo, ...] and "samples": N; then its entry is
{"values": [...], "albedo": [[mean r, g, b, standard error r, g, b], ...]}: the mean weight
of N samples of bsdf.sample from each wo (numbers from a fixed-seed generator), which is
Mitsuba's own estimate of the albedo its sampling delivers.
"""

import json
import random
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


def albedo(case):
    bsdf = mi.load_dict(case["bsdf"])
    ctx = mi.BSDFContext()
    rng = random.Random(7)
    n = case["samples"]
    out = []
    for wo in case["albedo_from"]:
        si = mi.SurfaceInteraction3f()
        si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
        si.n = mi.Normal3f(0, 0, 1)
        si.wi = mi.Vector3f(*wo)
        total = [0.0, 0.0, 0.0]
        squares = [0.0, 0.0, 0.0]
        for _ in range(n):
            sample2 = mi.Point2f(rng.random(), rng.random())
            _, weight = bsdf.sample(ctx, si, rng.random(), sample2)
            for c in range(3):
                w = float(weight[c])
                total[c] += w
                squares[c] += w * w
        mean = [t / n for t in total]
        error = [max(q / n - m * m, 0.0) ** 0.5 / n**0.5 for q, m in zip(squares, mean)]
        out.append(mean + error)
    return out


def main():
    cases = json.load(sys.stdin)
    out = []
    for c in cases:
        if "albedo_from" in c:
            out.append({"values": values(c), "albedo": albedo(c)})
        else:
            out.append(values(c))
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main()
