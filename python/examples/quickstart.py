import numpy as np
import exidel

# Exact signs, one per row. Kettner et al.'s point p = (0.5, 0.5) moved by i ulps in x
# against the line through (12, 12) and (24, 24): the double formula gets some wrong.
p = np.array([0.5, 0.5]) + np.arange(256)[:, None] * [2.0 ** -53, 0.0]
exact = exidel.orient2d(p, [12, 12], [24, 24])
double = exidel.orient2d(p, [12, 12], [24, 24], kernel="double")
print("orient2d:", exact[:8], "... double wrong on", (double != exact).sum(), "of 256")

# A triangulation with scipy.spatial.Delaunay's names, certified exactly. A grid: every
# square's four corners are cocircular, where floating-point triangulators struggle.
points = np.array([[i, j] for i in range(8) for j in range(8)], dtype=float)
tri = exidel.Delaunay(points)
print(tri, "certified:", exidel.certify(points, tri).ok)

# The Voronoi diagram: one vertex per square (cocircular corners merged exactly), each
# vertex the nearest double to the exact centre.
vor = exidel.Voronoi(points)
print(len(vor.vertices), "Voronoi vertices, e.g.", vor.vertices[0])

# A picture (matplotlib).
import exidel.plot
ax = exidel.plot.triangulation(tri)
ax.figure.savefig("exidel-quickstart.png")
print("wrote exidel-quickstart.png")
