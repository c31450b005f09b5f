"""Exact research machinery, one layer above :mod:`paper_repro.core`.

Modular recovery of closed forms (``modular``), identity proofs (``identity_proof``), rational functions of
tan(alpha/4) (``ratfunc``), matrix closed forms (``matrix_forms``, ``elevation_forms``), elimination
(``elimination``), derivative values of the sign lemmas (``derivatives``), the alpha -> 0 limit (``limit_formula``,
``limits``), the level formulas (``general_formulas``), rank certificates (``rank``) and the all-n formula of
Question 1 with its proof ingredients (``question1``).  Imports go to ``core`` and ``util`` only.
"""
