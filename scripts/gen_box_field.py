#!/usr/bin/env python3
"""Writes a glTF field of boxes over a square (the scale series of scripts/bench_scene.sh) and a
preset that looks across it. Generated at benchmark time into a temporary folder, never committed.

  gen_box_field.py OUT_DIR TRIANGLES {one-mesh|nodes} [--field 400] [--camera low|high]

one-mesh: every box in one primitive; nodes: one box mesh placed by one node per box (the loader
flattens nodes to world space). Box positions come from a fixed-seed generator: the same field
every run. The camera looks across the field from its low corner (-x, -z; default) or its high
corner (+x, +z): the clusters' build order runs from the low corner, so the two views draw them
front to back and back to front unless the renderer orders them."""
import argparse, base64, json, os, random, struct

FACES = [  # (normal, four corners of the unit box, counter-clockwise seen from outside)
    ((0, 0, 1), [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]),
    ((0, 0, -1), [(1, 0, 0), (0, 0, 0), (0, 1, 0), (1, 1, 0)]),
    ((1, 0, 0), [(1, 0, 1), (1, 0, 0), (1, 1, 0), (1, 1, 1)]),
    ((-1, 0, 0), [(0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)]),
    ((0, 1, 0), [(0, 1, 1), (1, 1, 1), (1, 1, 0), (0, 1, 0)]),
    ((0, -1, 0), [(0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)]),
]


def box(offset, size):
    pos, nrm, idx = [], [], []
    for n, quad in FACES:
        base = len(pos)
        for c in quad:
            pos.append(tuple(offset[i] + c[i] * size[i] for i in range(3)))
            nrm.append(n)
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, idx


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("triangles", type=int)
    ap.add_argument("layout", choices=["one-mesh", "nodes"])
    ap.add_argument("--field", type=float, default=400.0)
    ap.add_argument("--camera", choices=["low", "high"], default="low")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    boxes = max(1, a.triangles // 12)
    rng = random.Random(11)
    half = a.field / 2
    places = []
    for _ in range(boxes):
        size = (rng.uniform(0.5, 2.0), rng.uniform(0.5, 4.0), rng.uniform(0.5, 2.0))
        places.append(((rng.uniform(-half, half - 2), 0.0, rng.uniform(-half, half - 2)), size))
    if a.layout == "one-mesh":
        pos, nrm, idx = [], [], []
        for off, size in places:
            p, n, i = box(off, size)
            idx += [k + len(pos) for k in i]
            pos += p
            nrm += n
        nodes = [{"mesh": 0}]
    else:
        pos, nrm, idx = box((0, 0, 0), (1, 1, 1))
        nodes = [{"mesh": 0, "translation": list(off), "scale": list(size)} for off, size in places]
    blob = b"".join(struct.pack("<3f", *p) for p in pos) + b"".join(struct.pack("<3f", *n) for n in nrm)
    ioff = len(blob)
    blob += struct.pack("<%dI" % len(idx), *idx)
    name = "field_%d_%s" % (a.triangles, a.layout)
    preset_name = name if a.camera == "low" else name + "_high"
    with open(os.path.join(a.out, name + ".bin"), "wb") as f:
        f.write(blob)
    lo = [min(p[i] for p in pos) for i in range(3)]
    hi = [max(p[i] for p in pos) for i in range(3)]
    nv = len(pos)
    gltf = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.7, 0.65, 1.0]}}],
        "buffers": [{"uri": name + ".bin", "byteLength": len(blob)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 12 * nv},
            {"buffer": 0, "byteOffset": 12 * nv, "byteLength": 12 * nv},
            {"buffer": 0, "byteOffset": ioff, "byteLength": 4 * len(idx)},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": nv, "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5126, "count": nv, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5125, "count": len(idx), "type": "SCALAR"},
        ],
    }
    with open(os.path.join(a.out, name + ".gltf"), "w") as f:
        json.dump(gltf, f)
    corner = -half - 5 if a.camera == "low" else half + 5
    preset = {
        "version": 1,
        "scene": name + ".gltf",
        "ground": True,
        "camera": {"position": [corner, 12.0, corner], "target": [0.0, 0.0, 0.0], "fovY": 60.0,
                   "nearPlane": 0.3, "farPlane": a.field * 1.6},
        "light": {"azimuth": 220.0, "elevation": 35.0},
        "cascades": {"count": 4, "mapSize": 2048, "fit": "sphere", "stabilize": True},
        "output": {"width": 1280, "height": 720},
    }
    with open(os.path.join(a.out, preset_name + ".json"), "w") as f:
        json.dump(preset, f, indent=1)
    print(os.path.join(a.out, preset_name + ".json"))


if __name__ == "__main__":
    main()
