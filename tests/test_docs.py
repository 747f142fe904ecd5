"""docs/case-reference.md and docs/output-reference.md list exactly what the solver accepts and writes,
config/schema/case.schema.json is the solver's own schema, the license and citation are there, and every
citation in the tree (model.md sections, the paper's equations, repository files) resolves."""
import json
import re
import subprocess

import yaml

from conftest import between_markers


def test_case_key_table_matches_solver(cellsim, root):
    doc = (root / "docs" / "case-reference.md").read_text()
    solver = subprocess.run([cellsim, "params"], check=True, capture_output=True, text=True).stdout
    assert between_markers(doc, "case-keys") == solver, "run scripts/update-docs"


def test_output_table_matches_solver(cellsim, root):
    doc = (root / "docs" / "output-reference.md").read_text()
    solver = subprocess.run([cellsim, "outputs"], check=True, capture_output=True, text=True).stdout
    assert between_markers(doc, "output-timeseries") == solver, "run scripts/update-docs"


def test_case_schema_file_matches_solver(cellsim, root):
    """The workflow validates cases against config/schema/case.schema.json: it is the solver's own."""
    solver = subprocess.run([cellsim, "schema"], check=True, capture_output=True, text=True).stdout
    assert (root / "config" / "schema" / "case.schema.json").read_text() == solver, "run scripts/update-docs"


def test_energy_terms_file_matches_solver(cellsim, root):
    """The workflow's aggregation reads the energy account's terms from config/schema/energy_terms.json."""
    solver = subprocess.run([cellsim, "energy-terms"], check=True, capture_output=True, text=True).stdout
    assert (root / "config" / "schema" / "energy_terms.json").read_text() == solver, "run scripts/update-docs"
    terms = json.loads(solver)
    assert {t["role"] for t in terms} == {"stored", "flow", "loss"} and len(terms) > 15


def test_case_reference_names_every_section_of_the_schema(cellsim, root):
    schema = json.loads(subprocess.run([cellsim, "schema"], check=True, capture_output=True, text=True).stdout)
    sections = {name for name, spec in schema["properties"].items() if spec.get("type") == "object"}
    assert {"cell", "wall", "settle", "tissue"} <= sections, sections  # the test reads what it should
    intro = (root / "docs" / "case-reference.md").read_text().split("## ", 1)[0]
    named = set(re.findall(r"`(\w+)`", intro.split("sections (", 1)[1].split(")", 1)[0]))
    assert named == sections, f"docs/case-reference.md names {sorted(named)}, the schema has {sorted(sections)}"
    words = {8: "eight", 9: "nine", 10: "ten", 11: "eleven", 12: "twelve"}
    assert f"up to {words[len(sections)]} sections" in intro


def test_license_and_citation(root):
    """A lab adopting the repository needs a license and a citation: the paper reproduced and the
    project, at the version the build reports."""
    assert (root / "LICENSE").read_text().startswith("MIT License")
    cff = yaml.safe_load((root / "CITATION.cff").read_text())
    assert cff["cff-version"] == "1.2.0" and cff["license"] == "MIT"
    version = re.search(r"project\(cellsim VERSION ([\d.]+)", (root / "CMakeLists.txt").read_text()).group(1)
    assert cff["version"] == version
    paper = cff["preferred-citation"]
    assert paper["doi"] == "10.1371/journal.pone.0235712" and paper["year"] == 2020
    assert [a["family-names"] for a in paper["authors"]][0] == "Rathnayaka"


def test_required_key_paths_exist(cellsim):
    """The workflow and users' scripts rely on these paths (issue: solver foundation)."""
    solver = subprocess.run([cellsim, "params"], check=True, capture_output=True, text=True).stdout
    for key in ["cell.diameter_um", "cell.n_wall", "cell.n_fluid", "cell.turgor_kPa", "wall.G_MPa",
                "wall.thickness_um", "drying.dryness", "drying.steps", "compression.steps",
                "compression.plate_speed_m_s", "output.record_every"]:
        assert f"| `{key}` |" in solver, key


def test_example_case_is_valid_and_at_paper_baseline(cellsim, root):
    example = root / "solver" / "examples" / "apple-baseline.json"
    out = subprocess.run([cellsim, "validate", str(example)], check=True, capture_output=True, text=True).stdout
    resolved = json.loads(out)
    assert resolved["cell"]["diameter_um"] == 150
    assert resolved["cell"]["turgor_kPa"] == 200
    assert resolved["wall"]["G_MPa"] == 18
    assert resolved["drying"]["steps"] == 80000  # the cap; drying ends at steady state
    assert resolved["compression"]["steps"] == 25000
    # The caps are left derived (null), so another time step gets the same durations (issue 51: pinned at
    # 1 ns's counts, a run at 0.5 ns stopped its compression at strain 0.067).
    written = json.loads(example.read_text())
    assert written["drying"]["steps"] is None and written["compression"]["steps"] is None
    out = subprocess.run([cellsim, "validate", str(example), "--set", "time.dt_ns=0.5"], check=True,
                         capture_output=True, text=True).stdout
    assert json.loads(out)["compression"]["steps"] == 50000 and json.loads(out)["drying"]["steps"] == 160000


# --- citations: every "model.md §N", "Eq N" and docs/ link in the tree points at something that exists

SOURCES = ["README.md", "Snakefile", "docs", "solver/src", "solver/tests", "solver/examples", "analysis",
           "workflow", "scripts", "config", "tests", "paper", "data/references"]
TEXT_SUFFIXES = {".md", ".cpp", ".hpp", ".in", ".py", ".smk", ".yaml", ".json", ".txt", ".html", ""}


def tree_texts(root):
    for source in SOURCES:
        path = root / source
        files = [path] if path.is_file() else sorted(p for p in path.rglob("*") if p.is_file())
        for f in files:
            if f.suffix in TEXT_SUFFIXES and "__pycache__" not in f.parts:
                yield f, f.read_text(errors="replace")


def model_sections(root):
    """The headings' section names: '1' ... '10', and lettered ones between them ('3b')."""
    return set(re.findall(r"^## §(\d+[a-z]?) ", (root / "docs" / "model.md").read_text(), flags=re.M))


CITATION = re.compile(r"model\.md\)?\s*((?:§\d+[a-z]?(?:-§?\d+[a-z]?)?(?:,\s*|\s+and\s+)?)+)")


def cited_sections(citation):
    """'§3-5, §3b-§3c' -> ['3', '4', '5', '3b', '3c']: a range of numbers expands, lettered ends stand alone."""
    out = []
    for first, last in re.findall(r"§(\d+[a-z]?)(?:-§?(\d+[a-z]?))?", citation):
        if first.isdigit() and last.isdigit():
            out += [str(n) for n in range(int(first), int(last) + 1)]
        else:
            out += [first] + ([last] if last else [])
    return out


def test_every_model_md_section_cited_exists(root):
    sections = model_sections(root)
    numbered = {int(s) for s in sections if s.isdigit()}
    assert numbered == set(range(1, len(numbered) + 1)) and len(numbered) >= 9, sections
    cited = 0
    for path, text in tree_texts(root):
        spans = [m.span(1) for m in CITATION.finditer(text)]
        if path.name not in ("model.md", "test_docs.py"):  # its own headings; this test's patterns
            for bare in re.finditer(r"§\d", text):
                assert any(a <= bare.start() < b for a, b in spans), \
                    f"{path.relative_to(root)}: '{text[bare.start() - 20:bare.end() + 5]}' cites § without model.md"
        for match in CITATION.finditer(text):
            for n in cited_sections(match.group(1)):
                cited += 1
                assert n in sections, f"{path.relative_to(root)} cites model.md §{n}, which does not exist"
        assert not re.search(r"\bmodel §\d", text), f"{path.relative_to(root)}: write 'model.md §N'"
    assert cited > 50  # the tree does cite it: the test is not vacuous


def test_every_paper_equation_cited_exists(root):
    """The paper numbers its equations 1-23; a citation outside that range is a typo."""
    for path, text in tree_texts(root):
        for first, last in re.findall(r"\bEqs?\.? ?\(?(\d+)\)?(?:-(\d+))?", text):
            for n in (int(first), int(last or first)):
                assert 1 <= n <= 23, f"{path.relative_to(root)} cites Eq {n}"


def test_docs_the_tree_names_exist(root):
    for path, text in tree_texts(root):
        for name in re.findall(r"\bdocs/([\w-]+\.md)", text):
            assert (root / "docs" / name).exists(), f"{path.relative_to(root)} names docs/{name}"
        for outside in ("engineering", "studies", "tissue"):  # specs the project does not contain
            assert f"{outside}.md" not in text, f"{path.relative_to(root)} cites {outside}, which the project does not contain"
        if path.suffix == ".md":
            for target in re.findall(r"\]\(([\w./-]+\.md)(?:#[\w-]*)?\)", text):
                assert (path.parent / target).exists(), f"{path.relative_to(root)} links {target}"


# A path into the repository as the tree writes it (`docs/model.md`, data/references/<name>.csv), up to
# its file's extension; a path with a wildcard or a placeholder (<case>, {fig}) is a pattern, not a file.
REPO_PATH = re.compile(r"(?<![\w./-])((?:docs|data|config|scripts|tests|solver|workflow|analysis|paper)/[\w./+-]*\w)")
EXTENSION = re.compile(r"^.*?\.(?:md|py|yaml|json|csv|cpp|hpp|smk|html|txt|cff|sh|in)(?![\w])")
MISSING_ON_PURPOSE = {"data/references/none.csv"}  # the bad-input tests' reference file that does not exist


def test_every_file_the_tree_cites_is_in_the_repository(root):
    """No file cites a document the repository does not contain: every path into the tree resolves,
    and nothing points outside it (the project stands alone)."""
    checked = 0
    for path, text in tree_texts(root):
        for cited in REPO_PATH.findall(text):
            if any(c in cited for c in "*<{") or cited in MISSING_ON_PURPOSE:
                continue
            as_file = EXTENSION.match(cited)
            target = as_file.group(0) if as_file else cited
            checked += 1
            assert (root / target).exists(), f"{path.relative_to(root)} cites {target}, which is not in the repository"
        outside = "../" + "shared"  # written in two parts so that this line does not match itself
        assert outside not in text, f"{path.relative_to(root)} points outside the repository"
    assert checked > 100, checked  # the tree does cite its files: the test is not vacuous


def test_output_reference_lists_everything_a_run_writes(cellsim, root, tmp_path):
    """Every attribute and dataset of a real result file (snapshot steps folded to <step>) is named in
    docs/output-reference.md."""
    h5py = __import__("pytest").importorskip("h5py")
    case = tmp_path / "case.json"
    case.write_text('{"cell": {"n_wall": 402, "n_fluid": 400}, "coupling": {"repulsion_f0_N_m": 1.5e-11},'
                    ' "drying": {"steps": 100}, "compression": {"steps": 100}, "output": {"snapshot_every": 100}}')
    subprocess.run([cellsim, "run", str(case), "-o", str(tmp_path / "out.h5"), "--quiet"], check=True,
                   capture_output=True)
    doc = (root / "docs" / "output-reference.md").read_text()
    names = set()
    with h5py.File(tmp_path / "out.h5") as f:
        names.update(f.attrs)

        def visit(name, obj):
            if name.startswith("timeseries/"):
                return  # the generated table above checks these
            names.add(name.split("/")[-1])
            names.update(obj.attrs)
        f.visititems(visit)
    undocumented = sorted(n for n in names if not re.fullmatch(r"\d{9}", n) and f"`{n}`" not in doc
                          and f"/{n}`" not in doc and f"/{n}/" not in doc)
    assert not undocumented, f"written but not in docs/output-reference.md: {undocumented}"
    assert "`failure`" in doc  # written only by a failed run
