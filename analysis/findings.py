"""The report's findings section: first what this run's own tables say (its configuration and how far to
trust it, the claims' verdicts, the dried volumes, the base cell's stresses, the energy account), each
number computed here from the run; then the project's findings from all its targets, docs/findings.md,
whose numbers come from runs this one did not make and say so."""
import html
import pathlib

import markdown
import numpy as np

from analysis import matrix
from analysis.claims import rows_at

LEVEL_1_WALL = 2067  # the paper's wall particle count: resolution level 1 (docs/findings.md)


def configuration(config):
    """(coupling, resolution in words, words on how far this configuration's stresses are converged)."""
    base = config["base"]
    coupling = base.get("coupling", {}).get("model", "lennard_jones")
    n_wall = base.get("cell", {}).get("n_wall", LEVEL_1_WALL)
    level = round(np.log2(n_wall / LEVEL_1_WALL)) + 1  # each level doubles the wall particles
    if level < 1:
        return (coupling, f"reduced cells ({n_wall} wall particles, coarser than the paper's level 1)",
                "a quick look: its numbers are not the paper's and not converged")
    resolution = f"resolution level {level}"
    if coupling == "lennard_jones":
        trust = ("the paper's Lennard-Jones coupling: its stresses depend on the particle count at every strain "
                 "(findings 6-7 below), so read them as the paper's model, not as converged numbers; at the paper's "
                 "level 1 each figure's caption and each claim give their band from level 1 to 2 (the LJ ladder)")
    elif level >= 2:
        trust = ("the pressure coupling: its stresses hold to 8 % up to strain 0.05 at level 2, a band rather than a "
                 "converged value (finding 3 below), and are banded beyond (finding 6 below)")
    else:
        trust = "the pressure coupling at level 1: up to strain 0.05 within 0-16 % of level 2 (finding 3 below)"
    return coupling, resolution, trust


def this_run(config, summary, claim_rows):
    """Sentences of this run's numbers (HTML list items)."""
    coupling, resolution, trust = configuration(config)
    name = {"lennard_jones": "Lennard-Jones"}.get(coupling, coupling)
    items = [f"{len(summary)} cases, {html.escape(name)} coupling, "
             f"{html.escape(resolution, quote=False)}: {html.escape(trust, quote=False)}."]
    verdicts = [row["verdict"] for row in claim_rows]
    counts = ", ".join(f"{verdicts.count(v)} {v}" for v in ("agree", "disagree", "not reached", "not run")
                       if verdicts.count(v))
    items.append(f"The paper's {len(verdicts)} claims: {counts} (the claims table below).")
    base = {axis: matrix.base_value(config, axis) for axis in config["axes"] if axis != "dryness" and axis in summary}
    base = {axis: value for axis, value in base.items() if value is not None}
    cells = rows_at(summary, **base).sort_values("dryness", ascending=False)
    if len(cells):
        dried = ", ".join(f"{row.dried_V_over_V0:.3f} at X/X0 = {matrix.fmt(row.dryness)}"
                          for row in cells.itertuples() if row.dryness < 1)
        if dried:
            items.append(f"Volume at the end of drying, V/V0: {dried} (the base cell).")
        fresh = cells[np.isclose(cells["dryness"], 1.0)].head(1)
        stress = {strain: fresh[f"smoothed_stress_kPa_at_{strain}"].iloc[0] for strain in ("0.05", "0.10")
                  if len(fresh) and f"smoothed_stress_kPa_at_{strain}" in fresh}
        reached = [f"{value:.1f} kPa at strain {strain}" for strain, value in stress.items() if np.isfinite(value)]
        if reached:
            items.append(f"The fresh base cell's plate stress: {' and '.join(reached)} (mean over +-0.01 strain).")
    residual = summary["compression_energy_residual_over_work"].abs().dropna()
    if len(residual):
        items.append(f"The energy account of the compressions: residual {100 * residual.min():.2g}-"
                     f"{100 * residual.max():.2g} % of the plate work (median {100 * residual.median():.2g} %).")
    return items


def section(config, summary, claim_rows, root="."):
    """'Findings': this run's numbers, then the project's findings and limitations (docs/findings.md)."""
    text = (pathlib.Path(root) / "docs" / "findings.md").read_text()
    body = text.split("\n", 1)[1]  # its own title gives way to the report's headings
    # sane_lists keeps each section's numbering (findings 6-11 start at 6): the text cites findings by number.
    project = markdown.markdown(body.replace("\n## ", "\n### "), extensions=["tables", "sane_lists"])
    return ("<h2>Findings</h2><h3>This run</h3><ul>" + "".join(f"<li>{item}</li>" for item in
            this_run(config, summary, claim_rows)) + "</ul><h3>What the project's runs found</h3>"
            "<p class='meta'>From docs/findings.md: the numbers there come from the targets named with each "
            "finding, not from this run.</p>" + project)
