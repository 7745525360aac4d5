#!/usr/bin/python3
"""Writes the collision meshes of the unit-block types of urdf/bricks.urdf.

Caroline Pratt's wooden unit blocks that are not boxes or cylinders: the half
circle, the triangle, the ramp and the crown of the small arch (the arch is
not convex, so its crown is cut into pieces that are, between the vertices of
its opening). Each mesh is an ASCII STL in metres, already in its type's
frame (centred on the type's bounding box, lying flat), so the URDF gives it
no <origin>. Standard library only: it must run with Debian's /usr/bin/python3.

Usage: scripts/make_unit_block_meshes.py [output directory]
       (default: meshes/unit_blocks next to this script's directory)
"""

import math
import os
import sys

INCH = 0.0254  # [m], exact by definition

# Sizes of the unit-block system [m]: the unit is 5.5 x 2.75 x 1.375 in.
UNIT = 5.5 * INCH
WIDTH = 2.75 * INCH
THICK = 1.375 * INCH

HALF_CIRCLE_SEGMENTS = 32  # over the half circle's arc
ARCH_OPENING_SEGMENTS = 16  # over the arch opening's half circle


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def polygon_area(polygon):
    """Signed area of a 2-D polygon (positive when counter-clockwise)."""
    total = 0.0
    for i, (u0, v0) in enumerate(polygon):
        u1, v1 = polygon[(i + 1) % len(polygon)]
        total += u0 * v1 - u1 * v0
    return 0.5 * total


def prism(polygon, depth, to_xyz):
    """Triangles of the convex 2-D `polygon` extruded over [-depth/2, depth/2].

    `to_xyz(u, v, w)` maps the polygon's plane (u, v) and the extrusion w to
    the type frame. Triangles are ordered so that their right-hand normals
    point out of the solid, checked against its centroid below.
    """
    if polygon_area(polygon) < 0.0:
        polygon = list(reversed(polygon))
    n = len(polygon)
    low = [to_xyz(u, v, -0.5 * depth) for u, v in polygon]
    high = [to_xyz(u, v, 0.5 * depth) for u, v in polygon]
    triangles = []
    for i in range(1, n - 1):
        triangles.append((high[0], high[i], high[i + 1]))
        triangles.append((low[0], low[i + 1], low[i]))
    for i in range(n):
        j = (i + 1) % n
        triangles.append((low[i], low[j], high[j]))
        triangles.append((low[i], high[j], high[i]))
    # A mapping that mirrors (u, v, w) turns every triangle inside out: the
    # centroid check catches that and flips the whole solid.
    centre = tuple(sum(p[k] for p in low + high) / (2 * n) for k in range(3))
    outward = [dot(cross(sub(b, a), sub(c, a)), sub(a, centre)) for a, b, c in triangles]
    if all(o < 0.0 for o in outward):
        triangles = [(a, c, b) for a, b, c in triangles]
    elif not all(o > 0.0 for o in outward):
        raise ValueError("prism is not convex or has a degenerate face")
    return triangles


def check_closed(triangles, name):
    """Every edge is used once in each direction: a closed, consistently oriented surface."""
    edges = {}
    for triangle in triangles:
        for i in range(3):
            edge = (triangle[i], triangle[(i + 1) % 3])
            edges[edge] = edges.get(edge, 0) + 1
    for (a, b), count in edges.items():
        if count != 1 or edges.get((b, a)) != 1:
            raise ValueError("%s: edge %s-%s is not shared by exactly two faces" % (name, a, b))


def write_stl(path, name, triangles):
    check_closed(triangles, name)
    lines = ["solid " + name]
    for a, b, c in triangles:
        normal = cross(sub(b, a), sub(c, a))
        length = math.sqrt(dot(normal, normal))
        normal = tuple(x / length for x in normal)
        lines.append("  facet normal %.9e %.9e %.9e" % normal)
        lines.append("    outer loop")
        for p in (a, b, c):
            lines.append("      vertex %r %r %r" % p)
        lines.append("    endloop")
        lines.append("  endfacet")
    lines.append("endsolid " + name)
    with open(path, "w") as stl:
        stl.write("\n".join(lines) + "\n")


def half_circle():
    """A half disc of radius WIDTH lying flat, bulging towards +y, thickness along z."""
    radius = WIDTH
    arc = [(radius * math.cos(math.pi * k / HALF_CIRCLE_SEGMENTS),
            radius * math.sin(math.pi * k / HALF_CIRCLE_SEGMENTS))
           for k in range(HALF_CIRCLE_SEGMENTS + 1)]
    # sin(pi) is not exactly 0: the flat side must lie exactly on y = 0. The
    # top of the arc (k = 16) has sin = 1 exactly, so the bounds reach y = radius.
    arc[-1] = (-radius, 0.0)
    centre_y = 0.5 * radius
    return prism(arc, THICK, lambda u, v, w: (u, v - centre_y, w))


def triangle():
    """The half unit cut on its diagonal: legs along x and y, right angle at (-, -)."""
    legs = [(0.0, 0.0), (WIDTH, 0.0), (0.0, WIDTH)]
    half = 0.5 * WIDTH
    return prism(legs, THICK, lambda u, v, w: (u - half, v - half, w))


def ramp():
    """The unit cut through its thickness: rises from 0 at -x to THICK at +x."""
    wedge = [(0.0, 0.0), (UNIT, 0.0), (UNIT, THICK)]
    return prism(wedge, WIDTH, lambda u, v, w: (u - 0.5 * UNIT, w, v - 0.5 * THICK))


def arch_crown_pieces():
    """The part of the small arch above its opening, cut at the opening's vertices.

    The arch is 4 r long, 2 r tall and r deep (r = THICK = the opening's
    radius); its frame is centred on its bounds, so the springing line of the
    opening is at z = -r and the top at z = +r. Piece k spans the opening's
    chord k, from the chord up to the top.
    """
    r = THICK
    opening = [(r * math.cos(math.pi * k / ARCH_OPENING_SEGMENTS),
                r * math.sin(math.pi * k / ARCH_OPENING_SEGMENTS))
               for k in range(ARCH_OPENING_SEGMENTS + 1)]
    # cos(pi/2) and sin(pi) are not exactly 0: the crown's middle cut is
    # exactly vertical and the opening ends exactly on the springing line.
    opening[ARCH_OPENING_SEGMENTS // 2] = (0.0, r)
    opening[-1] = (-r, 0.0)
    top = 2.0 * r
    pieces = []
    for k in range(ARCH_OPENING_SEGMENTS):
        (x0, z0), (x1, z1) = opening[k], opening[k + 1]
        outline = [(x0, z0), (x1, z1), (x1, top), (x0, top)]
        pieces.append(prism(outline, r, lambda u, v, w: (u, w, v - r)))
    return pieces


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    directory = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "meshes", "unit_blocks")
    os.makedirs(directory, exist_ok=True)
    solids = [("unit_half_circle", half_circle()), ("unit_triangle", triangle()), ("unit_ramp", ramp())]
    for k, piece in enumerate(arch_crown_pieces()):
        solids.append(("unit_arch_crown_%02d" % k, piece))
    for name, triangles in solids:
        write_stl(os.path.join(directory, name + ".stl"), name, triangles)
    print("wrote %d meshes to %s" % (len(solids), os.path.normpath(directory)))


if __name__ == "__main__":
    main()
