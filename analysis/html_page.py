"""The HTML building blocks every page of the report uses (the index page, convergence, tissue,
extensions): the page with its style, tables from pandas frames, the figure list, the energy warning."""
import html
import os
import pathlib

from analysis import provenance


STYLE = ("body{font-family:sans-serif;max-width:1100px;margin:auto;padding:1em}"
         ".wide{overflow-x:auto}table{border-collapse:collapse;font-size:80%}td,th{border:1px solid #ccc;padding:2px 5px}"
         "img{max-width:100%}figure{margin:2em 0}.agree td.verdict{color:green}"
         ".disagree td.verdict{color:#b00}.not-run td.verdict,.not-reached td.verdict{color:grey}"
         ".warning{border:2px solid #b00;background:#fee;padding:0.5em 1em;margin:1em 0}")


def write_page(path, title, parts):
    """An HTML page of the report: its parts (HTML strings) in order, with the report's style, under a
    header naming the version and commit of the code that made it."""
    header = f"<p class='meta'>Made by {html.escape(provenance.line())}.</p>"
    pathlib.Path(path).write_text(f"<!doctype html><html><head><meta charset='utf-8'><title>{html.escape(title)}"
                                  f"</title><style>{STYLE}</style></head><body>{header}{''.join(parts)}</body></html>\n")


def figure_list(config, figure_files, here):
    """'Figures' and each figure (PNG relative to the page's folder `here`) with its title as caption."""
    parts = ["<h2>Figures</h2>"]
    for fig, png in figure_files.items():
        parts.append(f"<figure id='{fig}'><img src='{html.escape(os.path.relpath(png, here))}' alt='{fig}'>"
                     f"<figcaption><b>{fig}.</b> {html.escape(config['figures'][fig]['title'])}.</figcaption></figure>")
    return "".join(parts)


def untitled_figures(figure_files, here):
    """'Figures' and each figure (PNG relative to the page's folder `here`) without a caption: a target's own
    figures, which have no entry under config's `figures` (the sensitivity and calibrate pages)."""
    return "<h2>Figures</h2>" + "".join(
        f"<figure id='{name}'><img src='{html.escape(os.path.relpath(png, here))}' alt='{name}'></figure>"
        for name, png in figure_files.items())


def cell_text(value):
    """A table cell's text: numbers to 4 significant digits, whole numbers (counts) and numbers of
    10 000 and more in full (a force of 10690 uN, not 1.069e+04), NaN as empty, names as they are."""
    if isinstance(value, float):
        if value != value:
            return ""
        in_full = (value.is_integer() or abs(value) >= 1e4) and abs(value) < 1e15
        return f"{value:.0f}" if in_full else f"{value:.4g}"
    return html.escape(str(value))


def frame_table(frame):
    """A pandas frame as an HTML table, headings from its columns; a table wider than the page scrolls in
    its own box, not the page."""
    head = "".join(f"<th>{html.escape(str(c))}</th>" for c in frame.columns)
    body = "".join("<tr>" + "".join(f"<td>{cell_text(v)}</td>" for v in row) + "</tr>"
                   for row in frame.itertuples(index=False))
    return f"<div class='wide'><table><tr>{head}</tr>{body}</table></div>"


ENERGY_TOLERANCE = 0.1  # |energy residual| over the plate work of a compression above which it is flagged


def energy_box(summary):
    """Compressions whose energy account does not close (docs/model.md §8): the residual is more than a tenth
    of the plate work, so energy was made or lost by the numerics (at the default settings it is about 1 %).
    A visible box, or nothing."""
    column = "compression_energy_residual_over_work"
    if column not in summary.columns:
        return ""
    flagged = summary[summary[column].abs() > ENERGY_TOLERANCE]
    if flagged.empty:
        return ""
    items = "".join(f"<li><code>{html.escape(r['case'])}</code>: residual {100 * r[column]:+.0f} % of the plate work"
                    f"</li>" for _, r in flagged.iterrows())
    return (f"<div class='warning'><b>Warning: {len(flagged)} of {len(summary)} compressions do not conserve "
            f"energy</b> (the residual of the energy account is more than {100 * ENERGY_TOLERANCE:.0f} % of the plate "
            f"work): the numerics made or destroyed that energy, usually because the time step is too large for the "
            f"case. Their curves are not physics where the residual grows (time series energy_residual_J); try half "
            f"the time step.<ul>{items}</ul></div>")


WARNING_KINDS = ("start", "cap", "energy")


def warning_kind(part):
    """What one of the solver's warnings is about: the compression's cap ('compression reached ...'), an
    energy account left open ('energy account: ...', past kEnergyResidualTolerance), or the start and the
    drying (the rest)."""
    if part.startswith("compression reached"):
        return "cap"
    return "energy" if part.startswith("energy account") else "start"


def _warning_parts(summary, kind):
    """Each case's warnings ('; '-joined by the solver) of one kind (WARNING_KINDS), as {case: text} of the
    cases that have any."""
    out = {}
    for _, row in summary.iterrows():
        parts = [p for p in str(row.get("warning") or "").split("; ") if p and warning_kind(p) == kind]
        if parts:
            out[row["case"]] = "; ".join(parts)
    return out


def warnings_box(summary):
    """Cases whose start or drying did not end as it should (drying at its cap unsteady, a relaxation at
    rest that did not converge), and stages whose energy account is open: visible boxes at the top; and,
    as a note below them, the compressions that stopped at compression.steps before the end they were
    asked for (their curves end short)."""
    if "warning" not in summary.columns:
        return ""
    summary = summary.assign(warning=summary["warning"].fillna(""))
    flagged, capped, open_account = (_warning_parts(summary, kind) for kind in WARNING_KINDS)

    def items(cases):
        return "<ul>" + "".join(f"<li><code>{html.escape(c)}</code>: {html.escape(w)}</li>" for c, w in cases.items()) + "</ul>"

    box = ""
    if flagged:
        box += (f"<div class='warning'><b>Warning: {len(flagged)} of {len(summary)} cases did not reach steady "
                f"state as they should.</b> Their compressions start from a cell still settling; raise drying.steps "
                f"or settle.max_iterations in config.{items(flagged)}</div>")
    if open_account:
        box += (f"<div class='warning'><b>Warning: {len(open_account)} of {len(summary)} cases leave their energy "
                f"account open</b> (a stage's residual beyond the solver's tolerance, docs/model.md §8): energy "
                f"was made or lost that no term of the account explains.{items(open_account)}</div>")
    if capped:
        box += (f"<details><summary>Note: {len(capped)} of {len(summary)} compressions stopped at their cap "
                f"(compression.steps) before the end they were asked for; their curves end at the strain "
                f"given.</summary>{items(capped)}</details>")
    return box
