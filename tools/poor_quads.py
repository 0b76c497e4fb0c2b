#!/usr/bin/env python3
"""Where the quads below 0.3 scaled Jacobian sit in an output of the pipeline.

Reads the binary PLY that meshlabserver writes with `-m fq fc` (acceptance.sh's outputs): quads
are triangle pairs sharing a faux edge (face flag bits 18-20), front edges are selected face-edges
(bits 15-17). Prints how many poor quads have 0-4 corners on the front, and for those with all
four on it (no node may move there) how thin they are (shortest side / longest).

    tools/poor_quads.py OUT/block.ply
"""
import collections
import math
import struct
import sys

FACE_EDGE_SELECTED_BIT, FAUX_BIT = 15, 18  # vcg's FaceEdgeS and faux flags, edge k at bit + k
FAIR_QUAD = 0.3

TYPES = {'char': 'b', 'uchar': 'B', 'short': 'h', 'ushort': 'H', 'int': 'i', 'uint': 'I', 'float': 'f', 'double': 'd'}


def read_ply(path):
    data = open(path, 'rb').read()
    end = data.index(b'end_header\n') + len(b'end_header\n')
    elements = []
    for line in data[:end].decode().splitlines():
        words = line.split()
        if words[:1] == ['format'] and words[1] != 'binary_little_endian':
            sys.exit('binary little-endian PLY expected')
        if words[:1] == ['element']:
            elements.append((words[1], int(words[2]), []))
        elif words[:1] == ['property']:
            elements[-1][2].append(words[1:])
    offset, out = end, {}
    for name, count, props in elements:
        rows = []
        for _ in range(count):
            row = {}
            for p in props:
                if p[0] == 'list':
                    (n,) = struct.unpack_from('<' + TYPES[p[1]], data, offset)
                    offset += struct.calcsize(TYPES[p[1]])
                    row[p[3]] = struct.unpack_from('<%d%s' % (n, TYPES[p[2]]), data, offset)
                    offset += n * struct.calcsize(TYPES[p[2]])
                else:
                    (row[p[1]],) = struct.unpack_from('<' + TYPES[p[0]], data, offset)
                    offset += struct.calcsize(TYPES[p[0]])
            rows.append(row)
        out[name] = rows
    return out


def sub(p, q): return [p[i] - q[i] for i in range(3)]
def cross(u, w): return [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
def dot(u, w): return sum(u[i] * w[i] for i in range(3))
def norm(u): return math.sqrt(dot(u, u))


def main(path):
    ply = read_ply(path)
    points = [(v['x'], v['y'], v['z']) for v in ply['vertex']]
    faces = [(f['vertex_indices'], f['flags']) for f in ply['face']]
    front, open_faux, quads = set(), {}, []
    for i, (f, flags) in enumerate(faces):
        for k in range(3):
            a, b = f[k], f[(k + 1) % 3]
            if flags >> (FACE_EDGE_SELECTED_BIT + k) & 1:
                front.update((a, b))
            if flags >> (FAUX_BIT + k) & 1:  # the quad's diagonal: pair the two triangles
                key = (min(a, b), max(a, b))
                if key in open_faux:
                    other = faces[open_faux.pop(key)][0]
                    opposite = [v for v in other if v not in (a, b)][0]
                    quads.append((f[(k + 2) % 3], a, opposite, b))
                else:
                    open_faux[key] = i
    on_front, thin = collections.Counter(), collections.Counter()
    for q in quads:
        p = [points[v] for v in q]
        n = [0.0, 0.0, 0.0]
        for k in range(4):
            n = [n[i] + cross(p[k], p[(k + 1) % 4])[i] for i in range(3)]
        length = norm(n) or 1.0
        n = [x / length for x in n]
        jacobian = min(dot(cross(sub(p[(k + 1) % 4], p[k]), sub(p[(k + 3) % 4], p[k])), n) /
                       (norm(sub(p[(k + 1) % 4], p[k])) * norm(sub(p[(k + 3) % 4], p[k])) or 1.0) for k in range(4))
        if jacobian >= FAIR_QUAD:
            continue
        corners = sum(v in front for v in q)
        on_front[corners] += 1
        if corners == 4:
            sides = [norm(sub(p[(k + 1) % 4], p[k])) for k in range(4)]
            thin[round(min(sides) / max(sides), 1)] += 1
    print('%s: %d quads, %d below %.1f' % (path, len(quads), sum(on_front.values()), FAIR_QUAD))
    for corners in sorted(on_front):
        print('  with %d corners on the front: %d' % (corners, on_front[corners]))
    print('  all four on the front, by shortest / longest side:', dict(sorted(thin.items())))


if __name__ == '__main__':
    main(sys.argv[1])
