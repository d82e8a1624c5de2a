"""A creep curve against Carter and a fretting loop against Mindlin-Deresiewicz, from Python.

Run (after installing the package, README "From Python"):

    python examples/creep_and_fretting.py [OUT.png]

It solves the reference Carter scene at 50 creepages on one model (built once), the traction at one creepage, and
the reference fretting loop (P, then Q up to Q* = 0.5 mu P, down to -Q*, back up), and draws them beside the closed
forms computed here, into OUT.png (default creep_and_fretting.png).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import rollbem

SCENES = Path(__file__).resolve().parent.parent / "reference" / "scenes"


def hertz_half_width(load: float, radius: float, e_star: float) -> float:
    """2D Hertz: a^2 = 4PR/(pi E*)."""
    return math.sqrt(4.0 * load * radius / (math.pi * e_star))


def carter_force(xi: np.ndarray, mu: float, a: float, radius: float) -> np.ndarray:
    """Carter: |Q|/(mu P) = 1 - (1 - |xi| R/(mu a))^2, saturating at 1 for |xi| >= mu a/R."""
    s = np.minimum(np.abs(xi) * radius / (mu * a), 1.0)
    return 1.0 - (1.0 - s) ** 2


def carter_traction(x: np.ndarray, xi: float, mu: float, a: float, p0: float, radius: float) -> np.ndarray:
    """Carter's shear over mu p0, rolling towards +x: the stick zone of half-width c = a(1 - xi R/(mu a)) at the
    leading edge; q/(mu p0) = sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - ((x - a + c)/c)^2)."""
    c = a * (1.0 - xi * radius / (mu * a))
    full = np.sqrt(np.clip(1.0 - (x / a) ** 2, 0.0, None))
    stick = (c / a) * np.sqrt(np.clip(1.0 - ((x - (a - c)) / c) ** 2, 0.0, None))
    return full - stick


def creep_curve(ax_curve: plt.Axes, ax_traction: plt.Axes) -> None:
    scene = rollbem.Scene.from_file(SCENES / "carter-steady-rolling.toml").edit({"solvers.use": ["active_set"]})
    wheel = scene.to_dict()["wheel"]
    mu, radius, load = scene.friction, scene.radius, scene.drive["normal_load"]
    e_star = wheel["youngs_modulus"] / (1.0 - wheel["poisson_ratio"] ** 2)
    a = hertz_half_width(load, radius, e_star)
    p0 = 2.0 * load / (math.pi * a)
    xi_sat = mu * a / radius
    model = rollbem.Model(scene)
    xis = np.linspace(0.0, 1.5 * xi_sat, 50)
    reports = model.solve_all([{"creepage": float(x)} for x in xis], check=True)
    q = np.array([abs(r.run().tangential_load) / (mu * load) for r in reports])
    fine = np.linspace(0.0, 1.5 * xi_sat, 400)
    ax_curve.plot(fine / xi_sat, carter_force(fine, mu, a, radius), "k-", lw=1, label="Carter")
    ax_curve.plot(xis / xi_sat, q, "o", ms=3.5, color="tab:blue", label="rollbem (50 creepages, one model)")
    ax_curve.set_xlabel(r"creepage $\xi R/(\mu a)$")
    ax_curve.set_ylabel(r"creep force $|Q|/(\mu P)$")
    ax_curve.set_title(f"Creep curve, half-plane, $\\mu$ = {mu}, P = {load / 1000:g} kN/mm")
    ax_curve.legend(loc="lower right")
    ax_curve.grid(alpha=0.3)

    xi = 0.5 * xi_sat
    run = model.solve(creepage=xi).run()
    x = np.linspace(-a, a, 600)
    ax_traction.plot(x / a, np.sqrt(1 - (x / a) ** 2), ":", color="gray", lw=1, label=r"$\mu p/(\mu p_0)$ (Hertz)")
    ax_traction.plot(x / a, carter_traction(x, xi, mu, a, p0, radius), "k-", lw=1, label="Carter")
    colours = {"stick": "tab:green", "slip": "tab:red", "separated": "lightgray"}
    states = np.array(run.state_names)
    for name, colour in colours.items():
        sel = states == name
        ax_traction.plot(run.x[sel] / a, -run.shear[sel] / (mu * p0), "o", ms=3, color=colour, label=f"rollbem: {name}")
    ax_traction.set_xlim(-1.25, 1.25)
    ax_traction.set_ylim(-0.05, 1.3)
    ax_traction.set_xlabel("x / a   (rolling towards +x)")
    ax_traction.set_ylabel(r"shear $-q/(\mu p_0)$")
    ax_traction.set_title(r"Traction at $\xi = 0.5\,\mu a/R$")
    ax_traction.legend(loc="upper center", ncol=3, fontsize=8)
    ax_traction.grid(alpha=0.3)


def md_shift(branch: str, q: np.ndarray, q_star: float, mu_p: float, a: float, e_star: float, datum: float) -> np.ndarray:
    """Mindlin-Deresiewicz's tangential displacement of the counter-body against a log datum (2D, beta = 0):
    delta = lambda Q + (mu P/(pi E*)) {sgn(Q) Phi(1 - |Q|/mu P); -(2 Phi(g') - Phi(g*)); 2 Phi(g'') - Phi(g*)},
    lambda = (2/(pi E*))(ln(2D/a) + 1/2), Phi(g) = g ln g (tests/history.rs, src/theory/mindlin_deresiewicz.rs)."""

    def phi(g: np.ndarray) -> np.ndarray:
        return np.where(g > 0, g * np.log(np.where(g > 0, g, 1.0)), 0.0)

    lam = 2.0 / (math.pi * e_star) * (math.log(2.0 * datum / a) + 0.5)
    k = mu_p / (math.pi * e_star)
    g_star = 1.0 - q_star / mu_p
    if branch == "loading":
        return lam * q + np.sign(q) * k * phi(1.0 - np.abs(q) / mu_p)
    if branch == "unloading":
        return lam * q - k * (2.0 * phi(1.0 - (q_star - q) / (2.0 * mu_p)) - phi(g_star))
    return lam * q + k * (2.0 * phi(1.0 - (q_star + q) / (2.0 * mu_p)) - phi(g_star))


def fretting_loop(ax: plt.Axes) -> None:
    scene = rollbem.Scene.from_file(SCENES / "md-fretting-loop.toml").edit({"solvers.use": ["active_set"]})
    wheel = scene.to_dict()["wheel"]
    mu, radius = scene.friction, scene.radius
    load = scene.steps[0]["normal_load"]
    q_star = scene.steps[1]["tangential_load"]
    e_star = wheel["youngs_modulus"] / (1.0 - wheel["poisson_ratio"] ** 2)
    a = hertz_half_width(load, radius, e_star)
    mu_p = mu * load
    report = rollbem.run(scene, check=True)
    h = report.history()
    # The half-plane's datum is its material point at depth R; theory's log datum is D' = R e^(1/(2(1 - nu))); the
    # wheel's shift is minus the counter-body's delta.
    datum = radius * math.exp(0.5 / (1.0 - wheel["poisson_ratio"]))
    # In 2D the shift is mostly the elastic compliance lambda Q (linear in Q, ln(2D/a) large): the loop is drawn
    # with that linear part taken off, d_T + lambda Q, which leaves the micro-slip's hysteresis.
    lam = 2.0 / (math.pi * e_star) * (math.log(2.0 * datum / a) + 0.5)
    um = 1e3  # mm -> um
    branches = [("loading", 0.0, q_star), ("unloading", q_star, -q_star), ("reloading", -q_star, q_star)]
    for i, (branch, q0, q1) in enumerate(branches):
        q = np.linspace(q0, q1, 200)
        theory = -md_shift(branch, q, q_star, mu_p, a, e_star, datum) + lam * q
        ax.plot(theory * um, q / mu_p, "k-", lw=1, label="Mindlin-Deresiewicz" if i == 0 else None)
    shift = h["tangential_shift"] + lam * h["tangential_load"]
    ax.plot(shift * um, h["tangential_load"] / mu_p, "o", ms=3.5, color="tab:orange",
            label="rollbem (51 substeps, friction with memory)")
    w = np.sum(h["dissipated"][h["step"] >= 2])
    g = 1.0 - q_star / mu_p
    w_exact = 2.0 * mu_p**2 / (math.pi * e_star) * (1.0 - g * g + 2.0 * g * math.log(g))
    ax.text(0.97, 0.04, f"energy per cycle: {w:.4g} N·mm/mm (theory {w_exact:.4g})", transform=ax.transAxes,
            ha="right", va="bottom", fontsize=8)
    ax.set_xlabel(r"shift of the wheel less its elastic part, $d_T + \lambda Q$ [$\mu$m]")
    ax.set_ylabel(r"$Q/(\mu P)$")
    ax.set_title(f"Fretting loop, $Q^* = {q_star / mu_p:g}\\,\\mu P$")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)


def main() -> None:
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("creep_and_fretting.png")
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.8), constrained_layout=True)
    creep_curve(axes[0], axes[1])
    fretting_loop(axes[2])
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
