"""Limited-memory BFGS with a backtracking line search, numpy only.

The log-linear model's objective is convex and smooth; a fixed number of Adam steps
stops wherever the step count says, so the model depended on how many features it had
(Adam moves every weight by about the same step, rare or not). Minimising to
convergence makes the penalty alone decide how large weights grow.
"""
from __future__ import annotations

import numpy as np

MEMORY = 10


def minimise(value_and_gradient, x0: np.ndarray, iterations: int = 200,
             tolerance: float = 1e-6) -> tuple[np.ndarray, int]:
    """(the minimiser of a smooth function from `x0` (1-d), the iterations it took):
    `value_and_gradient(x) -> (f, grad)`."""
    x = x0.copy()
    f, g = value_and_gradient(x)
    steps: list = []    # (s, y, 1 / y.s) of the last MEMORY iterations
    done = 0
    for done in range(1, iterations + 1):
        if np.abs(g).max() < tolerance:
            done -= 1
            break
        d = _direction(g, steps)
        slope = g @ d
        if slope >= 0:                      # not a descent direction: forget the curvature
            steps.clear()
            d, slope = -g, -(g @ g)
        t = 1.0 if steps else min(1.0, 1.0 / (np.abs(g).sum() + 1e-12))
        while True:
            xn = x + t * d
            fn, gn = value_and_gradient(xn)
            if fn <= f + 1e-4 * t * slope or t < 1e-10:
                break
            t *= 0.5
        s, y = xn - x, gn - g
        sy = s @ y
        if sy > 1e-10:
            steps.append((s, y, 1.0 / sy))
            if len(steps) > MEMORY:
                steps.pop(0)
        if f - fn < 1e-12 * max(1.0, abs(f)):
            x, f, g = xn, fn, gn
            break
        x, f, g = xn, fn, gn
    return x, done


def _direction(g: np.ndarray, steps: list) -> np.ndarray:
    """-H g by the two-loop recursion over the remembered steps."""
    q = g.copy()
    alphas = []
    for s, y, rho in reversed(steps):
        a = rho * (s @ q)
        q -= a * y
        alphas.append(a)
    if steps:
        s, y, _ = steps[-1]
        q *= (s @ y) / (y @ y)
    for (s, y, rho), a in zip(steps, reversed(alphas)):
        q += (a - rho * (y @ q)) * s
    return -q
