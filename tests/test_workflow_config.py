"""The workflow's config: bad configs stop before any job with the key named; the default config
plans every case and figure; a study and a figure added in config are planned."""
import re
import subprocess

import pytest
import yaml

SNAKEMAKE = ["snakemake", "--nolock", "-n", "--cores", "2"]


def dry_run(root, *extra):
    return subprocess.run(SNAKEMAKE + list(extra), cwd=root, capture_output=True, text=True, timeout=300)


def job_counts(output):
    """{rule: count} from snakemake's 'Job stats' table."""
    counts = {}
    for line in output.splitlines():
        m = re.match(r"^(\w+)\s+(\d+)(\s+\d+\s+\d+)?\s*$", line.strip())
        if m and m.group(1) != "total":
            counts[m.group(1)] = int(m.group(2))
    return counts


def test_default_config_plans_every_case_and_figure(root, tmp_path):
    done = dry_run(root, "--config", f"output_dir={tmp_path}")
    assert done.returncode == 0, done.stderr
    counts = job_counts(done.stdout)
    # 18 + 9 + 6 + 12 + 3 distinct cases; plate speed shares its dried states: 39 dryings.
    assert counts["compress"] == 48
    assert counts["dry"] == 39
    assert counts["figure"] == 18
    assert counts["report"] == 1 and counts["aggregate"] == 1


def write_config(tmp_path, change):
    """config/ci.yaml-style overrides in a file, merged over config/config.yaml by snakemake."""
    path = tmp_path / "extra.yaml"
    path.write_text(yaml.safe_dump(change))
    return path


@pytest.mark.parametrize("change, named", [
    ({"base": {"wall": {"G_Mpa": 18}}}, "G_Mpa"),                                   # misspelt key
    ({"base": {"drying": {"dryness": 1.5}}}, "1.5"),                                # out of range
    ({"base": {"cell": {"n_wall": "many"}}}, "many"),                               # wrong type
    ({"studies": {"extra": {"vary": {"dryness": [0.5]}, "colour": "red"}}}, "colour"),  # unknown key
    ({"studies": {"extra": {"vary": {"dryness": [1.5]}}}}, "drying.dryness = 1.5"),  # bad study value
    ({"studies": {"extra": {"vary": {"humidity": [0.5]}}}}, "humidity"),             # unknown axis
    ({"figures": {"fig99": {"family": "curves", "study": "nope", "title": "t", "x": "time_s", "y": ["area_m2"]}}},
     "nope"),                                                                        # unknown study
    ({"figures": {"fig99": {"family": "curves", "study": "plate_speed", "title": "t", "x": "time_s",
                            "y": ["stres"]}}}, "stres"),                             # unknown quantity
    ({"references": {"r": {"file": "data/references/none.csv", "strain_unit": "1", "stress_unit": "kPa",
                           "label": "l", "provenance": "p"}}}, "none.csv"),          # missing file
])
def test_bad_config_stops_before_any_job_and_names_the_key(root, tmp_path, change, named):
    done = dry_run(root, "--configfile", str(write_config(tmp_path, change)), "--config", f"output_dir={tmp_path}")
    assert done.returncode != 0
    message = done.stdout + done.stderr
    assert named in message, message[-2000:]
    assert "Job stats" not in done.stdout  # nothing was planned


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
