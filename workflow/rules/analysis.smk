# Manifest, tidy tables, one job per figure, and the report.
rule manifest:
    output:
        f"{OUT}/manifest.csv",
    params:
        cases=lambda w: [(c.name, c.dried, c.studies, c.values, case_file(c.name), run_file(c.name))
                         for c in map(CASES.get, DEFAULT_CASES)],
    script:
        "../scripts/manifest.py"


rule aggregate:
    input:
        runs=[run_file(c) for c in DEFAULT_CASES],
    output:
        timeseries=f"{OUT}/tables/timeseries.csv",
        summary=f"{OUT}/tables/summary.csv",
    script:
        "../scripts/aggregate.py"


# Each target but the default aggregates its own cases into tables/<target>/ (convergence, tissue, ...).
TARGET_CASES = {t: matrix.target_cases(config, CASES, t) for t in matrix.targets(config)}


rule aggregate_target:
    input:
        runs=lambda w: [run_file(c) for c in TARGET_CASES[w.target]],
    output:
        timeseries=f"{OUT}/tables/{{target}}/timeseries.csv",
        summary=f"{OUT}/tables/{{target}}/summary.csv",
    wildcard_constraints:
        target="|".join(TARGET_CASES) or "no-target",
    script:
        "../scripts/aggregate.py"


def figure_inputs(wildcards):
    # This run's files of the figure, as render.files_under names them: its cases' runs and dried states, and
    # the claim columns' counterparts and band beside them (analysis/columns.py).
    files = render.files_under(config, wildcards.fig, OUT, CASES)
    names = matrix.figure_cases(config, wildcards.fig, CASES)
    refs = [config["references"][r]["file"] for r in config["figures"][wildcards.fig].get("references", [])]
    # The other run's results of the same cases, where they exist (compare_with; analysis/comparison.py).
    other = (list(comparison.other_runs(config, {n: CASES[n] for n in names}).values())
             if comparison.overlaid(config, wildcards.fig) else [])
    return {"runs": list(files["runs"].values()), "dried": sorted(files["dried"].values()), "references": refs,
            "other_runs": other, "column_runs": [files["column_runs"][n] for n in sorted(files["column_runs"])]}


rule figure:
    input:
        unpack(figure_inputs),
    output:
        png=f"{OUT}/figures/{{fig}}.png",
        pdf=f"{OUT}/figures/{{fig}}.pdf",
    params:
        spec=lambda w: config["figures"][w.fig],
    script:
        "../scripts/figure.py"


rule report:
    input:
        summary=f"{OUT}/tables/summary.csv",
        timeseries=f"{OUT}/tables/timeseries.csv",
        figures=expand(f"{OUT}/figures/{{fig}}.png", fig=FIGURES),
        sources=["paper/report_intro.md", "docs/findings.md", "docs/model-closures.md"],
        band=[config["numerical_band"]["file"]] if "numerical_band" in config else [],  # the LJ ladder's table
        # The other run's claims, once it exists (compare_with): the report sets them beside this run's.
        other_claims=lambda w: [p for p in [comparison.other_claims_file(config)] if p and os.path.exists(p)],
        cells=expand(f"{OUT}/report/cells/{{case}}.html", case=DEFAULT_CASES),
        js=[f"{OUT}/report/js/three.min.js", f"{OUT}/report/js/OrbitControls.js"],
    output:
        html=f"{OUT}/report/index.html",
        claims=f"{OUT}/tables/claims.csv",
        columns=f"{OUT}/tables/claim_columns.csv",      # config claim_columns (analysis/columns.py); empty without
        provenance=f"{OUT}/tables/provenance.json",     # the version and commit that made the tables
    script:
        "../scripts/report.py"


# The cell in 3-D in the browser: one page per case, and three.js from Debian's libjs-three copied
# beside them, so the report works offline from the results folder.
THREE_JS = "/usr/share/javascript/three"


rule three_js:
    output:
        three=f"{OUT}/report/js/three.min.js",
        controls=f"{OUT}/report/js/OrbitControls.js",
    params:
        source=THREE_JS,
    shell:
        "test -f {params.source:q}/three.min.js || "
        "{{ echo 'three.js not found in {params.source}: install libjs-three (scripts/setup)' >&2; exit 1; }}; "
        "cp {params.source:q}/three.min.js {output.three:q} && "
        "cp {params.source:q}/examples/js/controls/OrbitControls.js {output.controls:q}"


rule cell_view:
    input:
        run=lambda w: run_file(w.case),
        dried=lambda w: dried_file(CASES[w.case].dried),
        template="paper/cell_view.html",
        code="analysis/cell_view.py",
    output:
        html=f"{OUT}/report/cells/{{case}}.html",
        data=f"{OUT}/report/cells/{{case}}.data.js",
    params:
        plate_um=lambda w: matrix.get_key(CASES[w.case].case, "compression.plate_length_um") or 150.0,
    script:
        "../scripts/cell_view.py"
