"""Reads a .msh and a .vtu written by ruppert with meshio and compares them with what the test
expects (tests/core/test_consumers.cpp writes EXPECTED from the mesh in memory, not from the writers).

usage: /usr/bin/python3 check_with_meshio.py EXPECTED MSH VTU
EXPECTED, whitespace-separated:
  points N, then N lines "x y vertexKind marker" (marker "-" when the mesh has none)
  triangles T, then T lines "a b c physicalTag regionAttribute minAngleDegrees"
  lines L, then L lines "a b physicalTag"
Prints what differs and exits 1, or prints a one-line summary and exits 0.
"""
import sys
from collections import Counter

import meshio
import numpy as np


def read_expected(path):
    words = open(path).read().split()
    pos = 0

    def take(n):
        nonlocal pos
        out = words[pos:pos + n]
        pos += n
        return out

    assert take(1) == ["points"]
    n = int(take(1)[0])
    points = [take(4) for _ in range(n)]
    assert take(1) == ["triangles"]
    t = int(take(1)[0])
    triangles = [take(6) for _ in range(t)]
    assert take(1) == ["lines"]
    l = int(take(1)[0])
    lines = [take(3) for _ in range(l)]
    return points, triangles, lines


def rotated(tri):
    """The same oriented triangle starting from its smallest index."""
    k = tri.index(min(tri))
    return tuple(tri[k:] + tri[:k])


def cells_of(mesh, kind, data_name):
    """Every cell of `kind` with its value of cell data `data_name`, over all blocks."""
    out = []
    for block, values in zip(mesh.cells, mesh.cell_data[data_name]):
        if block.type == kind:
            out += [(list(map(int, c)), v) for c, v in zip(block.data, values)]
    return out


def main():
    expected_path, msh_path, vtu_path = sys.argv[1:4]
    points, triangles, lines = read_expected(expected_path)
    xy = np.array([[float(p[0]), float(p[1])] for p in points])
    problems = []

    msh = meshio.read(msh_path)
    if msh.points.shape[0] != len(points) or not np.array_equal(msh.points[:, :2], xy):
        problems.append(f"msh: {msh.points.shape[0]} points, expected {len(points)} equal ones")
    elif not np.all(msh.points[:, 2] == 0):
        problems.append("msh: z is not 0")
    got = Counter((rotated(c), int(tag)) for c, tag in cells_of(msh, "triangle", "gmsh:physical"))
    want = Counter((rotated([int(v) for v in t[:3]]), int(t[3])) for t in triangles)
    if got != want:
        problems.append(f"msh: triangles differ: {len(got - want)} unexpected, {len(want - got)} missing "
                        f"(of {sum(want.values())})")
    got = Counter((tuple(c), int(tag)) for c, tag in cells_of(msh, "line", "gmsh:physical"))
    want = Counter(((int(s[0]), int(s[1])), int(s[2])) for s in lines)
    if got != want:
        problems.append(f"msh: lines differ: {len(got - want)} unexpected, {len(want - got)} missing "
                        f"(of {sum(want.values())})")

    vtu = meshio.read(vtu_path)
    if vtu.points.shape[0] != len(points) or not np.array_equal(vtu.points[:, :2], xy):
        problems.append(f"vtu: {vtu.points.shape[0]} points, expected {len(points)} equal ones")
    blocks = [b for b in vtu.cells if b.type == "triangle"]
    if len(blocks) != 1 or len(vtu.cells) != 1:
        problems.append(f"vtu: {len(vtu.cells)} cell blocks, expected one of triangles")
    else:
        want = np.array([[int(v) for v in t[:3]] for t in triangles]).reshape(-1, 3)
        if not np.array_equal(blocks[0].data, want):
            problems.append("vtu: triangles differ from the mesh's (same order expected)")
        attributes = np.array([float(t[4]) for t in triangles])
        angles = np.array([float(t[5]) for t in triangles])
        if not np.array_equal(vtu.cell_data["regionAttribute"][0], attributes):
            problems.append("vtu: regionAttribute differs")
        if not np.allclose(vtu.cell_data["minAngle"][0], angles, rtol=0, atol=1e-9):
            problems.append("vtu: minAngle differs by more than 1e-9 degrees")
    kinds = np.array([int(p[2]) for p in points])
    if not np.array_equal(vtu.point_data["vertexKind"], kinds):
        problems.append("vtu: vertexKind differs")
    if points and points[0][3] != "-":
        markers = np.array([int(p[3]) for p in points])
        if "pointMarker" not in vtu.point_data or not np.array_equal(vtu.point_data["pointMarker"], markers):
            problems.append("vtu: pointMarker missing or different")
    elif "pointMarker" in vtu.point_data:
        problems.append("vtu: pointMarker written for a mesh without markers")

    if problems:
        print("\n".join(problems))
        return 1
    print(f"meshio read {len(points)} points, {len(triangles)} triangles, {len(lines)} lines from both files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
