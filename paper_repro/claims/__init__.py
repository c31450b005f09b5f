"""Claim modules, one per claim of the paper (registered in :mod:`paper_repro.util.registry`)."""
