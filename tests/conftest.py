"""Shared test set-up: deterministic hypothesis runs (seeded, no deadline)."""

import os

from hypothesis import HealthCheck, settings

settings.register_profile("repro", derandomize=True, deadline=None, max_examples=40,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repro"))
