"""Writes, for each PLY and .serialized file in a directory, what Mitsuba 3 loads from it, as the
JSON files that `mitsuba_reads_the_same_meshes_when_its_dumps_are_present` compares with the
workbook's readers.

    VENV/bin/python mitsuba_mesh_dump.py MESH_DIR DUMP_DIR [SHAPES_PER_SERIALIZED]
    MITSUBA_MESH_DUMPS=DUMP_DIR cargo test -p common --lib mitsuba_reads -- --nocapture

VENV is a virtual environment with Mitsuba 3 (see the shared Mitsuba setup). Every mesh of a
.serialized file is dumped, up to SHAPES_PER_SERIALIZED (default 8) or the first index Mitsuba
refuses.
"""

import json
import os
import sys

import mitsuba as mi

mi.set_variant("scalar_rgb")


def dump(kind, path, shape_index):
    props = {"type": kind, "filename": path}
    if kind == "serialized":
        props["shape_index"] = shape_index
    params = mi.traverse(mi.load_dict(props))

    def flat(key):
        return [float(x) for x in params[key]] if key in params else []

    return {
        "file": path,
        "kind": kind,
        "shape_index": shape_index,
        "positions": flat("vertex_positions"),
        "faces": [int(x) for x in params["faces"]],
        "normals": flat("vertex_normals"),
        "uvs": flat("vertex_texcoords"),
    }


def main():
    source, target = sys.argv[1], sys.argv[2]
    most = int(sys.argv[3]) if len(sys.argv) > 3 else 8
    os.makedirs(target, exist_ok=True)
    for name in sorted(os.listdir(source)):
        path = os.path.abspath(os.path.join(source, name))
        kind = os.path.splitext(name)[1].lstrip(".")
        if kind not in ("ply", "serialized"):
            continue
        for shape_index in range(most if kind == "serialized" else 1):
            try:
                record = dump(kind, path, shape_index)
            except Exception as error:  # Mitsuba refuses: no such mesh, or a broken file
                if shape_index == 0:
                    print(f"Mitsuba cannot load {name}: {error}", file=sys.stderr)
                break
            with open(os.path.join(target, f"{name}.{shape_index}.json"), "w") as out:
                json.dump(record, out)
            print(name, shape_index, len(record["positions"]) // 3, "vertices")


if __name__ == "__main__":
    main()
