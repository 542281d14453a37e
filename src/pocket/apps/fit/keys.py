"""The parameters a fit can vary: one ``Key`` per case-file key of a law, with its getter, setter and bounds.

A law's keys are its parameters by name (``c1``, ``c10``, ``jm``), a listed parameter one key per
term (Ogden's ``mu[0]``, ``exponents[0]``, ...). A key reads its value from a ``Material`` and
returns a new ``Material`` with another value (``dataclasses``-style: the material is not changed),
so that anything a material carries can be fitted by adding a key here. The last key of every law is
``prestretch``, the equibiaxial stretch lambda_p of the clamped flat sheet (``Material.prestretch``),
bounds [1, inf): the fit holds it at 1 unless asked to fit it (``pocket.apps.fit.leastsquares``).

The fit moves each key along its ``unknown`` coordinate, which is the value itself except for Ogden,
whose term p is fitted as its share of mu_0, s_p = mu_p alpha_p / 2 (a stress), and its exponent
alpha_p with that share held (mu_p = 2 s_p / alpha_p). The data fix mu_0 = sum s_p first and best, so
in these coordinates the valley of near-equal fits that every Ogden fit of several terms follows is
nearly straight, where in (mu_p, alpha_p) it bends (a change of alpha_p at fixed mu_p changes mu_0),
and the least-squares steps crawl along it (measured: a two-term fit to noise-free data from four
starts reached the data to 1e-11 in 40-80 evaluations from three of them in these coordinates, and
from none within 60 in (mu_p, alpha_p)). The reported values and their errors stay the keys'
(``pocket.apps.fit.stats`` maps the covariance through the coordinates' Jacobian).

Bounds are the box part of each law's admissible set: C1, mu, C10, Jm > 0. The rest of the set
(C1 + C2 > 0, C30 >= 0 and a Yeoh slope that stays positive, mu_p alpha_p > 0, Jm above the data's
largest I1 - 3, a Gent prestretch inside the locking) is not a box: a trial set outside it has no
state, and the fit treats it as it treats a datum with no state (``pocket.apps.fit.model``).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from typing import Any

from pocket.core.errors import InputError
from pocket.core.materials import LAWS, Material

__all__ = ["PRESTRETCH", "Key", "Subject", "key_named", "keys"]

#: what a key reads and moves: a ``Material``, or a capsule's rubber with its initial pressure
#: (``pocket.apps.fit.capsulemodel.Trial``)
Subject = Any
#: the key of the clamped sheet's prestretch (the case file's ``sheet.prestretch``)
PRESTRETCH = "prestretch"

#: (law, parameter name) -> its lower bound, where the law's admissible set bounds it alone
_LOWER = {("mooney-rivlin", "c1"): 0.0, ("neo-hookean", "mu"): 0.0, ("yeoh", "c10"): 0.0,
          ("gent", "mu"): 0.0, ("gent", "jm"): 0.0}


@dataclasses.dataclass(frozen=True)
class Key:
    """A fitted quantity: its ``name`` (a case-file key), ``unit`` ("stress", "dimensionless", or "pressure": a
    load in Pa whatever the thickness, a capsule's initial pressure, ``pocket.apps.fit.capsuletest``),
    ``lower`` and ``upper`` bounds (stresses in the material's unit: only 0 and inf are used),
    ``get(material) -> float`` and ``put(material, value) -> Material``; ``unknown`` is the (get, put)
    of the coordinate the fit moves it along (module docstring), None for the value itself."""

    name: str
    unit: str
    lower: float
    upper: float
    get: Callable[[Subject], float]
    put: Callable[[Subject, float], Subject]
    unknown: tuple[Callable[[Subject], float], Callable[[Subject, float], Subject]] | None = None

    def coordinate(self, material: Subject) -> float:
        """The fit's unknown for this key at ``material``."""
        return (self.unknown or (self.get, self.put))[0](material)

    def moved(self, material: Subject, value: float) -> Subject:
        """``material`` with this key's coordinate at ``value``."""
        return (self.unknown or (self.get, self.put))[1](material, value)


def _replaced(material: Material, name: str, value) -> Material:
    params = tuple((n, value if n == name else v) for n, v in material.params)
    return dataclasses.replace(material, params=params, exact_alpha=None)


def _plain(name: str) -> tuple[Callable, Callable]:
    return (lambda m: float(m[name])), (lambda m, v: _replaced(m, name, float(v)))


def _term(name: str, k: int) -> tuple[Callable, Callable]:
    def put(m, v):
        values = list(m[name])
        values[k] = float(v)
        return _replaced(m, name, tuple(values))

    return (lambda m: float(m[name][k])), put


def _ogden(k: int) -> dict[str, tuple[Callable, Callable]]:
    """Ogden's term ``k``: its share of mu_0 (a stress), its exponent at that share (module docstring)."""
    def share(m):
        return 0.5 * m["mu"][k] * m["exponents"][k]

    def put_share(m, v):
        return _term("mu", k)[1](m, 2.0 * v / m["exponents"][k])

    def put_exponent(m, v):
        mu = 2.0 * share(m) / v if v != 0.0 else math.nan  # a zero exponent: outside the admissible set
        return _term("exponents", k)[1](_term("mu", k)[1](m, mu), v)

    return {"mu": (share, put_share), "exponents": (_term("exponents", k)[0], put_exponent)}


def keys(law: str, terms: int = 1) -> tuple[Key, ...]:
    """The keys of ``law`` (a name of ``LAWS``), ``terms`` terms for a listed parameter (Ogden), then
    ``PRESTRETCH``."""
    out = []
    for q in LAWS[law].parameters:
        names = [(f"{q.name}[{k}]", _term(q.name, k), _ogden(k)[q.name] if law == "ogden" else None)
                 for k in range(terms)] if q.listed else [(q.name, _plain(q.name), None)]
        for name, (get, put), unknown in names:
            out.append(Key(name, q.unit, _LOWER.get((law, q.name), -math.inf), math.inf, get, put, unknown))
    out.append(Key(PRESTRETCH, "dimensionless", 1.0, math.inf, lambda m: m.prestretch,
                   lambda m, v: dataclasses.replace(m, prestretch=float(v))))
    return tuple(out)


def key_named(all_keys, name: str, flag: str) -> Key:
    """The key called ``name`` among ``all_keys``; an InputError naming ``flag`` otherwise."""
    for key in all_keys:
        if key.name == name:
            return key
    raise InputError(f"{flag} = {name!r}, but the law's keys are {', '.join(k.name for k in all_keys)}")
