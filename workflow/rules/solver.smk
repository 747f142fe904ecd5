# Builds cellsim with CMake (Release) when a source changes (every file under solver/src's layers).
from pathlib import Path

rule build_solver:
    input:
        "CMakeLists.txt",
        "solver/CMakeLists.txt",
        sorted(str(p) for p in Path("solver/src").rglob("*") if p.is_file()),
    output:
        SOLVER,
    log:
        f"{OUT}/logs/build_solver.log",
    threads: 2  # scaled down to --cores when fewer
    shell:
        "(cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && "
        "cmake --build build -j{threads} --target cellsim) > {log:q} 2>&1"
