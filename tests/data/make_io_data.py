#!/usr/bin/env python3
"""Writes the small STL, .binvox and .vxm files that tests/unit/io/malformed_test.cpp checks (and that
scripts/fuzz.sh uses as seeds): tests/data/malformed/ holds files every reader must refuse with a clear message,
tests/data/quirks/ holds valid files in unusual shapes that must load.

The .vxm files are written here from docs/file-format.md, independently of src/io/vxm.cpp, so the test
also checks that the document and the code agree. Run from anywhere; the output is deterministic.
"""
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
BAD = os.path.join(HERE, "malformed")
OK = os.path.join(HERE, "quirks")


def write(folder, name, data):
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


# ---- STL ----

TRI = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]


def binary_stl(tris, declared=None, header=b"voxmod test data"):
    out = header.ljust(80, b" ")[:80]
    out += struct.pack("<I", len(tris) if declared is None else declared)
    for t in tris:
        out += struct.pack("<3f", 0.0, 0.0, 1.0)
        for v in t:
            out += struct.pack("<3f", *v)
        out += b"\0\0"
    return out


def facet(v, normal="facet normal 0 0 1"):
    lines = [normal, "  outer loop"] + ["    vertex %s %s %s" % p for p in v] + ["  endloop", "endfacet"]
    return "\n".join(lines) + "\n"


V = [("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0")]

write(BAD, "empty.stl", b"")
write(BAD, "binary_truncated.stl", binary_stl([TRI] * 12)[: 84 + 50 * 5])
write(BAD, "not_stl_ply.stl", b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      b"property float y\nproperty float z\nend_header\n" + b"\0" * 36)
write(BAD, "not_stl_text.stl", "this is a text file with more than eighty-four bytes in it, but it is not an STL.\n" * 2)
write(BAD, "binary_zero_triangles.stl", binary_stl([]))
write(BAD, "binary_nan.stl", binary_stl([TRI, [(0.0, 0.0, 0.0), (float("nan"), 0.0, 0.0), (0.0, 1.0, 0.0)]]))
write(BAD, "binary_inf.stl", binary_stl([TRI, TRI, [(0.0, 0.0, float("inf")), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]]))
write(BAD, "binary_solid_header_truncated.stl", binary_stl([TRI] * 4, header=b"solid part")[:-20])
write(BAD, "too_short.stl", b"hello")
write(BAD, "ascii_nan.stl", "solid t\n" + facet([("0", "0", "0"), ("nan", "0", "0"), ("0", "1", "0")]) + "endsolid t\n")
write(BAD, "ascii_inf.stl", "solid t\n" + facet(V) + facet([("0", "0", "0"), ("1", "0", "-inf"), ("0", "1", "0")])
      + "endsolid t\n")
write(BAD, "ascii_out_of_range.stl", "solid t\n" + facet([("0", "0", "0"), ("1e39", "0", "0"), ("0", "1", "0")])
      + "endsolid t\n")
write(BAD, "ascii_bad_token.stl", "solid t\n" + facet([("0", "0", "0"), ("1", "0", "0"), ("0", "1x", "0")])
      + "endsolid t\n")
write(BAD, "ascii_missing_endloop.stl", "solid t\n" + facet(V).replace("  endloop\n", "") + "endsolid t\n")
write(BAD, "ascii_two_vertices.stl", "solid t\n" + facet(V[:2]) + "endsolid t\n")
write(BAD, "ascii_truncated.stl", ("solid t\n" + facet(V) + facet(V))[:-40])
# Cut in the middle of the last vertex's coordinate, as a download that stopped would leave it.
write(BAD, "ascii_cut_in_number.stl", "solid t\n" + facet(V) + facet([("-1.291420e+00", "0", "0")] + V[1:]).split("e+00")[0] + "e")
write(BAD, "ascii_no_triangles.stl", "solid empty\nendsolid empty\n")
write(BAD, "ascii_garbage_after_endsolid.stl", "solid t\n" + facet(V) + "endsolid t\nfacet\n")

# Valid files in shapes that real exporters write.
write(OK, "ascii_missing_normal.stl", "solid t\n" + facet(V, normal="facet") + "endsolid t\n")
write(OK, "ascii_zero_normal.stl", "solid t\n" + facet(V, normal="facet normal 0 0 0") + "endsolid t\n")
write(OK, "ascii_multiple_solids.stl", "solid a\n" + facet(V) + "endsolid a\nsolid b\n"
      + facet([("0", "0", "1"), ("1", "0", "1"), ("0", "1", "1")]) + "endsolid b\n")
write(OK, "ascii_crlf_exponents_bare_endsolid.stl",
      ("solid cad\r\n   facet normal 0.000000e+000 0.000000e+000 1.000000e+000\r\n      outer loop\r\n"
       "         vertex 0.000000e+000 0.000000e+000 0.000000e+000\r\n"
       "         vertex 1.000000e+000 0.000000e+000 0.000000e+000\r\n"
       "         vertex 0.000000e+000 2.500000e-001 +1.0E+002\r\n"
       "      endloop\r\n   endfacet\r\nendsolid").encode())
write(OK, "ascii_uppercase_tabs.stl", "SOLID T\n\tFACET NORMAL 0 0 1\n\t\tOUTER LOOP\n\t\t\tVERTEX 0 0 0\n"
      "\t\t\tVERTEX 1 0 0\n\t\t\tVERTEX 0 1 0\n\t\tENDLOOP\n\tENDFACET\nENDSOLID T")
write(OK, "ascii_degenerate.stl", "solid t\n" + facet(V) + facet([("0", "0", "0"), ("1", "0", "0"), ("2", "0", "0")])
      + "endsolid t\n")
write(OK, "binary_extra_bytes.stl", binary_stl([TRI] * 3, declared=2))
write(OK, "ascii_one_line.stl", "solid one line " + (facet(V) * 2).replace("\n", " ") + "endsolid one line")
write(OK, "binary_solid_header.stl", binary_stl([TRI, TRI], header=b"solid part exported by a CAD tool"))

# ---- .binvox (docs/conventions.md, ".binvox"; docs/file-format.md) ----


def binvox(dim, runs, header_extra="translate 0.5 -1 2\nscale 4\n", magic="#binvox 1\n"):
    head = magic + "dim %s\n" % dim + header_extra + "data\n"
    return head.encode() + bytes(b for r in runs for b in r)


# 4^3 = 64 voxels: 10 empty, 5 filled, 49 empty.
RUNS = [(0, 10), (1, 5), (0, 49)]
write(OK, "cuda_voxelizer_style.binvox", binvox("4 4 4", RUNS, header_extra=""))
write(OK, "crlf_header.binvox", binvox("4 4 4", RUNS).replace(b"\n", b"\r\n", 4))
write(BAD, "binvox_truncated.binvox", binvox("4 4 4", [(0, 10), (1, 5), (0, 40)]))
write(BAD, "binvox_odd_length.binvox", binvox("4 4 4", RUNS) + b"\0")
write(BAD, "binvox_overrun.binvox", binvox("4 4 4", RUNS + [(1, 2)]))
write(BAD, "binvox_bad_value.binvox", binvox("4 4 4", [(0, 10), (2, 5), (0, 49)]))
write(BAD, "binvox_version2.binvox", binvox("4 4 4", RUNS, magic="#binvox 2\n"))
write(BAD, "binvox_no_data.binvox", b"#binvox 1\ndim 4 4 4\ntranslate 0 0 0\nscale 1\n")
write(BAD, "binvox_no_dim.binvox", binvox("", RUNS).replace(b"dim \n", b""))
write(BAD, "binvox_huge_dim.binvox", binvox("20000 20000 20000", RUNS))
write(BAD, "binvox_not_binvox.binvox", b"P6\n4 4\n255\n")
write(BAD, "binvox_zero_run.binvox", binvox("4 4 4", [(0, 10), (1, 0)] + RUNS[1:] + [(0, 0)]))
write(BAD, "binvox_not_utf8_header.binvox", binvox("4 4 4", RUNS, header_extra="\xff\xfe\x01 data\n")
      .replace(b"\xc3\xbf\xc3\xbe", b"\xff\xfe"))

# ---- .vxm (docs/file-format.md) ----

VXM_MAGIC = b"\x89VXM\r\n\x1a\n"


def varint(n):
    out = b""
    while n >= 0x80:
        out += bytes([(n & 0x7F) | 0x80])
        n >>= 7
    return out + bytes([n])


def vxm(dims, runs, origin=(1.0, 2.0, 3.0), h=0.25, units="mm", source="part.stl", version=1,
        filled=None, nruns=None):
    body = b"".join(varint(r) for r in runs)
    if filled is None:
        filled = sum(runs[1::2])
    u, s = units.encode(), source.encode()
    header_size = 84 + 2 + len(u) + 2 + len(s) + 4
    head = VXM_MAGIC + struct.pack("<II", version, header_size) + struct.pack("<3I", *dims)
    head += struct.pack("<4d", *origin, h)
    head += struct.pack("<QQQ", filled, len(runs) if nruns is None else nruns, len(body))
    head += struct.pack("<H", len(u)) + u + struct.pack("<H", len(s)) + s
    head += struct.pack("<I", zlib.crc32(head))
    data = head + body
    return data + struct.pack("<I", zlib.crc32(data))


# 3 x 2 x 2 grid, x fastest: voxels 1, 2 and 7..11 filled.
SAMPLE_RUNS = [1, 2, 4, 5]
sample = vxm((3, 2, 2), SAMPLE_RUNS)
write(OK, "sample.vxm", sample)
write(BAD, "vxm_bad_magic.vxm", b"\x89VXN" + sample[4:])
write(BAD, "vxm_newer_version.vxm", vxm((3, 2, 2), SAMPLE_RUNS, version=3))
write(BAD, "vxm_truncated.vxm", sample[:-3])
flipped = bytearray(sample)
flipped[len(sample) - 6] ^= 0x01  # a body byte
write(BAD, "vxm_crc_mismatch.vxm", bytes(flipped))
flipped = bytearray(sample)
flipped[30] ^= 0x40  # inside the origin: the header CRC catches it
write(BAD, "vxm_header_corrupt.vxm", bytes(flipped))
write(BAD, "vxm_runs_short.vxm", vxm((3, 2, 2), [1, 2, 4, 4]))
write(BAD, "vxm_runs_long.vxm", vxm((3, 2, 2), [1, 2, 4, 6]))
write(BAD, "vxm_zero_run.vxm", vxm((3, 2, 2), [1, 2, 0, 4, 5]))
write(BAD, "vxm_filled_mismatch.vxm", vxm((3, 2, 2), SAMPLE_RUNS, filled=9))
write(BAD, "vxm_huge_dims.vxm", vxm((16384, 16384, 16384), [0, 16384 ** 3]))  # all filled: 512 GiB
write(BAD, "vxm_dims_too_large.vxm", vxm((20000, 1, 1), [20000]))
write(BAD, "vxm_zero_voxel_size.vxm", vxm((3, 2, 2), SAMPLE_RUNS, h=0.0))

# ---- Mesh and CAD formats read through loadMeshFile (docs/file-format.md, "Mesh and CAD input") ----
# tests/data/mesh/ holds a unit cube in every format assimp reads for voxmod (tests/unit/io/mesh_file_test.cpp, and
# scripts/fuzz.sh's seeds); tests/data/malformed/ the files each of those readers must refuse.

MESH = os.path.join(HERE, "mesh")
os.makedirs(MESH, exist_ok=True)
CUBE_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]  # outward
CUBE_TRIS = [t for q in CUBE_QUADS for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def ply_header(fmt, vertices, faces):
    return ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
            "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (fmt, vertices, faces))


def ply_binary(vertices, faces, declared_vertices=None):
    out = ply_header("binary_little_endian", declared_vertices or len(vertices), len(faces)).encode()
    out += b"".join(struct.pack("<3f", *v) for v in vertices)
    return out + b"".join(struct.pack("<B", len(f)) + struct.pack("<%di" % len(f), *f) for f in faces)


def zip_bytes(entries):
    import io
    import zipfile
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in entries:
            z.writestr(zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0)), data)
    return buf.getvalue()


def three_mf(unit, target="/3D/3dmodel.model"):
    verts = "".join('<vertex x="%d" y="%d" z="%d"/>' % v for v in CUBE_V)
    tris = "".join('<triangle v1="%d" v2="%d" v3="%d"/>' % t for t in CUBE_TRIS)
    model = ('<?xml version="1.0" encoding="UTF-8"?>\n<model unit="%s" xml:lang="en-US" '
             'xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02"><resources>'
             '<object id="1" name="cube" type="model"><mesh><vertices>%s</vertices><triangles>%s</triangles>'
             '</mesh></object></resources><build><item objectid="1"/></build></model>\n' % (unit, verts, tris))
    types = ('<?xml version="1.0" encoding="UTF-8"?>\n<Types xmlns="http://schemas.openxmlformats.org/package/2006/'
             'content-types"><Default Extension="rels" ContentType="application/vnd.openxmlformats-package.'
             'relationships+xml"/><Default Extension="model" ContentType="application/vnd.ms-package.'
             '3dmanufacturing-3dmodel+xml"/></Types>\n')
    rels = ('<?xml version="1.0" encoding="UTF-8"?>\n<Relationships xmlns="http://schemas.openxmlformats.org/package/'
            '2006/relationships"><Relationship Target="%s" Id="rel0" '
            'Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>\n' % target)
    return zip_bytes([("[Content_Types].xml", types), ("_rels/.rels", rels), ("3D/3dmodel.model", model)])


def gltf_parts():
    import json
    positions = b"".join(struct.pack("<3f", *v) for v in CUBE_V)
    indices = b"".join(struct.pack("<3H", *t) for t in CUBE_TRIS)
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "cube"}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
           "buffers": [{"byteLength": len(positions) + len(indices)}],
           "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                           {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices)}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
                          "min": [0, 0, 0], "max": [1, 1, 1]},
                         {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"}]}
    return doc, positions + indices


def gltf_embedded():
    import base64
    import json
    doc, data = gltf_parts()
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    return json.dumps(doc, indent=1) + "\n"


def glb():
    import json
    doc, data = gltf_parts()
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    data += b"\0" * (-len(data) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(data), 0x004E4942) + data
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


write(MESH, "cube.obj", "# unit cube\n" + "".join("v %d %d %d\n" % v for v in CUBE_V)
      + "".join("f %d %d %d %d\n" % tuple(i + 1 for i in q) for q in CUBE_QUADS))
write(MESH, "cube_ascii.ply", ply_header("ascii", 8, 6) + "".join("%d %d %d\n" % v for v in CUBE_V)
      + "".join("4 %d %d %d %d\n" % q for q in CUBE_QUADS))
write(MESH, "cube_binary.ply", ply_binary(CUBE_V, CUBE_QUADS))
write(MESH, "cube.off", "OFF\n8 6 0\n" + "".join("%d %d %d\n" % v for v in CUBE_V)
      + "".join("4 %d %d %d %d\n" % q for q in CUBE_QUADS))
write(MESH, "cube_micron.3mf", three_mf("micron"))  # 1 micron: read as 0.001 mm
write(MESH, "cube.gltf", gltf_embedded())
write(MESH, "cube.glb", glb())

write(BAD, "empty.obj", b"")
write(BAD, "obj_comments_only.obj", "# exported by nothing at all\n# no vertex, no face: nothing to voxelize here\n")
write(BAD, "ply_lying_counts.ply", ply_header("ascii", 9, 6) + "".join("%d %d %d\n" % v for v in CUBE_V)
      + "".join("4 %d %d %d %d\n" % q for q in CUBE_QUADS))
write(BAD, "ply_binary_truncated.ply", ply_binary(CUBE_V, CUBE_QUADS)[:-9])
write(BAD, "ply_bad_index.ply", ply_binary(CUBE_V, CUBE_QUADS[:5] + [(3, 0, 4, 8)]))
# A .glb whose JSON is cut short, its binary chunk a 3MF package whose relationship names a part it does not hold:
# neither glTF importer recognises it, and assimp's 3MF importer, tried next by signature, aborts on such a package.
def glb_chunks(text, data):
    text += b" " * (-len(text) % 4)
    data += b"\0" * (-len(data) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(data), 0x004E4942) + data
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


write(BAD, "glb_then_zip.glb", glb_chunks(b'{"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]',
                                          three_mf("millimeter", target="/3D/missing.model")))
# A .glb whose JSON chunk claims 4 GB: assimp would allocate that before comparing it with the file.
GLB_TOO_LONG = bytearray(glb())
struct.pack_into("<I", GLB_TOO_LONG, 12, 0xFFF00000)
write(BAD, "glb_chunk_too_long.glb", bytes(GLB_TOO_LONG))
# A .gltf cut short in the middle of its JSON (a download that stopped), and one whose index accessor points past
# the buffer views: JSON that parses, a document that does not hold together.
write(BAD, "gltf_truncated.gltf", gltf_embedded()[:400])
GLTF_BAD_VIEW, _ = gltf_parts()
GLTF_BAD_VIEW["accessors"][1]["bufferView"] = 7
write(BAD, "gltf_bad_buffer_view.gltf", json.dumps(GLTF_BAD_VIEW) + "\n")
write(BAD, "not_zip.3mf", '<?xml version="1.0"?>\n<model unit="millimeter"></model>\n')
write(BAD, "zip_without_model.3mf", zip_bytes([("[Content_Types].xml", "<Types/>\n")]))
STEP_START = ("ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('a truncated file'),'2;1');\n"
              "FILE_NAME('cut.step','2024-01-01T00:00:00',(''),(''),'','','');\n"
              "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n"
              "#1=CARTESIAN_POINT('',(0.,0.,0.));\n#2=DIRECTION('',(0.,0.,1.));\n")
write(BAD, "truncated.step", STEP_START)
write(BAD, "step_named.ply", STEP_START + "ENDSEC;\nEND-ISO-10303-21;\n")
IGES_START = ("a truncated IGES file".ljust(72) + "S      1\n"
              + "1H,,1H;,,,,,,,,,,,,,,,,,,,,,,,,,,,,,;".ljust(72) + "G      1\n")
write(BAD, "truncated.iges", IGES_START)
write(BAD, "off_bad_index.off", "OFF\n8 6 0\n" + "".join("%d %d %d\n" % v for v in CUBE_V)
      + "".join("4 %d %d %d %d\n" % q for q in CUBE_QUADS[:5]) + "4 3 0 4 8\n")
# Comment lines among the faces: assimp reads each as a face without corners and takes one off its face count for
# it; more of them than faces and the count wraps around (a crash).
write(BAD, "off_comment_among_faces.off", "OFF\n8 6 0\n" + "".join("%d %d %d\n" % v for v in CUBE_V)
      + "".join("4 %d %d %d %d\n" % q for q in CUBE_QUADS[:3]) + "# a comment\n" * 7
      + "".join("4 %d %d %d %d\n" % q for q in CUBE_QUADS[3:]))
write(BAD, "off_not_numbers.off", "OFF\n3 1 0\n0 0 0\n1 0 0&1\n0 1 0\n3 0 1 2\n")
