"""docs/case-reference.md must list exactly what the solver accepts and writes."""
import subprocess


def table_between(text, marker):
    begin, end = f"<!-- begin {marker} -->\n", f"<!-- end {marker} -->"
    return text.split(begin, 1)[1].split(end, 1)[0]


def test_case_key_table_matches_solver(cellsim, root):
    doc = (root / "docs" / "case-reference.md").read_text()
    solver = subprocess.run([cellsim, "params"], check=True, capture_output=True, text=True).stdout
    assert table_between(doc, "case-keys") == solver, "run scripts/update-docs"


def test_output_table_matches_solver(cellsim, root):
    doc = (root / "docs" / "case-reference.md").read_text()
    solver = subprocess.run([cellsim, "outputs"], check=True, capture_output=True, text=True).stdout
    assert table_between(doc, "output-timeseries") == solver, "run scripts/update-docs"


def test_required_key_paths_exist(cellsim):
    """The workflow and users' scripts rely on these paths (issue: solver foundation)."""
    solver = subprocess.run([cellsim, "params"], check=True, capture_output=True, text=True).stdout
    for key in ["cell.diameter_um", "cell.n_wall", "cell.n_fluid", "cell.turgor_kPa", "wall.G_MPa",
                "wall.thickness_um", "drying.dryness", "drying.steps", "compression.steps",
                "compression.plate_speed_m_s", "output.record_every"]:
        assert f"| `{key}` |" in solver, key


def test_example_case_is_valid_and_at_paper_baseline(cellsim, root):
    import json
    example = root / "solver" / "examples" / "apple-baseline.json"
    out = subprocess.run([cellsim, "validate", str(example)], check=True, capture_output=True, text=True).stdout
    resolved = json.loads(out)
    assert resolved["cell"]["diameter_um"] == 150
    assert resolved["cell"]["turgor_kPa"] == 200
    assert resolved["wall"]["G_MPa"] == 18
    assert resolved["drying"]["steps"] == 80000  # the cap; drying ends at steady state
    assert resolved["compression"]["steps"] == 25000
