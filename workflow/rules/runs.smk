# One case file per case, per dried state and per state at rest: settle each cell once, dry it to
# every dryness from there, and compress every case from its dried state.

wildcard_constraints:
    case="[A-Za-z0-9_.+-]+",
    dried="[A-Za-z0-9_.+-]+",
    rest="[A-Za-z0-9_.+-]+",


# The JSON is made here, when the workflow is parsed, and written by the shell: no Python process
# per file (a `script:` job spends most of a second importing Snakemake). A changed case changes the
# rule's params, which makes Snakemake write the file again.
rule case_file:
    output:
        f"{OUT}/cases/{{case}}.json",
    params:
        json=lambda w: matrix.case_json(CASES[w.case].case),
    shell:
        "printf '%s' {params.json:q} > {output:q}"


rule dried_case_file:
    output:
        f"{OUT}/cases/dried/{{dried}}.json",
    params:
        json=lambda w: matrix.case_json(DRIED[w.dried]),
    shell:
        "printf '%s' {params.json:q} > {output:q}"


rule rest_case_file:
    output:
        f"{OUT}/cases/rest/{{rest}}.json",
    params:
        json=lambda w: matrix.case_json(REST[w.rest]),
    shell:
        "printf '%s' {params.json:q} > {output:q}"


# The cell settled at rest (the relaxation before drying): its case has no drying and no compression.
rule settle:
    input:
        exe=SOLVER,
        case=f"{OUT}/cases/rest/{{rest}}.json",
    output:
        h5=f"{OUT}/runs/rest/{{rest}}.h5",
        wall=f"{OUT}/runs/rest/{{rest}}.wall.xdmf",
        fluid=f"{OUT}/runs/rest/{{rest}}.fluid.xdmf",
    log:
        f"{OUT}/logs/settle/{{rest}}.log",
    threads: lambda w: run_resources("dry", REST[w.rest], "threads", 1)
    resources:
        mem_mb=lambda w: run_resources("dry", REST[w.rest], "mem_mb", 1000),
        runtime=lambda w: run_resources("dry", REST[w.rest], "runtime_min", 30),
    shell:
        "{input.exe:q} run {input.case:q} --threads {threads} -o {output.h5:q} > {log:q} 2>&1"


# Drying starts from the state at rest: the same bits as settling again (solver/tests/test_continue.cpp).
rule dry:
    input:
        exe=SOLVER,
        case=f"{OUT}/cases/dried/{{dried}}.json",
        rest=lambda w: rest_file(REST_OF[w.dried]),
    output:
        h5=f"{OUT}/runs/dried/{{dried}}.h5",
        wall=f"{OUT}/runs/dried/{{dried}}.wall.xdmf",
        fluid=f"{OUT}/runs/dried/{{dried}}.fluid.xdmf",
    log:
        f"{OUT}/logs/dry/{{dried}}.log",
    threads: lambda w: run_resources("dry", DRIED[w.dried], "threads", 1)
    resources:
        mem_mb=lambda w: run_resources("dry", DRIED[w.dried], "mem_mb", 1000),
        runtime=lambda w: run_resources("dry", DRIED[w.dried], "runtime_min", 30),
    shell:
        "{input.exe:q} run {input.case:q} --from {input.rest:q} --set compression.steps=0 --threads {threads} "
        "-o {output.h5:q} > {log:q} 2>&1"


rule compress:
    input:
        exe=SOLVER,
        case=f"{OUT}/cases/{{case}}.json",
        dried=lambda w: dried_file(CASES[w.case].dried),
    output:
        h5=f"{OUT}/runs/{{case}}.h5",
        wall=f"{OUT}/runs/{{case}}.wall.xdmf",
        fluid=f"{OUT}/runs/{{case}}.fluid.xdmf",
    log:
        f"{OUT}/logs/compress/{{case}}.log",
    threads: lambda w: run_resources("compress", CASES[w.case].case, "threads", 1)
    resources:
        mem_mb=lambda w: run_resources("compress", CASES[w.case].case, "mem_mb", 1000),
        runtime=lambda w: run_resources("compress", CASES[w.case].case, "runtime_min", 20),
    shell:
        "{input.exe:q} run {input.case:q} --from {input.dried:q} --threads {threads} -o {output.h5:q} > {log:q} 2>&1"
