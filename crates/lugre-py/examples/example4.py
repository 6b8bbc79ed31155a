# The paper's Example 4 from Python: Theorem A, the minor loop's energies and a plot of the loop
# (as the paper's Fig. 15). Needs matplotlib: pip install matplotlib.
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import lugre

# The paper's Example 4: sigma0 = 6 (other parameters the paper's), bimodal input 0, 0.5, 1, 1.5.
hl = lugre.LuGre(sigma0=6).loop_bimodal(0, 0.5, 1, 1.5)
print(hl.theorem_a)                      # rho_0..rho_5, y° there, the minor loop [rho_1, rho_5]
major, minor = hl.loops
print(f"minor loop: W = {minor.work:.6f}, D = {minor.dissipation:.6f}, "
      f"dV = {minor.stored_energy_change:.6f}; work per period {hl.work_per_period:.6f}")

rho, u, y = hl.sample(2001)              # one period, float64 arrays
r = np.linspace(minor.start.rho, minor.end.rho, 500)
fig, ax = plt.subplots(figsize=(5, 4))
ax.plot(u, y, ":", color="gray", label="hysteresis loop $y^\\circ$")
ax.plot(hl.u_at(r), hl.y_at(r), "-", color="C0", label="minor loop $[\\varrho_1, \\varrho_5]$")
ax.plot(minor.start.u, minor.start.y, "o", mfc="none", color="C1", label="$t_1$")
ax.plot(minor.end.u, minor.end.y, "s", mfc="none", color="C3", label="$t_5$")
ax.set_xlabel("$u$"); ax.set_ylabel("$y^\\circ$"); ax.legend(loc="upper left"); fig.tight_layout()
fig.savefig("example4.png", dpi=100)  # crates/lugre-py/docs/example4.png
