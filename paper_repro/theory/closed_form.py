"""One closed form ``P(cos(alpha/2)) / sin^k(alpha/2)`` of a normalizing coefficient."""

from __future__ import annotations

from dataclasses import dataclass

from flint import fmpq, fmpq_poly

from paper_repro.core.domain import RationalAngle


def sin_power(label_j: int, n: int) -> int:
    return 2 * n + label_j


@dataclass
class ClosedForm:
    label: str
    sin_power: int
    numerator: fmpq_poly  # in c = cos(alpha/2)

    def value(self, alpha: RationalAngle) -> fmpq:
        return self.numerator(alpha.cos_half) / alpha.sin_half ** self.sin_power

    def as_json(self) -> dict:
        coeffs = [str(x) for x in self.numerator.coeffs()] or ["0"]
        return {"sin_power": self.sin_power, "numerator": coeffs}
