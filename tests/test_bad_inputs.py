"""Bad input never crashes, hangs or passes silently: every malformed case file, override and workflow
config gives a non-zero exit and a message naming the problem, and leaves nothing under the output
name. The case files and configs are in tests/bad_inputs/. Run with CELLSIM pointing at a sanitizer
build to also check that none of them trips AddressSanitizer or UndefinedBehaviorSanitizer."""
import pathlib
import subprocess

import pytest

HERE = pathlib.Path(__file__).parent / "bad_inputs"

# case file -> what its message must name
CASES = {
    "syntax_trailing_comma.json": "not valid JSON", "syntax_unclosed.json": "not valid JSON",
    "syntax_single_quotes.json": "not valid JSON", "syntax_empty.json": "not valid JSON",
    "syntax_nan_literal.json": "not valid JSON", "syntax_comment.json": "not valid JSON",
    "not_an_object.json": "JSON object", "unknown_section.json": "walls.G_MPa",
    "unknown_key.json": "wall.shear_modulus", "misspelt_key_case.json": "did you mean 'wall.G_MPa'",
    "misspelt_dryness.json": "did you mean 'drying.dryness'", "section_not_object.json": "cell = 150",
    "type_string_number.json": 'cell.turgor_kPa = "200"', "type_bool.json": "drying.dryness = true",
    "type_array.json": "cell.diameter_um = [150]", "type_null_required.json": "wall.G_MPa = null",
    "type_fractional_count.json": "cell.n_fluid = 3082.5", "overflow_inf.json": "wall.thickness_um = 1e999",
    "overflow_negative_inf.json": "cell.turgor_kPa = -1e999", "negative_diameter.json": "cell.diameter_um = -150",
    "zero_diameter.json": "cell.diameter_um = 0", "zero_fluid.json": "cell.n_fluid = 0",
    "negative_steps.json": "drying.steps = -5", "zero_dt.json": "time.dt_ns = 0",
    "zero_record_every.json": "output.record_every = 0", "dryness_above_one.json": "drying.dryness = 1.2",
    "dryness_zero.json": "drying.dryness = 0", "dryness_negative.json": "drying.dryness = -0.5",
    "end_strain_one.json": "compression.end_strain = 1.0", "too_few_wall_particles.json": "cell.n_wall = 3",
    "fill_gap_too_large.json": "cell.fill_gap_um = 90", "contraction_ratio_one.json": "wall.contraction_ratio = 1.0",
    "description_not_string.json": "description = 42", "dt_too_large.json": "wall-spring stability limit",
    "coupling_model_unknown.json": 'coupling.model = "springs": expected one of lennard_jones, pressure',
    "coupling_model_number.json": "coupling.model = 1",
    "tissue_cells_overlap.json": "tissue.centre_distance_over_diameter", "tissue_zero_cells.json": "tissue.cells_x = 0",
    "tissue_packing_unknown.json": 'tissue.packing = "hexagonal": expected one of cubic, close',
    "tissue_negative_strength.json": "tissue.lamella_strength_MPa = -1",
    "tissue_fracture_energy_below_elastic.json": "tissue.lamella_fracture_energy_J_m2 = 0.01",
    "smoothing_length_twice.json": "fluid.h0_um = 8 and fluid.h_over_dx = 1.2 both set the smoothing length",
    # found by the fuzzing campaign (issue 51; tests/fuzz/corpus holds them too)
    "duplicate_key.json": "cell.n_wall is given twice in case file",
    "too_many_particles.json": "particles in all, more than one run builds",
    "derived_cap_too_many_steps.json": "drying.steps = auto: 80 us at time.dt_ns = 1e-290",
    "fill_gap_leaves_no_fluid.json": "cell.fill_gap_um = 74.99: cell 0",
}

# workflow config (merged over config/config.yaml) -> what the message must name: the problem, and the
# key's path (analysis/config_errors.py: one line, "config: base.wall: unknown key ...")
CONFIGS = {
    "yaml_syntax.yaml": "yaml_syntax.yaml", "yaml_tab_indent.yaml": "yaml_tab_indent.yaml",
    "unknown_top_key.yaml": "config: the config: unknown key 'colour'; known keys: axes, base,",
    "base_unknown_key.yaml": "config: base.wall: unknown key 'G_Mpa'; did you mean 'G_MPa'?",
    "base_bad_range.yaml": "config: base.drying.dryness: 2 is greater than the maximum of 1.0",
    "base_wrong_type.yaml": "config: base.cell.n_wall: 'many' is not of type 'integer'",
    "study_unknown_axis.yaml": "studies.extra.vary.humidity: unknown axis",
    "study_value_out_of_range.yaml": "cell.turgor_kPa = -100",
    "study_empty_values.yaml": "config: studies.extra.vary.dryness: [] is too short",
    "study_value_string.yaml": "axis dryness: case D150_G18_P200_t6_v1_Xhalf has drying.dryness = 'half'",
    "figure_unknown_family.yaml": "config: figures.fig99.family: 'pie' is not one of ['model', 'shapes', 'curves',",
    "figure_unknown_quantity.yaml": "figures.fig99: unknown quantity 'stres'",
    "figure_unknown_reference.yaml": "figures.fig99.references: unknown reference 'oey2007'",
    "reference_missing_file.yaml": "references.r.file: no such file 'data/references/none.csv'",
    "reference_bad_unit.yaml": "config: references.r.strain_unit: 'permille' is not one of ['1', '%']",
    "study_unknown_level.yaml": "studies.extra.vary.resolution: value 5",
    "study_target_all.yaml": "'all' is not one of ['convergence', 'convergence_fine', 'tissue',",
    "shrinkage_reference_unknown.yaml": "figures.tis04.shrinkage_references: unknown reference 'nonesuch'",
    # found by the fuzzing campaign (issue 51): Snakemake's own merge stopped with a TypeError
    "value_for_mapping.yaml": "figures.fig01.where = '3.5': config/config.yaml has a mapping there",
    # a coupled key without its section: a ValueError in the matrix
    "coupled_key_without_section.yaml": "config: axes.cells.coupled.27: 'G_Mpa' does not match",
}


def run(cmd, cwd=None):
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=120, cwd=cwd)
    assert done.returncode >= 0, f"killed by signal {-done.returncode}: {done.stderr}"
    for marker in ("Sanitizer", "runtime error:", "Segmentation", "core dumped", "terminate called"):
        assert marker not in done.stderr, done.stderr
    return done


def test_every_bad_file_is_listed():
    assert sorted(p.name for p in (HERE / "cases").iterdir()) == sorted(CASES)
    assert sorted(p.name for p in (HERE / "configs").iterdir()) == sorted(CONFIGS)
    assert len(CASES) + len(CONFIGS) >= 30


@pytest.mark.parametrize("name", sorted(CASES))
def test_bad_case_file(cellsim, tmp_path, name):
    out = tmp_path / "out.h5"
    done = run([cellsim, "run", str(HERE / "cases" / name), "-o", str(out), "--quiet"])
    assert done.returncode == 2, done.stderr
    assert CASES[name] in done.stderr, done.stderr
    assert not out.exists() and not (tmp_path / "out.h5.partial").exists()
    assert run([cellsim, "validate", str(HERE / "cases" / name)]).returncode == 2


@pytest.mark.parametrize("args, named", [
    (["run", "MISSING.json", "-o", "OUT"], "MISSING.json"),
    (["run", "CASE", "-o", "/nonexistent-dir/out.h5"], "/nonexistent-dir"),
    (["run", "CASE", "-o", "/etc/hostname/out.h5"], "/etc/hostname"),
    (["run", "CASE", "-o", "OUT", "--from", "MISSING.h5"], "MISSING.h5"),
    (["run", "CASE", "-o", "OUT", "--set", "drying.dryness"], "key=value"),
    (["run", "CASE", "-o", "OUT", "--set", "drying.dryness=abc"], "drying.dryness"),
    (["run", "CASE", "-o", "OUT", "--set", "drying.dryness=inf"], "finite"),
    (["run", "CASE", "-o", "OUT", "--set", "drying.dryness=1e400"], "drying.dryness = 1e400: value must be finite"),
    (["run", "CASE", "-o", "OUT", "--set", "coupling.model=\udcff"], "coupling.model = "),  # the byte 0xff
    (["run", "CASE", "-o", "OUT", "--set", "cell.n_wal=100"], "cell.n_wall"),
    (["run", "CASE", "-o", "OUT", "--set", "coupling.model=springs"], "coupling.model"),
    (["run", "CASE", "-o"], "-o needs a value"),
    (["bench", "--steps", "0"], "--steps"),
    (["frobnicate"], "unknown command"),
])
def test_bad_command_line(cellsim, tmp_path, args, named):
    case = tmp_path / "case.json"
    case.write_text('{"cell": {"n_wall": 162, "n_fluid": 100}, "drying": {"steps": 0}, "compression": {"steps": 0}}')
    args = [str(case) if a == "CASE" else str(tmp_path / "out.h5") if a == "OUT" else a for a in args]
    done = run([cellsim] + args, cwd=tmp_path)
    assert done.returncode == 2, done.stderr
    assert named in done.stderr, done.stderr
    assert not (tmp_path / "out.h5").exists()


@pytest.mark.parametrize("name", sorted(CONFIGS))
def test_bad_workflow_config(root, tmp_path, name):
    done = run(["snakemake", "--nolock", "-n", "--cores", "2", "--configfile", str(HERE / "configs" / name),
                "--config", f"output_dir={tmp_path}"], cwd=root)
    assert done.returncode != 0
    message = done.stdout + done.stderr
    named = CONFIGS[name] if isinstance(CONFIGS[name], tuple) else (CONFIGS[name],)
    for words in named:
        assert words in message, message[-1500:]
    assert "Job stats" not in done.stdout


def test_missing_workflow_config(root, tmp_path):
    done = run(["snakemake", "--nolock", "-n", "--cores", "2", "--configfile", str(tmp_path / "nope.yaml")], cwd=root)
    assert done.returncode != 0 and "nope.yaml" in done.stdout + done.stderr


# A reduced cell that settles and runs (zero steps of drying and compression).
TINY_CASE = ('{"cell": {"n_wall": 402, "n_fluid": 400}, "coupling": {"repulsion_f0_N_m": 1.5e-11},'
             ' "drying": {"steps": 0}, "compression": {"steps": 0}}')


def test_file_system_refusal_says_what_hdf5_said(cellsim, tmp_path):
    """A place the system will not let us create a file in: exit 4 (not bad input) and the reason."""
    case = tmp_path / "case.json"
    case.write_text(TINY_CASE)
    done = run([cellsim, "run", str(case), "-o", "/proc/cellsim-out.h5", "--quiet"])
    assert done.returncode == 4, done.stderr
    assert "cannot create HDF5 file '/proc/cellsim-out.h5.partial'" in done.stderr, done.stderr
    assert "No such file or directory" in done.stderr, done.stderr
    assert done.stderr.count("\n") == 1, done.stderr


def test_a_lock_hdf5_cannot_take_names_the_locking_switch(cellsim, tmp_path):
    """Another process holds the file (HDF5 locks with flock, as on file systems without locking the
    lock request fails): the message says so and names HDF5_USE_FILE_LOCKING=FALSE."""
    h5py = pytest.importorskip("h5py")
    case = tmp_path / "case.json"
    case.write_text(TINY_CASE)
    out = tmp_path / "out.h5"
    with h5py.File(tmp_path / "out.h5.partial", "w"):  # held open for writing: locked
        done = run([cellsim, "run", str(case), "-o", str(out), "--quiet"])
    assert done.returncode == 4, done.stderr
    assert "unable to lock" in done.stderr and "HDF5_USE_FILE_LOCKING=FALSE" in done.stderr, done.stderr
    assert not out.exists()
    assert run([cellsim, "run", str(case), "-o", str(out), "--quiet"]).returncode == 0
    with h5py.File(out, "r+"):  # and a --from file another program is writing
        done = run([cellsim, "run", str(case), "--from", str(out), "-o", str(tmp_path / "next.h5"), "--quiet"])
    assert done.returncode == 4, done.stderr
    assert "--from" in done.stderr and "HDF5_USE_FILE_LOCKING=FALSE" in done.stderr, done.stderr


def test_a_file_nested_100_000_deep_is_refused_naming_it(cellsim, tmp_path):
    """Found by the fuzzer: the message showed the value by the JSON library's recursive dump, which
    overflowed the stack."""
    case = tmp_path / "deep.json"
    case.write_text("[" * 100_000 + "]" * 100_000)
    done = run([cellsim, "validate", str(case)])
    assert done.returncode == 2 and "deep.json' holds [[[...: an array nested over 8 deep" in done.stderr, done.stderr


def test_a_file_that_is_no_object_is_refused_with_a_set_too(cellsim, tmp_path):
    """Found by the fuzzer: --set made any top-level value into an object, and the file's content was
    dropped without a word."""
    done = run([cellsim, "validate", str(HERE / "cases" / "not_an_object.json"), "--set", "drying.dryness=0.5"])
    assert done.returncode == 2 and "not_an_object.json' holds [1,2,3]: a case is a JSON object" in done.stderr, done.stderr


def test_a_failure_in_the_first_step_after_a_snapshot_exits_3_with_its_partial_file(cellsim, tmp_path):
    """Found by the fuzzer: the failing state's snapshot took the name of the snapshot of the same step
    count (the failure comes before the step is counted), HDF5 refused it, and the run exited 1."""
    case = tmp_path / "case.json"
    case.write_text('{"cell": {"n_wall": 162, "n_fluid": 100}, "settle": {"max_iterations": 40}, '
                    '"tissue": {"cells_x": 2, "cells_y": 2, "lateral": "periodic", "period_viscosity_Pa_s": 1e-9}}')
    out = tmp_path / "out.h5"
    done = run([cellsim, "run", str(case), "-o", str(out), "--quiet"])
    assert done.returncode == 3, done.stderr
    assert "step 0 (t = 0.001 us, drying): the period would strain" in done.stderr
    assert not out.exists() and (tmp_path / "out.h5.partial").exists()


@pytest.fixture(scope="module")
def rest_state(cellsim, tmp_path_factory):
    """A small cell at rest (its case, its state), to continue from."""
    d = tmp_path_factory.mktemp("rest")
    case = d / "case.json"
    case.write_text('{"cell": {"n_wall": 162, "n_fluid": 100}, "settle": {"max_iterations": 40}, '
                    '"drying": {"steps": 0}, "compression": {"steps": 0}}')
    subprocess.run([cellsim, "run", str(case), "-o", str(d / "rest.h5"), "--quiet"], check=True)
    return case, d / "rest.h5"


def continue_from(cellsim, case, state, tmp_path):
    out = tmp_path / "out.h5"
    done = run([cellsim, "run", str(case), "--from", str(state), "-o", str(out), "--quiet", "--set", "drying.steps=5"])
    assert not out.exists() and not (tmp_path / "out.h5.partial").exists()
    return done


def test_a_bit_flipped_in_a_saved_state_is_refused_not_used(cellsim, rest_state, tmp_path):
    """Found by the fuzzer: a flipped bit in the saved positions was continued from without a word. Every
    dataset carries a Fletcher-32 checksum (docs/output-reference.md)."""
    import h5py
    case, state = rest_state
    flipped = tmp_path / "flipped.h5"
    data = bytearray(state.read_bytes())
    with h5py.File(state, "r") as f:  # the dataset is one chunk: where it starts in the file
        chunk = f["state/fluid_positions"].id.get_chunk_info(0).byte_offset
    data[chunk + 100] ^= 0x10  # a mantissa bit of a position: still a finite number
    flipped.write_bytes(bytes(data))
    done = continue_from(cellsim, case, flipped, tmp_path)
    assert done.returncode == 2, done.stderr
    assert f"--from '{flipped}' cannot be read as a cellsim result" in done.stderr and "fluid_positions" in done.stderr


def test_a_saved_state_with_an_array_one_short_is_refused_before_any_output(cellsim, rest_state, tmp_path):
    """Found by the fuzzer: a state's masses one shorter than its positions overran a buffer in the pair
    loop (AddressSanitizer)."""
    import h5py
    import shutil
    case, state = rest_state
    edited = tmp_path / "edited.h5"
    shutil.copy(state, edited)
    with h5py.File(edited, "r+") as f:
        masses = f["state/fluid_mass"][()]
        del f["state/fluid_mass"]
        f["state/fluid_mass"] = masses[:-1]
    done = continue_from(cellsim, case, edited, tmp_path)
    assert done.returncode == 2, done.stderr
    assert f"--from '{edited}': saved state has 99 fluid masses; the case builds 100" in done.stderr


def test_an_infinite_number_after_a_very_long_string_is_named(cellsim, tmp_path):
    """Found by the fuzzer: the search for the key of a number like 1e999 used std::regex, which recursed
    per character and overflowed the stack on a 100 000-character string before it."""
    case = tmp_path / "long.json"
    case.write_text('{"fluid": {"viscosity_Pa_s": "' + "x" * 100_000 + '"}, "tissue": {"cells_y": -1e999}}')
    done = run([cellsim, "validate", str(case)])
    assert done.returncode == 2 and "tissue.cells_y = -1e999: value must be finite" in done.stderr, done.stderr
