"""
How a control net is laid out
=============================

The control points of an order-:math:`n` patch sit over the domain as the nodes of the
paper's graph (Fig. 1, ``fig:oriented_graph``; Fig. 6, ``fig:associated_control_net``):

* the function :math:`\\sin^a\\frac{u}{2} \\sin^b\\frac{v}{2} \\sin^c\\frac{w}{2}
  \\cdot(\\text{cosines})` sits at the barycentric point :math:`(a, b, c)/(a+b+c)`
  (:func:`paper_repro.barycentric`; :func:`paper_repro.position` gives it in the plane);
* the three corners: :math:`\\mathbf{r}_{2n,2n,0}` at :math:`u = \\alpha`,
  :math:`\\mathbf{b}_{2n,2n,0}` at :math:`v = \\alpha`, :math:`\\mathbf{g}_{2n,2n,0}` at
  :math:`w = \\alpha` -- the patch passes through them;
* the boundary rows: :math:`\\mathbf{r}_{2n,2n-i,0}` on :math:`v = 0`,
  :math:`\\mathbf{g}_{2n,2n-i,0}` on :math:`u = 0`, :math:`\\mathbf{b}_{2n,2n-i,0}` on
  :math:`w = 0` (:math:`i = 0, \\dots, 2n`; :meth:`paper_repro.Patch.boundary_net`) --
  the control polygons of the boundary curves;
* level :math:`j = 0, \\dots, n-1` is the :math:`j`-th of the nested triangles, the
  centre :math:`\\mathbf{r}_{2n,n,n}` is level :math:`n`;
* the edges (:func:`paper_repro.net_edges`): consecutive nodes along each side of each
  level, and each inner node of a side to the node one level in -- :math:`6n^2 + 3n`
  edges bounding :math:`3n^2` quadrilaterals. A corner and the centre carry two or three
  labels (``r_{6,0,0}`` is ``g_{6,6,0}``); the net has one row for each.
"""

# %%
# The layout of order 3 (37 control points) over the domain, with every label:
import matplotlib.pyplot as plt
import numpy as np

import paper_repro as pr

n = 3
labels = pr.united_system(n)
xy = np.array([pr.position(lab) for lab in labels])
colour = {"r": "tab:red", "g": "tab:green", "b": "tab:blue"}
fig, ax = plt.subplots(figsize=(7, 6.3))
for a, b in pr.net_edges(n):
    ax.annotate("", xy=xy[b], xytext=xy[a],
                arrowprops=dict(arrowstyle="-|>", color="0.55", shrinkA=6, shrinkB=6))
for lab, p in zip(labels, xy):
    name = lab.control_point
    ax.plot(*p, "o", color="k" if lab.is_centre else colour[name[0]])
    ax.annotate(name, p, textcoords="offset points", xytext=(0, 7), ha="center",
                fontsize=7, bbox=dict(fc="white", ec="none", pad=0.5, alpha=0.85))
corners = (("u = α", (0, 0), (-12, -16)), ("w = α", (1, 0), (12, -16)),
           ("v = α", (0.5, np.sqrt(3) / 2), (40, -4)))
for text, p, off in corners:
    ax.annotate(text, p, textcoords="offset points", xytext=off, ha="center")
ax.set_aspect("equal")
ax.axis("off")
ax.set_title("order 3: labels over the domain, edges oriented towards the centre")

# %%
# The rows of the net, in order: the centre first, then the R, G and B functions, each
# colour by level ``j`` and then ``i``. The corners and the boundary rows:
print([lab.control_point for lab in labels][:8], "...")
print("corners:", pr.barycentric(labels[1]), "is", labels[1].control_point)
print(len(pr.net_edges(n)), "edges;", pr.delta(n), "control points")

# %%
# Placing control points from geometry
# -------------------------------------
# Lift each node onto the graph of a function over the triangle: the point
# ``(x, y, f(x, y))`` above the node's position. The patch then follows the graph's
# shape; its corners lie on the graph exactly.


def f(x, y):
    return 0.4 * np.sin(np.pi * x) * np.cos(np.pi * (y - 0.3))


net = np.column_stack([xy, f(xy[:, 0], xy[:, 1])])
patch = pr.Patch(n, "pi/2", net)
ax = patch.plot(labels=False)
ax.view_init(elev=28, azim=-62)
ax.set_title("order 3: the lifted net and its patch")
corner = patch.at_barycentric([[1, 0, 0]])[0]
print("corner u = alpha:", corner, "on the graph:",
      np.isclose(corner[2], f(*corner[:2])))

# %%
# The boundary curve ``v = 0`` and its control polygon (7 points for n = 3):
print(patch.boundary_net("v=0").round(3))
