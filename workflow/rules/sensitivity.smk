# The sensitivity and calibrate targets (issue 70; config: the studies with these targets, and `calibration`),
# never built by the default target:
#   sensitivity  a quasi-random design's closed-cell runs, an emulator of their answers checked on held-out
#                runs, Sobol indices beside one-at-a-time sensitivities, and the emulator's slider page
#   calibrate    the wall's unknowns against measured numbers: a posterior by MCMC on an emulator of the
#                calibration design's dried cells, its predictive beside the data, a run at its median
DESIGN_STUDIES = {"sensitivity": "sensitivity", "calibrate": config.get("calibration", {}).get("study")}
DESIGN_CASES = {t: matrix.target_cases(config, CASES, t) for t in DESIGN_STUDIES}


def design_files(study):
    """A design's result files: the compressed runs, or the dried states where nothing asks for a stress (a
    calibration whose targets are all of the drying: eps, V/V0)."""
    target = matrix.target_of(config, study)
    drying_only = target == "calibrate" and all(
        t.get("quantity") != "stress_kPa" for t in config["calibration"]["targets"].values())
    if drying_only:
        return sorted({dried_file(CASES[c].dried) for c in DESIGN_CASES[target]})
    return [run_file(c) for c in DESIGN_CASES[target]]


rule design_table:
    input:
        runs=lambda w: design_files(w.study),
        code=["analysis/design_runs.py", "analysis/design.py"],
    output:
        f"{OUT}/tables/design/{{study}}.csv",
    wildcard_constraints:
        study="|".join(s for s in DESIGN_STUDIES.values() if s),
    script:
        "../scripts/design_table.py"


rule sensitivity:
    input:
        page=f"{OUT}/report/sensitivity.html",
        emulator=f"{OUT}/report/emulator.html",


rule sensitivity_analysis:
    input:
        table=f"{OUT}/tables/design/sensitivity.csv",
        code=["analysis/sensitivity.py", "analysis/emulator.py", "analysis/sobol.py", "analysis/emulator_page.py",
              "analysis/sensitivity_page.py", "analysis/figures/sensitivity.py"],
    params:
        study="sensitivity",
    output:
        held_out=f"{OUT}/tables/sensitivity/held_out.csv",
        indices=f"{OUT}/tables/sensitivity/sobol.csv",
        check_point=f"{OUT}/tables/sensitivity/check_point.csv",
        emulators=f"{OUT}/tables/sensitivity/emulators.json",
        sensitivity_indices_png=f"{OUT}/figures/sensitivity_indices.png",
        sensitivity_indices_pdf=f"{OUT}/figures/sensitivity_indices.pdf",
        sensitivity_held_out_png=f"{OUT}/figures/sensitivity_held_out.png",
        sensitivity_held_out_pdf=f"{OUT}/figures/sensitivity_held_out.pdf",
        emulator_page=f"{OUT}/report/emulator.html",
        emulator_data=f"{OUT}/report/emulator.data.js",
        html=f"{OUT}/report/sensitivity.html",
    script:
        "../scripts/sensitivity.py"


CAL = f"{OUT}/tables/calibration"


rule calibrate:
    input:
        page=f"{OUT}/report/calibrate.html",


rule calibration_posterior:
    input:
        table=lambda w: f"{OUT}/tables/design/{config['calibration']['study']}.csv",
        code=["analysis/calibration.py", "analysis/emulator.py", "analysis/figures/calibration.py"],
    output:
        judged=f"{CAL}/emulators_judged.csv",
        emulators=f"{CAL}/emulators.json",
        posterior=f"{CAL}/posterior.csv",
        samples=f"{CAL}/samples.csv",
        diagnostics=f"{CAL}/diagnostics.json",
        predictive=f"{CAL}/predictive.csv",
        recovery=f"{CAL}/recovery.csv",
        posterior_png=f"{OUT}/figures/calibration_posterior.png",
        posterior_pdf=f"{OUT}/figures/calibration_posterior.pdf",
        predictive_png=f"{OUT}/figures/calibration_predictive.png",
        predictive_pdf=f"{OUT}/figures/calibration_predictive.pdf",
    script:
        "../scripts/calibrate.py"


# One full run at the posterior's median per moisture level the targets name (a solver run: not local).
rule calibration_confirm:
    input:
        exe=SOLVER,
        posterior=f"{CAL}/posterior.csv",
        emulators=f"{CAL}/emulators.json",
    output:
        table=f"{CAL}/confirm.csv",
        folder=directory(f"{OUT}/runs/calibration_median"),
    script:
        "../scripts/calibration_confirm.py"


rule calibration_page:
    input:
        judged=f"{CAL}/emulators_judged.csv",
        posterior=f"{CAL}/posterior.csv",
        predictive=f"{CAL}/predictive.csv",
        confirm=f"{CAL}/confirm.csv",
        recovery=f"{CAL}/recovery.csv",
        diagnostics=f"{CAL}/diagnostics.json",
        posterior_png=f"{OUT}/figures/calibration_posterior.png",
        predictive_png=f"{OUT}/figures/calibration_predictive.png",
        code="analysis/calibration_page.py",
    output:
        html=f"{OUT}/report/calibrate.html",
    script:
        "../scripts/calibration_page.py"
