"""The workflow's config: bad configs stop before any job with the key named; the default config
plans every case and figure; a study and a figure added in config are planned."""
import json
import subprocess

import pytest
import yaml

from analysis import matrix
from conftest import job_counts, workflow_config

SNAKEMAKE = ["snakemake", "--nolock", "-n", "--cores", "2"]


def dry_run(root, *extra):
    return subprocess.run(SNAKEMAKE + list(extra), cwd=root, capture_output=True, text=True, timeout=300)


def test_default_config_plans_every_case_and_figure(root, tmp_path):
    done = dry_run(root, "--config", f"output_dir={tmp_path}")
    assert done.returncode == 0, done.stderr
    counts = job_counts(done.stdout)
    # 18 + 9 + 6 + 12 + 3 distinct cases; plate speed shares its dried states: 39 dryings. Every
    # dryness of a cell dries from one settle: 3 turgors, 2 other G, 4 other thicknesses, 1 other size.
    assert counts["compress"] == 48
    assert counts["dry"] == 39
    assert counts["settle"] == counts["rest_case_file"] == 10
    assert counts["figure"] == 18
    assert counts["report"] == 1 and counts["aggregate"] == 1


# What the solver's static checks read of a case (its cell, wall, tissue, time step, fluid model and plates):
# one case of each is validated below.
SOLVER_CHECKED = ("cell", "wall", "tissue", "time", "heterogeneity")


@pytest.mark.parametrize("configs", [[], ["config/converged.yaml"]], ids=["config.yaml", "converged.yaml"])
def test_every_case_of_a_shipped_config_is_one_the_solver_accepts(root, cellsim, tmp_path, configs):
    """Every case a shipped config runs, of every target, passes `cellsim validate`, which builds its cell
    and holds its time step to the wall springs' limit: a case refused there stops its job (exit 2) partway
    through a target's run (converged.yaml's wall of t0 = 100 um at level 2, whose limit is 0.9997 ns, did
    so 17 minutes into the file's run at 1 ns). One case of each cell, wall, tissue, time step, fluid model
    and plate; the refused are named."""
    cases = matrix.expand(workflow_config(root, configs))
    distinct = {}
    for name, case in cases.items():
        checked = {section: case.case.get(section) for section in SOLVER_CHECKED}
        checked.update(fluid=case.case.get("fluid", {}).get("model"),
                       plates=case.case.get("compression", {}).get("plate_stiffness_N_m"))
        distinct.setdefault(json.dumps(checked, sort_keys=True, default=str), name)
    refused = {}
    for name in distinct.values():
        path = tmp_path / f"{name}.json"
        path.write_text(matrix.case_json(cases[name].case))
        done = subprocess.run([cellsim, "validate", str(path)], capture_output=True, text=True, timeout=120)
        if done.returncode != 0:
            refused[name] = done.stderr.strip()
    assert len(distinct) > 20
    assert not refused, refused


def test_each_drying_starts_from_a_rest_state_that_differs_only_where_the_settle_cannot_see(root):
    """What the solver allows (--from a state at rest: dryness, drying steps, compression, output) is
    all that separates a dried case from its rest case; and a dryness axis does not split rest states."""
    config = yaml.safe_load((root / "config" / "config.yaml").read_text())
    cases = matrix.expand(config)
    rests = matrix.rest_states(cases)
    for case in cases.values():
        rest = rests[case.rest]
        assert rest["drying"]["steps"] == 0 and rest["compression"] == {"steps": 0}
        differ = {f"{section}.{key}" for section in case.case for key in case.case[section]
                  if case.case[section][key] != rest.get(section, {}).get(key)}
        assert differ <= {"drying.dryness", "drying.steps"} | {f"compression.{k}" for k in case.case["compression"]}
        assert not any(p.startswith("X") for p in case.rest.split("_")) and case.dried.startswith(case.rest)
    dried_per_rest = {}
    for case in cases.values():
        dried_per_rest.setdefault(case.rest, set()).add(case.dried)
    assert len(dried_per_rest["D150_G18_P200_t6"]) == 6  # the baseline cell, at 1.0, 0.9, ... 0.1


def test_cases_that_would_share_a_rest_state_but_settle_differently_are_refused():
    a = matrix.Case("a_X1", "a_X1", "a", {}, {"cell": {"turgor_kPa": 200}, "drying": {}, "compression": {}})
    b = matrix.Case("a_X0.5", "a_X0.5", "a", {}, {"cell": {"turgor_kPa": 300}, "drying": {}, "compression": {}})
    with pytest.raises(matrix.ConfigError, match="'a'"):
        matrix.rest_states({"a_X1": a, "a_X0.5": b})


def write_config(tmp_path, change):
    """config/ci.yaml-style overrides in a file, merged over config/config.yaml by snakemake."""
    path = tmp_path / "extra.yaml"
    path.write_text(yaml.safe_dump(change))
    return path


@pytest.mark.parametrize("change, named", [
    ({"base": {"wall": {"G_Mpa": 18}}},                                              # misspelt key
     ["config: base.wall: unknown key 'G_Mpa'; did you mean 'G_MPa'?"]),
    ({"base": {"cell": {"turgor_kPA": 150}}},                                        # misspelt unit
     ["config: base.cell: unknown key 'turgor_kPA'; did you mean 'turgor_kPa'?"]),
    ({"base": {"drying": {"dryness": 1.5}}},                                         # out of range
     ["config: base.drying.dryness: 1.5 is greater than the maximum of 1.0"]),
    ({"base": {"cell": {"n_wall": "many"}}},                                         # wrong type
     ["config: base.cell.n_wall: 'many' is not of type 'integer'"]),
    ({"studies": {"extra": {"vary": {"dryness": [0.5]}, "colour": "red"}}},          # unknown key, nothing near
     ["config: studies.extra: unknown key 'colour'; known keys: design, target, title, vary"]),
    ({"studies": {"extra": {"vary": {"dryness": [1.5]}}}},                           # bad study value
     ["studies extra: axis dryness", "drying.dryness = 1.5"]),
    ({"studies": {"extra": {"vary": {"humidity": [0.5]}}}},                          # unknown axis
     ["studies.extra.vary.humidity: unknown axis"]),
    ({"figures": {"fig99": {"family": "curves", "study": "nope", "title": "t", "x": "time_s", "y": ["area_m2"]}}},
     ["figures.fig99.study: unknown study 'nope'"]),                                # unknown study
    ({"figures": {"fig99": {"family": "curves", "study": "plate_speed", "title": "t", "x": "time_s",
                            "y": ["stres"]}}}, ["figures.fig99: unknown quantity 'stres'"]),  # unknown quantity
    ({"references": {"r": {"file": "data/references/none.csv", "strain_unit": "1", "stress_unit": "kPa",
                           "label": "l", "provenance": "p"}}},
     ["references.r.file: no such file 'data/references/none.csv'"]),               # missing file
    ({"axes": {"G_again": {"key": "wall.G_MPa", "label": "Gg"}}},
     ["G_again", "its key 'wall.G_MPa'", "two axes cannot set one key"]),            # two axes, one key
    ({"compare_with": {"output_dir": "results", "label": "paper", "this_run": "ours", "figures": ["fig02"]}},
     ["compare_with.figures: 'fig02' is not a curves figure"]),                     # shapes have no curves
    ({"compare_with": {"output_dir": "results", "label": "paper"}},
     ["config: compare_with: 'this_run' is a required property"]),                  # incomplete comparison
    ({"base": {"cell": {"n_fluid": 8717, "n_wall": 4134}, "settle": {"max_iterations": 40000}}},
     ["axes.resolution: base sets cell.n_fluid = 8717", "as its value 2 does",
      "studies.convergence_resolution"]),                                          # level-2 cells called level 1
    ({"calibration": {"targets": {"my_probe": {"quantity": "volumetric_modulus_MPa", "where": {"dryness": 1.0},
                                               "value": 3.0, "provenance": "my lab"}}}},
     ["calibration.targets.my_probe: no uncertainty"]),                             # a target believed exactly
    ({"calibration": {"unknowns": ["contraction_N_m", "turgor_kPa"]}},
     ["calibration.unknowns: 'turgor_kPa' has no prior range"]),                     # an unknown without a prior
    ({"studies": {"sensitivity": {"design": {"factors": {"G_MPa": {"range": [18, 0.18]}}}}}},
     ["studies.sensitivity.design.factors.G_MPa.range: [18, 0.18] is not low < high"]),  # a design's bad range
])
def test_bad_config_stops_before_any_job_and_names_the_key(root, tmp_path, change, named):
    done = dry_run(root, "--configfile", str(write_config(tmp_path, change)), "--config", f"output_dir={tmp_path}")
    assert done.returncode != 0
    message = done.stdout + done.stderr
    for words in named:
        assert words in message, message[-2000:]
    assert "Job stats" not in done.stdout  # nothing was planned
    assert "Failed validating" not in message and len(message.splitlines()) < 8  # the key, not the schema


def test_a_comparison_with_its_own_output_folder_is_refused(root, tmp_path):
    change = {"compare_with": {"output_dir": str(tmp_path), "label": "paper", "this_run": "ours"}}
    done = dry_run(root, "--configfile", str(write_config(tmp_path, change)), "--config", f"output_dir={tmp_path}")
    assert done.returncode != 0
    assert f"compare_with.output_dir: '{tmp_path}' is this run's own output_dir" in done.stdout + done.stderr


def test_converged_config_plans_the_claims_three_ways_in_its_own_folder(root, tmp_path):
    """config/converged.yaml: the paper's 48 cases under converged SPH numerics (the same names), the band's
    3 + 3 (level 3 at 0.75 ns, level 2 at 0.5 ns), the closed cell's 26 claim cases at each of two K and its
    band's 3 + 3 at level 3, the texture analyser's 4; 18 + 1 figures; its own folder, not the paper's. The
    rate and drainage bounds are a target of their own (converged_bounds): 9 slower, 6 drained, and the
    quasi-static closed cell's 6 as their slow end, 2 figures."""
    assert yaml.safe_load((root / "config" / "converged.yaml").read_text())["output_dir"] == "results-converged"
    done = dry_run(root, "--configfile", "config/converged.yaml", "--printshellcmds", "--config", f"output_dir={tmp_path}")
    assert done.returncode == 0, done.stderr[-2000:]
    counts = job_counts(done.stdout)
    assert counts["compress"] == 48 + 6 + 2 * 26 + 6 + 4 and counts["figure"] == 19
    assert f"{tmp_path}/figures/texture01.png" in done.stdout and "rate01" not in done.stdout
    for name in ("D150_dt0.75_G18_P200_R3_t6_v1_X0.5", "D150_dt0.5_G18_P200_t6_v1_X0.1",
                 "D150_dt100_Fclosed_cell_G18_K2200_P200_t0.1_v1_X0.5", "D150_dt100_Fclosed_cell_G18_P200_R3_t6_v1_X1"):
        assert f"{tmp_path}/runs/{name}.h5" in done.stdout, name
    for setting in ('"n_fluid": 8717', '"model": "pressure"', '"h_over_dx": 1.2', '"dt_ns": 1', '"tolerance": 1e-05',
                    '"dt_ns": 0.75', '"model": "cavity"', '"scheme": "quasi_static"', '"dt_ns": 100'):
        assert setting in done.stdout, setting
    bounds = dry_run(root, "converged_bounds", "--configfile", "config/converged.yaml", "--printshellcmds",
                     "--config", f"output_dir={tmp_path}")
    assert bounds.returncode == 0, bounds.stderr[-2000:]
    counts = job_counts(bounds.stdout)
    assert counts["compress"] == 12 + 9 + 6 - 3 and counts["figure"] == 2  # 1 m/s closed: rate's and drainage's
    assert f"{tmp_path}/runs/D150_G18_P200_t6_v0.1_X0.1.h5" in bounds.stdout
    assert f"{tmp_path}/runs/D150_dt100_Fclosed_cell_G18_Lp1e-06_P200_t6_v1_X0.5.h5" in bounds.stdout


def test_converged_config_labels_the_levels_its_inherited_studies_vary_by_their_cells(root):
    """Its base is resolution level 2 at h0/dx 1.2, so the convergence target's studies would have called
    those cells level 1 and h0/dx 0.888 (and run level 2 twice, as 1 and 2): the file relabels the two axes."""
    cases = matrix.expand(workflow_config(root, ["config/converged.yaml"]))
    levels = {}
    for case in cases.values():
        if "convergence_resolution" in case.studies and case.values["dryness"] == 1.0:
            levels[case.values["resolution"]] = (case.case["cell"]["n_fluid"], case.case["cell"]["n_wall"])
    assert levels == {1: (3082, 2067), 2: (8717, 4134), 3: (24656, 8268)}
    smoothing = {case.values["smoothing"]: case.case["fluid"]["h_over_dx"] for case in cases.values()
                 if "smoothing_ratio" in case.studies and case.values["dryness"] == 1.0}
    assert smoothing == {0.888: None, 1.2: 1.2, 1.5: 1.5}  # None: the paper's h0, derived
    bodies = [json.dumps(case.case, sort_keys=True) for case in cases.values()]
    assert len(set(bodies)) == len(bodies), "two names, one case"


def test_added_study_and_figure_are_planned(root, tmp_path):
    change = {
        "studies": {"bending": {"vary": {"dryness": [1.0, 0.1], "k_b_J": [1e-10, 1e-9]}}},
        "axes": {"k_b_J": {"key": "wall.bending_stiffness_J", "label": "kb", "title": "k_b [J]"}},
        "base": {"wall": {"bending_stiffness_J": 1e-10}},
        "figures": {"fig19": {"family": "curves", "study": "bending", "title": "Bending stiffness", "x": "nominal_strain",
                              "y": ["plate_stress_Pa"], "lines": "k_b_J", "panels": "dryness"}},
    }
    done = dry_run(root, "--configfile", str(write_config(tmp_path, change)), "--config", f"output_dir={tmp_path}",
                   "--printshellcmds")
    assert done.returncode == 0, done.stderr[-2000:]
    counts = job_counts(done.stdout)
    assert counts["figure"] == 19
    assert counts["compress"] == 48 + 2  # k_b = 1e-10 is the base: only the 1e-9 cases are new
    assert "kb1e-09" in done.stdout and f"{tmp_path}/figures/fig19.png" in done.stdout
