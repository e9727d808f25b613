#!/usr/bin/env python3
"""CIELAB ΔE (1976) between palette colours as seen with normal vision and
under simulated protanopia, deuteranopia and tritanopia (Machado, Oliveira &
Fernandes 2009, severity 1), read from docs/colours.md's table.

  /usr/bin/python3 scripts/colour_blind_check.py [NAME NAME ...]

With names (e.g. polhode separatrix): those pairs; else every pair, worst first.
"""
import itertools
import pathlib
import re
import sys

import numpy as np

MACHADO = {
    "protan": [[0.152286, 1.052583, -0.204868], [0.114503, 0.786281, 0.099216], [-0.003882, -0.048116, 1.051998]],
    "deutan": [[0.367322, 0.860646, -0.227968], [0.280085, 0.672501, 0.047413], [-0.011820, 0.042940, 0.968881]],
    "tritan": [[1.255528, -0.076749, -0.178779], [-0.078411, 0.930809, 0.147602], [0.004733, 0.691367, 0.303900]],
}


def linear(c):
    c = np.asarray(c, float)  # the table's values as displayed (sRGB-encoded)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def lab(rgb_linear):
    xyz = np.array([[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722], [0.0193, 0.1192, 0.9505]]) @ np.clip(rgb_linear, 0, 1)
    f = xyz / np.array([0.95047, 1.0, 1.08883])
    f = np.where(f > 0.008856, np.cbrt(f), 7.787 * f + 16 / 116)
    return np.array([116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])])


def seen(c):
    out = {"normal": lab(linear(c))}
    for k, m in MACHADO.items():
        out[k] = lab(np.array(m) @ linear(c))
    return out


def table():
    doc = (pathlib.Path(__file__).resolve().parent.parent / "docs" / "colours.md").read_text()
    rows = re.findall(r"^\| `(\w+)` \|[^|]*\| ([^|]+) \| ([0-9.]+), ([0-9.]+), ([0-9.]+) \|$", doc, re.M)
    return {name: (colour.strip(), tuple(float(x) for x in rgb)) for name, colour, *rgb in rows}


def main():
    t = table()
    names = sys.argv[1:]
    pairs = list(itertools.combinations(names, 2)) if names else list(itertools.combinations([n for n in t if n != "ink"], 2))
    rows = []
    for a, b in pairs:
        sa, sb = seen(t[a][1]), seen(t[b][1])
        d = {k: float(np.linalg.norm(sa[k] - sb[k])) for k in sa}
        rows.append((min(d.values()), a, b, d))
    rows.sort()
    for worst, a, b, d in rows:
        print(f"{a} ({t[a][0]}) vs {b} ({t[b][0]}): worst ΔE {worst:.1f}  " + "  ".join(f"{k} {v:.1f}" for k, v in d.items()))


if __name__ == "__main__":
    main()
