# Builds cellsim with CMake (Release) when a source changes.
rule build_solver:
    input:
        "CMakeLists.txt",
        "solver/CMakeLists.txt",
        expand("solver/src/{name}", name=sorted(glob_wildcards("solver/src/{name}").name)),
    output:
        SOLVER,
    log:
        f"{OUT}/logs/build_solver.log",
    threads: 2  # scaled down to --cores when fewer
    shell:
        "(cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && "
        "cmake --build build -j{threads} --target cellsim) > {log:q} 2>&1"
