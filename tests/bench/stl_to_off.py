#!/usr/bin/env python3
"""STL (ASCII or binary) to OFF, merging vertices with identical coordinates (as STL repeats every
corner per facet). Facets with two equal corners are dropped. Used by cad_meshes.sh.
    stl_to_off.py IN.stl OUT.off"""
import struct
import sys


def facets(data):
    """Corner triples, in file order."""
    if len(data) >= 84:
        count = struct.unpack_from('<I', data, 80)[0]
        if 84 + 50 * count == len(data):  # binary: the size says so (ASCII files may start with 'solid' too)
            for i in range(count):
                v = struct.unpack_from('<9f', data, 84 + 50 * i + 12)
                yield (v[0:3], v[3:6], v[6:9])
            return
    corners = []
    for line in data.decode('ascii', 'replace').splitlines():
        t = line.split()
        if t and t[0] == 'vertex':
            corners.append(tuple(float(x) for x in t[1:4]))
            if len(corners) == 3:
                yield tuple(corners)
                corners = []


def main(src, dst):
    index, verts, faces = {}, [], []
    for tri in facets(open(src, 'rb').read()):
        ids = []
        for p in tri:
            if p not in index:
                index[p] = len(verts)
                verts.append(p)
            ids.append(index[p])
        if len(set(ids)) == 3:
            faces.append(ids)
    with open(dst, 'w') as out:
        out.write('OFF\n%d %d 0\n' % (len(verts), len(faces)))
        out.writelines('%.9g %.9g %.9g\n' % p for p in verts)
        out.writelines('3 %d %d %d\n' % tuple(f) for f in faces)


if __name__ == '__main__':
    main(sys.argv[1], sys.argv[2])
