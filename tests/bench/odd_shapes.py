#!/usr/bin/env python3
"""Closed synthetic solids of the kinds CAD parts have and the shared meshes lack, as OFF files, for
judging the defaults on them (thin walls, slots, holes far smaller than the automatic length, tiny
inputs, extreme scales) -- with, for each OFF mesh given, copies scaled by 1e-5 and 1e5 and copies
squashed 20 times along x and along z.
    tests/bench/odd_shapes.py OUT_DIR [MESH.off ...]
then, e.g.:
    ../shared/tools/quadcheck/acceptance.sh build/mlstage/bin/meshlabserver \\
        filter_qmorph_front/scripts/closed_mesh_to_quads.mlx /tmp/acc_odd OUT_DIR/*.off
Every solid is a closed 2-manifold, oriented outward."""
import math
import os
import sys


def write_off(path, verts, faces):
    with open(path, 'w') as out:
        out.write('OFF\n%d %d 0\n' % (len(verts), len(faces)))
        out.writelines('%.17g %.17g %.17g\n' % tuple(v) for v in verts)
        out.writelines('3 %d %d %d\n' % tuple(f) for f in faces)


def read_off(path):
    lines = [l for l in open(path).read().split('\n') if l.strip() and not l.startswith('#')]
    tokens = ' '.join(lines[1:]).split()
    nv, nf = int(tokens[0]), int(tokens[1])
    at = 3
    verts, faces = [], []
    for _ in range(nv):
        verts.append([float(x) for x in tokens[at:at + 3]])
        at += 3
    for _ in range(nf):
        n = int(tokens[at])
        faces.append([int(x) for x in tokens[at + 1:at + 1 + n]])
        at += 1 + n
    return verts, faces


def box(sx, sy, sz, n):
    """[0,sx] x [0,sy] x [0,sz], each side an n x n grid of cells cut into two triangles."""
    verts, faces, index = [], [], {}

    def vertex(p):
        key = tuple(round(x, 12) for x in p)
        if key not in index:
            index[key] = len(verts)
            verts.append(p)
        return index[key]

    for axis in range(3):
        u, w = (axis + 1) % 3, (axis + 2) % 3
        for side in (0, 1):
            for i in range(n):
                for j in range(n):
                    quad = []
                    for a, b in ((i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)):
                        p = [0.0] * 3
                        p[axis], p[u], p[w] = side, a / n, b / n
                        quad.append(vertex(p))
                    if side == 0:
                        quad.reverse()
                    faces += [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]]
    return [[v[0] * sx, v[1] * sy, v[2] * sz] for v in verts], faces


def ear_clip(polygon):
    """Triangles of a simple counter-clockwise polygon."""
    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    def inside(p, a, b, c):
        return cross(a, b, p) >= 0 and cross(b, c, p) >= 0 and cross(c, a, p) >= 0

    left, triangles = list(range(len(polygon))), []
    while len(left) > 3:
        for k in range(len(left)):
            i0, i1, i2 = left[k - 1], left[k], left[(k + 1) % len(left)]
            a, b, c = polygon[i0], polygon[i1], polygon[i2]
            if cross(a, b, c) <= 1e-15 or any(inside(polygon[j], a, b, c) for j in left if j not in (i0, i1, i2)):
                continue
            triangles.append((i0, i1, i2))
            left.pop(k)
            break
        else:
            raise ValueError('not a simple counter-clockwise polygon')
    triangles.append(tuple(left))
    return triangles


def extrude(polygon, height, rows=1):
    """A prism over a counter-clockwise polygon: sides in `rows` rows, caps ear-clipped (slivers)."""
    n = len(polygon)
    verts = [[p[0], p[1], height * r / rows] for r in range(rows + 1) for p in polygon]
    faces = []
    for r in range(rows):
        for i in range(n):
            a, b, c, d = r * n + i, r * n + (i + 1) % n, (r + 1) * n + (i + 1) % n, (r + 1) * n + i
            faces += [[a, b, c], [a, c, d]]
    cap = ear_clip(polygon)
    faces += [[t[2], t[1], t[0]] for t in cap]
    faces += [[rows * n + t[0], rows * n + t[1], rows * n + t[2]] for t in cap]
    return verts, faces


def annulus_prism(outer, inner, height, rows=1):
    """A prism over the ring between two loops of equal length (counter-clockwise, point i of one
    facing point i of the other): a tube, or a plate with a hole."""
    n = len(outer)
    verts = []
    for r in range(rows + 1):
        for loop in (outer, inner):
            verts += [[p[0], p[1], height * r / rows] for p in loop]

    def o(r, i):
        return r * 2 * n + i % n

    def q(r, i):
        return r * 2 * n + n + i % n

    faces = []
    for i in range(n):
        faces += [[o(0, i), q(0, i + 1), o(0, i + 1)], [o(0, i), q(0, i), q(0, i + 1)]]
        faces += [[o(rows, i), o(rows, i + 1), q(rows, i + 1)], [o(rows, i), q(rows, i + 1), q(rows, i)]]
        for r in range(rows):
            faces += [[o(r, i), o(r, i + 1), o(r + 1, i + 1)], [o(r, i), o(r + 1, i + 1), o(r + 1, i)]]
            faces += [[q(r, i), q(r + 1, i + 1), q(r, i + 1)], [q(r, i), q(r + 1, i), q(r + 1, i + 1)]]
    return verts, faces


def circle(r, n):
    return [(r * math.cos(2 * math.pi * i / n), r * math.sin(2 * math.pi * i / n)) for i in range(n)]


def square_around(half, n):
    """n points on the square [-half, half]^2, on the rays of circle(1, n) (n a multiple of 8)."""
    points = []
    for c, s in circle(1, n):
        k = half / max(abs(c), abs(s))
        points.append((k * c, k * s))
    return points


def shapes():
    yield 'tetrahedron', ([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    yield 'cube12', box(1, 1, 1, 1)
    yield 'cube432', box(1, 1, 1, 6)
    for t in (0.001, 0.003, 0.007, 0.02):  # thin plates: rims of slivers (1) or of needles (8 x 8)
        for n in (1, 8):
            yield 'plate_t%g_n%d' % (t, n), box(1, 1, t, n)
    yield 'fin', box(1, 0.004, 0.2, 4)
    yield 'coin', extrude(circle(1, 64), 0.005)
    yield 'coin_rows', extrude(circle(1, 64), 0.005, 4)
    bracket = [(0, 0), (1, 0), (1, 0.01), (0.01, 0.01), (0.01, 1), (0, 1)]
    yield 'lbracket', extrude(bracket, 1.0)
    yield 'lbracket_rows', extrude(bracket, 1.0, 8)
    channel = [(0, 0), (1, 0), (1, 0.5), (0.99, 0.5), (0.99, 0.01), (0.01, 0.01), (0.01, 0.5), (0, 0.5)]
    yield 'uchannel', extrude(channel, 2.0, 4)
    yield 'tube', annulus_prism(circle(1, 64), circle(0.98, 64), 2.0, 4)
    for r, name in ((0.1, 'plate_hole'), (0.003, 'plate_tinyhole'), (0.0005, 'plate_pinhole')):
        yield name, annulus_prism(square_around(0.5, 16), circle(r, 16), 0.1)
    slot = [(0, 0), (1, 0), (1, 1), (0.501, 1), (0.501, 0.3), (0.499, 0.3), (0.499, 1), (0, 1)]
    yield 'slot', extrude(slot, 0.3)
    yield 'slot_rows', extrude(slot, 0.3, 6)
    comb = [(0, 0), (1, 0), (1, 1)]
    for k in range(5):
        x = 0.9 - 0.2 * k
        comb += [(x + 0.003, 1), (x + 0.003, 0.2), (x - 0.003, 0.2), (x - 0.003, 1)]
    yield 'comb', extrude(comb + [(0, 1)], 0.2)
    gear = [(r * c, r * s) for i, (c, s) in enumerate(circle(1, 48)) for r in [1.0 if (i // 2) % 2 == 0 else 0.85]]
    yield 'gear', extrude(gear, 0.3)
    big, small = box(1, 1, 1, 4), box(0.05, 0.05, 0.05, 2)  # two components far apart in size
    yield 'two_cubes', (big[0] + [[x + 2 for x in v] for v in small[0]], big[1] + [[i + len(big[0]) for i in f] for f in small[1]])


def main(out, meshes):
    os.makedirs(out, exist_ok=True)
    count = 0
    for name, (verts, faces) in shapes():
        write_off(os.path.join(out, name + '.off'), verts, faces)
        count += 1
    for path in meshes:
        verts, faces = read_off(path)
        name = os.path.splitext(os.path.basename(path))[0]
        for tag, scale in (('tiny', (1e-5,) * 3), ('huge', (1e5,) * 3), ('thin', (0.05, 1, 1)), ('flat', (1, 1, 0.05))):
            write_off(os.path.join(out, '%s_%s.off' % (name, tag)), [[v[i] * scale[i] for i in range(3)] for v in verts], faces)
            count += 1
    print('odd_shapes: %d meshes in %s' % (count, out))


if __name__ == '__main__':
    main(sys.argv[1], sys.argv[2:])
