#!/usr/bin/env python3
"""Writes cube.gltf: a unit cube (24 vertices with face normals, 12 triangles) in one embedded
base64 buffer, under a node that scales it by 10 and lifts it by 5 along glTF's +y (up), so it
stands on its origin as a 10 m box. The loader test checks that transform."""
import base64, json, pathlib, struct

faces = [  # normal, then two in-face axes u, v with u x v = normal (counter-clockwise outside)
    ((1, 0, 0), (0, 1, 0), (0, 0, 1)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
    ((0, 1, 0), (0, 0, 1), (1, 0, 0)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
    ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (0, 1, 0), (1, 0, 0))]
positions, normals, indices = [], [], []
for n, u, v in faces:
    first = len(positions)
    for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
        positions.append(tuple(0.5 * (n[i] + su * u[i] + sv * v[i]) for i in range(3)))
        normals.append(n)
    indices += [first, first + 1, first + 2, first, first + 2, first + 3]

blob = b"".join(struct.pack("<3f", *p) for p in positions)
blob += b"".join(struct.pack("<3f", *n) for n in normals)
blob += struct.pack(f"<{len(indices)}H", *indices)
vertex_bytes = 12 * len(positions)
gltf = {
    "asset": {"version": "2.0", "generator": "aerial examples/scenes/make_cube_gltf.py"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"name": "cube", "mesh": 0, "translation": [0, 5, 0], "scale": [10, 10, 10]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2,
                                "material": 0}]}],
    "materials": [{"name": "terracotta",
                   "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.25, 0.12, 1.0]}}],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
         "min": [-0.5] * 3, "max": [0.5] * 3},
        {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
        {"bufferView": 2, "componentType": 5123, "count": len(indices), "type": "SCALAR"}],
    "bufferViews": [
        {"buffer": 0, "byteOffset": 0, "byteLength": vertex_bytes, "target": 34962},
        {"buffer": 0, "byteOffset": vertex_bytes, "byteLength": vertex_bytes, "target": 34962},
        {"buffer": 0, "byteOffset": 2 * vertex_bytes, "byteLength": 2 * len(indices),
         "target": 34963}],
    "buffers": [{"byteLength": len(blob),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
}
out = pathlib.Path(__file__).with_name("cube.gltf")
out.write_text(json.dumps(gltf, indent=1) + "\n")
