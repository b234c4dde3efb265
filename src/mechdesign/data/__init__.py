"""Engineering data shipped with the package (catalogues and material tables).

The files are in course units with the unit in each column or key name (mm, MPa, kW,
rpm, kN); :mod:`mechdesign.data.catalogues` converts them to SI once, at this boundary.
"""
from __future__ import annotations

import csv
from functools import lru_cache
from importlib import resources

import yaml


@lru_cache(maxsize=None)
def load_yaml(name: str):
    """Parse the shipped YAML file ``name`` (e.g. ``"materials.yaml"``). libyaml's safe
    loader where PyYAML has it (ten times the pure-Python loader's speed: ~0.08 s of a
    run); these files are ours, so the brief loader's limits are not needed here."""
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    with resources.files(__name__).joinpath(name).open(encoding="utf-8") as fh:
        return yaml.load(fh, Loader=loader)  # noqa: S506 - a safe loader


@lru_cache(maxsize=None)
def load_csv(name: str) -> tuple[dict, ...]:
    """Rows of the shipped CSV file ``name`` as dicts of strings (lines starting
    with ``#`` are comments)."""
    with resources.files(__name__).joinpath(name).open(encoding="utf-8") as fh:
        lines = [line for line in fh if not line.startswith("#")]
    return tuple(csv.DictReader(lines))
