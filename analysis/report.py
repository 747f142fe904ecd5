"""The reproduction report (HTML): intro, the findings (this run's, then the project's), the paper's claims
against this run, every figure with its caption, the run matrix, and the model closures. Sources:
paper/report_intro.md, docs/findings.md, docs/model-closures.md."""
import datetime
import html
import os
import pathlib

import markdown

from analysis import bounds, columns, comparison, findings, numerical_band
from analysis.claims import METHOD
from analysis.html_page import cell_text, energy_box, warnings_box, write_page
from analysis.matrix import figure_cases, figure_studies


def caption(config, fig, cases, band=None):
    """The figure's title, studies and cases, reference curves, and with `band` (the LJ ladder's table) the
    level 1 to 2 change of what it plots."""
    spec = config["figures"][fig]
    names = figure_cases(config, fig, cases)
    studies = ", ".join(f"'{s}'" for s in figure_studies(spec))
    text = f"{spec['title']}. {spec.get('caption', '')} Stud{'ies' if ',' in studies else 'y'} {studies}, {len(names)} cases"
    if spec.get("where"):
        text += " with " + ", ".join(f"{k} = {v}" for k, v in spec["where"].items())
    text += "."
    refs = spec.get("references", [])
    if refs:
        text += " Reference curves: " + "; ".join(
            f"{config['references'][r]['label']}: {config['references'][r]['provenance']}" for r in refs) + "."
        text += " No dried-apple reference data are available; none are drawn."
    if band is not None:
        text += " " + numerical_band.caption(band, spec, config["numerical_band"]["file"])
    return text


def claims_table(rows):
    """The claims with their curve-level verdicts, the old point values beside them, and the method."""
    number = lambda v: "" if v != v else f"{v:.4g}"  # noqa: E731 (NaN: empty)
    band = any("level_1_to_2" in r for r in rows)  # the LJ ladder's change of what the claim's figure plots
    out = [f"<p>{html.escape(METHOD)}</p>",
           "<table><tr><th>paper's claim</th><th>fig</th><th>measured here</th><th>value</th>"
           "<th>agree if</th><th>verdict</th><th>point value (strain 0.05)</th><th>note</th>"
           + ("<th>numerical band: level 1 to 2</th>" if band else "") + "</tr>"]
    for r in rows:
        out.append(f"<tr class='{r['verdict'].replace(' ', '-')}'><td>{html.escape(r['claim'])}</td><td>{r['figure']}</td>"
                   f"<td>{html.escape(r['measured'])}</td><td>{number(r['value'])}</td><td>{html.escape(r['threshold'])}</td>"
                   f"<td class='verdict'><b>{r['verdict']}</b></td><td>{number(r.get('point_value', float('nan')))}</td>"
                   f"<td>{html.escape(str(r.get('note', '')))}</td>"
                   + (f"<td>{html.escape(str(r.get('level_1_to_2', '')))}</td>" if band else "") + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def matrix_table(summary, axes, cell_links=None):
    """One row per case; with cell_links ({case: relative path}), a link to its 3-D page."""
    columns = ["case"] + list(axes) + ["studies", "drying_steady_time_us", "dried_M_over_M0", "dried_V_over_V0",
                                       "dried_mean_pressure_kPa",
                                       "strain_reached", "compression_at_cap", "stress_kPa_at_0.05", "stress_kPa_at_0.10",
                                       "peak_force_top_uN"]
    columns = [c for c in columns if c in summary.columns]
    links = cell_links or {}
    head = ("<th>3-D</th>" if links else "") + "".join(f"<th>{html.escape(c)}</th>" for c in columns)
    body = []
    for _, row in summary[columns].iterrows():
        cells = "".join(f"<td>{cell_text(v)}</td>" for v in row)
        if links:
            link = links.get(row["case"])
            cells = (f"<td><a href='{html.escape(link)}'>view</a></td>" if link else "<td></td>") + cells
        body.append(f"<tr>{cells}</tr>")
    return f"<div class='wide'><table><tr>{head}</tr>{''.join(body)}</table></div>"  # scrolls in its own box


def write(path, config, cases, summary, claim_rows, figure_files, root=".", cell_pages=(), column_rows=None,
          band=None):
    """cell_pages: the cases' 3-D pages (analysis/cell_view.py), linked from the run matrix; column_rows:
    this run's claim columns (analysis/columns.py), set beside the other run's claims where given."""
    root = pathlib.Path(root)
    here = pathlib.Path(path).parent
    cell_links = {pathlib.Path(p).stem: os.path.relpath(p, here) for p in cell_pages}
    parts = [markdown.markdown((root / "paper" / "report_intro.md").read_text())]
    parts.append(f"<p class='meta'>Generated {datetime.date.today().isoformat()} from {len(cases)} cases "
                 f"(output folder <code>{html.escape(config['output_dir'])}</code>).</p>")
    if comparison.other(config):
        other_dir, other_label, this_label = comparison.other(config)
        parts.append(f"<p class='meta'>This run: the <b>{html.escape(this_label)}</b>, beside the "
                     f"{html.escape(other_label)} (<code>{html.escape(other_dir)}</code>).</p>")
        parts.append(comparison.made_by_note(config))
    parts.append(warnings_box(summary))
    parts.append(energy_box(summary))
    parts.append(findings.section(config, summary, claim_rows, root))
    parts.append("<h2>The paper's claims and this run</h2>")
    parts.append(claims_table(claim_rows))
    if column_rows and comparison.other(config):
        other_dir, other_label, _ = comparison.other(config)
        parts.append(f"<h2>The claims judged {1 + len(column_rows)} ways</h2>"
                     + comparison.missing_note(config)
                     + columns.section(config, column_rows, comparison.read_other_claims(comparison.other_claims_file(config)),
                                       other_label))
    elif comparison.other(config):
        parts.append(f"<h2>The claims under both configurations</h2>{comparison.section(config, claim_rows)}")
    parts.append(bounds.section(config, summary))
    parts.append(bounds.texture_section(config, summary, root))
    parts.append("<h2>Figures</h2>")
    for fig, png in figure_files.items():
        rel = os.path.relpath(png, here)
        parts.append(f"<figure id='{fig}'><img src='{html.escape(rel)}' alt='{fig}'>"
                     f"<figcaption><b>{fig}.</b> {html.escape(caption(config, fig, cases, band))}</figcaption></figure>")
    parts.append("<h2>Run matrix</h2>")
    if cell_links:
        parts.append("<p>'view' opens the case in 3-D: the wall as a surface and the fluid as points, turned with the "
                     "mouse, a slider over the snapshots of drying and compression, coloured by fluid pressure or "
                     "wall bond strain. The pages work offline, from this folder.</p>")
    parts.append(matrix_table(summary, config["axes"], cell_links))
    parts.append("<h2>Convergence and the wall-fluid coupling</h2>")
    parts.append("<p>How much of these curves is the particle count? The convergence studies (three resolutions, "
                 "two time steps, and the paper's Lennard-Jones coupling against our pressure coupling) are a target "
                 "of their own: <code>snakemake --cores 2 convergence</code> writes "
                 "<a href='convergence.html'>convergence.html</a> beside this page, with its tables and figures (the "
                 "link works once that target has run). What they showed is summed up under 'Convergence' in the "
                 "model closures below.</p>")
    parts.append("<h2>Tissues</h2>")
    parts.append("<p>The paper's future work: tissues of 8 and 27 of its cells, bonded by a middle lamella, dried "
                 "and compressed beside the single cell (docs/model.md §10). They are a target of their own: "
                 "<code>snakemake --cores 2 tissue</code> writes <a href='tissue.html'>tissue.html</a> beside this "
                 "page (the link works once that target has run), with the tissues' stress against the single "
                 "cell's, their shrinkage against reference lines, and their bonds. The same target runs a slab "
                 "of cells periodic in x and y, with a strain gauge inside it, and answers the paper's conjecture "
                 "that a tissue is less stiff than one cell from its numbers; what it found is under 'The tissue "
                 "study' in the model closures below.</p>")
    parts.append("<h2>Model closures</h2>")
    parts.append(markdown.markdown((root / "docs" / "model-closures.md").read_text(), extensions=["tables"]))
    write_page(path, "cellsim reproduction report", parts)
