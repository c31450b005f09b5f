"""
The Fourier basis and the transformation
========================================

The normalized basis :math:`\\bar T_{2n}^\\alpha` and the truncated Fourier basis
:math:`V_n^\\alpha` of Section 4 span the same space;
:func:`paper_repro.transformation_matrix` gives the matrix :math:`M` with
:math:`V_n = \\bar T_{2n} M` (Question 7.2). Its columns are the control nets of the
Fourier functions, so ``M @ a`` turns Fourier coefficients into a control net.
"""

# %%
import numpy as np

import paper_repro as pr
from paper_repro.core.fourier import evaluate_v, v_labels

n, alpha = 2, np.pi / 2
M = pr.transformation_matrix(n, alpha)
print(M.shape, v_labels(n)[:5])
q = pr.sample_points(alpha, 50, seed=1)
V = evaluate_v(n, alpha, q)
T = pr.evaluate_normalized(n, alpha, q)
print(f"max |V - T M| = {abs(V - T @ M).max():.1e}")
assert abs(V - T @ M).max() < 1e-10

# %%
# A surface given by Fourier coefficients, as a patch:
coef = np.zeros((pr.delta(n), 3))
coef[0] = [0, 0, 1]  # the constant 1 -> z = 1
coef[1:4] = np.eye(3)
net = M @ coef
patch = pr.Patch(n, alpha, net)
print(f"max deviation: {abs(patch(q) - V @ coef).max():.1e}")

# %%
# Exactly, at a rational-tangent alpha (entries are rationals):
a = pr.rational_alpha((1, 2))
Me = pr.transformation_matrix(1, a)
print(Me[:3, :3])
