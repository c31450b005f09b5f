"""
Order elevation
===============

The same patch written in a higher order (Section 7 of the paper, ``elevation_matrix``):
the target order is given by ``to=`` (or the number of steps by ``times=``, both
keyword-only).
"""

# %%
import matplotlib.pyplot as plt
import numpy as np

import paper_repro as pr

alpha = np.pi / 2
# a net from geometry: the nodes over the domain lifted onto a saddle
xy = np.array([pr.position(lab) for lab in pr.united_system(3)])
net3 = np.column_stack([xy, 2 * ((xy[:, 0] - 0.5) ** 2 - (xy[:, 1] - 0.3) ** 2)])
p3 = pr.Patch(3, alpha, net3)
q = pr.sample_points(alpha, 200, seed=2)
for order in (4, 8):
    net = pr.elevate(net3, 3, alpha, to=order)
    diff = abs(pr.Patch(order, alpha, net)(q) - p3(q)).max()
    print(f"order {order}: {len(net)} control points, largest change {diff:.1e}")
    assert diff < 1e-12

# %%
# The elevated net is closer to the surface (Fig. 10 of the paper, for order 1 to 2):
fig = plt.figure(figsize=(10, 4.5))
for k, (order, net) in enumerate(((3, net3), (4, pr.elevate(net3, 3, alpha, to=4)))):
    ax = fig.add_subplot(1, 2, k + 1, projection="3d")
    pr.Patch(order, alpha, net).plot(ax=ax)
    ax.set_title(f"order {order}")
