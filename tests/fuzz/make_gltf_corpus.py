#!/usr/bin/env python3
"""Writes the glTF seed corpus of fuzz_gltf into tests/fuzz/corpus/gltf/ (python3 standard library only).

Run it again only when the seeds should change; the files it writes are committed. Every seed is a
valid scene (fuzz_gltf loads each without error) that exercises one part of the loader; the
mutations start from there. External files ("a.bin", "a.png", "sub/a.bin") exist in fuzz_gltf's
folder with the same content as here (makeTriangleBuffer, kPng2x2 in fuzz_gltf.cpp).
"""
import base64
import json
import os
import struct
import zlib

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "gltf")

# The triangle: positions (0,0,0) (1,0,0) (0,1,0) @0, normals (0,0,1) @36, uvs @72, u16 0 1 2 @96.
FLOATS = [0, 0, 0, 1, 0, 0, 0, 1, 0] + [0, 0, 1] * 3 + [0, 0, 1, 0, 0, 1]
TRIANGLE = struct.pack("<24f", *FLOATS) + struct.pack("<4H", 0, 1, 2, 0)
assert len(TRIANGLE) == 104


def png_2x2():
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    rows = b"\x00" + bytes([255, 0, 0, 255, 0, 255, 0, 128]) + b"\x00" + bytes([0, 0, 255, 255, 255, 255, 255, 0])
    ihdr = struct.pack(">IIBBBBB", 2, 2, 8, 6, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")


PNG = png_2x2()
# 4x4 baseline JPEG (oiiotool --nosoftwareattrib --pattern checker ... -o t.jpg), 850 bytes.
JPEG_B64 = (
    "/9j/4AAQSkZJRgABAQAAAQABAAD/2wBDAAEBAQEBAQEBAQEBAQEBAQIBAQEBAQIBAQECAgICAgICAgIDAwQDAwMDAwICAwQDAwQEBAQEAgMFBQQE"
    "BQQEBAT/2wBDAQEBAQEBAQIBAQIEAwIDBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAQEBAT/wAARCAAEAAQD"
    "ASIAAhEBAxEB/8QAHwAAAQUBAQEBAQEAAAAAAAAAAAECAwQFBgcICQoL/8QAtRAAAgEDAwIEAwUFBAQAAAF9AQIDAAQRBRIhMUEGE1FhByJxFDKB"
    "kaEII0KxwRVS0fAkM2JyggkKFhcYGRolJicoKSo0NTY3ODk6Q0RFRkdISUpTVFVWV1hZWmNkZWZnaGlqc3R1dnd4eXqDhIWGh4iJipKTlJWWl5iZ"
    "mqKjpKWmp6ipqrKztLW2t7i5usLDxMXGx8jJytLT1NXW19jZ2uHi4+Tl5ufo6erx8vP09fb3+Pn6/8QAHwEAAwEBAQEBAQEBAQAAAAAAAAECAwQF"
    "BgcICQoL/8QAtREAAgECBAQDBAcFBAQAAQJ3AAECAxEEBSExBhJBUQdhcRMiMoEIFEKRobHBCSMzUvAVYnLRChYkNOEl8RcYGRomJygpKjU2Nzg5"
    "OkNERUZHSElKU1RVVldYWVpjZGVmZ2hpanN0dXZ3eHl6goOEhYaHiImKkpOUlZaXmJmaoqOkpaanqKmqsrO0tba3uLm6wsPExcbHyMnK0tPU1dbX"
    "2Nna4uPk5ebn6Onq8vP09fb3+Pn6/9oADAMBAAIRAxEAPwD+dLwH4D8KfE3wppXjjxxpX9t+KNb8/wDtTVPt1zpv2r7NczWcH7i3kjhXbDbwp8iD"
    "OzJySSSiivkPpY/Sx+lP4W/Sn8S/DLwy8S+IMo4byjiDOcBl+X4DOcxweBwGBweY4nD4TBYLCYfE08PhcJhcPTp0MPh6FOFGhRhClShGEYxX/Xr9"
    "GX6Mv0bvEf6N3h94h+Ifh9keacQZpkeU43HY7G5TgMVjMbjMVgMPXxWLxeKr4epXxOJxNepOtXr1pzq1qs51Kk5Tk2//2Q=="
)


def data_uri(mime, payload):
    return "data:" + mime + ";base64," + base64.b64encode(payload).decode()


def triangle_gltf(buffer_uri=None, index_type=5123, with_normals=True, with_uvs=True):
    """The one-triangle scene over TRIANGLE; buffer_uri None = no uri (GLB BIN chunk)."""
    buffer = {"byteLength": len(TRIANGLE)}
    if buffer_uri is not None:
        buffer["uri"] = buffer_uri
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": 36, "target": 34962},
             {"buffer": 0, "byteOffset": 36, "byteLength": 36, "target": 34962},
             {"buffer": 0, "byteOffset": 72, "byteLength": 24, "target": 34962},
             {"buffer": 0, "byteOffset": 96, "byteLength": 6, "target": 34963}]
    accessors = [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                 {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
                 {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"},
                 {"bufferView": 3, "componentType": index_type, "count": 3, "type": "SCALAR"}]
    attributes = {"POSITION": 0}
    if with_normals:
        attributes["NORMAL"] = 1
    if with_uvs:
        attributes["TEXCOORD_0"] = 2
    return {
        "asset": {"version": "2.0", "generator": "shadowtune make_gltf_corpus.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "translation": [1, 2, 3], "rotation": [0, 0.7071068, 0, 0.7071068], "scale": [2, 2, 2]}],
        "meshes": [{"primitives": [{"attributes": attributes, "indices": 3, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.5, 0.2, 1.0]}}],
        "buffers": [buffer],
        "bufferViews": views,
        "accessors": accessors,
    }


def textured(doc, image):
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    doc["materials"][0].update({"alphaMode": "MASK", "alphaCutoff": 0.4, "doubleSided": True})
    doc["textures"] = [{"source": 0, "sampler": 0}]
    doc["samplers"] = [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 33648}]
    doc["images"] = [image]
    return doc


def glb(doc, bin_chunk):
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    bin_chunk += b"\0" * (-len(bin_chunk) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text
    if bin_chunk:
        body += struct.pack("<II", len(bin_chunk), 0x004E4942) + bin_chunk
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


def write(name, content):
    if isinstance(content, dict):
        content = json.dumps(content, separators=(",", ":")).encode()
    assert len(content) < 20 * 1024, name
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(content)


def main():
    os.makedirs(OUT, exist_ok=True)
    octet = "application/octet-stream"

    # Embedded buffer, u16 indices, TRS node.
    write("triangle-data-uri.gltf", triangle_gltf(data_uri(octet, TRIANGLE)))

    # External buffer and PNG texture; alpha mask, double-sided; a node tree with a matrix and a
    # negative scale (winding flip) around the TRS child.
    doc = textured(triangle_gltf("a.bin"), {"uri": "a.png"})
    doc["nodes"] = [{"children": [1], "matrix": [-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1]},
                    {"mesh": 0, "scale": [1, 1, 1]}]
    write("external-textured.gltf", doc)

    # Buffer one folder down; no normals (flat normals generated) and no uvs; u8 indices in the
    # view that holds the u16 ones (0 1 2 read as bytes 0 0 1: a degenerate but valid triangle).
    doc = triangle_gltf("sub/a.bin", index_type=5121, with_normals=False, with_uvs=False)
    doc["accessors"][3]["count"] = 3
    write("subfolder-flat.gltf", doc)

    # Non-indexed primitive plus an indexed one with u32 indices from its own data: buffer, two
    # materials, an instanced mesh, a default scene with two roots.
    doc = triangle_gltf(data_uri(octet, TRIANGLE))
    doc["buffers"].append({"byteLength": 12, "uri": data_uri(octet, struct.pack("<3I", 2, 1, 0))})
    doc["bufferViews"].append({"buffer": 1, "byteLength": 12})
    doc["accessors"].append({"bufferView": 4, "componentType": 5125, "count": 3, "type": "SCALAR"})
    doc["meshes"][0]["primitives"] = [{"attributes": {"POSITION": 0, "NORMAL": 1}, "material": 1},
                                      {"attributes": {"POSITION": 0}, "indices": 4}]
    doc["materials"].append({"doubleSided": True})
    doc["nodes"].append({"mesh": 0, "translation": [0, 0, -4]})
    doc["scenes"] = [{"nodes": [1]}, {"nodes": [0, 1]}]
    doc["scene"] = 1
    write("multi-primitive.gltf", doc)

    # Embedded PNG and JPEG images, one used by the material; a camera, an unknown extension and a
    # primitive with a sparse accessor (skipped with a warning), which must not fail the load.
    doc = textured(triangle_gltf(data_uri(octet, TRIANGLE)), {"uri": data_uri("image/png", PNG)})
    doc["images"].append({"uri": "data:image/jpeg;base64," + JPEG_B64})
    doc["textures"].append({"source": 1})
    doc["accessors"].append({"componentType": 5126, "count": 3, "type": "VEC2",
                             "sparse": {"count": 1, "indices": {"bufferView": 3, "componentType": 5123},
                                        "values": {"bufferView": 2}}})
    doc["meshes"][0]["primitives"].append({"attributes": {"POSITION": 0, "TEXCOORD_0": 4}})  # skipped: sparse
    doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 1.0, "znear": 0.1}}]
    doc["nodes"][0]["camera"] = 0
    doc["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    write("images-and-extras.gltf", doc)

    # GLB: JSON + BIN chunk, texture from a buffer view of the BIN chunk.
    doc = textured(triangle_gltf(None), {"bufferView": 4, "mimeType": "image/png"})
    bin_chunk = TRIANGLE + PNG
    doc["bufferViews"].append({"buffer": 0, "byteOffset": len(TRIANGLE), "byteLength": len(PNG)})
    doc["buffers"][0]["byteLength"] = len(bin_chunk)
    write("triangle.glb", glb(doc, bin_chunk))

    # GLB without a BIN chunk: the buffer is an external file.
    write("external-buffer.glb", glb(triangle_gltf("a.bin"), b""))

    # KHR_mesh_quantization: normalized u16 positions, i8 normals, node matrix.
    # (x, y, z, pad) u16 per vertex, then (x, y, z, pad) i8 per normal.
    quant = struct.pack("<12H", 0, 0, 0, 0, 65535, 0, 0, 0, 0, 65535, 0, 0) + struct.pack("<4b", 0, 0, 127, 0) * 3
    doc = triangle_gltf(data_uri(octet, quant), with_uvs=False)
    doc["extensionsUsed"] = doc["extensionsRequired"] = ["KHR_mesh_quantization"]
    doc["bufferViews"] = [{"buffer": 0, "byteLength": 24, "byteStride": 8},
                          {"buffer": 0, "byteOffset": 24, "byteLength": 12, "byteStride": 4}]
    doc["accessors"] = [{"bufferView": 0, "componentType": 5123, "normalized": True, "count": 3, "type": "VEC3",
                         "min": [0, 0, 0], "max": [65535, 65535, 0]},
                        {"bufferView": 1, "componentType": 5120, "normalized": True, "count": 3, "type": "VEC3"}]
    doc["meshes"][0]["primitives"][0].pop("indices")
    doc["buffers"][0]["byteLength"] = len(quant)
    doc["nodes"][0] = {"mesh": 0, "matrix": [0.01, 0, 0, 0, 0, 0.01, 0, 0, 0, 0, 0.01, 0, 0, 0, 0, 1]}
    write("quantized.gltf", doc)


if __name__ == "__main__":
    main()
