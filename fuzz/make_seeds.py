#!/usr/bin/env python3
"""Writes the small seed files of fuzz/seeds/ from the shared samples in data/ (first points of
data/velodyne_pair/fast_gicp_251370668.pcd and data/kitti00_pair/000000.xyz32.bin). The TUM and
OXTS seeds are hand-made (data/ has no such file). Run from the repository root."""
import struct

HEADER_END = b"DATA binary\n"


def velodyne_points(n):
    raw = open("data/velodyne_pair/fast_gicp_251370668.pcd", "rb").read()
    body = raw[raw.index(HEADER_END) + len(HEADER_END):]
    return [struct.unpack_from("<4f", body, 16 * i) for i in range(n)]


def pcd_header(n, data):
    return ("# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z intensity\n"
            "SIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\nWIDTH %d\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
            "POINTS %d\nDATA %s\n" % (n, n, data)).encode()


def lzf_literals(data):  # a valid LZF stream made of literal runs only (≤ 32 bytes each)
    out = bytearray()
    for i in range(0, len(data), 32):
        chunk = data[i:i + 32]
        out.append(len(chunk) - 1)
        out += chunk
    return bytes(out)


pts = velodyne_points(12)
binary = b"".join(struct.pack("<4f", *p) for p in pts)
open("fuzz/seeds/binary.pcd", "wb").write(pcd_header(len(pts), "binary") + binary)
text = "".join("%.6g %.6g %.6g %.6g\n" % p for p in pts)
open("fuzz/seeds/ascii.pcd", "wb").write(pcd_header(len(pts), "ascii") + text.encode())
soa = b"".join(struct.pack("<%df" % len(pts), *[p[k] for p in pts]) for k in range(4))
packed = lzf_literals(soa)
open("fuzz/seeds/binary_compressed.pcd", "wb").write(
    pcd_header(len(pts), "binary_compressed") + struct.pack("<II", len(packed), len(soa)) + packed)
ply = ("ply\nformat %s 1.0\ncomment from data/velodyne_pair\nelement vertex %d\nproperty float x\n"
       "property float y\nproperty float z\nproperty float intensity\nelement face 1\n"
       "property list uchar int vertex_indices\nend_header\n")
open("fuzz/seeds/ascii.ply", "wb").write((ply % ("ascii", len(pts))).encode() + text.encode() + b"3 0 1 2\n")
open("fuzz/seeds/binary.ply", "wb").write((ply % ("binary_little_endian", len(pts))).encode() + binary +
                                          struct.pack("<B3i", 3, 0, 1, 2))
open("fuzz/seeds/points.csv", "w").write("x,y,z,intensity\n" + text.replace(" ", ","))
open("fuzz/seeds/small.bin", "wb").write(binary)
kitti = open("data/kitti00_pair/000000.xyz32.bin", "rb").read()[:12 * 12]
open("fuzz/seeds/small.xyz32.bin", "wb").write(kitti)
open("fuzz/seeds/small.3d", "w").write("".join(open("data/uos_3dtk/scan000.3d").readlines()[:13]))
open("fuzz/seeds/tum.txt", "w").write("# timestamp tx ty tz qx qy qz qw\n0.0 0 0 0 0 0 0 1\n"
                                     "0.1 0.5 0.01 0 0 0 0.0499792 0.99875\n")
open("fuzz/seeds/oxts.txt", "w").write(
    "49.015003823272 8.4342971002335 116.43032836914 0.035752 0.00903 -2.6087069803847 -7.2694536005 "
    "-3.5394727142 -8.0287893 0.41268 -0.056599 0.10116 -0.39082 9.8146 0.057289 -0.11466 9.8229 "
    "-0.0079283 0.0043634 -0.0036047 -0.0077437 0.0051617 -0.0035022 0.49194 0.2 4 10 4 4 0\n")
