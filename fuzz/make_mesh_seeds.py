#!/usr/bin/env python3
"""Writes the seed corpus of mesh_fuzzer (fuzz/corpus/mesh_fuzzer/): small
meshes in each format the readers take, with the features they handle (OBJ
polygons, negative and slashed indices, groups; glTF data URIs, node
transforms, strips, fans, lines; GLB with normals and texture coordinates),
and the broken files of tests/mesh_io_test.cpp. Small on purpose: libFuzzer
mutates faster and reaches as much code as with the 100 KB samples of
models/meshes/. Run from anywhere; rewrites the folder's files."""
import base64, json, os, struct

out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "mesh_fuzzer")
os.makedirs(out, exist_ok=True)

def write(name, data):
    with open(os.path.join(out, name), "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)

corners = [(v & 1, v >> 1 & 1, v >> 2 & 1) for v in range(8)]
cube = [1, 3, 7, 1, 7, 5, 0, 4, 6, 0, 6, 2, 2, 6, 7, 2, 7, 3, 0, 1, 5, 0, 5, 4,
        4, 5, 7, 4, 7, 6, 0, 2, 3, 0, 3, 1]

# OBJ
obj = "mtllib missing.mtl\no cube\n" + "".join("v %d %d %d\n" % c for c in corners)
obj += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
obj += ("f 2/1/1 4/2/1 8/3/1 6/4/1\nf 1/1/1 5/2/1 7/3/1 3/4/1\nf 3/1/1 7/2/1 8/3/1 4/4/1\n"
        "f 1 2 6 5\ng top\nf 5/1 6/2 8/3 7/4\nf -8 -6 -5 -7\nl 1 2\n")
write("cube_quads.obj", obj)
write("pentagon.obj", "v 0 0 0\nv 1 0 0\nv 1.5 1 0\nv 0.5 1.5 0\nv -0.5 1 0\nf 1 2 3 4 5\n")
write("fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n")
good = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
write("sheet.obj", good + "f 1 2 3\n")
write("lines.obj", good + "l 1 2 3\np 1\n")
write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n")
write("range.obj", good + "f 1 2 9\n")
write("back.obj", good + "f 1 2 -4\n")
write("zero.obj", good + "f 0 1 2\n")
write("collapsed.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n")

# glTF with a data URI: positions (float VEC3) then indices (uint16).
def gltf_json(floats, indices, rest, uri=True, extra_bin=b""):
    blob = struct.pack("<%df" % len(floats), *floats) + struct.pack("<%dH" % len(indices), *indices)
    while len(blob) % 4:
        blob += b"\0"
    buf = {"byteLength": len(blob)}
    if uri:
        buf["uri"] = "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
    doc = {"asset": {"version": "2.0"}, "buffers": [buf],
           "bufferViews": [{"buffer": 0, "byteLength": len(floats) * 4},
                           {"buffer": 0, "byteOffset": len(floats) * 4, "byteLength": len(indices) * 2}]}
    doc.update(rest)
    return doc, blob

flat = [c for v in corners for c in v]
idx = cube + [0, 1, 2, 3, 0, 1, 3, 2]
rest = {
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 8},
        {"bufferView": 1, "componentType": 5123, "type": "SCALAR", "count": 36},
        {"bufferView": 1, "byteOffset": 72, "componentType": 5123, "type": "SCALAR", "count": 4},
        {"bufferView": 1, "byteOffset": 80, "componentType": 5123, "type": "SCALAR", "count": 4}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1},
                               {"attributes": {"POSITION": 0}, "indices": 1, "mode": 1}]},
               {"primitives": [{"attributes": {"POSITION": 0}, "indices": 2, "mode": 5}]},
               {"primitives": [{"attributes": {"POSITION": 0}, "indices": 3, "mode": 6}]}],
    "nodes": [{"scale": [-2, 2, 2], "mesh": 0, "children": [1]},
              {"translation": [10, 0, 0], "mesh": 1, "children": [2]},
              {"mesh": 2}, {"mesh": 0, "rotation": [0, 0.7071068, 0, 0.7071068]}],
    "scenes": [{"nodes": [3]}, {"nodes": [0]}], "scene": 1}
doc, _ = gltf_json(flat, idx, rest)
write("nodes_strips_fans.gltf", json.dumps(doc))
simple = {"accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 8},
                        {"bufferView": 1, "componentType": 5123, "type": "SCALAR", "count": 36}],
          "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
          "nodes": [{"mesh": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}],
          "scenes": [{"nodes": [0]}]}
doc, _ = gltf_json(flat, cube, simple)
write("cube.gltf", json.dumps(doc))
cycle = dict(simple, nodes=[{"mesh": 0, "children": [1]}, {"children": [0]}])
doc, _ = gltf_json(flat, cube, cycle)
write("cycle.gltf", json.dumps(doc))
draco = dict(simple, extensionsUsed=["KHR_draco_mesh_compression"],
             extensionsRequired=["KHR_draco_mesh_compression"])
doc, _ = gltf_json(flat, cube, draco)
write("draco.gltf", json.dumps(doc))

# GLB: the cube with normals and texture coordinates in the binary chunk,
# uint32 indices, placed by a rotated, scaled node.
pos = struct.pack("<24f", *flat)
nrm = struct.pack("<24f", *([0, 0, 1] * 8))
uv = struct.pack("<16f", *([0.5, 0.5] * 8))
ind = struct.pack("<36I", *cube)
blob = pos + nrm + uv + ind
views, off = [], 0
for part in (pos, nrm, uv, ind):
    views.append({"buffer": 0, "byteOffset": off, "byteLength": len(part)})
    off += len(part)
doc = {"asset": {"version": "2.0"}, "buffers": [{"byteLength": len(blob)}], "bufferViews": views,
       "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 8,
                      "min": [0, 0, 0], "max": [1, 1, 1]},
                     {"bufferView": 1, "componentType": 5126, "type": "VEC3", "count": 8},
                     {"bufferView": 2, "componentType": 5126, "type": "VEC2", "count": 8},
                     {"bufferView": 3, "componentType": 5125, "type": "SCALAR", "count": 36}],
       "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                   "indices": 3}]}],
       "nodes": [{"mesh": 0, "rotation": [0.7071068, 0, 0, 0.7071068], "scale": [2, 2, 2]}],
       "scenes": [{"nodes": [0]}], "scene": 0}
js = json.dumps(doc).encode()
while len(js) % 4:
    js += b" "
glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(js) + 8 + len(blob))
glb += struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(blob), b"BIN\0") + blob
write("cube.glb", glb)
write("cube_cut.glb", glb[: len(glb) // 2])
write("header.glb", glb[:12])
