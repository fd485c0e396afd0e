#!/usr/bin/env python3
"""Writes the seed inputs of the scan fuzz targets (fuzz/corpus/scan_*/): for each format a small
sound volume (a 10^3 ball of 16-bit values) and the kinds of broken header a reliability probe
found crashing VTK's readers. Run once when the seeds change: python3 fuzz/make_scan_seeds.py"""
import gzip
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
N = 10


def ball():
    values = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                r = math.dist((i, j, k), ((N - 1) / 2,) * 3)
                values.append(max(0, min(300, int(100 * (4 - r)))))
    return struct.pack("<%dH" % len(values), *values)


def nifti(datatype=512, bitpix=16, rank=3, nt=1):
    h = bytearray(352)
    struct.pack_into("<i", h, 0, 348)
    struct.pack_into("<8h", h, 40, rank, N, N, N, nt, 1, 1, 1)
    struct.pack_into("<hh", h, 70, datatype, bitpix)
    struct.pack_into("<8f", h, 76, *([1.0] * 8))
    struct.pack_into("<ff", h, 108, 352.0, 1.0)
    h[344:348] = b"n+1\0"
    return bytes(h)


def element(group, elem, vr, value):
    head = struct.pack("<HH", group, elem) + vr.encode()
    if vr in ("OW", "OB"):
        return head + b"\0\0" + struct.pack("<I", len(value)) + value
    return head + struct.pack("<H", len(value)) + value


def dicom_slice(z, rows=N, columns=N, pixels=None):
    meta = element(2, 0x10, "UI", b"1.2.840.10008.1.2.1\0")
    body = b"".join([
        element(0x18, 0x50, "DS", b"1 "), element(0x20, 0x13, "IS", b"%d " % z),
        element(0x20, 0x32, "DS", b"0\\0\\%d " % z), element(0x28, 2, "US", struct.pack("<H", 1)),
        element(0x28, 0x10, "US", struct.pack("<H", rows)),
        element(0x28, 0x11, "US", struct.pack("<H", columns)),
        element(0x28, 0x30, "DS", b"1\\1 "), element(0x28, 0x100, "US", struct.pack("<H", 16)),
        element(0x28, 0x101, "US", struct.pack("<H", 16)),
        element(0x28, 0x103, "US", struct.pack("<H", 0))])
    data = pixels if pixels is not None else ball()[z * N * N * 2:(z + 1) * N * N * 2]
    return (b"\0" * 128 + b"DICM" + element(2, 0, "UL", struct.pack("<I", len(meta))) + meta +
            body + element(0x7FE0, 0x10, "OW", data))


def write(target, name, data):
    folder = os.path.join(HERE, "corpus", target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def main():
    raw = ball()
    nrrd = b"NRRD0004\ntype: ushort\nencoding: %s\nendian: little\ndimension: %s\nsizes: %s\n\n"
    write("scan_nrrd", "ball.nrrd", nrrd % (b"raw", b"3", b"10 10 10") + raw)
    write("scan_nrrd", "ball-gzip.nrrd", nrrd % (b"gzip", b"3", b"10 10 10") + gzip.compress(raw))
    write("scan_nrrd", "dimension-5.nrrd", nrrd % (b"raw", b"5", b"1 10 10 10 1") + raw)
    write("scan_nrrd", "negative-size.nrrd", nrrd % (b"raw", b"3", b"-10 10 10") + raw)
    meta = b"ObjectType = Image\nNDims = %s\nDimSize = %s\nElementType = MET_USHORT\n%sElementDataFile = LOCAL\n"
    write("scan_mha", "ball.mha", meta % (b"3", b"10 10 10", b"") + raw)
    write("scan_mha", "ndims-4.mha", meta % (b"4", b"10 10 10 1", b"") + raw)
    packed = zlib.compress(raw)
    write("scan_mha", "compressed.mha", meta % (b"3", b"10 10 10", b"CompressedData = True\n"
                                                b"CompressedDataSize = %d\n" % len(packed)) + packed)
    write("scan_nii", "ball.nii", nifti() + raw)
    write("scan_nii", "datatype-4242.nii", nifti(4242) + raw)
    write("scan_nii_gz", "ball.nii.gz", gzip.compress(nifti() + raw))
    write("scan_vtk", "ball.vtk", b"# vtk DataFile Version 3.0\nball\nBINARY\nDATASET STRUCTURED_POINTS\n"
          b"DIMENSIONS 10 10 10\nSPACING 1 1 1\nORIGIN 0 0 0\nPOINT_DATA 1000\n"
          b"SCALARS v unsigned_short 1\nLOOKUP_TABLE default\n" + struct.pack(">1000H", *struct.unpack("<1000H", raw)))
    write("scan_dicom", "series", b"LUCENTSLICE".join(dicom_slice(z) for z in range(4)))
    write("scan_dicom", "rows-65535", b"LUCENTSLICE".join(
        dicom_slice(z, rows=65535 if z == 2 else N) for z in range(4)))


main()
