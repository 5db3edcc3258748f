#!/usr/bin/env python3
# Writes the STL meshes of cases/ensembles/hopper_discharge_mesh.toml (millimetres; the case scales
# them by 1e-3): the hopper of cases/canonical/hopper_discharge.toml as triangles.
#   hopper.stl — the barrel (a cylinder of radius 15 from z = 3 to 63) and the shallow conical
#                bottom (radius 6 at z = 0 up to 15 at z = 3) as one welded surface, 64 sides;
#   catch.stl  — the bin under it, [-40, 40]² × [-30, 100] open at the top (two triangles a face).
# Corners on the circles are exact polygons inscribed in them (a side sits 15·(1 − cos(π/64)) =
# 0.018 mm inside the round barrel). Run from this folder: python3 make_hopper_meshes.py
import math

from stl_ascii import write

SIDES = 64


def ring(radius, z):
    return [(radius * math.cos(2 * math.pi * k / SIDES), radius * math.sin(2 * math.pi * k / SIDES), z)
            for k in range(SIDES)]


def band(lower, upper):
    """Two triangles per side between two rings of the same number of corners."""
    out = []
    for k in range(SIDES):
        a, b = lower[k], lower[(k + 1) % SIDES]
        c, d = upper[k], upper[(k + 1) % SIDES]
        out += [(a, b, d), (a, d, c)]
    return out


orifice, rim, top = ring(6.0, 0.0), ring(15.0, 3.0), ring(15.0, 63.0)
write("hopper.stl", "hopper", band(orifice, rim) + band(rim, top))

lo, hi = (-40.0, -40.0, -30.0), (40.0, 40.0, 100.0)
x0, y0, z0 = lo
x1, y1, z1 = hi
quads = [
    [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)],  # floor
    [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],  # y = -40
    [(x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)],  # y = +40
    [(x0, y0, z0), (x0, y1, z0), (x0, y1, z1), (x0, y0, z1)],  # x = -40
    [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],  # x = +40
]
write("catch.stl", "catch", [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))])
