#!/usr/bin/env python3
# Writes box_hopper.stl (millimetres; cases/ensembles/hopper_box_mesh.toml scales it by 1e-3): a
# flat-bottomed box hopper, 30 x 30 mm inside (15 bead diameters) and 63 mm tall, whose floor at
# z = 0 has a square orifice 12 mm across (6 d) at its centre. The floor is the 3 x 3 grid of
# rectangles on x, y in {-15, -6, 6, 15} without the middle one, so that neighbouring rectangles
# share their corners (no vertex lies inside another's edge); each rectangle and each side wall is
# two triangles. The catch bin under it is catch.stl (make_hopper_meshes.py).
# Run from this folder: python3 make_box_hopper_mesh.py
from stl_ascii import write

HALF = 15.0      # the box's inner half-width
ORIFICE = 6.0    # the orifice's half-side
HEIGHT = 63.0


def quad(a, b, c, d):
    """Two triangles of the quadrilateral a b c d (corners in order round it)."""
    return [(a, b, c), (a, c, d)]


cuts = [-HALF, -ORIFICE, ORIFICE, HALF]
floor = []
for i in range(3):
    for j in range(3):
        if i == 1 and j == 1:
            continue  # the orifice
        x0, x1, y0, y1 = cuts[i], cuts[i + 1], cuts[j], cuts[j + 1]
        floor += quad((x0, y0, 0.0), (x1, y0, 0.0), (x1, y1, 0.0), (x0, y1, 0.0))
h, t = HALF, HEIGHT
sides = (quad((-h, -h, 0.0), (h, -h, 0.0), (h, -h, t), (-h, -h, t))      # y = -15
         + quad((-h, h, 0.0), (h, h, 0.0), (h, h, t), (-h, h, t))        # y = +15
         + quad((-h, -h, 0.0), (-h, h, 0.0), (-h, h, t), (-h, -h, t))    # x = -15
         + quad((h, -h, 0.0), (h, h, 0.0), (h, h, t), (h, -h, t)))       # x = +15
write("box_hopper.stl", "box_hopper", floor + sides)
