"""ASCII STL output shared by the mesh scripts of this folder."""


def write(name, solid, triangles):
    """Writes the triangles (three (x, y, z) corners each) to `name` as the ASCII STL solid `solid`,
    every facet normal written as zero."""
    with open(name, "w") as f:
        f.write(f"solid {solid}\n")
        for t in triangles:
            f.write("  facet normal 0 0 0\n    outer loop\n")
            for v in t:
                f.write("      vertex {:.17g} {:.17g} {:.17g}\n".format(*v))
            f.write("    endloop\n  endfacet\n")
        f.write(f"endsolid {solid}\n")
