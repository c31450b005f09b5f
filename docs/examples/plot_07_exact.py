"""
Exact and ball arithmetic
=========================

With :math:`\\alpha = 4 \\arctan t` for a rational :math:`t`, every half-angle sine and
cosine is rational, so patches evaluate exactly at rational points; ``"ball"`` gives
certified enclosures.
"""

# %%
import numpy as np

import paper_repro as pr

a = pr.rational_alpha((1, 2))  # alpha = 4 atan(1/2)
q = pr.Patch(2, a, np.arange(57).reshape(19, 3))  # an integer net
# rational quarter-angle tangents of u and v:
rp = pr.RationalPoints(a, ((1, 5), (1, 9)), ((1, 7), (1, 3)))
print(q(rp, arith="exact")[0])  # exact rationals
print(q(rp, arith="ball")[0])  # arb balls containing them
c = pr.coefficients(2, a, "exact")
print(c["r_{4,2,2}"])
