#!/usr/bin/env python3
"""Writes the small STL, .binvox and .vxm files that tests/unit/io/malformed_test.cpp checks (and that
scripts/fuzz.sh uses as seeds): tests/data/malformed/ holds files every reader must refuse with a clear message,
tests/data/quirks/ holds valid files in unusual shapes that must load.

The .vxm files are written here from docs/file-format.md, independently of src/io/vxm.cpp, so the test
also checks that the document and the code agree. Run from anywhere; the output is deterministic.
"""
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
