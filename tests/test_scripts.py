"""The scripts find Python the way a user's machine has it (scripts/lib/python.sh), and the SLURM
profile stops on a Snakemake it does not support with the way forward."""
import pathlib
import subprocess

import yaml

ROOT = pathlib.Path(__file__).resolve().parent.parent
LIB = ROOT / "scripts" / "lib" / "python.sh"


def find_python(modules, env_extra, tmp_path):
    script = f'source "{LIB}"; find_python {" ".join(modules)} && echo "PYTHON=$PYTHON"'
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path)} | env_extra
    return subprocess.run(["bash", "-c", script], capture_output=True, text=True, env=env, timeout=60)


def fake_python(directory, exit_code):
    """A python3 that answers every import check with exit_code (0: 'has' every module)."""
    directory.mkdir(parents=True, exist_ok=True)
    fake = directory / "python3"
    fake.write_text(f"#!/bin/sh\nexit {exit_code}\n")
    fake.chmod(0o755)
    return fake


def test_debian_python_comes_first_when_it_has_the_modules(tmp_path):
    broken = fake_python(tmp_path / "pyenv shims", 1)  # first on PATH, imports nothing (a space, too)
    done = find_python(["json", "numpy"], {"PATH": f"{broken.parent}:/usr/bin:/bin"}, tmp_path)
    assert done.returncode == 0, done.stderr
    assert "PYTHON=/usr/bin/python3" in done.stdout


def test_another_python3_on_path_is_used_when_debians_lacks_a_module(tmp_path):
    able = fake_python(tmp_path / "conda bin", 0)
    done = find_python(["no_such_module_cellsim"], {"PATH": f"/usr/bin:{able.parent}:/bin"}, tmp_path)
    assert done.returncode == 0, done.stderr
    assert f"PYTHON={able}" in done.stdout


def test_no_python_with_the_modules_is_a_clear_error(tmp_path):
    done = find_python(["no_such_module_cellsim"], {}, tmp_path)
    assert done.returncode == 1
    assert "no Python 3 here imports all of: no_such_module_cellsim" in done.stderr
    assert "tried: /usr/bin/python3" in done.stderr and "scripts/setup" in done.stderr


def test_cellsim_python_is_the_only_candidate_when_set(tmp_path):
    broken = fake_python(tmp_path / "mine", 1)
    done = find_python(["json"], {"CELLSIM_PYTHON": str(broken)}, tmp_path)
    assert done.returncode == 1
    assert f"tried: {broken}" in done.stderr and "CELLSIM_PYTHON" in done.stderr


def test_no_script_hard_codes_a_python():
    for path in list((ROOT / "scripts").rglob("*")) + list((ROOT / "workflow").rglob("*")):
        if path.is_file() and path.suffix not in (".pyc",) and path != LIB:
            text = path.read_text(errors="replace")
            assert not text.startswith("#!/usr/bin/python"), path
            code = [line for line in text.splitlines() if not line.lstrip().startswith("#")]
            assert not any("/usr/bin/python3" in line for line in code), path


def test_slurm_profile_stops_on_snakemake_8_with_the_way_forward(tmp_path):
    """Snakemake 8+ reads config.v8+.yaml (Snakemake 7 ignores it); the key it sets makes the
    Snakefile stop with the executor plugin's command and resource names."""
    v8 = yaml.safe_load((ROOT / "workflow" / "profiles" / "slurm" / "config.v8+.yaml").read_text())
    assert v8 == {"config": ["slurm_profile_needs_snakemake_7=true"]}
    assert "cluster" in yaml.safe_load((ROOT / "workflow" / "profiles" / "slurm" / "config.yaml").read_text())
    done = subprocess.run(["snakemake", "-n", "--nolock", "--cores", "1", "--config", v8["config"][0],
                           f"output_dir={tmp_path}"], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert done.returncode != 0
    message = done.stdout + done.stderr
    for words in ("Snakemake 7.x only", "snakemake-executor-plugin-slurm", "--executor slurm", "slurm_partition",
                  "slurm_account", "mem_mb", "runtime"):
        assert words in message, message[-2000:]


def test_workflow_rules_have_no_run_blocks():
    """Snakemake 7 spawns a `run:` job with an unquoted `cd <working directory>`, which fails in a
    checkout whose path contains a space; `shell:` (paths quoted with :q) and `script:` do not."""
    import re
    for path in [ROOT / "Snakefile", *sorted((ROOT / "workflow" / "rules").glob("*.smk"))]:
        assert not re.search(r"^\s+run:\s*$", path.read_text(), flags=re.M), path
        for command in re.findall(r"\{(input|output|log)(?:\.\w+)?\}", path.read_text()):
            raise AssertionError(f"{path.name}: quote {{{command}...}} in shell commands with :q")
