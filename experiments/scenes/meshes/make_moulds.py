#!/usr/bin/env python3
"""Writes the moulds of the shipped scenes and their lids as closed OBJ prisms with rounded
corners: onigiri_mould.obj (a rounded equilateral triangle, paper Fig. 16) and shari_mould.obj
(a rounded oblong, Fig. 14), each standing on z = 0 in metres, and onigiri_lid.obj and
shari_lid.obj, 1 cm thick, the same outline 2 mm in from the mould's walls (a lid as wide as
the mould would wedge grains between itself and the walls); drop_cup.obj; and the rice cooker's
pot, rice_cooker_pot.obj (a cylinder's room 20 cm across) and rice_cooker_pot_walls.obj (the pot,
open at the top), the same pot 1.5 m tall as a chute,
rice_cooker_chute.obj, and the paddle's blade, shamoji.obj.
Rerun after changing a size:
    python3 experiments/scenes/meshes/make_moulds.py
"""
import math
import pathlib


def rounded_outline(corners, radius, per_corner=8):
    """Points around a convex polygon (counter-clockwise corners) with each corner rounded."""
    n = len(corners)
    points = []
    for k in range(n):
        (px, py), (cx, cy), (nx, ny) = corners[k - 1], corners[k], corners[(k + 1) % n]
        # The arc's centre: the corner moved inward by radius / sin(half the inner angle).
        a = math.atan2(py - cy, px - cx)
        b = math.atan2(ny - cy, nx - cx)
        half = ((a - b) % (2 * math.pi)) / 2
        bisector = b + half
        d = radius / math.sin(half)
        ox, oy = cx + d * math.cos(bisector), cy + d * math.sin(bisector)
        start = a + math.pi / 2  # outward normal of the incoming edge
        end = b - math.pi / 2    # outward normal of the outgoing edge
        sweep = (end - start) % (2 * math.pi)
        for i in range(per_corner + 1):
            t = start + sweep * i / per_corner
            points.append((ox + radius * math.cos(t), oy + radius * math.sin(t)))
    return points


def write_prism(path, outline, height):
    """A closed prism over the outline (counter-clockwise), faces outward."""
    n = len(outline)
    lines = ["# " + path.name + ": written by make_moulds.py"]
    for z in (0.0, height):
        lines += ["v %.6f %.6f %.6f" % (x, y, z) for x, y in outline]
    cx = sum(x for x, _ in outline) / n
    cy = sum(y for _, y in outline) / n
    lines += ["v %.6f %.6f 0" % (cx, cy), "v %.6f %.6f %.6f" % (cx, cy, height)]
    bottom_centre, top_centre = 2 * n + 1, 2 * n + 2
    for i in range(n):
        j = (i + 1) % n
        a, b, c, d = i + 1, j + 1, n + j + 1, n + i + 1
        lines += ["f %d %d %d" % (a, b, c), "f %d %d %d" % (a, c, d)]
        lines += ["f %d %d %d" % (bottom_centre, b, a), "f %d %d %d" % (top_centre, n + i + 1, n + j + 1)]
    path.write_text("\n".join(lines) + "\n")


def write_blade(path, outline, edge, middle, rings=6):
    """A closed blade over the outline (counter-clockwise), faces outward: a flat lower face in z = 0
    and an upper face that thickens from `edge` at the outline to `middle` at its centre, a thin
    edge that slides between grains. The upper face's rings are the outline scaled about its
    centre by s = 1 - k / rings; the thickness there is edge + (middle - edge) (1 - s^2)."""
    n = len(outline)
    cx = sum(x for x, _ in outline) / n
    cy = sum(y for _, y in outline) / n
    lines = ["# " + path.name + ": written by make_moulds.py"]
    lines += ["v %.6f %.6f 0" % (x, y) for x, y in outline]
    for k in range(rings):
        s = 1 - k / rings
        z = edge + (middle - edge) * (1 - s * s)
        lines += ["v %.6f %.6f %.6f" % (cx + s * (x - cx), cy + s * (y - cy), z) for x, y in outline]
    lines += ["v %.6f %.6f 0" % (cx, cy), "v %.6f %.6f %.6f" % (cx, cy, middle)]
    bottom_centre, top_centre = (rings + 1) * n + 1, (rings + 1) * n + 2
    for i in range(n):
        j = (i + 1) % n
        lines.append("f %d %d %d" % (bottom_centre, j + 1, i + 1))
        for k in range(rings):  # the side wall (k = 0), then the upper face's bands inwards
            a, b, c, d = k * n + i + 1, k * n + j + 1, (k + 1) * n + j + 1, (k + 1) * n + i + 1
            lines += ["f %d %d %d" % (a, b, c), "f %d %d %d" % (a, c, d)]
        lines.append("f %d %d %d" % (top_centre, rings * n + i + 1, rings * n + j + 1))
    path.write_text("\n".join(lines) + "\n")


def write_lathe(path, profile, segments=64):
    """A closed solid of revolution about the z axis: `profile`, points (r, z) that start and end
    on the axis (r = 0), turned through a full circle; faces outward when the profile runs
    counter-clockwise in the (r, z) plane, seen with r to the right and z up."""
    inner = profile[1:-1]  # the points off the axis, each a ring
    n = len(inner)
    lines = ["# " + path.name + ": written by make_moulds.py"]
    for r, z in inner:
        angles = [2 * math.pi * k / segments for k in range(segments)]
        lines += ["v %.6f %.6f %.6f" % (r * math.cos(a), r * math.sin(a), z) for a in angles]
    lines += ["v 0 0 %.6f" % profile[0][1], "v 0 0 %.6f" % profile[-1][1]]
    first, last = n * segments + 1, n * segments + 2
    ring = lambda i, k: i * segments + k % segments + 1
    for k in range(segments):
        lines.append("f %d %d %d" % (first, ring(0, k + 1), ring(0, k)))
        for i in range(n - 1):
            a, b, c, d = ring(i, k), ring(i + 1, k), ring(i + 1, k + 1), ring(i, k + 1)
            lines += ["f %d %d %d" % (a, c, b), "f %d %d %d" % (a, d, c)]
        lines.append("f %d %d %d" % (last, ring(n - 1, k), ring(n - 1, k + 1)))
    path.write_text("\n".join(lines) + "\n")


here = pathlib.Path(__file__).resolve().parent
GAP = 0.002  # between a lid and its mould's walls [m]


def triangle(side):
    return [(side * math.cos(math.radians(90 + 120 * k)) / math.sqrt(3),
             side * math.sin(math.radians(90 + 120 * k)) / math.sqrt(3)) for k in range(3)]


def oblong(length, width):
    return [(-length / 2, -width / 2), (length / 2, -width / 2), (length / 2, width / 2), (-length / 2, width / 2)]


side, corner = 0.075, 0.012  # onigiri: the triangle's side and corner radius [m]
write_prism(here / "onigiri_mould.obj", rounded_outline(triangle(side), corner), 0.05)
# A triangle's outline moves in by GAP when its side shrinks by 2 sqrt(3) GAP.
write_prism(here / "onigiri_lid.obj", rounded_outline(triangle(side - 2 * math.sqrt(3) * GAP), corner - GAP), 0.01)
length, width, corner = 0.05, 0.022, 0.008  # shari: an oblong [m]
write_prism(here / "shari_mould.obj", rounded_outline(oblong(length, width), corner), 0.04)
write_prism(here / "shari_lid.obj", rounded_outline(oblong(length - 2 * GAP, width - 2 * GAP), corner - GAP), 0.01)
side, corner = 0.024, 0.008  # drop cup: a rounded square [m], filled and then taken away from under the grains
write_prism(here / "drop_cup.obj", rounded_outline(oblong(side, side), corner), 0.04)


def circle(radius, segments=64):
    return [(radius * math.cos(2 * math.pi * k / segments), radius * math.sin(2 * math.pi * k / segments))
            for k in range(segments)]


# Rice cooker: the inner pot of a 5.5-cup cooker, 20 cm across and 12 cm deep: the room inside it,
# closed at its rim, that the fill drops grains into, and the pot itself, open at the top: a wall
# 3 mm thick and a floor 3 mm thick under z = 0.
write_prism(here / "rice_cooker_pot.obj", circle(0.1), 0.12)
write_lathe(here / "rice_cooker_pot_walls.obj",
            [(0, -0.003), (0.103, -0.003), (0.103, 0.12), (0.1, 0.12), (0.1, 0), (0, 0)])
# The same pot with its wall carried up to 1.5 m, a chute that holds a clump of 34,000 grains
# stacked on the clump's lattice before it drops (scenes/cases/cooker_drop.toml).
write_prism(here / "rice_cooker_chute.obj", circle(0.1), 1.5)
# Shamoji (rice paddle): its blade, a rounded oblong 9 x 7 cm, flat below (z = 0), 4 mm thick at its
# centre and 1 mm at its edge; the scene turns and moves it.
write_blade(here / "shamoji.obj", rounded_outline(oblong(0.09, 0.07), 0.03), 0.001, 0.004)
