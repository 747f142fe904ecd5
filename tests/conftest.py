"""Shared fixtures and helpers: where the built solver is, the repository root, small solver runs, and
the workflow run as a user runs it (a config merged over config/config.yaml, into its own folder):
the CI study and the tiny matrix, each run once per test session for every test that reads it."""
import os
import pathlib
import re
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the analysis package

from analysis import matrix  # noqa: E402


def between_markers(text, marker):
    """What a document holds between its `<!-- begin marker -->` line and `<!-- end marker -->`."""
    begin, end = f"<!-- begin {marker} -->\n", f"<!-- end {marker} -->"
    assert begin in text and end in text, f"no {marker} markers"
    return text.split(begin, 1)[1].split(end, 1)[0]


@pytest.fixture(scope="session")
def cellsim():
    """Path of the cellsim executable (scripts/test builds it and sets CELLSIM)."""
    exe = os.environ.get("CELLSIM") or str(ROOT / "build" / "solver" / "cellsim")
    if not (os.path.isfile(exe) and os.access(exe, os.X_OK)):
        pytest.fail(f"cellsim not built at {exe}: run scripts/test (or set CELLSIM)")
    return exe


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def small_runs(cellsim, tmp_path_factory):
    """{dryness: (result, dried state)} of a small cell (the regression cells' settings), fresh and
    X/X0 = 0.5 dried to steady state, compressed briefly (fast, to strain ~0.1: the tissue's mid-sections
    ask for a snapshot there), with snapshots in both stages: ~10 s, real files for the figures and the
    3-D pages."""
    d = tmp_path_factory.mktemp("small runs")  # a space in the path, as users' paths may have
    case = d / "case.json"
    case.write_text('{"cell": {"n_wall": 642, "n_fluid": 700, "turgor_kPa": 100}, "coupling": {"repulsion_f0_N_m": 1.5e-11},'
                    ' "drying": {"steps": 120000, "ramp_time_us": 16, "steady_rms_speed_m_s": 0.05},'
                    ' "compression": {"steps": 1200, "plate_speed_m_s": 16}, "output": {"snapshot_every": 1000}}')
    runs = {}
    for dryness in (1.0, 0.5):
        dried, result = d / f"dried X{dryness}.h5", d / f"run X{dryness}.h5"
        for args in (["-o", str(dried), "--set", "compression.steps=0"], ["--from", str(dried), "-o", str(result)]):
            subprocess.run([cellsim, "run", str(case), "--quiet", "--set", f"drying.dryness={dryness}", *args],
                           check=True, capture_output=True)
        runs[dryness] = (str(result), str(dried))
    return runs


CI = ["config/ci.yaml"]                                 # the paper's 48 cases on reduced cells
TINY = ["config/ci.yaml", "tests/tiny_matrix.yaml"]    # a case or two of each study: every rule, 5 cases


def workflow_config(root, configs, out=None):
    """The config a workflow run on `configs` (merged over config/config.yaml) sees, writing to `out`."""
    config = matrix.workflow_config(configs, root)
    if out is not None:
        config["output_dir"] = str(out)
    return config


def job_counts(output):
    """{rule: count} from snakemake's 'Job stats' table."""
    counts = {}
    for line in output.splitlines():
        m = re.match(r"^(\w+)\s+(\d+)(\s+\d+\s+\d+)?\s*$", line.strip())
        if m and m.group(1) != "total":
            counts[m.group(1)] = int(m.group(2))
    return counts


def workflow_options(out, configs):
    """config/config.yaml with `configs` merged over it, writing into `out` (each run its own folder)."""
    return ["--configfile", *configs, "--config", f"output_dir={out}"]


def workflow_command(out, configs, *extra):
    """snakemake [targets and options in extra] on `configs` into `out` (the config options go last:
    they take lists, which would swallow a target after them)."""
    return ["snakemake", "--cores", "2", *extra, *workflow_options(out, configs)]


def run_workflow(root, out, configs, *extra, timeout=1800):
    """Runs the workflow (without its lock: tests run several at once) and asserts that it succeeds."""
    done = subprocess.run(workflow_command(out, configs, *extra, "--nolock", "-q"), cwd=root, capture_output=True,
                          text=True, timeout=timeout)
    assert done.returncode == 0, (done.stdout + done.stderr)[-4000:]
    return out


def run_reduced_target(root, out, target, reduced_config, timeout=1800):
    """snakemake `target` on config/ci.yaml and a reduced config (tests/*_reduced.yaml) into `out`."""
    return run_workflow(root, out, CI + [reduced_config], target, timeout=timeout)


def reduced_target_fixture(target, reduced_config, timeout=2400):
    """A module fixture: the folder of one run of `target` on a reduced config (run_reduced_target)."""
    @pytest.fixture(scope="module")
    def run(root, tmp_path_factory):
        return run_reduced_target(root, tmp_path_factory.mktemp(f"{target} results"), target, reduced_config,
                                  timeout=timeout)
    return run


def check_target_page(root, out, target, reduced_config, page, headings, figures, tmp_path):
    """A target's page has its headings and shows its figures, each figure is what its spec asks
    (figure_checks.py), and nothing of the default target was written. Returns the page's text."""
    from analysis import matrix
    from figure_checks import check_figures
    text = (out / "report" / page).read_text()
    for heading in headings:
        assert heading in text
    config = workflow_config(root, CI + [reduced_config], out)
    assert matrix.target_figures(config, target) == figures
    check_figures(config, out, root, tmp_path, figures)
    for fig in figures:
        assert f"figures/{fig}.png" in text
    assert not (out / "figures" / "fig01.png").exists()
    assert not (out / "report" / "index.html").exists()
    return text


def assert_same_results(out, reference):
    """Every result, table, figure and page of `out` is byte for byte the one of the reference run (the
    report names its own output folder: that name aside)."""
    written = sorted(p.relative_to(reference) for p in reference.rglob("*")
                     if p.is_file() and p.parts[len(reference.parts)] in ("runs", "tables", "figures", "report", "cases"))
    assert len(written) > 50, written
    for path in written:
        ours, theirs = (out / path).read_bytes(), (reference / path).read_bytes()
        if path.suffix == ".html":
            ours, theirs = ours.replace(bytes(out), b"OUT"), theirs.replace(bytes(reference), b"OUT")
        assert ours == theirs, f"{path} differs from the uninterrupted run"


@pytest.fixture(scope="session")
def ci_run(root, tmp_path_factory):
    """The whole workflow on config/ci.yaml, uninterrupted; shared by the tests that need it."""
    return run_workflow(root, tmp_path_factory.mktemp("ci-results"), CI)


@pytest.fixture(scope="session")
def tiny_run(root, tmp_path_factory):
    """The workflow on the tiny matrix, uninterrupted, on the local machine: the reference that a resumed
    run and a run through SLURM must equal byte for byte."""
    return run_workflow(root, tmp_path_factory.mktemp("tiny-results"), TINY)


def emulator_page_prediction(page, fragment):
    """The emulator's slider page (analysis/emulator_page.py) opened in headless Chromium at a setting in
    its address: (its status line, its prediction table as rows of strain, median, 95 % low and high)."""
    import shutil
    import numpy as np
    dom = subprocess.run([shutil.which("chromium"), "--headless", "--no-sandbox", "--virtual-time-budget=5000",
                          "--dump-dom", f"{page.as_uri()}#{fragment}"], capture_output=True, text=True,
                         timeout=120).stdout
    status = re.search(r'<div id="status">([^<]*)</div>', dom)
    rows = re.findall(r"<tr><td>([\d.]+)</td><td>([\d.e+-]+)</td><td>([\d.e+-]+)</td><td>([\d.e+-]+)</td></tr>", dom)
    return (status.group(1) if status else dom[-1500:]), np.array(rows, dtype=float)
